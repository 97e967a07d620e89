//! End-to-end: building a body model (GPA + snapshot PCA) and its quality curves.

mod pca_support;

use bodyspace::pca::gram::snapshot_pca;
use bodyspace::pca::metrics::generalization;
use bodyspace::pca::{build_body_model, BuildParams, PoseRemoval};

fn all_modes() -> BuildParams {
    BuildParams {
        variance: 1.0,
        ..BuildParams::default()
    }
}

#[test]
fn with_all_modes_every_subject_is_reconstructed_exactly() {
    let set = pca_support::training_set(12, 1);
    let model = build_body_model(&set, &all_modes()).unwrap();
    assert!(model.whole.mode_count() <= 11);
    for (i, shape) in set.shapes.iter().enumerate() {
        let p = model.project(shape).unwrap();
        // Mean per-vertex distance after GPA, metres; f32 storage limits it to ~1e-7.
        assert!(p.residual < 1e-5, "subject {i}: residual {}", p.residual);
        let scores = model.whole.subject_scores(i).unwrap();
        for (a, b) in p.coefficients.whole.iter().zip(scores) {
            assert!((a - *b as f64).abs() < 1e-4, "subject {i}: {a} vs {b}");
        }
        for s in 0..6 {
            let seg = &model.segments[s];
            let rebuilt = seg
                .reconstruct(p.coefficients.segments[s].as_ref().unwrap())
                .unwrap();
            let whole = model.whole.reconstruct(&p.coefficients.whole).unwrap();
            for (j, &v) in seg.vertex_indices.iter().enumerate() {
                for a in 0..3 {
                    assert!((rebuilt[3 * j + a] - whole[3 * v as usize + a]).abs() < 1e-5);
                }
            }
        }
    }
}

#[test]
fn bases_are_orthonormal_and_variances_descend() {
    let set = pca_support::training_set(10, 2);
    let model = build_body_model(&set, &all_modes()).unwrap();
    for m in std::iter::once(&model.whole).chain(&model.segments) {
        pca_support::check_orthonormal(m);
        assert!(m.mode_count() >= 1 && m.mode_count() <= 9);
        assert!(m.variances.windows(2).all(|w| w[0] >= w[1]));
        assert!((m.quality.compactness.last().unwrap() - 1.0).abs() < 1e-12);
    }
}

#[test]
fn variance_threshold_keeps_fewer_modes_and_gpa_removes_pose() {
    let set = pca_support::training_set(10, 3);
    let full = build_body_model(&set, &all_modes()).unwrap();
    let model = build_body_model(&set, &BuildParams::default()).unwrap();
    let kept = model.whole.mode_count();
    assert!(kept <= full.whole.mode_count());
    assert!(model.whole.quality.compactness[kept - 1] >= 0.99);
    // The subjects vary in 4 shape parameters (height, girth, belly, head tilt); the random
    // rigid poses must not add modes.
    assert!(kept <= 4, "kept {kept} modes");
    let unaligned = build_body_model(
        &set,
        &BuildParams {
            gpa: bodyspace::pca::GpaParams {
                pose: PoseRemoval::None,
                ..Default::default()
            },
            ..BuildParams::default()
        },
    )
    .unwrap();
    assert!(unaligned.whole.variances[0] > 10.0 * model.whole.variances[0]);
}

#[test]
fn leave_one_out_generalization_matches_a_hand_computed_case() {
    // 4 shapes of 3 points: shape j = base + aⱼ·d₁ + bⱼ·d₂ with d₁ = vertex 1 along y and
    // d₂ = vertex 0 along x, a = (3, −3, 0, 0), b = (0, 0, 1, −1).
    // Leaving out shape 0 or 1, the other three vary most along d₁ (Σa'² = 6 > Σb'² = 2, no
    // covariance) and the left-out shape differs only along d₁: residual 0.
    // Leaving out shape 2: the others have a = (3, −3, 0), b = (0, 0, −1): mode 1 is d₁
    // (18 > 2/3); the left-out shape lies 4/3 along d₂ from their mean, all at vertex 0, so the
    // mean per-vertex distance is (4/3)/3 = 4/9; shape 3 likewise. G(1) = (0 + 0 + 4/9 + 4/9)/4
    // = 2/9, and G(2) = 0 because three shapes span two modes.
    let base = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0];
    let rows: Vec<Vec<f64>> = [(3.0, 0.0), (-3.0, 0.0), (0.0, 1.0), (0.0, -1.0)]
        .iter()
        .map(|&(a, b)| {
            let mut r = base.to_vec();
            r[4] += a;
            r[0] += b;
            r
        })
        .collect();
    let pca = snapshot_pca(&rows);
    let (g, _) = generalization(&pca, 5);
    assert_eq!(g.len(), 2);
    assert!((g[0] - 2.0 / 9.0).abs() < 1e-12, "G(1) = {}", g[0]);
    assert!(g[1].abs() < 1e-12, "G(2) = {}", g[1]);
}

#[test]
fn quality_curves_have_the_expected_shape() {
    let set = pca_support::training_set(12, 4);
    let model = build_body_model(&set, &all_modes()).unwrap();
    let q = &model.whole.quality;
    assert!(!q.generalization.is_empty() && !q.specificity.is_empty());
    // More modes generalize better (never worse, up to rounding).
    assert!(q.generalization.windows(2).all(|w| w[1] <= w[0] + 1e-9));
    assert!(q.specificity.iter().all(|s| s.is_finite() && *s > 0.0));
    assert!(q.compactness.windows(2).all(|w| w[1] >= w[0]));
}

#[test]
fn generalization_in_coefficient_space_matches_rebuilding_each_model() {
    let rows: Vec<Vec<f64>> = pca_support::subjects(7, 41)
        .iter()
        .map(|s| s.iter().flat_map(|p| [p.x, p.y, p.z]).collect())
        .collect();
    let (fast, _) = generalization(&snapshot_pca(&rows), 10);
    assert_eq!(fast.len(), 5);
    for (m, g) in fast.iter().enumerate() {
        let mut total = 0.0;
        for i in 0..rows.len() {
            let others: Vec<Vec<f64>> = (0..rows.len())
                .filter(|&j| j != i)
                .map(|j| rows[j].clone())
                .collect();
            let loo = snapshot_pca(&others);
            let mut r: Vec<f64> = rows[i]
                .iter()
                .zip(&loo.mean)
                .map(|(x, mu)| x - mu)
                .collect();
            for phi in loo.modes.iter().take(m + 1) {
                let c: f64 = r.iter().zip(phi).map(|(a, b)| a * b).sum();
                r.iter_mut().zip(phi).for_each(|(a, b)| *a -= c * b);
            }
            total += bodyspace::pca::metrics::mean_vertex_norm(&r) / rows.len() as f64;
        }
        assert!(
            (g - total).abs() < 1e-9 * total.max(1e-3),
            "G({}) = {g}, rebuilt {total}",
            m + 1
        );
    }
}

#[test]
fn a_fixed_mode_count_overrides_the_variance_cut_and_is_recorded() {
    let set = pca_support::training_set(10, 4);
    let params = |modes| BuildParams {
        modes: Some(modes),
        compute_quality: false,
        ..BuildParams::default()
    };
    // The subjects vary in 4 shape parameters plus noise, so 99 % keeps at most 4 modes; a fixed
    // count keeps exactly 6 in every model, and never more than the N − 1 = 9 that exist.
    let six = build_body_model(&set, &params(6)).unwrap();
    for m in std::iter::once(&six.whole).chain(&six.segments) {
        assert_eq!(m.mode_count(), 6.min(m.all_variances.len()));
        pca_support::check_orthonormal(m);
    }
    assert_eq!(six.whole.mode_count(), 6);
    let many = build_body_model(&set, &params(50)).unwrap();
    for m in std::iter::once(&many.whole).chain(&many.segments) {
        assert_eq!(m.mode_count(), m.all_variances.len());
        assert!(m.mode_count() <= 9);
    }
    // Recorded in the settings, and in the file.
    let bytes = bodyspace::model_file::file::write_model(
        &six,
        bodyspace::model_file::file::BasisPrecision::F32,
    );
    let read = bodyspace::model_file::file::read_model(&bytes).unwrap();
    assert_eq!(read.settings.modes, Some(6));
    assert!(build_body_model(&set, &params(0)).is_err());
    // Settings written before the field existed read as "no fixed count".
    let mut json = serde_json::to_value(BuildParams::default()).unwrap();
    json.as_object_mut().unwrap().remove("modes");
    let old: BuildParams = serde_json::from_value(json).unwrap();
    assert_eq!(old.modes, None);
}
