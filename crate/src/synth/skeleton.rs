//! MakeHuman's skeleton on a morphed body and linear-blend skinning.
//!
//! The rig (`src/json/rigs/default.json`) names, per bone, its head and tail joints and its
//! parent. A joint's position is the mean of its `joint_pos_idxs` vertices *on the morphed
//! mesh* (MakeHuman places its skeleton the same way), so the skeleton follows every subject.
//! Skin weights are the model's 4 influences per vertex (bone `X` is stored as `X____head`).

use std::collections::{BTreeMap, HashMap};

use nalgebra::{Matrix3, Point3, Rotation3, Vector3};

use super::error::SynthError;

/// One bone of the rig.
#[derive(Debug, Clone, PartialEq)]
pub struct RigBone {
    pub name: String,
    /// Joint whose position is the bone's head (its pivot).
    pub head_joint: String,
    /// Index of the parent bone in [`Rig::bones`]; `None` for the root.
    pub parent: Option<usize>,
}

/// The rig: bones in parent-before-child order.
#[derive(Debug, Clone, Default)]
pub struct Rig {
    pub bones: Vec<RigBone>,
    index: HashMap<String, usize>,
}

impl Rig {
    /// Parses `default.json` (`{"bones": {name: {"head": joint, "parent": name|null, ...}}}`).
    pub fn from_json(bytes: &[u8], path: &str) -> Result<Self, SynthError> {
        let fmt = |m: String| SynthError::Format {
            path: path.to_string(),
            message: m,
        };
        let value: serde_json::Value =
            serde_json::from_slice(bytes).map_err(|e| fmt(format!("not JSON ({e})")))?;
        let bones = value
            .get("bones")
            .and_then(|b| b.as_object())
            .ok_or_else(|| fmt("no `bones` object".into()))?;
        let mut raw: BTreeMap<&str, (String, Option<String>)> = BTreeMap::new();
        for (name, b) in bones {
            let head = b
                .get("head")
                .and_then(|h| h.as_str())
                .ok_or_else(|| fmt(format!("bone `{name}` has no head joint")))?;
            let parent = b.get("parent").and_then(|p| p.as_str()).map(str::to_string);
            raw.insert(name.as_str(), (head.to_string(), parent));
        }
        // Parent-before-child order by repeated passes (the rig is a small tree).
        let mut rig = Rig::default();
        while rig.bones.len() < raw.len() {
            let before = rig.bones.len();
            for (name, (head, parent)) in &raw {
                if rig.index.contains_key(*name) {
                    continue;
                }
                let parent_index = match parent {
                    None => None,
                    Some(p) if !raw.contains_key(p.as_str()) => {
                        return Err(fmt(format!("bone `{name}` has unknown parent `{p}`")))
                    }
                    Some(p) => match rig.index.get(p) {
                        Some(&i) => Some(i),
                        None => continue,
                    },
                };
                rig.index.insert(name.to_string(), rig.bones.len());
                rig.bones.push(RigBone {
                    name: name.to_string(),
                    head_joint: head.clone(),
                    parent: parent_index,
                });
            }
            if rig.bones.len() == before {
                return Err(fmt("the bone hierarchy has a cycle".into()));
            }
        }
        Ok(rig)
    }

    /// Index of bone `name`.
    pub fn bone(&self, name: &str) -> Option<usize> {
        self.index.get(name).copied()
    }
}

/// A rigid transform `x ↦ R·x + t`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rigid {
    pub rotation: Matrix3<f64>,
    pub translation: Vector3<f64>,
}

impl Rigid {
    fn identity() -> Self {
        Self {
            rotation: Matrix3::identity(),
            translation: Vector3::zeros(),
        }
    }

    /// Applies the transform to a point.
    pub fn apply(&self, p: &Point3<f64>) -> Point3<f64> {
        Point3::from(self.rotation * p.coords + self.translation)
    }
}

/// Per-bone world transforms for local rotations `pose` (bone index → rotation about the bone's
/// rest head, in world axes): `T_b = T_parent ∘ (x ↦ h_b + Q_b (x − h_b))`.
pub fn bone_transforms(
    rig: &Rig,
    heads: &[Point3<f64>],
    pose: &HashMap<usize, Rotation3<f64>>,
) -> Vec<Rigid> {
    let mut out = vec![Rigid::identity(); rig.bones.len()];
    for (b, bone) in rig.bones.iter().enumerate() {
        let parent = bone.parent.map(|p| out[p]).unwrap_or_else(Rigid::identity);
        let q = pose
            .get(&b)
            .map(|r| *r.matrix())
            .unwrap_or_else(Matrix3::identity);
        let h = heads[b].coords;
        out[b] = Rigid {
            rotation: parent.rotation * q,
            translation: parent.rotation * (h - q * h) + parent.translation,
        };
    }
    out
}

/// Linear-blend skinning: `x' = Σᵢ wᵢ · T_{bᵢ}(x)` with the weights renormalised to sum 1.
/// `influences[v]` lists `(bone, weight)` pairs of vertex `v`; a vertex without influence stays.
pub fn skin(
    positions: &[Point3<f64>],
    influences: &[Vec<(usize, f64)>],
    transforms: &[Rigid],
) -> Vec<Point3<f64>> {
    positions
        .iter()
        .zip(influences)
        .map(|(p, inf)| {
            let total: f64 = inf.iter().map(|(_, w)| w).sum();
            if total <= 0.0 {
                return *p;
            }
            let sum = inf.iter().fold(Vector3::zeros(), |acc, (b, w)| {
                acc + transforms[*b].apply(p).coords * *w
            });
            Point3::from(sum / total)
        })
        .collect()
}

/// Joint positions: the mean of each joint's vertices in `positions` (all model vertices).
pub fn joint_positions(
    rig: &Rig,
    joint_vertices: &BTreeMap<String, Vec<u32>>,
    positions: &[Point3<f64>],
) -> Result<Vec<Point3<f64>>, SynthError> {
    rig.bones
        .iter()
        .map(|b| {
            let idx = joint_vertices
                .get(&b.head_joint)
                .filter(|i| !i.is_empty())
                .ok_or_else(|| {
                    SynthError::Rig(format!("joint `{}` has no vertices", b.head_joint))
                })?;
            let mut sum = Vector3::zeros();
            for &i in idx {
                let p = positions.get(i as usize).ok_or_else(|| {
                    SynthError::Rig(format!(
                        "joint `{}` names vertex {i}, beyond the mesh",
                        b.head_joint
                    ))
                })?;
                sum += p.coords;
            }
            Ok(Point3::from(sum / idx.len() as f64))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn arm_rig() -> Rig {
        let json = br#"{"bones": {
            "root": {"head": "root____head", "parent": null},
            "arm": {"head": "arm____head", "parent": "root"}}}"#;
        Rig::from_json(json, "rig.json").unwrap()
    }

    #[test]
    fn parents_come_first_and_rotation_pivots_at_the_head() {
        let rig = arm_rig();
        assert_eq!(rig.bones[0].name, "root");
        let arm = rig.bone("arm").unwrap();
        let heads = vec![Point3::origin(), Point3::new(1.0, 0.0, 0.0)];
        let mut pose = HashMap::new();
        pose.insert(
            arm,
            Rotation3::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2),
        );
        let t = bone_transforms(&rig, &heads, &pose);
        let p = t[arm].apply(&Point3::new(2.0, 0.0, 0.0));
        assert!((p - Point3::new(1.0, 1.0, 0.0)).norm() < 1e-12);
        // Half-weighted vertex moves half way.
        let q = skin(
            &[Point3::new(2.0, 0.0, 0.0)],
            &[vec![(0, 0.5), (arm, 0.5)]],
            &t,
        );
        assert!((q[0] - Point3::new(1.5, 0.5, 0.0)).norm() < 1e-12);
    }

    #[test]
    fn cycles_are_an_error() {
        let json =
            br#"{"bones": {"a": {"head": "x", "parent": "b"}, "b": {"head": "y", "parent": "a"}}}"#;
        assert!(Rig::from_json(json, "rig.json").is_err());
    }
}
