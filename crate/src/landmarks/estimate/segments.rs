//! The segment-wise (articulated) fit: the template's own segments (head, torso, arms, legs —
//! the six of paper §4.2.1, with their blend weights) with the arms split at the elbow and the
//! legs at the knee, each moved rigidly (at the body's common scale) by iterative closest
//! points, the vertex positions blended by the weights as in linear blend skinning. It takes the
//! template from the similarity fit to the scan's pose (arms down or raised, hands on hips, feet
//! apart or together) before the stiff non-rigid fit; no skeleton and no shape model are needed.

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

/// One rigid part: its weight at every vertex, its parent and the joint (template frame) it
/// shares with the parent.
#[derive(Debug, Clone)]
pub struct Part {
    pub name: &'static str,
    pub weights: Vec<f64>,
    pub parent: Option<usize>,
    pub joint: Point3<f64>,
}

/// The ten parts of `template` (base resolution): torso, head, and upper and lower part of each
/// limb, parents before children. The shoulder, hip and neck joints are the centres of the
/// segments' overlap bands; the elbow and knee the midpoints of the epicondyle landmarks.
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
        },
        Part {
            name: "head",
            weights: (0..n).map(|v| w(v, Segment::Head)).collect(),
            parent: Some(0),
            joint: band_centre(Segment::Head),
        },
    ];
    let limbs = [
        (
            Segment::LeftArm,
            "left upper arm",
            "left forearm",
            "Lt. Humeral",
        ),
        (
            Segment::RightArm,
            "right upper arm",
            "right forearm",
            "Rt. Humeral",
        ),
        (
            Segment::LeftLeg,
            "left thigh",
            "left lower leg",
            "Lt. Femoral",
        ),
        (
            Segment::RightLeg,
            "right thigh",
            "right lower leg",
            "Rt. Femoral",
        ),
    ];
    for (segment, upper, lower, epicondyles) in limbs {
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
            });
            continue;
        };
        let axis = (bend - root).normalize();
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
        });
        parts.push(Part {
            name: lower,
            weights: (0..n).map(|v| limb[v] * lower_share(&rest[v])).collect(),
            parent: Some(upper_index),
            joint: bend,
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
pub fn blend(parts: &[Part], transforms: &[Similarity], rest: &[Point3<f64>]) -> Vec<Point3<f64>> {
    rest.iter()
        .enumerate()
        .map(|(v, p)| {
            let mut sum = Vector3::zeros();
            let mut total = 0.0;
            for (part, t) in parts.iter().zip(transforms) {
                let w = part.weights[v];
                if w > 0.0 {
                    sum += t.apply(p).coords * w;
                    total += w;
                }
            }
            if total > 0.0 {
                Point3::from(sum / total)
            } else {
                transforms[0].apply(p)
            }
        })
        .collect()
}

/// Fits every part rigidly (at `start`'s scale) by ICP from `start`: each iteration blends the
/// template, matches `vertices` to the scan, then fits each part, parents first, to the matches
/// of the vertices it dominates plus its joint held where its (already moved) parent puts it.
/// Returns the blended positions, or `None` when the caller cancelled.
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
    let mut transforms = vec![start; parts.len()];
    let dominant: Vec<Option<usize>> = (0..rest.len())
        .map(|v| {
            (0..parts.len())
                .filter(|&k| parts[k].weights[v] >= 0.5)
                .max_by(|&a, &b| parts[a].weights[v].total_cmp(&parts[b].weights[v]))
        })
        .collect();
    for _ in 0..iterations {
        let positions = blend(parts, &transforms, rest);
        let normals = vertex_normals(&positions, triangles);
        let pairs = matching.pairs(vertices, &positions, &normals);
        if ticker.tick(Matching::rms(&pairs), pairs.len()) == ControlFlow::Break(()) {
            return None;
        }
        for (k, part) in parts.iter().enumerate() {
            let mut from = Vec::new();
            let mut to = Vec::new();
            for p in &pairs {
                if dominant[p.vertex as usize] == Some(k) {
                    from.push(rest[p.vertex as usize] * scale);
                    to.push(p.target);
                }
            }
            if from.len() < 10 {
                continue;
            }
            if let Some(parent) = part.parent {
                // The joint stays attached: as many copies as a fifth of the part's matches.
                let held = transforms[parent].apply(&part.joint);
                for _ in 0..(from.len() / 5).max(3) {
                    from.push(part.joint * scale);
                    to.push(held);
                }
            }
            if let Some(rigid) = similarity(&from, &to, false) {
                transforms[k] = Similarity {
                    scale,
                    rotation: rigid.rotation,
                    translation: rigid.translation,
                };
            }
        }
    }
    Some(blend(parts, &transforms, rest))
}
