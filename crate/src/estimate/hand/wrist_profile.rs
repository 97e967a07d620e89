//! The wrist along the forearm from the forearm's width profile: the forearm narrowing to the
//! wrist and widening into the hand, on the scan against the posed template.

use nalgebra::Point3;

use crate::estimate::params::{HandParams, ProfileParams};
use crate::estimate::profile::{profile, register_shift, triangles_near, LimbLine};
use crate::mesh::surface_points::surface_samples;
use crate::mesh::Mesh;
use crate::template::hand::{mid, wrist_and_axis, Hand};

/// What a forearm's profile is taken from: the template's triangles (at the positions fitted)
/// and the scan, and the profiles' parameters.
pub(super) struct Profiles<'a> {
    pub(super) triangles: &'a [[u32; 3]],
    pub(super) scan: &'a Mesh,
    pub(super) params: &'a ProfileParams,
}

/// How far (m) the wrist lies along the forearm from where the fit put it, from the forearm's
/// width profile ([`profile`] of the surfaces' samples near the line from the elbow
/// `params.profile.line` times the way to the wrist): the shift (up to `params.max_slide`
/// towards the hand, half of it back) that brings the posed template's profile over
/// `params.profile.window` of its wrist — the forearm
/// narrowing to the wrist, the hand widening out of it — nearest the scan's
/// ([`register_shift`]). A hand is wider than the wrist whatever it rests on; a single feature
/// (where the width rises fastest) was also taken from the hip beyond a hollow under the hand
/// (held-out seed 1111). `None` when the profiles overlap too little.
pub(super) fn wrist_from_profile(
    hand: &Hand,
    positions: &[Point3<f64>],
    profiles: &Profiles<'_>,
    params: &HandParams,
) -> Option<f64> {
    let (line_reach, radius) = (params.profile.line, params.profile.radius);
    let (wrist, _) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    let elbow = mid(positions, hand.epicondyles);
    let line = LimbLine {
        root: elbow,
        end: elbow + (wrist - elbow) * line_reach,
    };
    let length = (line.end - line.root).norm();
    let at_wrist = 1.0 / line_reach;
    let points = |positions: &[Point3<f64>], triangles: &[[u32; 3]]| {
        let near = triangles_near(positions, triangles, &line, radius);
        surface_samples(positions, &near, params.profile.spacing)
    };
    let template = profile(
        &points(positions, profiles.triangles),
        &[line],
        0,
        radius,
        profiles.params,
    );
    let scan = profile(
        &points(&profiles.scan.positions, &profiles.scan.triangles),
        &[line],
        0,
        radius,
        profiles.params,
    );
    let window = (
        at_wrist + params.profile.window.0 / length,
        at_wrist + params.profile.window.1 / length,
    );
    let shifts = (-params.max_slide / 2.0 / length, params.max_slide / length);
    Some(register_shift(&template, &scan, window, shifts, profiles.params)? * length)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimate::hand::slide_wrist;
    use crate::template::fixture::{base_body, BaseBody};

    #[test]
    fn a_longer_forearm_is_found_from_where_it_widens_into_the_hand() {
        let BaseBody {
            rest,
            triangles,
            hands,
            ..
        } = base_body();
        for hand in &hands {
            for longer in [0.0, 0.03, -0.02] {
                // The "scan": the template with the forearm 3 cm longer (2 cm shorter), the
                // hand carried along.
                let mut scan = rest.to_vec();
                let (_, axis) = wrist_and_axis(&scan, hand.styloids, hand.epicondyles);
                slide_wrist(hand, &mut scan, axis, longer);
                let mesh = Mesh::new(scan, triangles.clone());
                let profiles = Profiles {
                    triangles: &triangles,
                    scan: &mesh,
                    params: &ProfileParams::default(),
                };
                let found =
                    wrist_from_profile(hand, &rest, &profiles, &HandParams::default()).unwrap();
                assert!(
                    (found - longer).abs() < 0.006,
                    "{} {longer}: {found}",
                    hand.side
                );
            }
        }
    }
}
