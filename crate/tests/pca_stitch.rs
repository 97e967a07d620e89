//! End-to-end: stitched segment reconstructions, the f32 slider fast path and seam quality.

mod pca_support;

use bodyspace::pca::{
    build_body_model, BodyModel, BuildParams, Coefficients, ModeDelta, ModeTarget,
};
use bodyspace::template::Segment;

fn model(variance: f64) -> (BodyModel, Vec<Vec<nalgebra::Point3<f64>>>) {
    let set = pca_support::training_set(12, 11);
    let params = BuildParams {
        variance,
        compute_quality: false,
        ..BuildParams::default()
    };
    (build_body_model(&set, &params).unwrap(), set.shapes)
}

fn max_abs_diff(a: &[f64], b: &[f32]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - *y as f64).abs())
        .fold(0.0, f64::max)
}

#[test]
fn segments_from_the_same_body_stitch_back_to_that_body() {
    let (model, shapes) = model(1.0);
    for shape in &shapes[..4] {
        let c = model.project(shape).unwrap().coefficients;
        let whole_only = Coefficients {
            whole: c.whole.clone(),
            ..Coefficients::default()
        };
        let stitched = model.reconstruct(&c).unwrap();
        let whole = model.reconstruct(&whole_only).unwrap();
        let worst = stitched
            .iter()
            .zip(&whole)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(
            worst < 1e-5,
            "stitched differs from the whole body by {worst} m"
        );
        let seam = model.seam_report(&c).unwrap();
        assert!(seam.max_jump < 1e-5, "seam jump {} m", seam.max_jump);
        assert!(seam.segments.is_some());
    }
}

#[test]
fn mixing_two_bodies_is_continuous_across_the_bands() {
    let (model, shapes) = model(1.0);
    let a = model.project(&shapes[0]).unwrap().coefficients;
    let b = model.project(&shapes[1]).unwrap().coefficients;
    // Torso of subject 0, legs of subject 1, everything else from subject 0's whole body.
    let mut mixed = Coefficients {
        whole: a.whole.clone(),
        ..Coefficients::default()
    };
    mixed.segments[Segment::Torso.index()] = a.segments[Segment::Torso.index()].clone();
    for leg in [Segment::LeftLeg, Segment::RightLeg] {
        mixed.segments[leg.index()] = b.segments[leg.index()].clone();
    }
    let x = model.reconstruct(&mixed).unwrap();
    let uncovered = bodyspace::pca::segments::edges_without_common_segment(
        &model.triangles,
        &model.segment_weights,
    );
    // Only the left/right leg boundary (x = 0 between two columns, front and back, 6 rings).
    assert!(
        !uncovered.is_empty() && uncovered.len() <= 2 * 3 * 8,
        "{} edges",
        uncovered.len()
    );
    let seam = model.seam_report(&mixed).unwrap();
    assert!(
        seam.max_jump > 1e-3,
        "subjects 0 and 1 differ, jump {}",
        seam.max_jump
    );
    let parts = model.segment_reconstructions(&mixed).unwrap();
    // Per edge, the stitched edge can exceed the longest per-segment edge only by the blend's
    // share of the jump: ‖Δx‖ ≤ maxₛ‖Δx⁽ˢ⁾‖ + Σₛ|Δw̃ₛ|·max_jump (no tearing).
    let weights = &model.segment_weights;
    let blend = |v: usize| {
        let w = weights[v];
        let t: f32 = w.iter().sum();
        w.map(|x| (x / t) as f64)
    };
    let local: Vec<Vec<Option<usize>>> = model
        .segments
        .iter()
        .map(|m| {
            let mut l = vec![None; model.template.vertex_count];
            for (j, &v) in m.vertex_indices.iter().enumerate() {
                l[v as usize] = Some(j);
            }
            l
        })
        .collect();
    for tri in &model.triangles {
        for (u, v) in [(tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])] {
            let (u, v) = (u as usize, v as usize);
            let edge = |p: &[f64], i: usize, j: usize| {
                (0..3)
                    .map(|k| (p[3 * i + k] - p[3 * j + k]).powi(2))
                    .sum::<f64>()
                    .sqrt()
            };
            let stitched = edge(&x, u, v);
            let mut longest: f64 = 0.0;
            for s in 0..6 {
                if let (Some(i), Some(j)) = (local[s][u], local[s][v]) {
                    longest = longest.max(edge(&parts[s], i, j));
                }
            }
            if longest == 0.0 {
                // No segment holds this edge (the two legs meet without an overlap band in this
                // test template); counted below.
                continue;
            }
            let (wu, wv) = (blend(u), blend(v));
            let dw: f64 = (0..6).map(|s| (wu[s] - wv[s]).abs()).sum();
            assert!(
                stitched <= longest + dw * seam.max_jump + 1e-9,
                "edge {u}-{v} tears"
            );
        }
    }
}

#[test]
fn fast_path_and_incremental_updates_match_the_reference() {
    let (model, shapes) = model(1.0);
    let a = model.project(&shapes[2]).unwrap().coefficients;
    let v = model.template.vertex_count;
    let mut out = vec![0.0f32; 3 * v];

    let whole = Coefficients {
        whole: a.whole.clone(),
        ..Coefficients::default()
    };
    let plan = model.reconstruct_into(&whole, &mut out).unwrap();
    assert!(max_abs_diff(&model.reconstruct(&whole).unwrap(), &out) < 1e-5);

    // Slider moves on the whole body: x += Δb·φₖ.
    let mut moved = whole.clone();
    moved.whole[0] += 0.5;
    moved.whole[2] -= 0.25;
    model
        .apply_delta(
            &plan,
            ModeDelta {
                target: ModeTarget::Whole,
                mode: 0,
                delta: 0.5,
            },
            &mut out,
        )
        .unwrap();
    model
        .apply_delta(
            &plan,
            ModeDelta {
                target: ModeTarget::Whole,
                mode: 2,
                delta: -0.25,
            },
            &mut out,
        )
        .unwrap();
    assert!(max_abs_diff(&model.reconstruct(&moved).unwrap(), &out) < 1e-5);

    // With the torso overridden, whole-body and torso sliders both act through the blend.
    let mut mixed = moved.clone();
    mixed.segments[Segment::Torso.index()] = a.segments[Segment::Torso.index()].clone();
    let plan = model.reconstruct_into(&mixed, &mut out).unwrap();
    assert!(max_abs_diff(&model.reconstruct(&mixed).unwrap(), &out) < 1e-5);
    model
        .apply_delta(
            &plan,
            ModeDelta {
                target: ModeTarget::Whole,
                mode: 1,
                delta: 0.3,
            },
            &mut out,
        )
        .unwrap();
    model
        .apply_delta(
            &plan,
            ModeDelta {
                target: ModeTarget::Segment(Segment::Torso),
                mode: 0,
                delta: -0.4,
            },
            &mut out,
        )
        .unwrap();
    mixed.whole[1] += 0.3;
    mixed.segments[Segment::Torso.index()].as_mut().unwrap()[0] -= 0.4;
    assert!(max_abs_diff(&model.reconstruct(&mixed).unwrap(), &out) < 1e-5);

    // All six overridden: the whole body has no weight anywhere, and the fast path skips its
    // basis (blocks without whole-body weight), still equal to the reference.
    let b = model.project(&shapes[3]).unwrap().coefficients;
    let mut all = mixed.clone();
    for s in Segment::ALL {
        let from = if s.index() % 2 == 0 { &a } else { &b };
        all.segments[s.index()] = from.segments[s.index()].clone();
    }
    let plan_all = model.reconstruct_into(&all, &mut out).unwrap();
    assert!(max_abs_diff(&model.reconstruct(&all).unwrap(), &out) < 1e-5);
    model
        .apply_delta(
            &plan_all,
            ModeDelta {
                target: ModeTarget::Segment(Segment::Head),
                mode: 0,
                delta: 0.2,
            },
            &mut out,
        )
        .unwrap();
    all.segments[Segment::Head.index()].as_mut().unwrap()[0] += 0.2;
    assert!(max_abs_diff(&model.reconstruct(&all).unwrap(), &out) < 1e-5);

    // A segment that is not overridden in the plan cannot be moved incrementally.
    assert!(model
        .apply_delta(
            &plan,
            ModeDelta {
                target: ModeTarget::Segment(Segment::Head),
                mode: 0,
                delta: 1.0
            },
            &mut out
        )
        .is_err());
    assert!(model
        .apply_delta(
            &plan,
            ModeDelta {
                target: ModeTarget::Whole,
                mode: 99,
                delta: 1.0
            },
            &mut out
        )
        .is_err());
    assert!(model.reconstruct_into(&mixed, &mut out[..3]).is_err());
    let too_long = Coefficients {
        whole: vec![0.0; 99],
        ..Coefficients::default()
    };
    assert!(model.reconstruct_into(&too_long, &mut out).is_err());
}

#[test]
fn sigma_units_scale_by_the_standard_deviation() {
    let (model, _) = model(0.99);
    let b = model.whole.coefficients_from_sigma(&[2.0]).unwrap();
    assert!((b[0] - 2.0 * model.whole.variances[0].sqrt()).abs() < 1e-12);
    assert!((model.whole.sigma_from_coefficients(&b)[0] - 2.0).abs() < 1e-12);
    let random = model.whole.random_coefficients(7);
    assert_eq!(random.len(), model.whole.mode_count());
    assert_eq!(random, model.whole.random_coefficients(7));
    assert_ne!(random, model.whole.random_coefficients(8));
    // A few thousand draws: every mode's standard deviation is its √λ within 5 %.
    let draws: Vec<Vec<f64>> = (0..4000)
        .map(|s| model.whole.random_coefficients(s))
        .collect();
    for k in 0..model.whole.mode_count() {
        let var = draws.iter().map(|d| d[k] * d[k]).sum::<f64>() / draws.len() as f64;
        let ratio = (var / model.whole.variances[k]).sqrt();
        assert!((ratio - 1.0).abs() < 0.05, "mode {k}: sd ratio {ratio}");
    }
}
