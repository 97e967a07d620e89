//! The segment-wise (articulated) fit: the template's own segments (head, torso, arms, legs —
//! the six of paper §4.2.1, with their blend weights) with the arms split at the elbow and the
//! legs at the knee, each moved rigidly (at the body's common scale) by iterative closest
//! points, the vertex positions blended by the weights as in linear blend skinning. It takes the
//! template from the similarity fit to the scan's pose (arms down or raised, hands on hips, feet
//! apart or together) before the stiff non-rigid fit; no skeleton and no shape model are needed.
//!
//! The thigh and the lower leg also stretch along their own axis (about the hip or the knee):
//! the body's common scale leaves them as long as the template's, whatever the subject's leg
//! proportions. (Stretching the arm parts, a hand part of its own and pulling a thigh towards
//! where the lower leg puts the knee were measured and made the estimate worse:
//! docs/landmarks-estimate.md.)

use std::ops::ControlFlow;

use nalgebra::{Point3, Vector3};

use super::matching::Matching;
use super::tick::Ticker;
use crate::mesh::normals::vertex_normals;
use crate::mesh::similarity::{similarity, Similarity};
use crate::template::{Segment, Template};

/// Half-width (m) of the blend between the upper and lower part of a limb around the elbow or
/// knee.
const LIMB_BLEND: f64 = 0.05;

/// The range of a leg part's stretch along its axis (a quarter shorter to a third longer than
/// the template's at the body's scale).
const STRETCH_RANGE: (f64, f64) = (0.75, 1.33);

/// One part: its weight at every vertex, its parent, the joint (template frame) it shares with
/// the parent, and for a leg part the axis (unit, template frame, through the joint) along which
/// it stretches.
#[derive(Debug, Clone)]
pub struct Part {
    pub name: &'static str,
    pub weights: Vec<f64>,
    pub parent: Option<usize>,
    pub joint: Point3<f64>,
    pub axis: Option<Vector3<f64>>,
}

/// Where a part is: a similarity (at the body's scale) after a stretch by `stretch` along the
/// part's axis about its joint.
#[derive(Debug, Clone, Copy)]
pub struct PartPose {
    pub transform: Similarity,
    pub stretch: f64,
}

impl Part {
    /// `p` (template frame) stretched along the part's axis about its joint.
    fn stretched(&self, p: &Point3<f64>, stretch: f64) -> Point3<f64> {
        match self.axis {
            Some(a) => p + a * ((stretch - 1.0) * (p - self.joint).dot(&a)),
            None => *p,
        }
    }

    /// `p` (template frame) where `pose` puts it.
    pub fn apply(&self, pose: &PartPose, p: &Point3<f64>) -> Point3<f64> {
        pose.transform.apply(&self.stretched(p, pose.stretch))
    }
}

/// The ten parts of `template` (base resolution): torso, head, and upper and lower part of each
/// limb, parents before children. The shoulder, hip and neck joints are the centres of the
/// segments' overlap bands; the elbow and knee the midpoints of the epicondyle landmarks. The
/// thigh stretches along the line from the hip to the knee, the lower leg along the line from
/// the knee to the midpoint of the malleoli.
pub fn parts(template: &Template) -> Vec<Part> {
    let rest = &template.mesh().positions;
    let n = rest.len();
    let w = |v: usize, s: Segment| template.segment_weights(v as u32)[s.index()] as f64;
    let band_centre = |s: Segment| {
        let (mut sum, mut count) = (Vector3::zeros(), 0.0);
        for (v, p) in rest.iter().enumerate() {
            if w(v, s) > 0.0 && w(v, Segment::Torso) > 0.0 {
                sum += p.coords;
                count += 1.0;
            }
        }
        Point3::from(sum / f64::max(count, 1.0))
    };
    let landmark = |name: &str| {
        template
            .landmark_vertices()
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| rest[*v as usize])
    };
    let midpoint = |a: &str, b: &str| match (landmark(a), landmark(b)) {
        (Some(p), Some(q)) => Some(Point3::from((p.coords + q.coords) / 2.0)),
        _ => None,
    };
    let mut parts = vec![
        Part {
            name: "torso",
            weights: (0..n).map(|v| w(v, Segment::Torso)).collect(),
            parent: None,
            joint: Point3::origin(),
            axis: None,
        },
        Part {
            name: "head",
            weights: (0..n).map(|v| w(v, Segment::Head)).collect(),
            parent: Some(0),
            joint: band_centre(Segment::Head),
            axis: None,
        },
    ];
    // Segment, its parts, the prefix of its epicondyles, the prefix of the malleoli that end a
    // stretching lower part (None: the parts do not stretch).
    let limbs = [
        (
            Segment::LeftArm,
            "left upper arm",
            "left forearm",
            "Lt. Humeral",
            None,
        ),
        (
            Segment::RightArm,
            "right upper arm",
            "right forearm",
            "Rt. Humeral",
            None,
        ),
        (
            Segment::LeftLeg,
            "left thigh",
            "left lower leg",
            "Lt. Femoral",
            Some("Lt."),
        ),
        (
            Segment::RightLeg,
            "right thigh",
            "right lower leg",
            "Rt. Femoral",
            Some("Rt."),
        ),
    ];
    for (segment, upper, lower, epicondyles, malleoli) in limbs {
        let root = band_centre(segment);
        let limb: Vec<f64> = (0..n).map(|v| w(v, segment)).collect();
        let bend = midpoint(
            &format!("{epicondyles} Lateral Epicn"),
            &format!("{epicondyles} Medial Epicn"),
        );
        let Some(bend) = bend.filter(|b| (b - root).norm() > 1e-6) else {
            parts.push(Part {
                name: upper,
                weights: limb,
                parent: Some(0),
                joint: root,
                axis: None,
            });
            continue;
        };
        let axis = (bend - root).normalize();
        let ankle = malleoli.and_then(|side| {
            midpoint(
                &format!("{side} Lateral Malleolus"),
                &format!("{side} Medial Malleolus"),
            )
        });
        let lower_axis = ankle
            .filter(|a| (a - bend).norm() > 1e-6)
            .map(|a| (a - bend).normalize());
        let at_bend = (bend - root).dot(&axis);
        let lower_share = |p: &Point3<f64>| {
            let t = ((p - root).dot(&axis) - at_bend) / (2.0 * LIMB_BLEND) + 0.5;
            let t = t.clamp(0.0, 1.0);
            t * t * (3.0 - 2.0 * t)
        };
        let upper_index = parts.len();
        parts.push(Part {
            name: upper,
            weights: (0..n)
                .map(|v| limb[v] * (1.0 - lower_share(&rest[v])))
                .collect(),
            parent: Some(0),
            joint: root,
            axis: lower_axis.map(|_| axis),
        });
        parts.push(Part {
            name: lower,
            weights: (0..n).map(|v| limb[v] * lower_share(&rest[v])).collect(),
            parent: Some(upper_index),
            joint: bend,
            axis: lower_axis,
        });
    }
    parts
}

/// The part with the largest weight at `vertex`.
pub fn dominant_part(parts: &[Part], vertex: u32) -> usize {
    (0..parts.len())
        .max_by(|&a, &b| {
            parts[a].weights[vertex as usize].total_cmp(&parts[b].weights[vertex as usize])
        })
        .unwrap_or(0)
}

/// The blended positions Σ_p w_p(v)·T_p(v) of the `rest` vertices.
pub fn blend(parts: &[Part], poses: &[PartPose], rest: &[Point3<f64>]) -> Vec<Point3<f64>> {
    rest.iter()
        .enumerate()
        .map(|(v, p)| {
            let mut sum = Vector3::zeros();
            let mut total = 0.0;
            for (part, pose) in parts.iter().zip(poses) {
                let w = part.weights[v];
                if w > 0.0 {
                    sum += part.apply(pose, p).coords * w;
                    total += w;
                }
            }
            if total > 0.0 {
                Point3::from(sum / total)
            } else {
                poses[0].transform.apply(p)
            }
        })
        .collect()
}

/// The stretch along `part`'s axis that best explains `wanted` (template point, where it should
/// go) in the placement `transform`: the least-squares ratio of the axial distances from the
/// joint, target over template, within [`STRETCH_RANGE`].
fn fit_stretch(
    part: &Part,
    axis: &Vector3<f64>,
    transform: &Similarity,
    wanted: &[(Point3<f64>, Point3<f64>)],
) -> Option<f64> {
    let (mut num, mut den) = (0.0, 0.0);
    for (p, q) in wanted {
        let u = (p - part.joint).dot(axis);
        num += u * (transform.apply_inverse(q) - part.joint).dot(axis);
        den += u * u;
    }
    (den > 0.0).then(|| (num / den).clamp(STRETCH_RANGE.0, STRETCH_RANGE.1))
}

/// Fits every part (rigid at `start`'s scale, a leg part stretched along its axis) by ICP from
/// `start`: each iteration blends the template, matches `vertices` to the scan, then fits each
/// part, parents first, to the matches of the vertices it dominates plus its joint held where
/// its (already moved) parent puts it — first the stretch in the part's last placement, then
/// the rigid motion of the stretched part. Returns the blended positions, or `None` when the
/// caller cancelled.
pub fn fit_segments(
    template: &Template,
    parts: &[Part],
    start: Similarity,
    vertices: &[u32],
    matching: &Matching<'_>,
    iterations: usize,
    ticker: &mut Ticker<'_>,
) -> Option<Vec<Point3<f64>>> {
    let rest = &template.mesh().positions;
    let triangles = &template.mesh().triangles;
    let scale = start.scale;
    let mut poses = vec![
        PartPose {
            transform: start,
            stretch: 1.0,
        };
        parts.len()
    ];
    let dominant: Vec<Option<usize>> = (0..rest.len())
        .map(|v| {
            (0..parts.len())
                .filter(|&k| parts[k].weights[v] >= 0.5)
                .max_by(|&a, &b| parts[a].weights[v].total_cmp(&parts[b].weights[v]))
        })
        .collect();
    for _ in 0..iterations {
        let positions = blend(parts, &poses, rest);
        let normals = vertex_normals(&positions, triangles);
        let pairs = matching.pairs(vertices, &positions, &normals);
        if ticker.tick(Matching::rms(&pairs), pairs.len()) == ControlFlow::Break(()) {
            return None;
        }
        for (k, part) in parts.iter().enumerate() {
            let mut wanted: Vec<(Point3<f64>, Point3<f64>)> = pairs
                .iter()
                .filter(|p| dominant[p.vertex as usize] == Some(k))
                .map(|p| (rest[p.vertex as usize], p.target))
                .collect();
            if wanted.len() < 10 {
                continue;
            }
            if let Some(parent) = part.parent {
                // The joint stays attached: as many copies as a fifth of the part's matches.
                let held = parts[parent].apply(&poses[parent], &part.joint);
                let copies = (wanted.len() / 5).max(3);
                wanted.extend(std::iter::repeat_n((part.joint, held), copies));
            }
            let stretch = part
                .axis
                .and_then(|a| fit_stretch(part, &a, &poses[k].transform, &wanted))
                .unwrap_or(poses[k].stretch);
            let from: Vec<_> = wanted
                .iter()
                .map(|(p, _)| part.stretched(p, stretch) * scale)
                .collect();
            let to: Vec<_> = wanted.iter().map(|(_, q)| *q).collect();
            if let Some(rigid) = similarity(&from, &to, false) {
                poses[k] = PartPose {
                    transform: Similarity {
                        scale,
                        rotation: rigid.rotation,
                        translation: rigid.translation,
                    },
                    stretch,
                };
            }
        }
    }
    Some(blend(parts, &poses, rest))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stretched_part_is_fitted_back() {
        let part = Part {
            name: "thigh",
            weights: Vec::new(),
            parent: None,
            joint: Point3::new(0.0, 0.0, 1.0),
            axis: Some(-Vector3::z()),
        };
        // The part 1.2 times as long along its axis, turned by the transform.
        let transform = Similarity {
            scale: 1.0,
            rotation: *nalgebra::Rotation3::from_axis_angle(&Vector3::x_axis(), 0.3).matrix(),
            translation: Vector3::new(0.1, 0.2, 0.3),
        };
        let pose = PartPose {
            transform,
            stretch: 1.2,
        };
        let wanted: Vec<_> = (0..20)
            .map(|i| {
                let p = Point3::new(0.05 * (i % 3) as f64, 0.02, 1.0 - 0.02 * i as f64);
                (p, part.apply(&pose, &p))
            })
            .collect();
        let s = fit_stretch(&part, &part.axis.unwrap(), &transform, &wanted).unwrap();
        assert!((s - 1.2).abs() < 1e-12, "{s}");
        // Beyond the range it is clamped.
        let far = PartPose {
            stretch: 2.0,
            ..pose
        };
        let wanted: Vec<_> = wanted
            .iter()
            .map(|(p, _)| (*p, part.apply(&far, p)))
            .collect();
        let s = fit_stretch(&part, &part.axis.unwrap(), &transform, &wanted).unwrap();
        assert_eq!(s, STRETCH_RANGE.1);
    }
}
