//! End-to-end: the held body of `pca::morph` follows slider moves by rank-1 updates and stays
//! equal to a full reconstruction (within 1e-6 m) after thousands of random moves.

mod pca_support;

use bodyspace::pca::morph::MAX_DELTAS;
use bodyspace::pca::random::NormalRng;
use bodyspace::pca::{
    build_body_model, BodyModel, BuildParams, Coefficients, ModeDelta, ModeTarget, Morph,
};
use bodyspace::template::Segment;

fn model() -> BodyModel {
    let set = pca_support::training_set(12, 11);
    let params = BuildParams {
        variance: 1.0,
        compute_quality: false,
        ..BuildParams::default()
    };
    build_body_model(&set, &params).unwrap()
}

fn max_abs_diff(a: &[f64], b: &[f32]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - *y as f64).abs())
        .fold(0.0, f64::max)
}

/// A body with the torso and the left leg overridden, all at random coefficients.
fn start(model: &BodyModel, rng: &mut NormalRng) -> Coefficients {
    let mut draw = |m: &bodyspace::pca::ShapeModel| {
        m.standard_deviations()
            .iter()
            .map(|sd| sd * rng.next_normal())
            .collect::<Vec<f64>>()
    };
    let mut c = Coefficients {
        whole: draw(&model.whole),
        ..Coefficients::default()
    };
    for s in [Segment::Torso, Segment::LeftLeg] {
        c.segments[s.index()] = Some(draw(model.segment(s)));
    }
    c
}

#[test]
fn thousands_of_slider_moves_stay_within_a_micrometre_of_a_full_reconstruction() {
    let model = model();
    let mut rng = NormalRng::new(2026);
    let mut c = start(&model, &mut rng);
    let mut morph = Morph::new(&model, &c).unwrap();
    // The same moves with plain f32 updates, to show what the compensation buys.
    let mut plain = morph.positions().to_vec();
    let plan = model.stitch_plan(c.overridden());
    let parts = [
        (ModeTarget::Whole, None),
        (ModeTarget::Segment(Segment::Torso), Some(Segment::Torso)),
        (
            ModeTarget::Segment(Segment::LeftLeg),
            Some(Segment::LeftLeg),
        ),
    ];
    let moves = 5000;
    for i in 0..moves {
        let (target, segment) = parts[i % 3];
        let values = match segment {
            None => &mut c.whole,
            Some(s) => c.segments[s.index()].as_mut().unwrap(),
        };
        let sds = match segment {
            None => model.whole.standard_deviations(),
            Some(s) => model.segment(s).standard_deviations(),
        };
        let k = (rng.next_normal().abs() * 7.0) as usize % values.len();
        // Slider values on the app's 0.001σ grid within ±3σ.
        let t = (rng.next_normal().clamp(-3.0, 3.0) * 1000.0).round() / 1000.0;
        let old = values[k];
        values[k] = t * sds[k];
        model
            .apply_delta(
                &plan,
                ModeDelta {
                    target,
                    mode: k,
                    delta: values[k] - old,
                },
                &mut plain,
            )
            .unwrap();
        let update = morph.update(&model, &c).unwrap();
        assert!(
            !update.rebuilt && update.deltas <= 1,
            "move {i}: {update:?}"
        );
    }
    let reference = model.reconstruct(&c).unwrap();
    let compensated = max_abs_diff(&reference, morph.positions());
    let drift = max_abs_diff(&reference, &plain);
    let mut full = vec![0.0f32; reference.len()];
    model.reconstruct_into(&c, &mut full).unwrap();
    let rebuilt = max_abs_diff(&reference, &full);
    eprintln!(
        "after {moves} moves: compensated {compensated:.2e} m, plain f32 {drift:.2e} m, full f32 reconstruction {rebuilt:.2e} m"
    );
    assert!(
        compensated < 1e-6,
        "compensated updates drifted {compensated} m"
    );
    let incremental_vs_full = morph
        .positions()
        .iter()
        .zip(&full)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0f32, f32::max);
    assert!(incremental_vs_full < 1e-6, "{incremental_vs_full} m");
}

#[test]
fn new_overrides_and_many_changes_rebuild_one_change_does_not() {
    let model = model();
    let mut rng = NormalRng::new(7);
    let mut c = start(&model, &mut rng);
    let mut morph = Morph::new(&model, &c).unwrap();

    // Nothing changed: nothing done.
    let same = morph.update(&model, &c).unwrap();
    assert_eq!((same.rebuilt, same.deltas), (false, 0));

    // One whole-body and one torso coefficient: two rank-1 updates.
    c.whole[0] += 0.1;
    c.segments[Segment::Torso.index()].as_mut().unwrap()[0] -= 0.05;
    let two = morph.update(&model, &c).unwrap();
    assert_eq!((two.rebuilt, two.deltas), (false, 2));
    assert!(max_abs_diff(&model.reconstruct(&c).unwrap(), morph.positions()) < 1e-6);

    // A segment gets its own coefficients: the blend changes, so the body is rebuilt.
    c.segments[Segment::Head.index()] = Some(vec![0.0]);
    assert!(morph.update(&model, &c).unwrap().rebuilt);
    // ... and when it follows the whole body again.
    c.segments[Segment::Head.index()] = None;
    assert!(morph.update(&model, &c).unwrap().rebuilt);

    // More than MAX_DELTAS coefficients at once (a random body): rebuilt.
    let n = model.whole.mode_count();
    for (k, b) in c.whole.iter_mut().enumerate() {
        *b += 0.01 * (k + 1) as f64;
    }
    for s in [Segment::Torso, Segment::LeftLeg] {
        for b in c.segments[s.index()].as_mut().unwrap() {
            *b += 0.01;
        }
    }
    assert!(n + 2 > MAX_DELTAS);
    assert!(morph.update(&model, &c).unwrap().rebuilt);
    assert!(max_abs_diff(&model.reconstruct(&c).unwrap(), morph.positions()) < 1e-6);

    // Shorter vectors are trailing zeros; longer ones and non-finite values are errors that
    // leave the body as it was.
    let before = morph.positions().to_vec();
    let mut bad = c.clone();
    bad.whole = vec![0.0; n + 1];
    assert!(morph.update(&model, &bad).is_err());
    bad.whole = vec![f64::NAN];
    assert!(morph.update(&model, &bad).is_err());
    assert_eq!(morph.positions(), &before[..]);
    let mut short = c.clone();
    short.whole.truncate(1);
    morph.update(&model, &short).unwrap();
    assert_eq!(morph.coefficients().whole.len(), n);
    assert!(max_abs_diff(&model.reconstruct(&short).unwrap(), morph.positions()) < 1e-6);
}
