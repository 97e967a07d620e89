//! Correspondence error against a ground truth: how far each fitted template vertex lies from the
//! point it should land on (a synthetic subject's true template vertex positions). This, not the
//! surface distance, is what a shape model depends on.

use nalgebra::Point3;
use serde::Serialize;

use crate::template::{body_parts, BodyPart, Segment, Template};

/// Summary of per-vertex correspondence errors, in millimetres.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct ErrorSummaryMm {
    /// Vertices compared.
    pub vertices: usize,
    pub mean_mm: f64,
    pub rms_mm: f64,
    /// 95th percentile.
    pub p95_mm: f64,
    pub max_mm: f64,
}

impl ErrorSummaryMm {
    /// Summary of `errors` (metres).
    pub fn of(errors: &[f64]) -> Self {
        if errors.is_empty() {
            return Self::default();
        }
        let n = errors.len() as f64;
        let mut sorted = errors.to_vec();
        sorted.sort_by(f64::total_cmp);
        let p95 = sorted[((sorted.len() - 1) as f64 * 0.95).round() as usize];
        Self {
            vertices: errors.len(),
            mean_mm: errors.iter().sum::<f64>() / n * 1e3,
            rms_mm: (errors.iter().map(|e| e * e).sum::<f64>() / n).sqrt() * 1e3,
            p95_mm: p95 * 1e3,
            max_mm: sorted[sorted.len() - 1] * 1e3,
        }
    }
}

/// One segment's share of the correspondence error.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SegmentError {
    /// Segment name ([`Segment::name`]).
    pub segment: &'static str,
    #[serde(flatten)]
    pub error: ErrorSummaryMm,
}

/// One body part's share of the correspondence error (see [`crate::template::body_part`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PartError {
    /// Part name ([`BodyPart::name`]).
    pub part: &'static str,
    #[serde(flatten)]
    pub error: ErrorSummaryMm,
}

/// Correspondence error after the RBF warp and after fine alignment.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CorrespondenceReport {
    /// The RBF-warped template (base vertices) against the truth.
    pub rough: ErrorSummaryMm,
    /// The fitted template against the truth.
    pub fitted: ErrorSummaryMm,
    /// The fitted template per segment, each vertex counted in its dominant segment.
    pub segments: Vec<SegmentError>,
    /// The fitted template per body part (head, torso, arms, hands, legs, feet).
    pub parts: Vec<PartError>,
}

/// Per-vertex distances between `fitted` and `truth` over the vertices both have (the base
/// vertices, which come first at every resolution, when one side is at `fine`).
pub fn correspondence_errors(fitted: &[Point3<f64>], truth: &[Point3<f64>]) -> Vec<f64> {
    fitted
        .iter()
        .zip(truth)
        .map(|(a, b)| (a - b).norm())
        .collect()
}

/// The report for a fit: `rough` and `fitted` are template positions (metres, scan frame,
/// template order), `truth` the true positions of at least the base vertices of `template`.
pub fn correspondence_report(
    template: &Template,
    rough: &[Point3<f64>],
    fitted: &[Point3<f64>],
    truth: &[Point3<f64>],
) -> CorrespondenceReport {
    let errors = correspondence_errors(fitted, truth);
    let mut by_segment: Vec<Vec<f64>> = vec![Vec::new(); Segment::ALL.len()];
    for (v, e) in errors.iter().enumerate() {
        let w = template.segment_weights(v as u32);
        let dominant = (0..w.len())
            .max_by(|&i, &j| w[i].total_cmp(&w[j]))
            .unwrap_or(0);
        by_segment[dominant].push(*e);
    }
    let mut by_part: Vec<Vec<f64>> = vec![Vec::new(); BodyPart::ALL.len()];
    for (e, part) in errors.iter().zip(body_parts(template)) {
        by_part[part.index()].push(*e);
    }
    CorrespondenceReport {
        rough: ErrorSummaryMm::of(&correspondence_errors(rough, truth)),
        fitted: ErrorSummaryMm::of(&errors),
        segments: Segment::ALL
            .iter()
            .zip(&by_segment)
            .map(|(s, e)| SegmentError {
                segment: s.name(),
                error: ErrorSummaryMm::of(e),
            })
            .collect(),
        parts: BodyPart::ALL
            .iter()
            .zip(&by_part)
            .map(|(p, e)| PartError {
                part: p.name(),
                error: ErrorSummaryMm::of(e),
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn summary_of_known_errors() {
        let errors: Vec<f64> = (1..=100).map(|i| i as f64 * 1e-3).collect();
        let s = ErrorSummaryMm::of(&errors);
        assert_eq!(s.vertices, 100);
        assert!((s.mean_mm - 50.5).abs() < 1e-9);
        assert!((s.max_mm - 100.0).abs() < 1e-9);
        assert!((s.p95_mm - 95.0).abs() < 1e-9, "{}", s.p95_mm);
        let rms = ((1..=100).map(|i| (i * i) as f64).sum::<f64>() / 100.0).sqrt();
        assert!((s.rms_mm - rms).abs() < 1e-9);
    }

    #[test]
    fn errors_cover_the_vertices_both_sides_have() {
        let a = [Point3::new(0.0, 0.0, 0.0), Point3::new(1.0, 0.0, 0.0)];
        let b = [Point3::new(0.0, 3.0, 4.0)];
        assert_eq!(correspondence_errors(&a, &b), vec![5.0]);
    }
}
