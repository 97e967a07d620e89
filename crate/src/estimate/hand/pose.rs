//! A hand's pose about the wrist, from the scan ([`pose_hands`]): the wrist slid along the
//! forearm, then a free hand turned and kept when its own vertices match better and stretched to
//! its fingertip (`length.rs`), or a hand resting on the body laid on it (`laid.rs`).

use nalgebra::{Point3, UnitQuaternion, Vector3};

use super::laid::laid_hand;
use super::laid_wrist::laid_wrist;
use super::length::stretch_to_fingertip;
use super::moments::{hand_like, hand_rotation, surface, BeyondWrist, Surface};
use super::wrist_profile::{wrist_from_profile, Profiles};
use super::{slide_wrist, HandPose};
use crate::estimate::matching::Matching;
use crate::estimate::params::{EstimateParams, HandParams};
use crate::mesh::normals::vertex_normals_into;
use crate::mesh::Mesh;
use crate::template::hand::{mid, turn_hand, wrist_and_axis, Hand};

/// Vertices and where they are.
type Placed = Vec<(u32, Point3<f64>)>;

/// Moves each hand of `hands` in `positions` (the segment-wise fit's, metres) to the scan's hand
/// (`scan`, metres, indexed by `matching`): the slide along the forearm, then the turn about the
/// wrist of a hand-like one (kept when it matches better); a hand resting on the body is laid on
/// it by [`laid_hand`] (`params.hand`; an arm is bent when bent more than
/// `params.segments.max_bend_deg`, its wrist's profile by `params.profile`). Per hand, what was done (`None`: a laid hand with no profile and no
/// plane or strip found; left as it was).
pub fn pose_hands(
    hands: &[Hand],
    positions: &mut [Point3<f64>],
    triangles: &[[u32; 3]],
    scan: &Mesh,
    matching: &Matching<'_>,
    params: &EstimateParams,
) -> Vec<Option<HandPose>> {
    let scan_surface = surface(&scan.positions, &scan.triangles);
    let profiles = Profiles {
        triangles,
        scan,
        params: &params.profile,
    };
    let max_bend = params.segments.max_bend_deg;
    hands
        .iter()
        .map(|hand| {
            pose_hand(
                hand,
                positions,
                &scan_surface,
                &profiles,
                matching,
                &params.hand,
                max_bend,
            )
        })
        .collect()
}

fn pose_hand(
    hand: &Hand,
    positions: &mut [Point3<f64>],
    scan_surface: &Surface,
    profiles: &Profiles<'_>,
    matching: &Matching<'_>,
    params: &HandParams,
    max_bend_deg: f64,
) -> Option<HandPose> {
    let max_slide = params.max_slide;
    let reach = |positions: &[Point3<f64>], wrist: Point3<f64>| {
        hand.share
            .iter()
            .map(|(v, _)| (positions[*v as usize] - wrist).norm())
            .fold(0.0, f64::max)
            * params.reach
    };
    let (wrist, axis) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    // Where the forearm narrows to the wrist and widens into the hand.
    let along = wrist_from_profile(hand, positions, profiles, params)
        .map(|d| d.clamp(-max_slide, max_slide));
    let r = reach(positions, wrist);
    // Only the scan's surface the slide can bring into the region.
    let near: Vec<(Point3<f64>, f64)> = scan_surface
        .iter()
        .filter(|(p, _)| (p - wrist).norm() < r + max_slide)
        .copied()
        .collect();
    let template = surface(positions, &hand.triangles);
    let region = BeyondWrist {
        wrist,
        axis,
        reach: r,
    };
    let free = hand_like(region, &template, &near, params);
    // An arm bent like the hands on the hips: the hand is laid on the body. Bent less, a hand
    // that is not free is when the forearm comes down onto the body and levels out onto it.
    let elbow = mid(positions, hand.epicondyles);
    let bend = (elbow - positions[hand.acromion as usize]).angle(&axis);
    let bent = bend > max_bend_deg.to_radians();
    if bent || (bend > params.laid.min_bend_deg.to_radians() && !free) {
        let scan = &profiles.scan.positions;
        let knee = laid_wrist(hand, positions, scan, params);
        if knee.is_some() || bent {
            return laid_hand(hand, positions, knee.or(along), scan, &params.laid);
        }
    }
    let slide = along.unwrap_or(0.0);
    slide_wrist(hand, positions, axis, slide);
    if !free {
        return Some(HandPose {
            slide,
            rotation: None,
            stretch: None,
        });
    }
    let (wrist, axis) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    let template = surface(positions, &hand.triangles);
    let region = BeyondWrist {
        wrist,
        axis,
        reach: reach(positions, wrist),
    };
    let mut rotation = hand_rotation(region, &template, &near, params);
    if let Some(turn) = rotation {
        // Kept when the hand's own vertices match the scan better for it.
        let mut normals = vec![Vector3::zeros(); positions.len()];
        let mut energy = |positions: &[Point3<f64>]| {
            let pairs = hand_pairs(hand, &hand.own, positions, &mut normals, matching);
            matching.energy(&pairs, hand.own.len())
        };
        let unturned = placed(hand, positions);
        let before = energy(positions);
        turn_hand(hand, positions, wrist, &UnitQuaternion::from(turn));
        let after = energy(positions);
        if after >= before {
            restore(positions, &unturned);
            rotation = None;
        }
    }
    let stretch = stretch_to_fingertip(hand, positions, &profiles.scan.positions, params);
    Some(HandPose {
        slide,
        rotation,
        stretch,
    })
}

/// Where the vertices `hand` moves (the forearm's and the hand's) are in `positions`.
fn placed(hand: &Hand, positions: &[Point3<f64>]) -> Placed {
    hand.slide
        .iter()
        .map(|(v, _)| (*v, positions[*v as usize]))
        .collect()
}

/// Puts the vertices of `at` back where they were.
fn restore(positions: &mut [Point3<f64>], at: &Placed) {
    for (v, p) in at {
        positions[*v as usize] = *p;
    }
}

/// The matches of the hand's own vertices `own` at `positions` (the hand's normals from its own
/// triangles, into `normals`).
fn hand_pairs(
    hand: &Hand,
    own: &[u32],
    positions: &[Point3<f64>],
    normals: &mut [Vector3<f64>],
    matching: &Matching<'_>,
) -> Vec<crate::estimate::matching::Pair> {
    vertex_normals_into(positions, &hand.triangles, normals);
    matching.pairs(own, positions, normals)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimate::hand::P;
    use crate::estimate::params::ProfileParams;
    use crate::template::fixture::{base_body, BaseBody};
    use crate::template::Template;
    use nalgebra::Matrix3;

    /// The template's triangles on `scan` (its vertices moved), indexed for matching.
    fn scan_index(scan: &[Point3<f64>], template: &Template) -> crate::align::SurfaceIndex {
        let mesh = Mesh::new(scan.to_vec(), template.mesh().triangles.clone());
        crate::align::SurfaceIndex::new(&mesh).unwrap()
    }

    /// Matching onto `index` as the estimate's (compatible normals, 10 cm outliers).
    fn matching_on(index: &crate::align::SurfaceIndex) -> Matching<'_> {
        Matching::new(index, &EstimateParams::default())
    }

    /// The template's hand `hand` posed onto `scan` (its surface as `scan_surface`) from the
    /// template's rest positions, as the estimate does (60° the most bend the profiles take).
    fn posed_on(
        template: &Template,
        hand: &Hand,
        scan: &Mesh,
        scan_surface: &Surface,
    ) -> (Vec<Point3<f64>>, HandPose) {
        let index = scan_index(&scan.positions, template);
        let profiles = Profiles {
            triangles: &template.mesh().triangles,
            scan,
            params: &ProfileParams::default(),
        };
        let mut positions = template.mesh().positions.clone();
        let matching = matching_on(&index);
        let pose = pose_hand(
            hand,
            &mut positions,
            scan_surface,
            &profiles,
            &matching,
            &P,
            60.0,
        );
        (positions, pose.unwrap())
    }

    #[test]
    fn a_turn_that_matches_the_hand_worse_is_not_kept() {
        let BaseBody {
            template,
            rest,
            hands,
            ..
        } = base_body();
        let hand = &hands[0];
        // The scan is the template, its surface beside a strip a third of the hand's area a
        // palm's breadth off the hand's flat side (a thigh's edge, a fold of clothing): the
        // moments turn the hand towards it, the hand's own vertices match best where they are.
        let mesh = template.mesh();
        let own: Vec<Point3<f64>> = hand.own.iter().map(|v| rest[*v as usize]).collect();
        let centre =
            Point3::from(own.iter().map(|p| p.coords).sum::<Vector3<f64>>() / own.len() as f64);
        let spread = own
            .iter()
            .map(|p| (p - centre) * (p - centre).transpose())
            .sum::<Matrix3<f64>>();
        let flat_side = spread.symmetric_eigen();
        let normal = flat_side
            .eigenvectors
            .column(flat_side.eigenvalues.imin())
            .into_owned();
        let (wrist, axis) = wrist_and_axis(&rest, hand.styloids, hand.epicondyles);
        let across = axis.cross(&normal).normalize();
        let area: f64 = surface(&rest, &hand.triangles).iter().map(|(_, a)| a).sum();
        let step = 0.002;
        let mut scan_surface = surface(&rest, &mesh.triangles);
        let (long, wide) = (0.08, area / 3.0 / 0.08);
        for i in 0..(long / step) as usize {
            for j in 0..(wide / step) as usize {
                let p = centre
                    + normal * 0.08
                    + axis * (i as f64 * step - long / 2.0)
                    + across * (j as f64 * step - wide / 2.0);
                scan_surface.push((p, step * step));
            }
        }
        let r = P.reach * own.iter().map(|p| (p - wrist).norm()).fold(0.0, f64::max);
        let template_hand = surface(&rest, &hand.triangles);
        let region = BeyondWrist {
            wrist,
            axis,
            reach: r,
        };
        let turn = hand_rotation(region, &template_hand, &scan_surface, &P).unwrap();
        assert!(turn.angle().to_degrees() > 5.0, "{turn:?}");
        let (positions, pose) = posed_on(&template, hand, mesh, &scan_surface);
        assert!(pose.rotation.is_none(), "{pose:?}");
        // Only slid along the forearm.
        for v in &hand.own {
            let moved = positions[*v as usize] - rest[*v as usize];
            assert!((moved - axis * pose.slide).norm() < 1e-9, "{moved}");
        }
    }

    #[test]
    fn a_hand_against_the_thigh_is_slid_along_the_forearm_but_not_turned() {
        let BaseBody {
            template,
            rest,
            triangles,
            hands,
            ..
        } = base_body();
        let hand = &hands[0];
        // The "scan": the template with the forearm 3 cm longer, and beside the hand a strip of
        // twice the hand's area (the thigh it hangs against): not hand-like, so not turned, but
        // its wrist is where the forearm's profile puts it.
        let mut scan = rest.to_vec();
        let (_, axis) = wrist_and_axis(&scan, hand.styloids, hand.epicondyles);
        slide_wrist(hand, &mut scan, axis, 0.03);
        let (wrist, axis) = wrist_and_axis(&scan, hand.styloids, hand.epicondyles);
        let across = axis.cross(&Vector3::z()).normalize();
        let area: f64 = surface(&scan, &hand.triangles).iter().map(|(_, a)| a).sum();
        let mut scan_surface = surface(&scan, &triangles);
        let (step, long) = (0.002, 0.16);
        let wide = 2.0 * area / long;
        for i in 0..(long / step) as usize {
            for j in 0..(wide / step) as usize {
                let p = wrist
                    + axis * (i as f64 * step)
                    + across * 0.04
                    + axis.cross(&across) * (j as f64 * step - wide / 2.0);
                scan_surface.push((p, step * step));
            }
        }
        let (at, along) = wrist_and_axis(&rest, hand.styloids, hand.epicondyles);
        let r = P.reach
            * hand
                .share
                .iter()
                .map(|(v, _)| (rest[*v as usize] - at).norm())
                .fold(0.0, f64::max);
        let template_hand = surface(&rest, &hand.triangles);
        let region = BeyondWrist {
            wrist: at,
            axis: along,
            reach: r,
        };
        assert!(!hand_like(region, &template_hand, &scan_surface, &P));
        let mesh = Mesh::new(scan, triangles.clone());
        let (positions, pose) = posed_on(&template, hand, &mesh, &scan_surface);
        assert!(pose.rotation.is_none(), "{pose:?}");
        assert!((pose.slide - 0.03).abs() < 0.006, "{}", pose.slide);
        for v in hand.styloids {
            let off = (positions[v as usize] - mesh.positions[v as usize]).norm();
            assert!(off < 0.006, "{off}");
        }
    }
}
