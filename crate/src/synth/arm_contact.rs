//! Arms against the body: the shoulder abduction at which a hanging arm's skin meets the
//! torso's, so the scanner sees one merged surface there (people often stand so in a scanner).
//!
//! The arm's *clearance* at an angle is `min_a (a − b)·n_b` over its vertices `a` (those every
//! influence of which is an arm bone, and at least [`CLEARANCE_FROM`] of the humerus's length
//! below the shoulder joint: the armpit's blended skin is left out), `b` the nearest vertex of the
//! body no arm bone moves and `n_b` its outward normal: the distance from the body's tangent
//! plane, negative inside. The clearance falls as the arm comes in; the angle where it is
//! `−press` (the soft tissue pressed that deep) is found by bisection, each arm on its own.

use kiddo::{ImmutableKdTree, SquaredEuclidean};
use nalgebra::{Point3, Vector3};

use super::data::MakeHumanData;
use super::error::SynthError;
use super::hand_on_hip::{arm_bones, ArmBones};
use super::population::{SubjectParams, A_POSE_ARM_DEG};
use super::skeleton::{bone_transforms, joint_positions, skin};
use super::subject::{fit_height, morphed, pose_rotations};
use crate::mesh::normals::vertex_normals;

/// The share of the humerus's length below the shoulder joint above which arm vertices are left
/// out of the clearance (the armpit's skin, blended between the arm and the torso).
pub const CLEARANCE_FROM: f64 = 0.3;

/// Bisection steps of [`arms_against_body`] (the angle to 40°/2¹⁶ ≈ 0.0006°).
const STEPS: usize = 16;

/// The body no arm bone moves, posed, for clearances.
struct Body {
    /// Every posed template vertex, and its outward normal.
    posed: Vec<Point3<f64>>,
    normals: Vec<Vector3<f64>>,
    /// The vertices no arm bone moves, and a k-d tree of them.
    vertices: Vec<usize>,
    tree: ImmutableKdTree<f64, 3>,
}

impl Body {
    fn new(
        data: &MakeHumanData,
        arms: &[ArmBones],
        posed: &[Point3<f64>],
    ) -> Result<Self, SynthError> {
        let moved = arm_bones(&data.rig, arms);
        let vertices: Vec<usize> = (0..posed.len())
            .filter(|&v| data.influences[v].iter().all(|(b, _)| !moved[*b]))
            .collect();
        let coords: Vec<[f64; 3]> = vertices.iter().map(|&v| posed[v].coords.into()).collect();
        let tree = ImmutableKdTree::<f64, 3>::new_from_slice(&coords)
            .map_err(|e| SynthError::Rig(format!("the body's vertices: {e}")))?;
        Ok(Self {
            posed: posed.to_vec(),
            normals: vertex_normals(posed, &data.skin.triangles),
            vertices,
            tree,
        })
    }

    /// `(a − b)·n_b`, `b` the body's vertex nearest to `a`.
    fn clearance(&self, a: &Point3<f64>) -> f64 {
        let hit = self
            .tree
            .query(&a.coords.into())
            .nearest_one::<SquaredEuclidean<f64>>()
            .execute();
        let b = self.vertices[hit.item as usize];
        (a - self.posed[b]).dot(&self.normals[b])
    }
}

/// The template vertices of `arm` (`rest` positions, `heads` its joints) whose influences are
/// all `bones` and that lie from [`CLEARANCE_FROM`] of the humerus's length below the shoulder
/// joint to `to` of it.
fn arm_vertices(
    data: &MakeHumanData,
    rest: &[Point3<f64>],
    heads: &[Point3<f64>],
    arm: &ArmBones,
    bones: impl Fn(usize) -> bool,
    to: f64,
) -> Vec<usize> {
    let (shoulder, elbow) = (heads[arm.upper], heads[arm.lower]);
    let humerus = elbow - shoulder;
    (0..rest.len())
        .filter(|&v| {
            let t = (rest[v] - shoulder).dot(&humerus) / humerus.norm_squared();
            t >= CLEARANCE_FROM
                && t <= to
                && data.influences[v]
                    .iter()
                    .all(|(b, w)| *w <= 0.0 || bones(*b))
        })
        .collect()
}

/// Rest template vertices, joints (bone heads) and the two arms of a morphed subject.
type RestBody = (Vec<Point3<f64>>, Vec<Point3<f64>>, [ArmBones; 2]);

/// The morphed subject's rest template vertices, joints and arms.
fn rest_body(data: &MakeHumanData, params: &SubjectParams) -> Result<RestBody, SynthError> {
    let full = morphed(data, params);
    let heads = joint_positions(&data.rig, &data.model.joint_pos_idxs, &full)?;
    let rest: Vec<Point3<f64>> = data.provenance.iter().map(|&v| full[v as usize]).collect();
    let arms = [
        ArmBones::find(&data.rig, "L")?,
        ArmBones::find(&data.rig, "R")?,
    ];
    Ok((rest, heads, arms))
}

/// `params` with both arms hanging straight (elbows not bent) and each shoulder's abduction the
/// one at which the arm's clearance is `−press` (metres): the arm's skin pressed `press` into the
/// torso's at the deepest. Searched between 0° and the A-pose's [`A_POSE_ARM_DEG`] from the body;
/// an arm that never reaches the body hangs at 0°.
pub fn arms_against_body(
    data: &MakeHumanData,
    params: &SubjectParams,
    press: f64,
) -> Result<SubjectParams, SynthError> {
    let mut p = fit_height(data, params);
    p.pose.left_elbow_flexion = 0.0;
    p.pose.right_elbow_flexion = 0.0;
    let (rest, heads, arms) = rest_body(data, &p)?;
    // The arms do not move the body: any arm pose serves.
    let posed = skin(
        &rest,
        &data.influences,
        &bone_transforms(&data.rig, &heads, &pose_rotations(data, &heads, &p.pose)?),
    );
    let body = Body::new(data, &arms, &posed)?;
    for (left, arm) in [true, false].into_iter().zip(arms) {
        let own = arm_bones(&data.rig, &[arm]);
        let verts = arm_vertices(data, &rest, &heads, &arm, |b| own[b], f64::INFINITY);
        let influences: Vec<Vec<(usize, f64)>> =
            verts.iter().map(|&v| data.influences[v].clone()).collect();
        let arm_rest: Vec<Point3<f64>> = verts.iter().map(|&v| rest[v]).collect();
        let mut clearance = |from_body: f64| -> Result<f64, SynthError> {
            let abduction = from_body - A_POSE_ARM_DEG;
            if left {
                p.pose.left_shoulder_abduction = abduction;
            } else {
                p.pose.right_shoulder_abduction = abduction;
            }
            let rotations = pose_rotations(data, &heads, &p.pose)?;
            let transforms = bone_transforms(&data.rig, &heads, &rotations);
            Ok(skin(&arm_rest, &influences, &transforms)
                .iter()
                .map(|a| body.clearance(a))
                .fold(f64::INFINITY, f64::min))
        };
        let (mut lo, mut hi) = (0.0, A_POSE_ARM_DEG);
        if clearance(lo)? >= -press {
            hi = lo;
        } else {
            for _ in 0..STEPS {
                let mid = 0.5 * (lo + hi);
                if clearance(mid)? >= -press {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
        }
        clearance(hi)?;
    }
    Ok(p)
}

/// The clearance (see the module documentation) of every vertex of the upper arm of `side`
/// ("L" or "R": the vertices only its two humerus bones move, down to the elbow joint) on the
/// posed `surface` (template vertices of the subject of `params`, as made): per vertex
/// `(height y, clearance)`, metres. How an arm lies on the body, for tests and reports.
pub fn upper_arm_clearance(
    data: &MakeHumanData,
    params: &SubjectParams,
    surface: &[Point3<f64>],
    side: &str,
) -> Result<Vec<(f64, f64)>, SynthError> {
    let (rest, heads, arms) = rest_body(data, params)?;
    let arm = if side == "L" { arms[0] } else { arms[1] };
    let body = Body::new(data, &arms, surface)?;
    let upper = [arm.upper, arm.upper_twist];
    Ok(
        arm_vertices(data, &rest, &heads, &arm, |b| upper.contains(&b), 1.0)
            .into_iter()
            .map(|v| (surface[v].y, body.clearance(&surface[v])))
            .collect(),
    )
}
