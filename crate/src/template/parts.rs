//! The template's rigid parts: its own segments (head, torso, arms, legs — the six of paper
//! §4.2.1, with their blend weights) with the arms split at the elbow and the legs at the knee,
//! each placed by a similarity after a stretch along its own axis, the vertex positions blended
//! by the weights as in linear blend skinning (`x(v) = Σ_p w_p(v)·T_p(x̄(v)) / Σ_p w_p(v)`). The
//! landmark estimate fits the parts to a scan (`estimate::segments`); the alignment poses the
//! template by them from given landmarks (`align::part_pose`).

use nalgebra::{Point3, Vector3};

use crate::mesh::similarity::Similarity;
use crate::template::{Segment, Template};

/// Half-width (m) of the blend between the upper and lower part of a limb around the elbow or
/// knee.
const LIMB_BLEND: f64 = 0.05;

/// One part: its weight at every vertex, its parent, the joint (template frame) it shares with
/// the parent (the torso's: the neck), and for a limb part and the torso the axis (unit, template
/// frame, through the joint) along which it stretches.
#[derive(Debug, Clone)]
pub struct Part {
    pub name: &'static str,
    pub weights: Vec<f64>,
    pub parent: Option<usize>,
    pub joint: Point3<f64>,
    pub axis: Option<Vector3<f64>>,
    /// For the lower part of a limb, the limb's end (template frame): the midpoint of the
    /// malleoli or of the wrist's styloids.
    pub end: Option<Point3<f64>>,
    /// Whether the ICP fits the stretch (the legs); an arm's is set only by its profile.
    pub stretches: bool,
    /// For a lower leg, the direction (unit, template frame, across its axis) from the knee to
    /// the knee crease: the back of the knee (its opposite, the front, places the knee).
    pub back: Option<Vector3<f64>>,
}

/// Where a part is: a similarity (at the body's scale) after a stretch by `stretch` along the
/// part's axis about its joint.
#[derive(Debug, Clone, Copy)]
pub struct PartPose {
    pub transform: Similarity,
    pub stretch: f64,
}

#[cfg(test)]
impl PartPose {
    /// The template's own placement: no motion, no stretch.
    pub(crate) fn identity() -> Self {
        Self {
            transform: Similarity::identity(),
            stretch: 1.0,
        }
    }
}

impl Part {
    /// `p` (template frame) stretched along the part's axis about its joint.
    pub(crate) fn stretched(&self, p: &Point3<f64>, stretch: f64) -> Point3<f64> {
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
/// upper part's axis is the line from the shoulder or hip to the elbow or knee, the lower
/// part's from there to the midpoint of the styloids or malleoli (the limb's `end`).
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
    let landmark = |name: &str| template.landmark_vertex(name).map(|v| rest[v as usize]);
    let midpoint = |a: &str, b: &str| match (landmark(a), landmark(b)) {
        (Some(p), Some(q)) => Some(Point3::from((p.coords + q.coords) / 2.0)),
        _ => None,
    };
    let neck = band_centre(Segment::Head);
    let mut parts = vec![
        Part {
            name: "torso",
            weights: (0..n).map(|v| w(v, Segment::Torso)).collect(),
            parent: None,
            joint: neck,
            axis: Some(-Vector3::y()),
            end: None,
            stretches: false,
            back: None,
        },
        Part {
            name: "head",
            weights: (0..n).map(|v| w(v, Segment::Head)).collect(),
            parent: Some(0),
            joint: neck,
            axis: None,
            end: None,
            stretches: false,
            back: None,
        },
    ];
    // Segment, its parts, the prefix of its epicondyles, the two landmarks whose midpoint ends
    // the limb (the wrist's styloids, the malleoli), whether the parts stretch.
    let limbs = [
        (
            Segment::LeftArm,
            "left upper arm",
            "left forearm",
            "Lt. Humeral",
            ["Lt. Radial Styloid", "Lt. Ulnar Styloid"],
            false,
        ),
        (
            Segment::RightArm,
            "right upper arm",
            "right forearm",
            "Rt. Humeral",
            ["Rt. Radial Styloid", "Rt. Ulnar Styloid"],
            false,
        ),
        (
            Segment::LeftLeg,
            "left thigh",
            "left lower leg",
            "Lt. Femoral",
            ["Lt. Lateral Malleolus", "Lt. Medial Malleolus"],
            true,
        ),
        (
            Segment::RightLeg,
            "right thigh",
            "right lower leg",
            "Rt. Femoral",
            ["Rt. Lateral Malleolus", "Rt. Medial Malleolus"],
            true,
        ),
    ];
    for (segment, upper, lower, epicondyles, [end_a, end_b], stretches) in limbs {
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
                end: None,
                stretches: false,
                back: None,
            });
            continue;
        };
        let axis = (bend - root).normalize();
        let crease = stretches
            .then(|| landmark(&format!("{} Knee Crease", &epicondyles[..3])))
            .flatten();
        let end = midpoint(end_a, end_b).filter(|a| (a - bend).norm() > 1e-6);
        let lower_axis = end
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
            end: None,
            stretches,
            back: None,
        });
        parts.push(Part {
            name: lower,
            weights: (0..n).map(|v| limb[v] * lower_share(&rest[v])).collect(),
            parent: Some(upper_index),
            joint: bend,
            axis: lower_axis,
            end,
            stretches,
            back: lower_axis.zip(crease).and_then(|(a, c)| {
                let v = (c - bend) - a * (c - bend).dot(&a);
                (v.norm() > 1e-6).then(|| v.normalize())
            }),
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

/// Per vertex, the part whose weight there is largest and at least ½.
pub(crate) fn dominant_parts(parts: &[Part], n: usize) -> Vec<Option<usize>> {
    (0..n)
        .map(|v| {
            (0..parts.len())
                .filter(|&k| parts[k].weights[v] >= 0.5)
                .max_by(|&a, &b| parts[a].weights[v].total_cmp(&parts[b].weights[v]))
        })
        .collect()
}

/// The bend (radians) of the limb of `upper` and `lower` (whose end is `end`, template frame) in
/// `poses`: the angle between the root → joint and joint → end lines (≈ 39° on the template's
/// straight A-pose arm, whose shoulder joint sits inside the shoulder).
pub fn limb_bend(
    parts: &[Part],
    poses: &[PartPose],
    upper: usize,
    lower: usize,
    end: &Point3<f64>,
) -> f64 {
    let root = parts[upper].apply(&poses[upper], &parts[upper].joint);
    let bend = parts[lower].apply(&poses[lower], &parts[lower].joint);
    let end = parts[lower].apply(&poses[lower], end);
    (bend - root).angle(&(end - bend))
}
