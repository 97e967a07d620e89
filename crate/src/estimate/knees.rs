//! The two knees, side against side. Each leg's profile places its knee on its own
//! (`segments.rs`, `place_joints`), and now and then one of them lands far along its leg from
//! the other: held-out seed 6161's subject 005 had its right knee 70 mm up the leg and the left
//! where it belongs; tuning seed 7531's subject 22 its knees 40 and 11 mm off along the legs, in
//! opposite directions. People's
//! femurs are about as long on the left as on the right (the synthetic bodies' within 14 mm), so
//! thighs far apart in length mean a misplaced knee — but not which one. The fit decides: when
//! the two knees' distances from their hips differ by more than
//! [`KneeParams::apart_mm`], the last iterations of the segment-wise fit run from each knee as
//! placed and from each knee moved to the other's distance, and the placement whose legs then
//! lie nearest the scan is kept (the ICP energy of the legs' vertices,
//! [`super::matching::Matching::energy`]).

use nalgebra::Point3;

use super::matching::Matching;
use super::params::KneeParams;
use crate::mesh::normals::vertex_normals;
use crate::template::parts::PartPose;

/// A knee as the profile placed it: the leg's parts, where along the hip → ankle line the fit had
/// it (`before`, a fraction) and the profile put it (`placed`), the line's length (m) and the
/// parts' stretches before the profile.
#[derive(Debug, Clone, Copy)]
pub struct PlacedKnee {
    pub upper: usize,
    pub lower: usize,
    pub before: f64,
    pub placed: f64,
    pub length: f64,
    pub stretches: (f64, f64),
}

impl PlacedKnee {
    /// The knee's distance from the hip joint along the leg (m).
    pub fn thigh(&self) -> f64 {
        self.placed * self.length
    }

    /// Sets the knee at `fraction` of the leg in `poses`: the thigh's stretch scaled to put it
    /// there, the lower leg's to keep the ankle, both within `range`. Returns the fraction the
    /// knee reached (another where a stretch met its range).
    pub fn place(&self, poses: &mut [PartPose], fraction: f64, range: (f64, f64)) -> f64 {
        let clamp = |s: f64| s.clamp(range.0, range.1);
        poses[self.upper].stretch = clamp(self.stretches.0 * fraction / self.before);
        poses[self.lower].stretch =
            clamp(self.stretches.1 * (1.0 - fraction) / (1.0 - self.before));
        self.before * poses[self.upper].stretch / self.stretches.0
    }
}

/// The placements of the knees to try: none but `poses` itself when there are not two knees or
/// their thighs differ by at most `params.apart_mm`; else also each knee moved to the other's
/// distance from its hip.
pub fn knee_placements(
    knees: &[PlacedKnee],
    poses: &[PartPose],
    params: &KneeParams,
    range: (f64, f64),
) -> Vec<Vec<PartPose>> {
    let mut placements = vec![poses.to_vec()];
    let [a, b] = knees else {
        return placements;
    };
    if (a.thigh() - b.thigh()).abs() * 1000.0 <= params.apart_mm {
        return placements;
    }
    for (moved, other) in [(a, b), (b, a)] {
        let mut p = poses.to_vec();
        moved.place(&mut p, other.thigh() / moved.length, range);
        placements.push(p);
    }
    placements
}

/// How far the legs lie from the scan with the template at `positions` (its `triangles`): the
/// ICP energy (m²) of the template's `vertices` that a leg part of `knees` dominates
/// (`dominant`, per template vertex).
pub fn legs_energy(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    vertices: &[u32],
    dominant: &[Option<usize>],
    knees: &[PlacedKnee],
    matching: &Matching<'_>,
) -> f64 {
    let legs: Vec<u32> = vertices
        .iter()
        .copied()
        .filter(|&v| {
            dominant[v as usize].is_some_and(|k| knees.iter().any(|n| n.upper == k || n.lower == k))
        })
        .collect();
    let normals = vertex_normals(positions, triangles);
    let pairs = matching.pairs(&legs, positions, &normals);
    matching.energy(&pairs, legs.len())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::similarity::Similarity;

    const RANGE: (f64, f64) = (0.75, 1.33);

    fn knee(upper: usize, placed: f64, length: f64) -> PlacedKnee {
        PlacedKnee {
            upper,
            lower: upper + 1,
            before: 0.5,
            placed,
            length,
            stretches: (1.0, 1.0),
        }
    }

    fn poses(n: usize) -> Vec<PartPose> {
        vec![
            PartPose {
                transform: Similarity::identity(),
                stretch: 1.0,
            };
            n
        ]
    }

    #[test]
    fn knees_that_agree_are_left_alone() {
        // Thighs 450 and 430 mm: 20 mm apart, under the default 40 mm.
        let knees = [knee(1, 0.5, 0.9), knee(3, 0.5, 0.86)];
        let placements = knee_placements(&knees, &poses(5), &KneeParams::default(), RANGE);
        assert_eq!(placements.len(), 1);
    }

    #[test]
    fn knees_far_apart_are_each_tried_at_the_others_distance() {
        // Right thigh 450 mm, left 0.4 × 0.9 = 360 mm.
        let knees = [knee(1, 0.5, 0.9), knee(3, 0.4, 0.9)];
        let placements = knee_placements(&knees, &poses(5), &KneeParams::default(), RANGE);
        assert_eq!(placements.len(), 3);
        // The right knee moved to 0.4 of its leg: the thigh 0.4 / 0.5 as long, the lower leg
        // 0.6 / 0.5 (the ankle kept); the left untouched.
        let right = &placements[1];
        assert!((right[1].stretch - 0.8).abs() < 1e-12);
        assert!((right[2].stretch - 1.2).abs() < 1e-12);
        assert_eq!(right[3].stretch, 1.0);
        // The left knee moved to 0.5 of its leg.
        let left = &placements[2];
        assert!((left[3].stretch - 1.0).abs() < 1e-12);
        assert_eq!(left[1].stretch, 1.0);
        // Whatever the placement, the stretch stays within its range.
        let far = [knee(1, 0.5, 0.9), knee(3, 0.1, 0.9)];
        let placements = knee_placements(&far, &poses(5), &KneeParams::default(), RANGE);
        assert_eq!(placements[1][1].stretch, RANGE.0);
    }
}
