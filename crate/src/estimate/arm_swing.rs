//! The arms' swing about the shoulder tried from several starts: the segment-wise fit's nearest
//! points only find an arm within about 20° of where the similarity fit left it (the template's
//! A-pose). An arm held down along the body (≈ 10° from it, 30° from the template's) stays
//! out at the side, its forearm and hand matched to the hip and thigh, and the fine fit then
//! drags the template's hand across the body (docs/landmarks-estimate.md). So each arm, with its
//! upper and lower part together, is turned about its shoulder in the body's frontal plane by
//! each of the turns of `ArmSwingParams::turns_deg` and kept at the turn whose matches fit best; the ICP then goes on from
//! there. An arm that none of those turns finds (raised beside or above the head, 90–150° from
//! the body) is tried at `ArmSwingParams::raised_turns_deg` too; an arm found among the first
//! turns makes no further run.

use nalgebra::{Point3, Rotation3, Unit, Vector3};

use super::matching::{Matching, Pair};
use super::params::ArmSwingParams;
use crate::mesh::normals::vertex_normals;
use crate::mesh::similarity::Similarity;
use crate::template::parts::{blend, Part, PartPose};

/// An arm: its upper and lower part (indices into the parts).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arm {
    pub upper: usize,
    pub lower: usize,
}

/// The arms among `parts`: a limb's lower part that does not stretch (`segments::parts`) and
/// its parent.
pub fn arms(parts: &[Part]) -> Vec<Arm> {
    parts
        .iter()
        .enumerate()
        .filter(|(_, p)| !p.stretches && p.end.is_some())
        .filter_map(|(lower, p)| {
            Some(Arm {
                upper: p.parent?,
                lower,
            })
        })
        .collect()
}

/// The template's frontal-plane normal and the trunk's up (unit, template frame): the normal
/// across the shoulders (the arms' joints) and the trunk's up (the torso's centroid of weight to
/// the head's joint), the up square to the shoulders' line.
fn body_axes(
    parts: &[Part],
    arms: &[Arm],
    rest: &[Point3<f64>],
) -> Option<(Vector3<f64>, Vector3<f64>)> {
    let [a, b] = arms else { return None };
    let across = parts[a.upper].joint - parts[b.upper].joint;
    let (mut sum, mut total) = (Vector3::zeros(), 0.0);
    for (p, w) in rest.iter().zip(&parts[0].weights) {
        sum += p.coords * *w;
        total += w;
    }
    let head = parts.iter().find(|p| p.name == "head")?;
    let up = head.joint.coords - sum / f64::max(total, 1e-12);
    let front = across.cross(&up).try_normalize(1e-9)?;
    Some((front, front.cross(&across).try_normalize(1e-9)?))
}

/// The scan's surface the rest of the body (trunk, head, legs) already explains: the cells (of
/// side `cell`, m) of its matches' targets. An arm turned into the trunk matches the trunk's surface as closely as
/// a right turn matches the arm's own; its matches there explain nothing new and count as
/// unmatched.
#[derive(Debug)]
pub struct Claimed {
    cells: std::collections::HashSet<[i64; 3]>,
    cell: f64,
}

impl Claimed {
    fn cell_of(p: &Point3<f64>, cell: f64) -> [i64; 3] {
        p.coords.map(|c| (c / cell).floor() as i64).into()
    }

    /// The cells (of side `cell`, m) of `pairs`' targets.
    pub fn of(pairs: &[Pair], cell: f64) -> Self {
        Self {
            cells: pairs
                .iter()
                .map(|p| Self::cell_of(&p.target, cell))
                .collect(),
            cell,
        }
    }

    /// Whether `p` lies in a claimed cell.
    pub fn contains(&self, p: &Point3<f64>) -> bool {
        self.cells.contains(&Self::cell_of(p, self.cell))
    }
}

/// The capped energy of `pairs` out of `tried` vertices, each distance capped at `cap` (m, see
/// `ArmSwingParams::cap`) and an unmatched vertex counting as `cap`, a match on `claimed`
/// surface counting as unmatched.
fn capped_energy(pairs: &[Pair], tried: usize, claimed: &Claimed, cap: f64) -> f64 {
    let own: Vec<f64> = pairs
        .iter()
        .filter(|p| !claimed.contains(&p.target))
        .map(|p| p.distance.min(cap).powi(2))
        .collect();
    let unmatched = tried.saturating_sub(own.len()) as f64;
    (own.iter().sum::<f64>() + unmatched * cap * cap) / tried.max(1) as f64
}

/// `transform` followed by the rotation `r` about `centre`.
fn turned(transform: &Similarity, r: &Rotation3<f64>, centre: &Point3<f64>) -> Similarity {
    Similarity {
        scale: transform.scale,
        rotation: r.matrix() * transform.rotation,
        translation: r * (transform.translation - centre.coords) + centre.coords,
    }
}

/// Turns each arm of `poses` about its shoulder, in the body's frontal plane, by each turn of
/// `params.turns_deg` (both arms at once), lets `refine` (the segment-wise fit's iterations, all
/// parts; `params.iterations` of them) go on from there, and keeps for each arm the run whose
/// matches of the arm's `vertices` (those `dominant` says are its parts') have the lowest
/// capped energy; the other parts are left as they were. An arm whose kept energy is still
/// above `params.raise_when` × `params.cap`² (badly matched from every one of those turns) is
/// then turned by each of `params.raised_turns_deg` from where the fit had it, the other arm
/// at its kept run ([`poorly_matched`]), and the lowest capped energy over all its runs kept.
/// Returns the turn kept per arm (degrees towards the body), or `None` when `refine` was
/// cancelled.
#[allow(clippy::too_many_arguments)]
pub fn swing_arms(
    parts: &[Part],
    poses: &mut [PartPose],
    rest: &[Point3<f64>],
    triangles: &[[u32; 3]],
    vertices: &[u32],
    dominant: &[Option<usize>],
    matching: &Matching<'_>,
    params: &ArmSwingParams,
    mut refine: impl FnMut(&mut [PartPose]) -> Option<()>,
) -> Option<Vec<f64>> {
    let arms = arms(parts);
    let Some((front, up)) = body_axes(parts, &arms, rest) else {
        return Some(Vec::new());
    };
    let of_arm = |v: u32, arm: &Arm| matches!(dominant[v as usize], Some(k) if k == arm.upper || k == arm.lower);
    let rest_of_body: Vec<u32> = vertices
        .iter()
        .copied()
        .filter(|&v| !arms.iter().any(|a| of_arm(v, a)))
        .collect();
    let own: Vec<Vec<u32>> = arms
        .iter()
        .map(|arm| {
            vertices
                .iter()
                .copied()
                .filter(|&v| of_arm(v, arm))
                .collect()
        })
        .collect();
    let axis = Unit::new_normalize(poses[0].transform.rotation * front);
    let up = poses[0].transform.rotation * up;
    // Each arm's shoulder and the sign of a turn towards the body: the one that moves the
    // elbow down along the trunk. (The neck's joint above the shoulder had served as up: it lies
    // 43° from the trunk's up at rest, across an arm at the template's 39.6°, and an arm found
    // a few degrees higher by the first iterations was turned the wrong way.)
    let pivots: Vec<(Point3<f64>, f64)> = arms
        .iter()
        .map(|arm| {
            let shoulder = parts[arm.upper].apply(&poses[arm.upper], &parts[arm.upper].joint);
            let elbow = parts[arm.lower].apply(&poses[arm.lower], &parts[arm.lower].joint);
            let down = axis.cross(&(elbow - shoulder)).dot(&up) <= 0.0;
            (shoulder, if down { 1.0 } else { -1.0 })
        })
        .collect();
    let start = poses.to_vec();
    // Per arm: (energy, turn, upper pose, lower pose) of the best run.
    let mut best: Vec<(f64, f64, PartPose, PartPose)> = arms
        .iter()
        .map(|a| (f64::INFINITY, 0.0, start[a.upper], start[a.lower]))
        .collect();
    // One run: the arms `turning` turned by `deg` from `start`, the others as in `from`; refined,
    // and each turned arm's best kept.
    let mut run_turn = |deg: f64,
                        turning: &[bool],
                        from: &[PartPose],
                        best: &mut [(f64, f64, PartPose, PartPose)]|
     -> Option<()> {
        let mut run = from.to_vec();
        for ((arm, (shoulder, sign)), _) in
            arms.iter().zip(&pivots).zip(turning).filter(|(_, t)| **t)
        {
            let r = Rotation3::from_axis_angle(&axis, sign * deg.to_radians());
            run[arm.upper].transform = turned(&start[arm.upper].transform, &r, shoulder);
            run[arm.lower].transform = turned(&start[arm.lower].transform, &r, shoulder);
        }
        refine(&mut run)?;
        let positions = blend(parts, &run, rest);
        let normals = vertex_normals(&positions, triangles);
        let claimed = Claimed::of(
            &matching.pairs(&rest_of_body, &positions, &normals),
            params.claim_cell,
        );
        for (a, arm) in arms.iter().enumerate().filter(|(a, _)| turning[*a]) {
            let pairs = matching.pairs(&own[a], &positions, &normals);
            let energy = capped_energy(&pairs, own[a].len(), &claimed, params.cap);
            if energy < best[a].0 {
                best[a] = (energy, deg, run[arm.upper], run[arm.lower]);
            }
        }
        Some(())
    };
    let all = vec![true; arms.len()];
    for &deg in &params.turns_deg {
        run_turn(deg, &all, &start, &mut best)?;
    }
    let energies: Vec<f64> = best.iter().map(|b| b.0).collect();
    let poor = poorly_matched(&energies, params);
    if poor.iter().any(|p| *p) {
        let mut kept = start.clone();
        for (arm, (_, _, upper, lower)) in arms.iter().zip(&best) {
            kept[arm.upper] = *upper;
            kept[arm.lower] = *lower;
        }
        for &deg in &params.raised_turns_deg {
            run_turn(deg, &poor, &kept, &mut best)?;
        }
    }
    for (arm, (_, _, upper, lower)) in arms.iter().zip(&best) {
        poses[arm.upper] = *upper;
        poses[arm.lower] = *lower;
    }
    Some(best.iter().map(|b| b.1).collect())
}

/// Which arms are matched badly from every turn of `params.turns_deg`: their capped energy
/// (`energies`, m², the lowest over those turns) above `params.raise_when` × `params.cap`²,
/// i.e. the share of the cap's square their average match costs. Only these are tried at
/// `params.raised_turns_deg`, so an arm found at an ordinary turn costs no further runs.
pub fn poorly_matched(energies: &[f64], params: &ArmSwingParams) -> Vec<bool> {
    let limit = params.raise_when * params.cap * params.cap;
    energies.iter().map(|e| *e > limit).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::align::SurfaceIndex;
    use crate::estimate::params::EstimateParams;
    use crate::template::fixture::base_body;
    use crate::template::parts::dominant_parts;

    #[test]
    fn arms_held_down_along_the_body_or_raised_are_found() {
        // Both arms found among the ordinary turns: no raised turn is tried.
        assert_eq!(arms_turned_by([30.0, 30.0]), 4);
        assert_eq!(arms_turned_by([-15.0, -15.0]), 4);
        // One arm raised 145° from the body (the template's 39.6° + 105°), the other where the
        // template has it: the raised turns are tried, for the raised arm only.
        assert_eq!(arms_turned_by([-105.0, 0.0]), 7);
        assert_eq!(arms_turned_by([15.0, -75.0]), 7);
    }

    /// The template with its arms turned `deg` towards the body as the "scan": the swing finds
    /// the turns and lays the arms on the scan's. Returns how many runs the swing made.
    fn arms_turned_by(deg: [f64; 2]) -> usize {
        let body = base_body();
        let (rest, parts) = (&body.rest, &body.parts);
        let identity = PartPose::identity();
        let arms = arms(parts);
        assert_eq!(arms.len(), 2);
        let (front, up) = body_axes(parts, &arms, rest).unwrap();
        let front = Unit::new_normalize(front);
        // The template's up is +y: a turn towards the body lowers the elbow, away raises it.
        assert!(up.y > 0.99, "{up:?}");
        let mut scan_poses = vec![identity; parts.len()];
        for (arm, deg) in arms.iter().zip(deg) {
            let shoulder = parts[arm.upper].joint;
            let elbow = parts[arm.lower].joint;
            let down = front.cross(&(elbow - shoulder)).dot(&up) <= 0.0;
            let sign = if down { 1.0 } else { -1.0 };
            let r = Rotation3::from_axis_angle(&front, sign * deg.to_radians());
            for k in [arm.upper, arm.lower] {
                scan_poses[k].transform = turned(&identity.transform, &r, &shoulder);
            }
            let moved = scan_poses[arm.lower].transform.apply(&elbow);
            assert_eq!(moved.y < elbow.y, deg > 0.0, "{deg}: {moved} from {elbow}");
        }
        let scan = body.posed(&scan_poses);
        let index = SurfaceIndex::new(&scan).unwrap();
        let matching = Matching::new(&index, &EstimateParams::default());
        let vertices: Vec<u32> = (0..rest.len() as u32).step_by(2).collect();
        let dominant = dominant_parts(parts, rest.len());
        // From the template's pose, the refinement (here none, or cancelled) given.
        let swing = |refine: &mut dyn FnMut(&mut [PartPose]) -> Option<()>| {
            let mut poses = vec![identity; parts.len()];
            let kept = swing_arms(
                parts,
                &mut poses,
                rest,
                &body.triangles,
                &vertices,
                &dominant,
                &matching,
                &ArmSwingParams::default(),
                refine,
            );
            kept.map(|k| (k, poses))
        };
        let mut runs = 0;
        let (kept, poses) = swing(&mut |_| {
            runs += 1;
            Some(())
        })
        .unwrap();
        assert_eq!(kept, deg.to_vec());
        // The turned arms now lie on the scan's.
        let fitted = blend(parts, &poses, rest);
        let worst = fitted
            .iter()
            .zip(&scan.positions)
            .map(|(p, q)| (p - q).norm())
            .fold(0.0, f64::max);
        assert!(worst < 1e-9, "{worst}");
        // A cancelled refinement cancels the swing.
        let cancelled = swing(&mut |_| None);
        assert!(cancelled.is_none());
        runs
    }

    #[test]
    fn only_arms_matched_worse_than_the_limit_are_poor() {
        let params = ArmSwingParams::default();
        let limit = params.raise_when * params.cap * params.cap;
        assert_eq!(
            poorly_matched(&[0.9 * limit, 1.1 * limit, f64::INFINITY], &params),
            vec![false, true, true]
        );
    }

    #[test]
    fn a_turn_about_a_centre_keeps_the_centre_and_turns_the_rest() {
        let t = Similarity {
            scale: 2.0,
            rotation: *Rotation3::from_axis_angle(&Vector3::z_axis(), 0.4).matrix(),
            translation: Vector3::new(1.0, -2.0, 0.5),
        };
        let centre = Point3::new(0.3, 0.1, 1.2);
        let r = Rotation3::from_axis_angle(&Vector3::y_axis(), 0.7);
        let u = turned(&t, &r, &centre);
        for p in [Point3::origin(), Point3::new(0.2, -0.5, 0.9)] {
            let want = r * (t.apply(&p) - centre) + centre.coords;
            assert!((u.apply(&p).coords - want).norm() < 1e-12);
        }
    }

    #[test]
    fn unmatched_and_far_matches_count_as_the_cap() {
        let pair = |d: f64| Pair {
            vertex: 0,
            target: Point3::origin(),
            distance: d,
        };
        let (cap, cell) = (0.03, 0.015);
        let e = capped_energy(&[pair(0.01), pair(0.5)], 3, &Claimed::of(&[], cell), cap);
        let want = (0.01f64.powi(2) + 2.0 * cap * cap) / 3.0;
        assert!((e - want).abs() < 1e-15);
        // A match on surface the rest of the body explains counts as unmatched.
        let claimed = Claimed::of(&[pair(0.0)], cell);
        let e = capped_energy(&[pair(0.01)], 1, &claimed, cap);
        assert!((e - cap * cap).abs() < 1e-15);
    }
}
