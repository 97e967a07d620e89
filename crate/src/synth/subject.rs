//! One synthetic subject: morph the base mesh, pose it, put it on the floor, scan it.

use std::collections::HashMap;

use nalgebra::{Point3, Rotation3, Vector3};
use rand::Rng;

use crate::mesh::{bounding_box, Mesh};

use super::data::MakeHumanData;
use super::error::SynthError;
use super::hand_on_hip::{arm_bones, bend_elbow, lay_hand, wrist_clearance, ArmBones};
use super::macros::macro_target_weights;
use super::population::{PoseParams, SubjectParams, A_POSE_ARM_DEG};
use super::scanner::{scan, Scan, ScannerParams};
use super::skeleton::{bone_transforms, joint_positions, skin};

/// A made subject, in the template frame (metres, y up, feet on y = 0, facing +z).
#[derive(Debug, Clone)]
pub struct Subject {
    pub params: SubjectParams,
    /// Standing height of the unposed, morphed body (top of head to soles), metres.
    pub stature: f64,
    /// The posed body: template base-mesh triangles on the subject's vertex positions, i.e. the
    /// noise-free surface *and* the ground-truth position of every template vertex.
    pub surface: Mesh,
    /// The virtual scan of `surface`.
    pub scan: Scan,
}

/// Template vertices at rest (morphed) and posed.
pub type RestAndPosed = (Vec<Point3<f64>>, Vec<Point3<f64>>);

/// Bones the pose moves (MakeHuman default rig names).
const TRUNK_BONE: &str = "spine04";
const HEAD_BONE: &str = "neck01";
const LEFT_THIGH_BONE: &str = "upperleg01.L";
const RIGHT_THIGH_BONE: &str = "upperleg01.R";
const LEFT_CLAVICLE_BONE: &str = "clavicle.L";
const RIGHT_CLAVICLE_BONE: &str = "clavicle.R";

/// The arm's angle from the body (degrees) beyond which the shoulder girdle rises with it.
pub const GIRDLE_FROM_DEG: f64 = 60.0;

/// The share of the arm's angle beyond [`GIRDLE_FROM_DEG`] the clavicle takes (a raised arm
/// lifts the shoulder: the scapula turns up about a third as far as the humerus, the
/// scapulohumeral rhythm); the humerus takes the rest, so the arm's angle is the pose's.
pub const GIRDLE_SHARE: f64 = 1.0 / 3.0;

/// The clavicle's elevation (degrees, ≥ 0) for a shoulder abduction of `abduction` degrees from
/// the model's A-pose: [`GIRDLE_SHARE`] of the arm's angle from the body beyond
/// [`GIRDLE_FROM_DEG`], 0 below it (so arms up to 60° from the body move the humerus alone).
pub fn shoulder_girdle_share(abduction: f64) -> f64 {
    GIRDLE_SHARE * (abduction + A_POSE_ARM_DEG - GIRDLE_FROM_DEG).max(0.0)
}

/// Morphs, poses and scans one subject; the scanner noise comes from `rng`.
pub fn make_subject<R: Rng>(
    data: &MakeHumanData,
    params: &SubjectParams,
    scanner: &ScannerParams,
    rng: &mut R,
) -> Result<Subject, SynthError> {
    make_covered_subject(data, params, scanner, |_| None, rng)
}

/// [`make_subject`] with what the scanner sees over the body: `cover` of the posed body surface
/// (hair, clothing; the same triangles on moved vertices), or the body itself when it gives
/// `None`. The subject's `surface` (the truth) stays the body's.
pub fn make_covered_subject<R: Rng>(
    data: &MakeHumanData,
    params: &SubjectParams,
    scanner: &ScannerParams,
    cover: impl FnOnce(&Mesh) -> Option<Mesh>,
    rng: &mut R,
) -> Result<Subject, SynthError> {
    let params = &fit_elbows(data, &fit_height(data, params))?;
    let (rest, posed) = shape_and_pose(data, params)?;
    let stature = extent_y(&rest);
    let surface = Mesh::new(posed, data.skin.triangles.clone());
    let scan = match cover(&surface) {
        Some(covered) => scan(&covered, scanner, rng),
        None => scan(&surface, scanner, rng),
    };
    Ok(Subject {
        params: params.clone(),
        stature,
        surface,
        scan,
    })
}

/// `params` with MakeHuman's height value solved so that the morphed body's stature is
/// `params.stature_target`. Target weights are piecewise linear in the height value with a kink
/// at 0.5, so stature is too (up to which vertex is the highest): evaluate it at 0, ½ and 1,
/// interpolate on the right half, and refine once by a secant step. Clamped to [0, 1].
pub fn fit_height(data: &MakeHumanData, params: &SubjectParams) -> SubjectParams {
    let mut p = params.clone();
    let at = |h: f64, p: &mut SubjectParams| {
        p.shape.height = h;
        rest_stature(data, p)
    };
    let (s0, s5, s1) = (at(0.0, &mut p), at(0.5, &mut p), at(1.0, &mut p));
    let target = params.stature_target;
    let (lo, hi, slo, shi) = if target <= s5 {
        (0.0, 0.5, s0, s5)
    } else {
        (0.5, 1.0, s5, s1)
    };
    let lerp = |a: f64, b: f64, sa: f64, sb: f64| {
        if (sb - sa).abs() < 1e-9 {
            a
        } else {
            (a + (b - a) * (target - sa) / (sb - sa)).clamp(lo, hi)
        }
    };
    let h1 = lerp(lo, hi, slo, shi);
    let s_h1 = at(h1, &mut p);
    // Secant step from the nearer end of the segment.
    let h2 = if (h1 - lo).abs() < (hi - h1).abs() {
        lerp(lo, h1, slo, s_h1)
    } else {
        lerp(h1, hi, s_h1, shi)
    };
    p.shape.height = h2;
    p
}

/// Stature (y extent of the body skin) of the morphed, unposed body.
pub fn rest_stature(data: &MakeHumanData, params: &SubjectParams) -> f64 {
    let full = morphed(data, params);
    let skin: Vec<Point3<f64>> = data.provenance.iter().map(|&v| full[v as usize]).collect();
    extent_y(&skin)
}

/// Every model vertex (skin and helpers) of the morphed, unposed body.
pub(super) fn morphed(data: &MakeHumanData, params: &SubjectParams) -> Vec<Point3<f64>> {
    let mut full: Vec<Vector3<f64>> = data.model.positions.iter().map(|p| p.coords).collect();
    let mut weights = macro_target_weights(&params.shape);
    weights.extend(params.local_target_weights());
    data.targets
        .blend_into(&weights, data.model.frame.scale, &mut full);
    full.into_iter().map(Point3::from).collect()
}

/// The subject's template vertices at rest (morphed only) and posed, both with feet on y = 0.
pub fn shape_and_pose(
    data: &MakeHumanData,
    params: &SubjectParams,
) -> Result<RestAndPosed, SynthError> {
    let full = morphed(data, params);
    let heads = joint_positions(&data.rig, &data.model.joint_pos_idxs, &full)?;
    let mut rest: Vec<Point3<f64>> = data.provenance.iter().map(|&v| full[v as usize]).collect();
    let mut pose = pose_rotations(data, &heads, &params.pose)?;
    lay_hands(data, &heads, &rest, &params.pose, &mut pose)?;
    let transforms = bone_transforms(&data.rig, &heads, &pose);
    let mut posed = skin(&rest, &data.influences, &transforms);
    on_floor(&mut rest);
    on_floor(&mut posed);
    Ok((rest, posed))
}

/// The pose's bone rotations (bone index → rotation about its rest head, template axes).
pub(super) fn pose_rotations(
    data: &MakeHumanData,
    heads: &[Point3<f64>],
    pose: &PoseParams,
) -> Result<HashMap<usize, Rotation3<f64>>, SynthError> {
    let bone = |name: &str| {
        data.rig
            .bone(name)
            .ok_or_else(|| SynthError::Rig(format!("bone `{name}` is missing")))
    };
    // Template-frame axes: x to the subject's left, y up, z forward. Flexion turns about +x
    // (top moves forward), lateral tilt about −z (top moves to the subject's left), turn about +y.
    let rot = |flex: f64, lateral: f64, turn: f64| {
        Rotation3::from_axis_angle(&Vector3::z_axis(), -lateral.to_radians())
            * Rotation3::from_axis_angle(&Vector3::x_axis(), flex.to_radians())
            * Rotation3::from_axis_angle(&Vector3::y_axis(), turn.to_radians())
    };
    // In the frontal plane a left limb (x > 0) moves away from the body turning about +z, a right
    // one about −z; the elbow bends the forearm the other way, towards the hip.
    let frontal =
        |degrees: f64| Rotation3::from_axis_angle(&Vector3::z_axis(), degrees.to_radians());
    let mut out = HashMap::new();
    out.insert(
        bone(TRUNK_BONE)?,
        rot(pose.trunk_flexion, pose.trunk_lateral, pose.trunk_turn),
    );
    out.insert(
        bone(HEAD_BONE)?,
        rot(pose.head_flexion, pose.head_lateral, pose.head_turn),
    );
    let limbs = [
        (LEFT_THIGH_BONE, pose.left_hip_abduction),
        (RIGHT_THIGH_BONE, -pose.right_hip_abduction),
    ];
    for (name, degrees) in limbs {
        out.insert(bone(name)?, frontal(degrees));
    }
    // Per side: the abduction from the A-pose and the turn's sign (left +z, right −z).
    let abductions = [
        (pose.left_shoulder_abduction, 1.0),
        (pose.right_shoulder_abduction, -1.0),
    ];
    let clavicles = [bone(LEFT_CLAVICLE_BONE)?, bone(RIGHT_CLAVICLE_BONE)?];
    for (((arm, flexion), (abduction, sign)), clavicle) in bent_arms(data, pose)?
        .into_iter()
        .zip(abductions)
        .zip(clavicles)
    {
        let girdle = shoulder_girdle_share(abduction);
        if girdle != 0.0 {
            out.insert(clavicle, frontal(sign * girdle));
        }
        out.insert(arm.upper, frontal(sign * (abduction - girdle)));
        if flexion == 0.0 {
            continue;
        }
        for (b, r) in bend_elbow(heads, &arm, flexion) {
            let q = out.get(&b).copied().unwrap_or_else(Rotation3::identity);
            out.insert(b, q * r);
        }
    }
    Ok(out)
}

/// The body's vertices no arm bone moves (`rest`, `heads` of the morphed body), posed by
/// `rotations`: what a hand on the hip rests on.
fn posed_body(
    data: &MakeHumanData,
    heads: &[Point3<f64>],
    rest: &[Point3<f64>],
    rotations: &HashMap<usize, Rotation3<f64>>,
) -> Result<Vec<Point3<f64>>, SynthError> {
    let arms = [
        ArmBones::find(&data.rig, "L")?,
        ArmBones::find(&data.rig, "R")?,
    ];
    let moved = arm_bones(&data.rig, &arms);
    let unmoved: Vec<usize> = (0..rest.len())
        .filter(|&v| data.influences[v].iter().all(|(b, _)| !moved[*b]))
        .collect();
    let body: Vec<Point3<f64>> = unmoved.iter().map(|&v| rest[v]).collect();
    let influences: Vec<Vec<(usize, f64)>> = unmoved
        .iter()
        .map(|&v| data.influences[v].clone())
        .collect();
    Ok(skin(
        &body,
        &influences,
        &bone_transforms(&data.rig, heads, rotations),
    ))
}

/// The arms' bones with the pose's elbow flexion of each.
fn bent_arms(data: &MakeHumanData, pose: &PoseParams) -> Result<[(ArmBones, f64); 2], SynthError> {
    Ok([
        (ArmBones::find(&data.rig, "L")?, pose.left_elbow_flexion),
        (ArmBones::find(&data.rig, "R")?, pose.right_elbow_flexion),
    ])
}

/// `params` with each bent elbow's flexion (hands on hips) no more than lets the wrist's joint
/// stay [`WRIST_RADIUS`] out of the body: a hand is laid on the hip, not into it. The drawn
/// flexion is kept when it does; otherwise the flexion is bisected down to
/// [`MIN_HANDS_ON_HIPS_FLEXION`] (the wrist moves out and down as the elbow opens).
pub fn fit_elbows(
    data: &MakeHumanData,
    params: &SubjectParams,
) -> Result<SubjectParams, SynthError> {
    let mut p = params.clone();
    if p.pose.left_elbow_flexion == 0.0 && p.pose.right_elbow_flexion == 0.0 {
        return Ok(p);
    }
    let full = morphed(data, params);
    let heads = joint_positions(&data.rig, &data.model.joint_pos_idxs, &full)?;
    let rest: Vec<Point3<f64>> = data.provenance.iter().map(|&v| full[v as usize]).collect();
    let body = posed_body(data, &heads, &rest, &pose_rotations(data, &heads, &p.pose)?)?;
    for (left, (arm, drawn)) in [true, false]
        .into_iter()
        .zip(bent_arms(data, &params.pose)?)
    {
        if drawn == 0.0 {
            continue;
        }
        let mut clear = |flexion: f64| -> Result<bool, SynthError> {
            let pose = &mut p.pose;
            *(if left {
                &mut pose.left_elbow_flexion
            } else {
                &mut pose.right_elbow_flexion
            }) = flexion;
            let rotations = pose_rotations(data, &heads, &p.pose)?;
            Ok(wrist_clearance(&data.rig, &heads, &rotations, &body, &arm) >= WRIST_RADIUS)
        };
        let (mut lo, mut hi) = (MIN_HANDS_ON_HIPS_FLEXION.min(drawn), drawn);
        if !clear(hi)? {
            for _ in 0..20 {
                let mid = 0.5 * (lo + hi);
                if clear(mid)? {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            hi = lo;
        }
        clear(hi)?;
    }
    Ok(p)
}

/// How far the wrist's joint stays out of the body with a hand on the hip, metres: the wrist's
/// half thickness.
const WRIST_RADIUS: f64 = 0.02;

/// The least elbow flexion [`fit_elbows`] gives hands on hips, degrees.
const MIN_HANDS_ON_HIPS_FLEXION: f64 = 45.0;

/// Each bent arm's hand laid on the body (`hand_on_hip::lay_hand`), the body posed by `rotations`.
fn lay_hands(
    data: &MakeHumanData,
    heads: &[Point3<f64>],
    rest: &[Point3<f64>],
    pose: &PoseParams,
    rotations: &mut HashMap<usize, Rotation3<f64>>,
) -> Result<(), SynthError> {
    if pose.left_elbow_flexion == 0.0 && pose.right_elbow_flexion == 0.0 {
        return Ok(());
    }
    let body = posed_body(data, heads, rest, rotations)?;
    for (arm, flexion) in bent_arms(data, pose)? {
        if flexion != 0.0 {
            for (b, r) in lay_hand(&data.rig, heads, rotations, &body, &arm) {
                rotations.insert(b, r);
            }
        }
    }
    Ok(())
}

fn extent_y(points: &[Point3<f64>]) -> f64 {
    bounding_box(points).map_or(0.0, |(lo, hi)| hi.y - lo.y)
}

fn on_floor(points: &mut [Point3<f64>]) {
    let lo = points.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
    if lo.is_finite() {
        for p in points {
            p.y -= lo;
        }
    }
}
