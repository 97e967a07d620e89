//! A foot's pose about the ankle, from the scan ([`pose_feet`]). After the segment-wise fit the
//! foot has moved rigidly with the lower leg: a foot turned at the ankle (rolled onto its outer
//! edge, pointed, or turned out) or an ankle a little higher or lower than the lower leg's
//! stretch puts it is not followed — the lower leg's matches are mostly the shin and calf. Here
//! each foot's own vertices (`template::foot`) are matched to the scan and the foot is moved
//! rigidly onto the matches, a few rounds as in ICP, the motion blended to nothing across the
//! ankle. The motion is kept only when it is small enough to be the ankle's (`FootParams`) and
//! the foot's vertices then match the scan better; a foot the scanner cut off (too few matches)
//! is left where the lower leg put it.

use nalgebra::{Matrix3, Point3, Rotation3, Vector3};

use super::matching::Matching;
use super::params::FootParams;
use crate::mesh::normals::vertex_normals_into;
use crate::mesh::similarity::similarity;
use crate::template::foot::Foot;
use crate::template::hand::mid;

/// Where a foot was moved: the turn about the ankle (degrees) and the ankle's shift (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FootPose {
    pub turn_deg: f64,
    pub shift: f64,
}

/// Moves each foot of `feet` in `positions` (the segment-wise fit's, metres) onto the scan
/// indexed by `matching`. Per foot, how it was moved (`None`: left
/// where it was).
pub fn pose_feet(
    feet: &[Foot],
    positions: &mut [Point3<f64>],
    matching: &Matching<'_>,
    params: &FootParams,
) -> Vec<Option<FootPose>> {
    feet.iter()
        .map(|foot| pose_foot(foot, positions, matching, params))
        .collect()
}

fn pose_foot(
    foot: &Foot,
    positions: &mut [Point3<f64>],
    matching: &Matching<'_>,
    params: &FootParams,
) -> Option<FootPose> {
    // The own vertices' normals from the foot's triangles alone (all those around them).
    let mut normals = vec![Vector3::zeros(); positions.len()];
    let mut pairs_at = |positions: &[Point3<f64>]| {
        vertex_normals_into(positions, &foot.triangles, &mut normals);
        matching.pairs(&foot.own, positions, &normals)
    };
    let ankle = mid(positions, foot.malleoli);
    let start: Vec<Point3<f64>> = foot
        .share
        .iter()
        .map(|(v, _)| positions[*v as usize])
        .collect();
    let mut pairs = pairs_at(positions);
    let tried = foot.own.len();
    if (pairs.len() as f64) < params.min_matched * tried as f64 {
        return None;
    }
    let before = matching.energy(&pairs, tried);
    // The motion so far, x ↦ R·x + t, applied to the foot as the segment-wise fit left it.
    let (mut rotation, mut translation) = (Matrix3::identity(), Vector3::zeros());
    for _ in 0..params.iterations {
        let from: Vec<Point3<f64>> = pairs.iter().map(|p| positions[p.vertex as usize]).collect();
        let to: Vec<Point3<f64>> = pairs.iter().map(|p| p.target).collect();
        let Some(step) = similarity(&from, &to, false) else {
            break;
        };
        rotation = step.rotation * rotation;
        translation = step.rotation * translation + step.translation;
        for ((v, s), p) in foot.share.iter().zip(&start) {
            let moved = rotation * p.coords + translation;
            positions[*v as usize] = Point3::from(p.coords + (moved - p.coords) * *s);
        }
        pairs = pairs_at(positions);
    }
    let turn_deg = Rotation3::from_matrix_unchecked(rotation)
        .angle()
        .to_degrees();
    let shift = ((rotation * ankle.coords + translation) - ankle.coords).norm();
    let better = matching.energy(&pairs, tried) < before;
    if turn_deg > params.max_turn_deg || shift > params.max_shift || !better {
        for ((v, _), p) in foot.share.iter().zip(&start) {
            positions[*v as usize] = *p;
        }
        return None;
    }
    Some(FootPose { turn_deg, shift })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::align::SurfaceIndex;
    use crate::estimate::params::EstimateParams;
    use crate::mesh::Mesh;
    use crate::template::fixture::{base_body, BaseBody};
    use crate::template::foot::feet;
    use nalgebra::UnitQuaternion;

    /// The template with `foot` (each vertex by its share) turned by `turn` about its ankle and
    /// shifted by `shift`: a made-up scan of a foot turned at the ankle.
    fn foot_moved(
        rest: &[Point3<f64>],
        foot: &Foot,
        turn: UnitQuaternion<f64>,
        shift: Vector3<f64>,
    ) -> Vec<Point3<f64>> {
        let ankle = mid(rest, foot.malleoli);
        let mut out = rest.to_vec();
        for (v, s) in &foot.share {
            let p = rest[*v as usize];
            let moved = ankle + turn * (p - ankle) + shift;
            out[*v as usize] = p + (moved - p) * *s;
        }
        out
    }

    /// `feet` posed from the template's `rest` positions onto the scan (`scan`, `triangles`) with
    /// the defaults: where they end and how each was moved.
    fn posed_on(
        rest: &[Point3<f64>],
        feet: &[Foot],
        scan: Vec<Point3<f64>>,
        triangles: Vec<[u32; 3]>,
    ) -> (Vec<Point3<f64>>, Vec<Option<FootPose>>) {
        let params = EstimateParams::default();
        let index = SurfaceIndex::new(&Mesh::new(scan, triangles)).unwrap();
        let matching = Matching::new(&index, &params);
        let mut positions = rest.to_vec();
        let poses = pose_feet(feet, &mut positions, &matching, &params.foot);
        (positions, poses)
    }

    #[test]
    fn a_foot_turned_at_the_ankle_is_turned_back_onto_the_scan() {
        let BaseBody {
            template,
            rest,
            triangles,
            ..
        } = base_body();
        for foot in &feet(&template) {
            // Pointed 8° and rolled 6° onto its outer edge, the ankle 5 mm lower.
            let turn = UnitQuaternion::from_euler_angles(0.14, 0.0, 0.1);
            let scan = foot_moved(&rest, foot, turn, Vector3::new(0.0, -0.005, 0.0));
            let (positions, poses) = posed_on(
                &rest,
                std::slice::from_ref(foot),
                scan.clone(),
                triangles.clone(),
            );
            let pose = poses[0].expect("the foot is moved");
            assert!(
                (7.0..13.0).contains(&pose.turn_deg),
                "{} {pose:?}",
                foot.side
            );
            let off = |at: &[Point3<f64>]| {
                foot.own
                    .iter()
                    .map(|v| (at[*v as usize] - scan[*v as usize]).norm())
                    .sum::<f64>()
                    / foot.own.len() as f64
            };
            // The foot moved 1.5 cm on average; it comes back within 2 mm of where the scan has it.
            assert!(off(&rest) > 0.01, "{}", off(&rest));
            assert!(off(&positions) < 0.002, "{} {}", foot.side, off(&positions));
        }
    }

    #[test]
    fn a_foot_the_scanner_cut_off_is_left_where_it_was() {
        let BaseBody {
            template,
            rest,
            triangles,
            ..
        } = base_body();
        let feet = feet(&template);
        // The scan: the template without the feet (their own triangles gone, their vertices far
        // off): only the lower legs' ends are left near the template's feet.
        let own: std::collections::HashSet<u32> =
            feet.iter().flat_map(|f| f.own.iter().copied()).collect();
        let kept: Vec<[u32; 3]> = triangles
            .iter()
            .filter(|t| !t.iter().any(|v| own.contains(v)))
            .copied()
            .collect();
        let scan: Vec<Point3<f64>> = rest
            .iter()
            .enumerate()
            .map(|(v, p)| {
                if own.contains(&(v as u32)) {
                    p + Vector3::new(10.0, 0.0, 0.0)
                } else {
                    *p
                }
            })
            .collect();
        let (positions, poses) = posed_on(&rest, &feet, scan, kept);
        assert_eq!(poses, vec![None, None]);
        assert_eq!(positions, rest);
    }
}
