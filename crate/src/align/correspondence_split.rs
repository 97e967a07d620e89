//! Correspondence error as a shape model sees it (issue 33): per body part, the part common to
//! every subject — which a model built on these fits absorbs into its mean — and each subject's
//! own part — which it takes into its modes as false variation.
//!
//! For subjects s = 1..n with fitted vertices f_s(v) and true vertices t_s(v) (template order):
//!
//! * e_s(v) = R_s·(f_s(v) − t_s(v)), the error vector turned into the template's frame by the
//!   rotation R_s of the similarity that maps t_s onto the template's rest shape
//!   ([`similarity`], with scale); lengths stay the subject's (R_s only rotates);
//! * common c(v) = (1/n)·Σ_s e_s(v); own o_s(v) = e_s(v) − c(v) (so Σ_s o_s = 0);
//! * leave one out: c₋s(v) = (Σ_{r≠s} e_r(v))/(n − 1), the common part learnt from the others,
//!   and o₋s(v) = e_s(v) − c₋s(v) = o_s(v)·n/(n − 1): what a bias learnt elsewhere would leave
//!   of a new subject.
//!
//! Each of ‖e_s‖, ‖c‖, ‖o_s‖, ‖c₋s‖, ‖o₋s‖ is summarised over a part's vertices (mean, RMS,
//! 95th percentile, largest: [`ErrorSummaryMm`]) per subject, and the summaries are averaged over
//! the subjects, field by field; `all` does the same over every vertex (so its mean is the
//! vertex-weighted mean of the parts').

use nalgebra::{Point3, Vector3};
use serde::Serialize;
use thiserror::Error;

use super::correspondence::ErrorSummaryMm;
use crate::mesh::similarity::similarity;
use crate::template::BodyPart;

/// One subject: its fitted and its true vertices, both `#V` points in template vertex order,
/// in metres and in the same (the subject's) frame.
#[derive(Debug, Clone, Copy)]
pub struct FitAndTruth<'a> {
    pub fitted: &'a [Point3<f64>],
    pub truth: &'a [Point3<f64>],
}

/// The split of one body part (or of all vertices): each field the mean over the subjects of
/// that subject's summary over the part's vertices, millimetres.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PartSplit {
    /// Part name ([`BodyPart::name`]), or `"all"`.
    pub part: &'static str,
    /// ‖e_s‖: the whole error.
    pub total: ErrorSummaryMm,
    /// ‖c‖: the part common to all subjects (the same for every subject).
    pub common: ErrorSummaryMm,
    /// ‖o_s‖ = ‖e_s − c‖: the subject's own part.
    pub own: ErrorSummaryMm,
    /// ‖c₋s‖: the common part estimated from the other subjects.
    pub common_others: ErrorSummaryMm,
    /// ‖o₋s‖ = ‖e_s − c₋s‖: the subject's own part, leave one out.
    pub own_others: ErrorSummaryMm,
}

/// The split per body part ([`BodyPart::ALL`] order) and over all vertices.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CorrespondenceSplit {
    /// Subjects n.
    pub subjects: usize,
    /// One per body part, [`BodyPart::ALL`] order (a part with no vertex has empty summaries).
    pub parts: Vec<PartSplit>,
    /// Over every vertex.
    pub all: PartSplit,
}

/// Why the split cannot be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CorrespondenceSplitError {
    /// Leave one out needs at least 2 subjects.
    #[error("the split needs at least 2 subjects, got {0}")]
    TooFewSubjects(usize),
    /// A subject's fitted or true vertices, or the parts, are not one per template vertex.
    #[error("subject {subject}: {what} has {got} vertices, the template {expected}")]
    VertexCount {
        subject: usize,
        what: &'static str,
        got: usize,
        expected: usize,
    },
    /// The similarity of a subject's truth onto the template has no solution (degenerate truth).
    #[error("subject {0}: no similarity maps its truth onto the template")]
    NoSimilarity(usize),
}

/// The common / own split of the correspondence error of `subjects` (see the module's formulas).
///
/// Shapes: `rest` the template's `#V` rest positions (any units: only the rotation of the
/// similarity truth → rest is used); `parts` `#V` body parts; every subject `#V` fitted and
/// `#V` true points, metres. Subject indices in errors are 0-based.
pub fn correspondence_split(
    subjects: &[FitAndTruth],
    rest: &[Point3<f64>],
    parts: &[BodyPart],
) -> Result<CorrespondenceSplit, CorrespondenceSplitError> {
    let n = subjects.len();
    if n < 2 {
        return Err(CorrespondenceSplitError::TooFewSubjects(n));
    }
    let v = rest.len();
    let count = |subject, what, got| {
        if got == v {
            Ok(())
        } else {
            Err(CorrespondenceSplitError::VertexCount {
                subject,
                what,
                got,
                expected: v,
            })
        }
    };
    count(0, "parts", parts.len())?;
    let mut errors = Vec::with_capacity(n);
    for (s, subject) in subjects.iter().enumerate() {
        count(s, "fitted", subject.fitted.len())?;
        count(s, "truth", subject.truth.len())?;
        let frame = similarity(subject.truth, rest, true)
            .ok_or(CorrespondenceSplitError::NoSimilarity(s))?;
        let e: Vec<Vector3<f64>> = subject
            .fitted
            .iter()
            .zip(subject.truth)
            .map(|(f, t)| frame.rotation * (f - t))
            .collect();
        errors.push(e);
    }
    let sum: Vec<Vector3<f64>> = (0..v).map(|i| errors.iter().map(|e| e[i]).sum()).collect();
    let m = n as f64;
    let split = |name: &'static str, vertices: &[usize]| {
        let mut columns = [ErrorSummaryMm::default(); 5];
        for e in &errors {
            let mut norms: [Vec<f64>; 5] = Default::default();
            for &i in vertices {
                let common = sum[i] / m;
                let others = (sum[i] - e[i]) / (m - 1.0);
                for (column, x) in
                    norms
                        .iter_mut()
                        .zip([e[i], common, e[i] - common, others, e[i] - others])
                {
                    column.push(x.norm());
                }
            }
            for (acc, column) in columns.iter_mut().zip(&norms) {
                add_scaled(acc, &ErrorSummaryMm::of(column), 1.0 / m);
            }
        }
        let [total, common, own, common_others, own_others] = columns;
        PartSplit {
            part: name,
            total,
            common,
            own,
            common_others,
            own_others,
        }
    };
    let parts_split = BodyPart::ALL
        .iter()
        .map(|part| {
            let vertices: Vec<usize> = (0..v).filter(|i| parts[*i] == *part).collect();
            split(part.name(), &vertices)
        })
        .collect();
    let every: Vec<usize> = (0..v).collect();
    Ok(CorrespondenceSplit {
        subjects: n,
        parts: parts_split,
        all: split("all", &every),
    })
}

/// acc += w·x, field by field (`vertices` is taken from `x`).
fn add_scaled(acc: &mut ErrorSummaryMm, x: &ErrorSummaryMm, w: f64) {
    acc.vertices = x.vertices;
    acc.mean_mm += w * x.mean_mm;
    acc.rms_mm += w * x.rms_mm;
    acc.p95_mm += w * x.p95_mm;
    acc.max_mm += w * x.max_mm;
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Rotation3, Unit};

    const HEAD: usize = 10;
    const TORSO: usize = 20;

    /// A rest shape that is not flat (the similarity needs three directions), metres.
    fn rest() -> Vec<Point3<f64>> {
        (0..HEAD + TORSO)
            .map(|i| {
                let t = i as f64;
                Point3::new((1.3 * t).sin(), (0.7 * t).cos(), 0.5 * (2.1 * t).sin())
            })
            .collect()
    }

    fn parts() -> Vec<BodyPart> {
        (0..HEAD + TORSO)
            .map(|i| {
                if i < HEAD {
                    BodyPart::Head
                } else {
                    BodyPart::Torso
                }
            })
            .collect()
    }

    /// Error of subject `s` of 3 at vertex `i`, mm: c(i) + o_s(i) with Σ_s o_s = 0. Head:
    /// c = 3·x, o = (6, −3, −3)·y; torso: c = (i − HEAD + 1)·z, o = 0.
    fn error_mm(s: usize, i: usize) -> Vector3<f64> {
        if i < HEAD {
            Vector3::new(3.0, [6.0, -3.0, -3.0][s], 0.0)
        } else {
            Vector3::new(0.0, 0.0, (i - HEAD + 1) as f64)
        }
    }

    /// A subject's fitted and true vertices.
    type Pair = (Vec<Point3<f64>>, Vec<Point3<f64>>);

    /// Three subjects whose truth is the rest shape, each fitted with `error_mm`.
    fn fits() -> Vec<Pair> {
        let truth = rest();
        (0..3)
            .map(|s| {
                let fitted = truth
                    .iter()
                    .enumerate()
                    .map(|(i, t)| t + error_mm(s, i) * 1e-3)
                    .collect();
                (fitted, truth.clone())
            })
            .collect()
    }

    fn split_of(fits: &[Pair]) -> CorrespondenceSplit {
        let subjects: Vec<FitAndTruth> = fits
            .iter()
            .map(|(fitted, truth)| FitAndTruth { fitted, truth })
            .collect();
        correspondence_split(&subjects, &rest(), &parts()).unwrap()
    }

    fn close(got: f64, expected: f64, what: &str) {
        assert!((got - expected).abs() < 1e-9, "{what}: {got} vs {expected}");
    }

    /// The head's and the torso's known answer (derivation beside each figure).
    fn check_known_answer(split: &CorrespondenceSplit) {
        let head = &split.parts[BodyPart::Head.index()];
        // ‖c + o_s‖ = √(9 + 36), √(9 + 9), √(9 + 9).
        close(
            head.total.mean_mm,
            (45f64.sqrt() + 2.0 * 18f64.sqrt()) / 3.0,
            "head total",
        );
        close(head.common.mean_mm, 3.0, "head common = ‖c‖");
        close(
            head.own.mean_mm,
            (6.0 + 3.0 + 3.0) / 3.0,
            "head own = ‖o_s‖",
        );
        // c₋s = c − o_s/(n − 1): ‖(3, −3)‖, ‖(3, 1.5)‖ twice.
        close(
            head.common_others.mean_mm,
            (18f64.sqrt() + 2.0 * 11.25f64.sqrt()) / 3.0,
            "head common, others",
        );
        // o₋s = o_s·n/(n − 1) = 1.5·o_s.
        close(head.own_others.mean_mm, 1.5 * 4.0, "head own, others");
        close(head.own_others.max_mm, 1.5 * 4.0, "head own, others, max");
        let torso = &split.parts[BodyPart::Torso.index()];
        // ‖c‖ = 1..20 mm, o = 0: mean 10.5, p95 the 19th of 20 (rank round(19·0.95) = 18).
        for (what, s) in [
            ("total", torso.total),
            ("common", torso.common),
            ("common, others", torso.common_others),
        ] {
            close(s.mean_mm, 10.5, what);
            close(s.p95_mm, 19.0, what);
            close(s.max_mm, 20.0, what);
            assert_eq!(s.vertices, TORSO);
        }
        close(torso.own.max_mm, 0.0, "torso own");
        close(torso.own_others.max_mm, 0.0, "torso own, others");
        // All vertices: vertex-weighted, (10·3 + 20·10.5)/30 = 8 and (10·4 + 0)/30.
        close(split.all.common.mean_mm, 8.0, "all common");
        close(split.all.own.mean_mm, 40.0 / 30.0, "all own");
        assert_eq!(split.all.total.vertices, HEAD + TORSO);
        assert_eq!(split.parts[BodyPart::Feet.index()].total.vertices, 0);
    }

    #[test]
    fn a_common_field_and_own_fields_summing_to_zero_are_found_exactly() {
        let split = split_of(&fits());
        assert_eq!(split.subjects, 3);
        check_known_answer(&split);
    }

    #[test]
    fn a_turned_and_moved_subject_is_turned_back_into_the_template_frame() {
        let mut fits = fits();
        let turn =
            Rotation3::from_axis_angle(&Unit::new_normalize(Vector3::new(1.0, 2.0, -0.5)), 2.0);
        let shift = Vector3::new(0.3, -1.2, 4.0);
        let moved = |p: &Point3<f64>| turn * p + shift;
        let (fitted, truth) = &mut fits[0];
        *fitted = fitted.iter().map(moved).collect();
        *truth = truth.iter().map(moved).collect();
        let split = split_of(&fits);
        // Without R_s the head's common part would be (Q·(3, 6) + 2·(3, −3))/3, not 3·x.
        check_known_answer(&split);
    }

    #[test]
    fn too_few_subjects_and_wrong_counts_are_errors() {
        let fits = fits();
        let (fitted, truth) = &fits[0];
        let one = [FitAndTruth { fitted, truth }];
        assert_eq!(
            correspondence_split(&one, &rest(), &parts()),
            Err(CorrespondenceSplitError::TooFewSubjects(1))
        );
        let short = &truth[1..];
        let two = [
            FitAndTruth { fitted, truth },
            FitAndTruth {
                fitted,
                truth: short,
            },
        ];
        assert_eq!(
            correspondence_split(&two, &rest(), &parts()),
            Err(CorrespondenceSplitError::VertexCount {
                subject: 1,
                what: "truth",
                got: HEAD + TORSO - 1,
                expected: HEAD + TORSO,
            })
        );
    }
}
