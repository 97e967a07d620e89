//! CSV exports of a model: eigenvalues, per-subject scores and quality curves (one row per mode
//! count M). Every table has a `model` column (`whole` or a segment name) so the seven models fit
//! in one file each.

use crate::pca::model::BodyModel;
use crate::pca::shape_model::ShapeModel;
use crate::template::Segment;
use std::fmt::Write;

fn models(model: &BodyModel) -> Vec<(&'static str, &ShapeModel)> {
    std::iter::once(("whole", &model.whole))
        .chain(Segment::ALL.iter().map(|s| (s.name(), model.segment(*s))))
        .collect()
}

fn cell(values: &[f64], i: usize) -> String {
    values.get(i).map_or(String::new(), |v| format!("{v}"))
}

/// `model,mode,eigenvalue,sd,explained,cumulative` for every non-zero mode (kept or not).
pub fn eigenvalues_csv(model: &BodyModel) -> String {
    let mut out = String::from("model,mode,eigenvalue,sd,explained,cumulative,kept\n");
    for (name, m) in models(model) {
        let total: f64 = m.all_variances.iter().sum();
        let mut cumulative = 0.0;
        for (k, &v) in m.all_variances.iter().enumerate() {
            cumulative += v;
            let _ = writeln!(
                out,
                "{name},{},{v},{},{},{},{}",
                k + 1,
                v.sqrt(),
                v / total,
                cumulative / total,
                k < m.mode_count()
            );
        }
    }
    out
}

/// `model,subject,mode,coefficient`: every training subject's coefficients on the kept modes
/// (long format, because the seven models keep different numbers of modes).
pub fn scores_csv(model: &BodyModel) -> String {
    let mut out = String::from("model,subject,mode,coefficient\n");
    for (name, m) in models(model) {
        for (i, subject) in model.subjects.iter().enumerate() {
            for (k, b) in m.subject_scores(i).unwrap_or(&[]).iter().enumerate() {
                let _ = writeln!(out, "{name},{subject},{},{b}", k + 1);
            }
        }
    }
    out
}

/// `model,modes,compactness,generalization,generalization_sd,specificity,specificity_sd`.
pub fn quality_csv(model: &BodyModel) -> String {
    let mut out = String::from(
        "model,modes,compactness,generalization,generalization_sd,specificity,specificity_sd\n",
    );
    for (name, m) in models(model) {
        let q = &m.quality;
        let rows = q
            .compactness
            .len()
            .max(q.generalization.len())
            .max(q.specificity.len());
        for i in 0..rows {
            let _ = writeln!(
                out,
                "{name},{},{},{},{},{},{}",
                i + 1,
                cell(&q.compactness, i),
                cell(&q.generalization, i),
                cell(&q.generalization_sd, i),
                cell(&q.specificity, i),
                cell(&q.specificity_sd, i)
            );
        }
    }
    out
}
