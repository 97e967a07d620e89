//! Hands on hips as a real arm lays them. A real elbow bends about one hinge, across the plane of
//! the upper arm and the forearm; to bring the hand in to the hip the humerus turns in about its
//! own axis, the elbow flexes about its hinge, and the wrist extends so the hand lies flat on the
//! side of the hip, the palm against it. Bending the forearm in the frontal plane instead (the
//! humerus not turned) leaves the hinge along that plane and the hand in the air in front of the
//! belly; turning the arm right but keeping the hand in line with the forearm buries the fingers
//! 6–10 cm deep in the hip.

use std::collections::HashMap;

use nalgebra::{Matrix3, Point3, Rotation3, UnitQuaternion, Vector3};

use super::error::SynthError;
use super::skeleton::{bone_transforms, Rig};
use crate::mesh::principal_axes::principal_axes;
use crate::mesh::similarity::centroid;

/// One arm's bones (MakeHuman default rig), by index.
#[derive(Debug, Clone, Copy)]
pub struct ArmBones {
    pub upper: usize,
    pub upper_twist: usize,
    pub lower: usize,
    pub lower_twist: usize,
    pub wrist: usize,
    /// The middle finger's base: the hand's axis runs from the wrist to it.
    pub middle: usize,
    /// The index and little fingers' bases: across the hand, radial side first.
    pub index: usize,
    pub little: usize,
    /// +1 for the left arm (the subject's left is +x), −1 for the right.
    pub side: f64,
}

impl ArmBones {
    /// The arm of `side` ("L" or "R").
    pub fn find(rig: &Rig, side: &str) -> Result<Self, SynthError> {
        let bone = |name: &str| {
            let name = format!("{name}.{side}");
            rig.bone(&name)
                .ok_or_else(|| SynthError::Rig(format!("bone `{name}` is missing")))
        };
        Ok(Self {
            upper: bone("upperarm01")?,
            upper_twist: bone("upperarm02")?,
            lower: bone("lowerarm01")?,
            lower_twist: bone("lowerarm02")?,
            wrist: bone("wrist")?,
            middle: bone("finger3-1")?,
            index: bone("finger2-1")?,
            little: bone("finger5-1")?,
            side: if side == "L" { 1.0 } else { -1.0 },
        })
    }
}

fn about(axis: Vector3<f64>, angle: f64) -> Rotation3<f64> {
    Rotation3::from_scaled_axis(axis * angle)
}

/// The elbow bent `flexion` degrees about its hinge, the forearm in towards the hip: the humerus
/// turned in about its own axis until the hinge points forward and back (the forearm then swings
/// in the frontal plane, towards the midline), and the elbow flexed about the hinge. The model's
/// elbows are already bent at rest (≈ 40°, the forearm forward), which gives the hinge: across
/// the plane of the two bones. The humerus's turn is split between it and its twist bone
/// (linear-blend skinning thins the skin where a turn is blended: ≈ 8 % at 45°, ≈ 30 % at 90°).
/// Returns the (bone, rotation in rest axes) to compose onto the pose.
pub fn bend_elbow(
    heads: &[Point3<f64>],
    arm: &ArmBones,
    flexion: f64,
) -> [(usize, Rotation3<f64>); 3] {
    let humerus = (heads[arm.lower] - heads[arm.upper]).normalize();
    let forearm = (heads[arm.wrist] - heads[arm.lower]).normalize();
    let hinge = humerus.cross(&forearm).normalize();
    let at_rest = humerus.angle(&forearm);
    // The forearm swings in towards the midline (−x for the left arm) about the hinge: the hinge
    // turned onto −side·z (left) / +z (right), across the humerus.
    let across = |v: Vector3<f64>| (v - humerus * v.dot(&humerus)).normalize();
    let (from, to) = (across(hinge), across(-Vector3::z() * arm.side));
    let turn_in = from.cross(&to).dot(&humerus).atan2(from.dot(&to));
    [
        (arm.upper, about(humerus, turn_in / 2.0)),
        (arm.upper_twist, about(humerus, turn_in / 2.0)),
        (arm.lower, about(hinge, flexion.to_radians() - at_rest)),
    ]
}

/// The hand laid flat on the body where the bent arm (`pose`) brings the wrist: the fingers down
/// along the body's surface (`body`: the vertices no arm bone moves, posed by `pose`), the palm
/// against it. The hand's turn against the forearm about the forearm's axis (pronation and
/// supination) is split between the forearm's twist bone and the wrist, the rest (the wrist's
/// extension) is the wrist's. Returns the (bone, rotation in rest axes) to put into the pose.
pub fn lay_hand(
    rig: &Rig,
    heads: &[Point3<f64>],
    pose: &HashMap<usize, Rotation3<f64>>,
    body: &[Point3<f64>],
    arm: &ArmBones,
) -> [(usize, Rotation3<f64>); 2] {
    let transforms = bone_transforms(rig, heads, pose);
    let wrist = transforms[arm.wrist].apply(&heads[arm.wrist]);
    // Down along the surface at the wrist, then turned out (or in) about the wrist until the
    // palm just rests on the body beneath it: the hip is convex and flares out below the waist.
    let (_, normal) = surface_at(body, &wrist, arm.side);
    let down = -Vector3::y();
    let down = (down - normal * down.dot(&normal)).normalize();
    let across = down.cross(&normal);
    let reach = HAND_REACH * (heads[arm.middle] - heads[arm.wrist]).norm();
    let lift = body
        .iter()
        .map(|p| p - wrist)
        .filter(|d| d.dot(&across).abs() < HAND_HALF_WIDTH)
        .map(|d| (d.dot(&down), d.dot(&normal)))
        .filter(|&(t, _)| (PALM_FROM..=reach).contains(&t))
        .map(|(t, h)| (h + HAND_HALF_THICKNESS).atan2(t))
        .fold(f64::NEG_INFINITY, f64::max);
    let lift = if lift.is_finite() { lift } else { 0.0 };
    let (along, normal) = (
        down * lift.cos() + normal * lift.sin(),
        normal * lift.cos() - down * lift.sin(),
    );
    // The hand's own frame: along it, the palm's normal (a mirror image on each side), across.
    let frame = |along: Vector3<f64>, palm: Vector3<f64>| {
        let palm = (palm - along * palm.dot(&along)).normalize();
        Matrix3::from_columns(&[along, palm, along.cross(&palm)])
    };
    let axis = (heads[arm.middle] - heads[arm.wrist]).normalize();
    let radial = heads[arm.index] - heads[arm.little];
    let palm = axis.cross(&radial) * arm.side;
    let laid = frame(along, -normal) * frame(axis, palm).transpose();
    let forearm = transforms[arm.lower].rotation;
    let relative = UnitQuaternion::from_matrix(&(forearm.transpose() * laid));
    let forearm_axis = (heads[arm.wrist] - heads[arm.lower]).normalize();
    // The quaternion's sign is free: take the twist the short way round.
    let twist =
        2.0 * (relative.imag().dot(&forearm_axis) * relative.w.signum()).atan2(relative.w.abs());
    let half = about(forearm_axis, twist / 2.0);
    [
        (arm.lower_twist, half),
        (arm.wrist, half.inverse() * Rotation3::from(relative)),
    ]
}

/// The wrist → fingertip distance in lengths of the wrist → middle finger's base.
const HAND_REACH: f64 = 2.0;

/// Half the hand's thickness and width, metres: the palm lies this far from the hand's axis
/// (through the wrist's joint), and the body this far to either side of it is under the hand.
const HAND_HALF_THICKNESS: f64 = 0.015;
const HAND_HALF_WIDTH: f64 = 0.04;

/// The hand rests on the body from this far past the wrist's joint (metres) to the fingertips.
const PALM_FROM: f64 = 0.03;

/// The plane through the `body` points within 5 cm of the nearest one to `point`: a point on it
/// and its normal, outwards (on the `side` of the midline: +1 left, +x).
fn surface_at(body: &[Point3<f64>], point: &Point3<f64>, side: f64) -> (Point3<f64>, Vector3<f64>) {
    let near = body
        .iter()
        .map(|p| (p - point).norm())
        .fold(f64::INFINITY, f64::min);
    let patch: Vec<Point3<f64>> = body
        .iter()
        .filter(|p| (*p - point).norm() <= near + 0.05)
        .copied()
        .collect();
    let centre = centroid(&patch);
    let normal: Vector3<f64> =
        principal_axes(&patch).map_or_else(Vector3::zeros, |axes| axes.column(2).into());
    (Point3::from(centre), normal * normal.x.signum() * side)
}

/// How far the wrist's joint lies out of the body (`body` as for [`lay_hand`]), metres: along
/// the surface's outward normal there (negative inside).
pub fn wrist_clearance(
    rig: &Rig,
    heads: &[Point3<f64>],
    pose: &HashMap<usize, Rotation3<f64>>,
    body: &[Point3<f64>],
    arm: &ArmBones,
) -> f64 {
    let wrist = bone_transforms(rig, heads, pose)[arm.wrist].apply(&heads[arm.wrist]);
    let (centre, normal) = surface_at(body, &wrist, arm.side);
    (wrist - centre).dot(&normal)
}

/// Which bones move with an arm (the upper arms and everything below them).
pub fn arm_bones(rig: &Rig, arms: &[ArmBones]) -> Vec<bool> {
    let mut moved = vec![false; rig.bones.len()];
    for (b, bone) in rig.bones.iter().enumerate() {
        moved[b] = arms.iter().any(|a| a.upper == b) || bone.parent.is_some_and(|p| moved[p]);
    }
    moved
}
