//! The wrist along the forearm from the forearm's width profile: the forearm narrowing to the
//! wrist and widening into the hand, on the scan against the posed template.

use nalgebra::Point3;

use super::MAX_SLIDE;
use crate::estimate::profile::{
    profile, register_shift, surface_samples, triangles_near, LimbLine,
};
use crate::mesh::Mesh;
use crate::template::hand::{mid, wrist_and_axis, Hand};

/// A forearm's profile runs from the elbow this many times the way to the wrist, over the
/// hand.
const PROFILE_LINE: f64 = 1.6;

/// Points farther (m) from the forearm's line are not the forearm or the hand.
const PROFILE_RADIUS: f64 = 0.06;

/// Points spread this far apart (m) over the surfaces profiled.
const PROFILE_SPACING: f64 = 0.004;

/// The part of the template's profile (m from its wrist) registered to the scan's: the
/// forearm's narrowing to the wrist and the hand widening out of it.
const PROFILE_WINDOW: (f64, f64) = (-0.06, 0.05);

/// What a forearm's profile is taken from: the template's triangles (at the positions fitted)
/// and the scan.
pub(super) struct Profiles<'a> {
    pub(super) triangles: &'a [[u32; 3]],
    pub(super) scan: &'a Mesh,
}

/// How far (m) the wrist lies along the forearm from where the fit put it, from the forearm's
/// width profile ([`profile`] of the surfaces' samples near the line from the elbow
/// [`PROFILE_LINE`] times the way to the wrist): the shift (up to [`MAX_SLIDE`] towards the
/// hand, half of it back)
/// that brings the posed template's profile over [`PROFILE_WINDOW`] of its wrist — the forearm
/// narrowing to the wrist, the hand widening out of it — nearest the scan's
/// ([`register_shift`]). A hand is wider than the wrist whatever it rests on; a single feature
/// (where the width rises fastest) was also taken from the hip beyond a hollow under the hand
/// (held-out seed 1111). `None` when the profiles overlap too little.
pub(super) fn wrist_from_profile(
    hand: &Hand,
    positions: &[Point3<f64>],
    profiles: &Profiles<'_>,
) -> Option<f64> {
    let (wrist, _) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    let elbow = mid(positions, hand.epicondyles);
    let line = LimbLine {
        root: elbow,
        end: elbow + (wrist - elbow) * PROFILE_LINE,
    };
    let length = (line.end - line.root).norm();
    let at_wrist = 1.0 / PROFILE_LINE;
    let points = |positions: &[Point3<f64>], triangles: &[[u32; 3]]| {
        let near = triangles_near(positions, triangles, &line, PROFILE_RADIUS);
        surface_samples(positions, &near, PROFILE_SPACING)
    };
    let template = profile(
        &points(positions, profiles.triangles),
        &[line],
        0,
        PROFILE_RADIUS,
    );
    let scan = profile(
        &points(&profiles.scan.positions, &profiles.scan.triangles),
        &[line],
        0,
        PROFILE_RADIUS,
    );
    let window = (
        at_wrist + PROFILE_WINDOW.0 / length,
        at_wrist + PROFILE_WINDOW.1 / length,
    );
    let shifts = (-MAX_SLIDE / 2.0 / length, MAX_SLIDE / length);
    Some(register_shift(&template, &scan, window, shifts)? * length)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimate::hand::slide_wrist;
    use crate::template::hand::base_hands;

    #[test]
    fn a_longer_forearm_is_found_from_where_it_widens_into_the_hand() {
        let (template, hands) = base_hands();
        let rest = &template.mesh().positions;
        let triangles = &template.mesh().triangles;
        for hand in &hands {
            for longer in [0.0, 0.03, -0.02] {
                // The "scan": the template with the forearm 3 cm longer (2 cm shorter), the
                // hand carried along.
                let mut scan = rest.to_vec();
                let (_, axis) = wrist_and_axis(&scan, hand.styloids, hand.epicondyles);
                slide_wrist(hand, &mut scan, axis, longer);
                let mesh = Mesh::new(scan, triangles.clone());
                let profiles = Profiles {
                    triangles,
                    scan: &mesh,
                };
                let found = wrist_from_profile(hand, rest, &profiles).unwrap();
                assert!(
                    (found - longer).abs() < 0.006,
                    "{} {longer}: {found}",
                    hand.side
                );
            }
        }
    }
}
