//! Accuracy on the `held-out` synthetic population (other shapes, poses and scanner than the
//! `tuning` population the defaults were tuned on; docs/synthetic-population.md), end to end
//! (`align_scan`), held to tolerances set from docs/benchmarks.md's "Held-out population" run
//! with margin; and the `paper` preset still gives today's figures on the tuning population.
//! Two subjects each keep it to seconds. Native only: it reads the MakeHuman data from
//! node_modules.
#![cfg(not(target_arch = "wasm32"))]

mod synth_support;

use std::sync::OnceLock;

use bodyspace::align::{align_scan, AlignInput, AlignParams, CorrespondenceReport, Preset};
use bodyspace::mesh::units::Units as ScanUnits;
use bodyspace::synth::*;
use bodyspace::template::{Resolution, Template};
use synth_support::{base_template_and_data, subject_in_metres};

fn data() -> &'static (MakeHumanData, Template) {
    static DATA: OnceLock<(MakeHumanData, Template)> = OnceLock::new();
    DATA.get_or_init(|| {
        let (template, data) = base_template_and_data();
        (data, template)
    })
}

/// Subject `id` aligned with `params` at `base`: (scan→template RMS mm, correspondence report).
fn fit(id: SubjectId, params: &AlignParams) -> (f64, CorrespondenceReport) {
    fit_at(id, params, Resolution::Base)
}

/// Subject `id` aligned with `params` at `resolution` (coarse to fine at `fine`), the
/// correspondence measured on the base vertices.
fn fit_at(
    id: SubjectId,
    params: &AlignParams,
    resolution: Resolution,
) -> (f64, CorrespondenceReport) {
    let (data, base) = data();
    let (scan, landmarks, truth) = subject_in_metres(data, base, id, &id.profile.scanner());
    let template = &base.at_resolution(resolution);
    let input = AlignInput {
        template,
        base_template: Some(base),
        scan: &scan,
        landmarks: &landmarks,
        units: Some(ScanUnits::Metres),
    };
    let mut result = align_scan(&input, params, &mut ()).unwrap();
    result.compare_with_truth(base, &truth);
    let rms = result.report.fine.as_ref().unwrap().scan_to_template.rms_mm;
    (rms, result.report.correspondence.unwrap())
}

#[test]
fn held_out_subjects_are_fitted_within_tolerance_by_both_presets() {
    for preset in Preset::ALL {
        let params = preset.params();
        assert_eq!(params.preset, preset);
        for index in [0u64, 1] {
            let id = SubjectId {
                profile: PopulationProfile::HeldOut,
                seed: 912,
                index,
            };
            let (rms, c) = fit(id, &params);
            let f = &c.fitted;
            eprintln!(
                "{} subject {index}: RMS {rms:.3} mm, correspondence {:.2} → {:.2} mm, p95 {:.1}, max {:.1}",
                preset.name(),
                c.rough.mean_mm,
                f.mean_mm,
                f.p95_mm,
                f.max_mm
            );
            // The held-out scanner's noise is 1.3 mm (noise floor ≈ 1.10 mm RMS).
            assert!(rms <= 1.4, "{}: RMS {rms} mm", preset.name());
            assert!(f.mean_mm < c.rough.mean_mm, "better than the warp alone");
            assert!(f.mean_mm <= 6.5, "{}: mean {} mm", preset.name(), f.mean_mm);
            assert!(f.p95_mm <= 19.0, "{}: p95 {} mm", preset.name(), f.p95_mm);
            assert!(f.max_mm <= 75.0, "{}: max {} mm", preset.name(), f.max_mm);
            if preset == Preset::Anchored {
                // Here 5.68 / 15.4 / 47.8 and 6.09 / 17.6 / 48.7 mm (paper: 5.62 / 17.2 / 53.7 and
                // 6.06 / 17.8 / 62.9 — these two stand arms down, where posing the arms costs
                // 0.1–0.2 mm of mean; it pays on posed arms, next test). Since 2026-11-24 16:40
                // anchored takes no match farther than 20 mm: the jaw line is no longer pulled
                // across the unscanned gap under the chin to the neck (before: 5.76 / 15.7 / 50.8
                // and 6.25 / 18.1 / 59.4 mm).
                assert!(f.mean_mm <= 6.3, "anchored: mean {} mm", f.mean_mm);
                assert!(f.p95_mm <= 18.0, "anchored: p95 {} mm", f.p95_mm);
                assert!(f.max_mm <= 52.0, "anchored: max {} mm", f.max_mm);
            }
            let parts: Vec<&str> = c.parts.iter().map(|p| p.part).collect();
            assert_eq!(parts, ["head", "torso", "arms", "hands", "legs", "feet"]);
        }
    }
}

#[test]
fn anchored_poses_the_arms_of_a_hands_on_hips_subject_before_the_warp() {
    // Held-out subject 003 stands with its hands on its hips (elbows bent 82° and 87°, the
    // hands laid on the hips, wrists bent back). The `paper` preset bends the template's
    // straight arms by the RBF alone: whole body 7.53 mm (docs/benchmarks.md). `anchored` poses
    // head and arms to their landmarks first and turns each hand at the wrist onto its own
    // landmarks: 7.06 mm, hands 5.23 mm mean, 38.5 mm worst (6.78 / 31.4 mm, whole body 7.52 mm,
    // without the hands' turn). On the generator's earlier pose (forearms bent in the frontal
    // plane, hands in front of the belly) it was 5.62 mm, hands 2.71 mm.
    let id = SubjectId {
        profile: PopulationProfile::HeldOut,
        seed: 912,
        index: 2,
    };
    let (rms, c) = fit(id, &Preset::Anchored.params());
    let hands = &c.parts.iter().find(|p| p.part == "hands").unwrap().error;
    eprintln!(
        "anchored, held-out subject 003: RMS {rms:.3} mm, mean {:.2}, hands {:.2} / max {:.2}",
        c.fitted.mean_mm, hands.mean_mm, hands.max_mm
    );
    assert!(rms <= 1.4, "RMS {rms} mm");
    assert!(c.fitted.mean_mm <= 7.3, "mean {} mm", c.fitted.mean_mm);
    assert!(hands.mean_mm <= 5.6, "hands: mean {} mm", hands.mean_mm);
    assert!(hands.max_mm <= 42.0, "hands: max {} mm", hands.max_mm);
}

#[test]
fn the_paper_preset_reproduces_todays_figures() {
    assert_eq!(Preset::Paper.params(), AlignParams::default());
    // Subject 001 of the demo population (seed 2026, index 0): RMS 0.945 mm, correspondence
    // 4.96 mm, p95 14.14 mm, max 72.49 mm since the template's landmark definitions of 2026-11-24
    // (Cervicale, 10th Rib Midspine, ASIS, Iliocristale moved; before: 0.944, 4.91, 13.89, 70.53).
    let id = SubjectId {
        profile: PopulationProfile::Tuning,
        seed: 2026,
        index: 0,
    };
    let (rms, c) = fit(id, &Preset::Paper.params());
    let f = &c.fitted;
    eprintln!(
        "paper, tuning subject 001: RMS {rms:.3} mm, mean {:.2}, p95 {:.2}, max {:.2}",
        f.mean_mm, f.p95_mm, f.max_mm
    );
    assert!((rms - 0.945).abs() < 0.002, "RMS {rms}");
    assert!((f.mean_mm - 4.96).abs() < 0.01, "mean {}", f.mean_mm);
    assert!((f.p95_mm - 14.14).abs() < 0.02, "p95 {}", f.p95_mm);
    assert!((f.max_mm - 72.49).abs() < 0.02, "max {}", f.max_mm);
}

#[test]
fn fine_keeps_the_base_correspondence_on_its_base_vertices() {
    // Issue 12: coarse to fine used to lose correspondence on the base vertices (5 held-out
    // subjects: +0.1 mm mean, +4–7 mm on the largest errors): new vertices on the rim of the
    // never-scanned mouth cavity got data, and the fine stage slid the base fit along the
    // surface. Now fine vertices get no more data weight than their base sources and the fine
    // stage holds each vertex along the carried base fit (`FineStageParams::tangential_weight`).
    // Held-out subject 001, anchored: base 5.64 / 15.3 / 47.8 mm, fine 5.65 / 15.4 / 47.6 mm
    // (mean / p95 / max; RMS 1.191 → 1.004 mm; with the hands turned onto their landmarks since
    // 2026-11-25, 5.68 / 15.4 / 47.8 and 5.69 / 15.4 / 47.6 mm before).
    let id = SubjectId {
        profile: PopulationProfile::HeldOut,
        seed: 912,
        index: 0,
    };
    let params = Preset::Anchored.params();
    let (base_rms, base) = fit_at(id, &params, Resolution::Base);
    let (fine_rms, fine) = fit_at(id, &params, Resolution::Fine);
    let (b, f) = (&base.fitted, &fine.fitted);
    eprintln!(
        "anchored, held-out subject 001: base RMS {base_rms:.3}, {:.3} / {:.2} / {:.2} mm; fine RMS {fine_rms:.3}, {:.3} / {:.2} / {:.2} mm",
        b.mean_mm, b.p95_mm, b.max_mm, f.mean_mm, f.p95_mm, f.max_mm
    );
    assert!(fine_rms < base_rms, "fine fits the surface closer");
    assert!(
        f.mean_mm <= b.mean_mm + 0.05,
        "mean {} vs {}",
        f.mean_mm,
        b.mean_mm
    );
    assert!(
        f.p95_mm <= b.p95_mm + 0.3,
        "p95 {} vs {}",
        f.p95_mm,
        b.p95_mm
    );
    assert!(
        f.max_mm <= b.max_mm + 2.0,
        "max {} vs {}",
        f.max_mm,
        b.max_mm
    );
}
