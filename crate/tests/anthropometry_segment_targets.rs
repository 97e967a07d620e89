//! End-to-end: targets of a segment act on its model (`anthropometry::segment_targets`) on the demo model
//! (`public/models/demo.bsm`). Which measurements belong to which segment; a head-girth and a
//! thigh-girth target met on the stitched body within 5 mm by the head and right-leg models with
//! the rest of the body held (vertices outside the segment do not move); a target of another
//! segment refused with a message that lists the segment's own.
#![cfg(not(target_arch = "wasm32"))]

use bodyspace::anthropometry::from_measurements::FromMeasurementsParams;
use bodyspace::anthropometry::segment_targets::{
    measurement_segment, segment_body_from_measurements, segment_measurements,
};
use bodyspace::cli::model::{base_measurer, load_model};
use bodyspace::measure::Measure;
use bodyspace::pca::{Coefficients, ModeDelta, ModeTarget};
use bodyspace::template::Segment;
use std::path::Path;

#[test]
fn segment_targets_act_on_the_segment_model_alone() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../public/models/demo.bsm"
    ));
    let (model, _) = load_model(path).unwrap();
    let measurer = base_measurer().unwrap();
    use Measure::*;
    assert_eq!(measurement_segment(HeadGirth), Some(Segment::Head));
    assert_eq!(measurement_segment(Stature), None);

    // The held body: a whole-body shape away from the mean, with the torso overridden.
    let held = Coefficients {
        whole: model
            .whole
            .coefficients_from_sigma(&[0.8, -0.5, 0.3])
            .unwrap(),
        segments: std::array::from_fn(|s| {
            (Segment::ALL[s] == Segment::Torso).then(|| {
                model
                    .segment(Segment::Torso)
                    .coefficients_from_sigma(&[0.5])
                    .unwrap()
            })
        }),
    };
    let before: Vec<f32> = model
        .reconstruct(&held)
        .unwrap()
        .iter()
        .map(|&x| x as f32)
        .collect();
    let start = measurer.measure(&before).unwrap();
    // Every segment's model moves each of its measurements: some mode at 1σ changes it by more
    // than 3 mm (a target there can be met), with the rest of the body held.
    let plan_of = |s: Segment| {
        let mut c = held.clone();
        let part = model.segment(s);
        c.segments[s.index()] =
            Some(part.project_flat(&model.segment_reconstructions(&held).unwrap()[s.index()]));
        c
    };
    for segment in Segment::ALL {
        let c = plan_of(segment);
        let mut x = vec![0.0f32; before.len()];
        let plan = model.reconstruct_into(&c, &mut x).unwrap();
        let base = measurer.measure(&x).unwrap();
        let part = model.segment(segment);
        let sd = part.standard_deviations();
        for m in segment_measurements(segment) {
            let largest = (0..part.mode_count())
                .map(|k| {
                    let mut moved = x.clone();
                    let change = ModeDelta {
                        target: ModeTarget::Segment(segment),
                        mode: k,
                        delta: sd[k],
                    };
                    model.apply_delta(&plan, change, &mut moved).unwrap();
                    (measurer.measure(&moved).unwrap().get(m).unwrap() - base.get(m).unwrap()).abs()
                })
                .fold(0.0, f64::max);
            eprintln!(
                "{:<10} {:<18} largest change at 1σ {:.1} mm",
                segment.name(),
                m.definition().name,
                largest * 1e3
            );
            assert!(
                largest > 0.003,
                "{} moves {} by {largest} m at most",
                segment.name(),
                m.definition().name
            );
        }
    }
    let params = FromMeasurementsParams::default();
    for (segment, m, change) in [
        (Segment::Head, HeadGirth, 0.02),
        (Segment::Head, HeadGirth, -0.015),
        (Segment::RightLeg, ThighGirth, 0.03),
        (Segment::RightArm, UpperArmGirth, -0.02),
        (Segment::Torso, WaistGirth, 0.04),
    ] {
        let target = start.get(m).unwrap() + change;
        let found = segment_body_from_measurements(
            &model,
            segment,
            &held,
            &measurer,
            &[(m, target)],
            &params,
        )
        .unwrap();
        let a = &found.found.achieved[0];
        eprintln!(
            "{} {}: target {:.4} achieved {:.4} in {} iterations",
            segment.name(),
            a.name,
            a.target,
            a.achieved,
            found.found.iterations
        );
        assert!((a.achieved - target).abs() <= 0.005 && a.met, "{a:?}");
        // Measured again on the stitched body of the returned coefficients.
        let after: Vec<f32> = model
            .reconstruct(&found.coefficients)
            .unwrap()
            .iter()
            .map(|&x| x as f32)
            .collect();
        let again = measurer.measure(&after).unwrap().get(m).unwrap();
        assert!((again - target).abs() <= 0.005, "{again} vs {target}");
        // Only the segment's coefficients changed, so vertices outside it stay put.
        assert_eq!(found.coefficients.whole, held.whole);
        for s in Segment::ALL.into_iter().filter(|&s| s != segment) {
            assert_eq!(
                found.coefficients.segments[s.index()],
                held.segments[s.index()]
            );
        }
        let inside = &model.segment(segment).vertex_indices;
        let mut in_segment = vec![false; before.len() / 3];
        inside.iter().for_each(|&v| in_segment[v as usize] = true);
        let moved_outside = (0..before.len() / 3)
            .filter(|&v| !in_segment[v])
            .map(|v| {
                (0..3)
                    .map(|k| (after[3 * v + k] - before[3 * v + k]).abs())
                    .fold(0.0, f32::max)
            })
            .fold(0.0, f32::max);
        assert!(
            moved_outside < 1e-5,
            "{moved_outside} m outside {}",
            segment.name()
        );
    }
    // A target of another segment is refused, naming the segment's own.
    let e = segment_body_from_measurements(
        &model,
        Segment::Head,
        &held,
        &measurer,
        &[(WaistGirth, 0.8)],
        &params,
    )
    .unwrap_err();
    assert!(e.to_string().contains("head_girth"), "{e}");
}
