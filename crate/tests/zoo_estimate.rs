//! The landmark estimate on the scanner zoo (issue 31): every scanner class of
//! `synth::zoo` (parts, cut crown and feet, floor, turntable, slices, blob, decimated, dense,
//! strays, raw) in two frames each and the classes of what people bring (arms touching, an arm
//! raised, hair, tight clothing) in one, the frame right (up and facing) and the landmarks within
//! the tolerances the measurement supports (docs/landmarks-estimate.md, "Scanner zoo"; the raised
//! arm since its frame candidates are centred on the trunk, "The frame candidates centred on the
//! trunk").
//! Held-out subjects in their own poses, at a coarse scanner step so the test stays fast. Native
//! only.
#![cfg(not(target_arch = "wasm32"))]

mod estimate_support;

use bodyspace::estimate::{Axis, EstimateParams, Orientation, Verdict};
use bodyspace::landmarks::LandmarkSet;
use bodyspace::mesh::topology::{component_labels, components};
use bodyspace::mesh::winding::{winding, Winding, WindingParams};
use bodyspace::mesh::Mesh;
use bodyspace::synth::zoo::parts::scan_labels;
use bodyspace::synth::{
    MakeHumanData, PopulationProfile, ScannerClass, ScannerParams, SubjectId, ZooParams,
};
use bodyspace::template::Template;
use estimate_support::{
    estimate_bare, estimate_given, frame_cosines, landmark_errors, load, only, placed, zoo_frames,
    Case, Frame, Zoo,
};
use nalgebra::Vector3;

/// A seed neither tuned on nor reported in the measurement.
const SEED: u64 = 5757;

/// Mean landmark error allowed per class (mm). Measured on held-out seed 4242 (3 subjects, four
/// frames, the profile's scanner; docs/landmarks-estimate.md): worst subject 16–24 mm on every
/// class, 25.4 mm with the feet cut; on this test's seed and coarse scanner 9.0–19.7 mm. A scan
/// estimated upside down or back to front is 250–800 mm off. With the floor taken off the scan
/// (2026-11-28) the floor and turntable classes measured 11.5–12.0 mm here, worst subject
/// 14.6–14.8 mm on fresh seed 7676.
fn tolerance_mm(class: ScannerClass) -> f64 {
    match class {
        ScannerClass::Floor | ScannerClass::Turntable => 18.0,
        ScannerClass::Raw | ScannerClass::CrownCut | ScannerClass::FeetCut => 30.0,
        _ => 25.0,
    }
}

/// The zoo on the held-out profile's scanner at `step` (m) both ways: coarse keeps the tests fast.
fn zoo_at<'a>(
    template: &'a Template,
    data: &'a MakeHumanData,
    step: f64,
    params: ZooParams,
) -> Zoo<'a> {
    Zoo {
        data,
        template,
        scanner: ScannerParams {
            vertical_step: step,
            horizontal_step: step,
            ..PopulationProfile::HeldOut.scanner()
        },
        params,
    }
}

/// The classes of what people bring to the scanner (poses, hair, clothing), not the scanner's.
fn people(class: ScannerClass) -> bool {
    matches!(
        class,
        ScannerClass::ArmsTouching
            | ScannerClass::ArmRaised
            | ScannerClass::Hair
            | ScannerClass::TightClothing
    )
}

#[test]
fn every_scanner_class_comes_out_the_right_way_up_in_two_frames() {
    let (template, data) = load();
    let frames = zoo_frames();
    // A coarse scanner (6 mm) and a dense class at 2 mm keep the test fast.
    let params = ZooParams {
        dense_step: 0.002,
        slice_ring_step: 0.002,
        ..ZooParams::default()
    };
    let zoo = zoo_at(&template, &data, 0.006, params);
    let mut failures = Vec::new();
    for (i, class) in ScannerClass::ALL.into_iter().enumerate() {
        let id = SubjectId {
            profile: PopulationProfile::HeldOut,
            seed: SEED,
            index: i as u64,
        };
        let subject = zoo.scanned(id, class);
        // The people's classes in one frame each: CI's time is short.
        let frame_count = if people(class) { 1 } else { 2 };
        for frame in (i..i + frame_count).map(|f| &frames[f % frames.len()]) {
            let c = placed(&template, subject.clone(), frame);
            if class == ScannerClass::Parts || class == ScannerClass::Raw {
                assert!(components(&c.scan) >= 5, "{}", class.name());
            }
            // Every class's triangles face out of the body, and turned over they face into it:
            // the app tells a click through a hole by it.
            let flipped = Mesh::new(
                c.scan.positions.clone(),
                c.scan
                    .triangles
                    .iter()
                    .map(|&[a, b, d]| [a, d, b])
                    .collect(),
            );
            let wound = (
                winding(&c.scan, &WindingParams::default()),
                winding(&flipped, &WindingParams::default()),
            );
            if wound != (Winding::Outward, Winding::Inward) {
                failures.push(format!(
                    "{} / {}: wound {wound:?}",
                    class.name(),
                    frame.name
                ));
            }
            let e = estimate_bare(&template, &c, &EstimateParams::default());
            let r = &e.report;
            let to_mm = e.scale_to_metres * 1000.0;
            let errors = landmark_errors(&c, &e.positions, to_mm);
            let mean = errors.iter().sum::<f64>() / errors.len() as f64;
            let (up, facing) = frame_cosines(frame, r.frame.up, r.frame.facing);
            let check = &r.self_check;
            eprintln!(
                "{} / {}: {} vertices, up {up:.2}, facing {facing:.2}, mean {mean:.1} mm, {:.0} ms, self-check {} (moved {:.1} mm, RMS {:.1} mm, {:.2} m, {} contradicting)",
                class.name(),
                frame.name,
                c.scan.positions.len(),
                r.total_ms,
                check.verdict.name(),
                check.evidence.fit_moved_mm,
                check.evidence.fit_rms_mm,
                check.evidence.stature_m,
                check.evidence.contradicting.len()
            );
            // A right estimate never calls itself failed (doubtful is allowed: a scan with its
            // feet cut off has template feet far from anything).
            let right = up > 0.9 && facing > 0.9 && mean < tolerance_mm(class);
            if !(right && check.verdict != Verdict::Failed) {
                failures.push(format!(
                    "{} / {}: up {up:.2}, facing {facing:.2}, mean {mean:.1} mm, self-check {:?}",
                    class.name(),
                    frame.name,
                    check
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn a_parts_scan_is_split_and_a_crown_cut_scan_has_nothing_above_the_cut() {
    let (template, data) = load();
    let zoo = zoo_at(&template, &data, 0.008, ZooParams::default());
    let id = |index| SubjectId {
        profile: PopulationProfile::HeldOut,
        seed: SEED,
        index,
    };
    // Every component of a parts scan lies in one of the template's six segments, and every
    // segment has a component.
    let parts = zoo.scanned(id(20), ScannerClass::Parts);
    let weights = template.segment_weight_table();
    let segment: Vec<u8> = (0..parts.surface.positions.len())
        .map(|v| {
            (0..6)
                .max_by(|&a, &b| weights[v][a].total_cmp(&weights[v][b]))
                .unwrap() as u8
        })
        .collect();
    let label = scan_labels(&parts.scan, &parts.surface.positions, &segment);
    let (component, count) = component_labels(&parts.scan.mesh);
    assert!(count >= 6);
    let mut of_component = vec![None; count];
    for (v, &k) in component.iter().enumerate() {
        if k == u32::MAX {
            continue;
        }
        let seen = of_component[k as usize].get_or_insert(label[v]);
        assert_eq!(*seen, label[v], "component {k} joins two segments");
    }
    for s in 0..6u8 {
        assert!(
            of_component.contains(&Some(s)),
            "segment {s} has no component"
        );
    }
    let crown = zoo.scanned(id(21), ScannerClass::CrownCut);
    let top = crown
        .surface
        .positions
        .iter()
        .map(|p| p.y)
        .fold(f64::MIN, f64::max);
    let highest = crown
        .scan
        .clean
        .iter()
        .map(|p| p.y)
        .fold(f64::MIN, f64::max);
    assert!(
        highest <= top - zoo.params.crown_cut.0,
        "{highest} vs top {top}"
    );
    let decimated = zoo.scanned(id(22), ScannerClass::Decimated);
    let n = decimated.scan.mesh.positions.len();
    assert!((7_000..=14_000).contains(&n), "decimated to {n} vertices");
}

/// An arm raised beside or above the head has no shoulder point, so its Acromion is the fit's
/// guess, 74 mm off on average on the zoo's raised arms (docs/landmarks-estimate.md, "Every
/// elbow where its axes meet; a raised arm"): its confidence says so, against the other Acromion's, and the upper arm measured
/// through it does not make the estimate doubtful (it did for every raised arm once the elbow
/// was placed where the arm's axes meet).
#[test]
fn a_raised_arm_says_its_acromion_is_unsure() {
    let (template, data) = load();
    let zoo = zoo_at(&template, &data, 0.006, ZooParams::default());
    let frame = zoo_frames()[0];
    for index in [30, 31] {
        let id = SubjectId {
            profile: PopulationProfile::HeldOut,
            seed: SEED,
            index,
        };
        let subject = zoo.scanned(id, ScannerClass::ArmRaised);
        let pose = &subject.params.pose;
        let (raised, down) = if pose.left_shoulder_abduction > pose.right_shoulder_abduction {
            ("Lt.", "Rt.")
        } else {
            ("Rt.", "Lt.")
        };
        let c = placed(&template, subject, &frame);
        let e = estimate_bare(&template, &c, &EstimateParams::default());
        let confidence = |side: &str| {
            e.report
                .landmarks
                .iter()
                .find(|l| l.name == format!("{side} Acromion"))
                .unwrap()
                .confidence
        };
        let (up, hanging) = (confidence(raised), confidence(down));
        let check = &e.report.self_check;
        eprintln!(
            "subject {index}: {raised} arm raised, Acromion confidence {up:.2} against {hanging:.2}, {}: {:?}",
            check.verdict.name(),
            check.reasons
        );
        assert!(up < 0.3 * hanging, "{index}: {up:.2} vs {hanging:.2}");
        let upper_arm = check
            .evidence
            .asymmetric
            .iter()
            .any(|a| a.segment == "upper arm");
        assert!(!upper_arm, "{index}: {:?}", check.reasons);
    }
}

/// Held-out subject `index` of `seed` as the `feet-cut` class delivers it at scanner `step` (m),
/// placed in `frame`: the scan `bodyspace synth --scanner-class feet-cut` (or `--zoo`) writes.
fn feet_cut_scan(
    template: &Template,
    data: &MakeHumanData,
    step: f64,
    seed: u64,
    index: u64,
    frame: &Frame,
) -> Case {
    let zoo = zoo_at(template, data, step, ZooParams::default());
    let id = SubjectId {
        profile: PopulationProfile::HeldOut,
        seed,
        index,
    };
    placed(template, zoo.scanned(id, ScannerClass::FeetCut), frame)
}

/// A scan whose feet the field of view cut off leaves the feet nothing to say about which way the
/// body faces. On the blind held-out zoo seed 8461 (subject 4, as `bodyspace synth --zoo --step 4`
/// writes it) the two facings' similarity fits came 0.6 % apart and the estimate went back to
/// front, its landmarks 437 mm off on average. The legs say it (`estimate::facing`: the thighs'
/// points lie forward of the calves'). The same estimate with the legs' cue turned off still goes
/// back to front, so the test sees the difference, and says that only the fits chose the facing
/// and how close they came; five landmarks clicked on the scan
/// (the person's way out, issue 31: 4–6 re-anchor the estimate) turn it the right way round.
/// When the person chose only the up axis, the legs still say the facing (before, a stated up
/// left the facing to the fits, which went back to front here as without the legs' cue).
#[test]
fn a_scan_without_its_feet_faces_the_way_its_legs_say() {
    let (template, data) = load();
    let frame = &zoo_frames()[0];
    let c = feet_cut_scan(&template, &data, 0.004, 8461, 3, frame);
    let estimated =
        |params: &EstimateParams, given: &LandmarkSet, orientation: Option<Orientation>| {
            let e = estimate_given(&template, &c, given, orientation, params);
            let errors = landmark_errors(&c, &e.positions, e.scale_to_metres * 1000.0);
            let (_, facing) = frame_cosines(frame, e.report.frame.up, e.report.frame.facing);
            let mean = errors.iter().sum::<f64>() / errors.len() as f64;
            (facing, mean, e.report.self_check)
        };
    let none = LandmarkSet::default();
    let (facing, mean, _) = estimated(&EstimateParams::default(), &none, None);
    let unsaid = EstimateParams {
        legs_forward_decisive: 0.0,
        ..EstimateParams::default()
    };
    let (facing_unsaid, mean_unsaid, check_unsaid) = estimated(&unsaid, &none, None);
    let clicked = only(&c.landmarks, &CLICKED);
    assert_eq!(clicked.landmarks.len(), CLICKED.len());
    let (facing_clicked, mean_clicked, _) = estimated(&unsaid, &clicked, None);
    // The person chose only the up axis (the app's way out): the legs still say the facing.
    let up = Axis::ALL
        .into_iter()
        .find(|a| (frame.rotation * Vector3::z() - a.vector()).norm() < 1e-9)
        .unwrap();
    let up_only = Some(Orientation { up, facing: None });
    let (facing_up, mean_up, _) = estimated(&EstimateParams::default(), &none, up_only);
    let (facing_up_unsaid, _, _) = estimated(&unsaid, &none, up_only);
    eprintln!(
        "facing {facing:.2}, mean {mean:.1} mm; without the legs facing {facing_unsaid:.2}, \
         mean {mean_unsaid:.1} mm; and with five clicked {facing_clicked:.2}, \
         {mean_clicked:.1} mm; up chosen {facing_up:.2}, {mean_up:.1} mm \
         (without the legs {facing_up_unsaid:.2})"
    );
    assert!(
        facing > 0.9 && mean < tolerance_mm(ScannerClass::FeetCut),
        "{facing:.2}, {mean:.1} mm"
    );
    assert!(
        facing_unsaid < -0.9,
        "without the legs' cue: facing {facing_unsaid:.2}"
    );
    // Back to front, it is not called good, and it says why.
    assert!(
        check_unsaid
            .reasons
            .iter()
            .any(|r| r.contains("only the fits chose which way the body faces")),
        "{check_unsaid:?}"
    );
    assert!(
        facing_clicked > 0.9 && mean_clicked < tolerance_mm(ScannerClass::FeetCut),
        "five clicked: {facing_clicked:.2}, {mean_clicked:.1} mm"
    );
    assert!(
        facing_up > 0.9 && mean_up < tolerance_mm(ScannerClass::FeetCut),
        "up chosen: {facing_up:.2}, {mean_up:.1} mm"
    );
    assert!(
        facing_up_unsaid < -0.9,
        "up chosen, without the legs' cue: facing {facing_up_unsaid:.2}"
    );
}

/// Landmarks a person clicks to re-anchor a wrong estimate: the face, the neck's front, both
/// shoulders and a hip bone, all on the front of the torso and the head.
const CLICKED: [&str; 5] = [
    "Sellion",
    "Suprasternale",
    "Rt. Acromion",
    "Lt. Acromion",
    "Rt. ASIS",
];

/// Legs fitted too short over cut feet: on held-out seed 6543 (`bodyspace synth --scanner-class
/// feet-cut --step 5 --seed 6543 --profile held-out`, file 033) both feet and ankles came out
/// 200–255 mm off, the landmarks 50 mm off on average, and the estimate called itself good (its
/// fit's RMS 2.8 mm over the template). The shins below the template's feet were left uncovered:
/// 1 % of the scan lies more than 20 mm from the fit, where good estimates leave at most 0.16 %.
/// A wrong estimate is never good: with the coverage judged it is doubtful and says where; with
/// it not judged (`uncovered` out of reach) the same estimate is called good, so the test sees
/// the difference.
#[test]
fn legs_fitted_too_short_leave_the_scan_uncovered_and_say_so() {
    let (template, data) = load();
    let frame = &zoo_frames()[0];
    let c = feet_cut_scan(&template, &data, 0.005, 6543, 32, frame);
    let estimated = |params: &EstimateParams| {
        let e = estimate_bare(&template, &c, params);
        let errors = landmark_errors(&c, &e.positions, e.scale_to_metres * 1000.0);
        let mean = errors.iter().sum::<f64>() / errors.len() as f64;
        (mean, e.report.self_check)
    };
    let (mean, check) = estimated(&EstimateParams::default());
    let mut unjudged = EstimateParams::default();
    unjudged.self_check.uncovered.1 = 1.0;
    let (mean_unjudged, check_unjudged) = estimated(&unjudged);
    eprintln!("mean {mean:.1} mm, {check:?}; unjudged {mean_unjudged:.1} mm, {check_unjudged:?}");
    assert!(mean > 30.0, "the case is no longer wrong: {mean:.1} mm");
    assert_eq!(check.verdict, Verdict::Doubtful, "{check:?}");
    assert!(
        check.reasons.iter().any(
            |r| r.contains("of the scan lies more than 20 mm from the fit")
                && r.contains("lower leg")
        ),
        "{:?}",
        check.reasons
    );
    assert_eq!(check_unjudged.verdict, Verdict::Good, "{check_unjudged:?}");
}

/// Stray points change nothing: the zoo's `stray` scan is its `clean` scan with 300 lone points
/// and 30 small blobs 10–40 cm around the body. The blobs are taken off as stray pieces; the lone
/// points, which no triangle uses, had widened the extents the frame candidates are scaled by,
/// and the body was fitted 3–6 % large (docs/landmarks-estimate.md, "The frame candidates from
/// the triangulated surface"). Now both scans give the same landmarks.
#[test]
fn stray_points_leave_the_estimate_as_it_is_without_them() {
    let (template, data) = load();
    let zoo = zoo_at(&template, &data, 0.006, ZooParams::default());
    let id = SubjectId {
        profile: PopulationProfile::HeldOut,
        seed: SEED,
        index: 40,
    };
    let frame = &zoo_frames()[1];
    let estimated = |class: ScannerClass| {
        let c = placed(&template, zoo.scanned(id, class), frame);
        let e = estimate_bare(&template, &c, &EstimateParams::default());
        let to_mm = e.scale_to_metres * 1000.0;
        let errors = landmark_errors(&c, &e.positions, to_mm);
        let mean = errors.iter().sum::<f64>() / errors.len() as f64;
        (e.positions, to_mm, mean)
    };
    let (clean, to_mm, clean_mean) = estimated(ScannerClass::Clean);
    let (stray, _, stray_mean) = estimated(ScannerClass::Stray);
    let apart = clean
        .iter()
        .zip(&stray)
        .filter_map(|(a, b)| Some((a.as_ref()? - b.as_ref()?).norm() * to_mm))
        .fold(0.0, f64::max);
    eprintln!("clean {clean_mean:.1} mm, stray {stray_mean:.1} mm, at most {apart:.3} mm apart");
    assert!(apart < 0.5, "the landmarks moved up to {apart:.1} mm");
}

/// A face placed on the throat: on the blind zoo 8461's `raw` scan (parts, the crown cut, slices,
/// a floor) the nose tip is found on the throat, Sellion 82 mm off and the face 80–88 mm off. The
/// line from the ears to the eyes is turned 31° down from the template's, where good estimates of
/// the tuning and held-out zoos stay within 15°. With the head's pitch judged it is doubtful and
/// says so, and the head's landmarks' confidences drop to the failed factor; with it out of reach,
/// good. Sellion and the Tragions placed by hand then re-pose the head
/// (`SegmentParams::given_min`). (The case was the tuning zoo 4242's `raw` scan of subject 1
/// until its frame candidates were started from the triangulated surface alone, 2026-12-06: its
/// face then came right, Sellion 4 mm off.)
#[test]
fn a_face_turned_far_down_is_doubtful() {
    let (template, data) = load();
    let c = blind_8461_raw(&template, &data);
    let estimated = |params: &EstimateParams| {
        let e = estimate_bare(&template, &c, params);
        let errors = landmark_errors(&c, &e.positions, e.scale_to_metres * 1000.0);
        (errors[0], e.confidence[0], e.report.self_check)
    };
    let (sellion, confidence, check) = estimated(&EstimateParams::default());
    let mut unjudged = EstimateParams::default();
    unjudged.self_check.head_pitch_deg = 90.0;
    let (_, confidence_unjudged, check_unjudged) = estimated(&unjudged);
    eprintln!("Sellion {sellion:.1} mm off, {check:?}; unjudged {check_unjudged:?}");
    assert!(
        sellion > 50.0,
        "the case is no longer wrong: Sellion {sellion:.1} mm off"
    );
    assert_eq!(check.verdict, Verdict::Doubtful, "{check:?}");
    assert!(
        check
            .reasons
            .iter()
            .any(|r| r.starts_with("the face is turned") && r.contains("° down")),
        "{:?}",
        check.reasons
    );
    assert_eq!(check_unjudged.verdict, Verdict::Good, "{check_unjudged:?}");
    // The face's confidences say it: no more than 10 %, where the unjudged estimate gave more.
    assert!(
        confidence <= 0.1 && confidence_unjudged > 0.1,
        "Sellion's confidence {confidence:.2}, unjudged {confidence_unjudged:.2}"
    );
    // The person is sent to the face's landmarks first, not to the frame.
    assert_eq!(
        check.check_first.first().map(String::as_str),
        Some("Sellion")
    );
    assert!(!check.frame_in_doubt, "{check:?}");

    // The way out it names: Sellion and the Tragions placed by hand (their true positions) pull
    // the head's rigid fit, and the face comes right; without that pull (`given_min` out of
    // reach) the three were only anchors of the fine fit, and the face stayed on the throat.
    let face = only(&c.landmarks, &["Sellion", "Rt. Tragion", "Lt. Tragion"]);
    assert_eq!(face.landmarks.len(), 3);
    let placed_by_hand = |params: &EstimateParams| {
        let e = estimate_given(&template, &c, &face, None, params);
        let errors = landmark_errors(&c, &e.positions, e.scale_to_metres * 1000.0);
        let infraorbitale = bodyspace::landmarks::caesar_index("Rt. Infraorbitale").unwrap();
        (errors[infraorbitale], e.report.self_check.verdict)
    };
    let (eyes, verdict) = placed_by_hand(&EstimateParams::default());
    let mut unpulled = EstimateParams::default();
    unpulled.segments.given_min = usize::MAX;
    let (eyes_unpulled, _) = placed_by_hand(&unpulled);
    eprintln!("Rt. Infraorbitale with three placed: {eyes:.1} mm ({verdict:?}), unpulled {eyes_unpulled:.1} mm");
    assert!(
        eyes < 25.0 && verdict == Verdict::Good,
        "{eyes:.1} mm, {verdict:?}"
    );
    assert!(eyes_unpulled > 40.0, "{eyes_unpulled:.1} mm");
}

/// Landmarks placed on one limb say nothing of the body's frame: on the tuning zoo's `crown-cut`
/// scan of seed 4242 (subject 1, hands on hips) the estimate is doubtful and names the left
/// forearm's landmarks; four of them given (the styloids, Dactylion, Olecranon) once set a frame
/// of their own, back to front, and the estimate failed 515 mm off. Now a frame needs given
/// landmarks on `given_frame_parts` parts, and the four re-pose the forearm instead (16.4 mm).
#[test]
fn landmarks_on_one_forearm_do_not_set_the_frame() {
    let (template, data) = load();
    let c = tuning_4242_subject_1(&template, &data, ScannerClass::CrownCut);
    let forearm = only(
        &c.landmarks,
        &[
            "Lt. Ulnar Styloid",
            "Lt. Radial Styloid",
            "Lt. Dactylion",
            "Lt. Olecranon",
        ],
    );
    assert_eq!(forearm.landmarks.len(), 4);
    let estimated = |params: &EstimateParams| {
        let e = estimate_given(&template, &c, &forearm, None, params);
        let errors = landmark_errors(&c, &e.positions, e.scale_to_metres * 1000.0);
        let mean = errors.iter().sum::<f64>() / errors.len() as f64;
        (
            mean,
            e.report.frame.facing_axis,
            e.report.self_check.verdict,
        )
    };
    let (mean, facing, verdict) = estimated(&EstimateParams::default());
    let one_part = EstimateParams {
        given_frame_parts: 1,
        ..EstimateParams::default()
    };
    let (mean_one, facing_one, verdict_one) = estimated(&one_part);
    eprintln!("{mean:.1} mm, facing {facing}, {verdict:?}; from one part {mean_one:.1} mm, {facing_one}, {verdict_one:?}");
    assert_eq!(facing, "-y");
    assert!(
        mean < 25.0 && verdict != Verdict::Failed,
        "{mean:.1} mm, {verdict:?}"
    );
    assert!(mean_one > 100.0, "from one part: {mean_one:.1} mm");
}

/// The blind zoo 8461's `raw` scan (subject 012 of `bodyspace synth --n 16 --zoo --step 4 --seed
/// 8461 --profile held-out`: the body in parts, the crown cut, slices, a floor), in the zoo's
/// first frame (z up, millimetres): its face is found on the throat.
fn blind_8461_raw(template: &Template, data: &MakeHumanData) -> Case {
    let zoo = Zoo {
        data,
        template,
        scanner: ScannerParams {
            vertical_step: 0.004,
            horizontal_step: 0.004,
            ..PopulationProfile::HeldOut.scanner()
        },
        params: ZooParams::default(),
    };
    let id = SubjectId {
        profile: PopulationProfile::HeldOut,
        seed: 8461,
        index: 11,
    };
    placed(
        template,
        zoo.scanned(id, ScannerClass::Raw),
        &zoo_frames()[0],
    )
}

/// Subject 1 of the tuning zoo's seed 4242 (the `held-out` profile) scanned by `class`, in the
/// zoo's first frame (z up, millimetres).
fn tuning_4242_subject_1(template: &Template, data: &MakeHumanData, class: ScannerClass) -> Case {
    let zoo = Zoo {
        data,
        template,
        scanner: PopulationProfile::HeldOut.scanner(),
        params: ZooParams::default(),
    };
    let id = SubjectId {
        profile: PopulationProfile::HeldOut,
        seed: 4242,
        index: 1,
    };
    placed(template, zoo.scanned(id, class), &zoo_frames()[0])
}
