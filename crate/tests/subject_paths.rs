//! The one path from a subject's files to a checked fit (`crate/src/subject/`), end to end:
//! `bodyspace align`, `bodyspace batch` and the core's own function give the same report for the
//! same files; a CAESAR `.lnd` (millimetres) beside a scan in metres fits as the same landmarks in
//! a CSV in metres; the same subject in any frame and units (y-up m, z-up mm, turned cm, −x up)
//! gives the same fit in the template's frame; a partial file of correct landmarks never makes the
//! fit worse than no file (the estimate fills in the rest).

mod synth_support;

use std::path::{Path, PathBuf};
use std::process::Command;

use bodyspace::io::{write_lnd, write_ply};
use bodyspace::landmarks::{Landmark, LandmarkSet};
use bodyspace::mesh::units::Units;
use bodyspace::mesh::winding::{face_out, WindingParams};
use bodyspace::mesh::{bounding_box, Mesh};
use bodyspace::subject::{
    fit_subject, fit_subject_files, GivenLandmarks, SubjectFit, SubjectInput, SubjectOptions,
    SubjectReport,
};
use bodyspace::synth::{PopulationProfile, ScannerParams, SubjectId};
use bodyspace::template::Template;
use nalgebra::{Point3, Rotation3, Vector3};
use synth_support::partial::{correspondence_mm, only, PARTIAL_FILES};
use synth_support::{base_template_and_data, subject_in_metres};

/// Held-out subject 0 of a population nothing was tuned on, scanned coarsely (quick to fit), in
/// metres, y up: its scan and its 73 landmarks.
fn subject() -> (Template, Mesh, LandmarkSet) {
    let (template, scan, landmarks, _) = subject_with_truth();
    (template, scan, landmarks)
}

/// [`subject`] with its truth (every base template vertex on the subject, metres).
fn subject_with_truth() -> (Template, Mesh, LandmarkSet, Vec<Point3<f64>>) {
    let (template, data) = base_template_and_data();
    let id = SubjectId {
        profile: PopulationProfile::HeldOut,
        seed: 5151,
        index: 0,
    };
    let scanner = ScannerParams {
        vertical_step: 0.012,
        horizontal_step: 0.012,
        ..id.profile.scanner()
    };
    let (scan, landmarks, truth) = subject_in_metres(&data, &template, id, &scanner);
    (template, scan, landmarks, truth)
}

/// `scan` (metres) fitted by the one path, from `landmarks` when given.
fn fit_scan(template: &Template, scan: &Mesh, landmarks: Option<&LandmarkSet>) -> SubjectFit {
    let input = SubjectInput {
        name: "subject".to_string(),
        scan: scan.clone(),
        units: None,
        given: landmarks.map(|set| GivenLandmarks {
            set: set.clone(),
            units: None,
            file: String::new(),
        }),
    };
    fit_subject(template, None, &input, None, &options(), &mut ()).unwrap()
}

fn options() -> SubjectOptions {
    let mut options = SubjectOptions::default();
    options.params.fine.max_iterations = 40;
    options
}

fn csv(set: &LandmarkSet) -> String {
    let mut text = String::from("name,x,y,z\n");
    for l in &set.landmarks {
        let p = l.position;
        text += &format!("\"{}\",{:.9},{:.9},{:.9}\n", l.name, p.x, p.y, p.z);
    }
    text
}

fn bodyspace(args: &[&str]) -> serde_json::Value {
    let out = Command::new(env!("CARGO_BIN_EXE_bodyspace"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The report without what differs from run to run by nature: times, and the batch's record.
fn comparable(mut report: serde_json::Value) -> serde_json::Value {
    fn strip(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Object(map) => {
                map.retain(|k, _| !(k.ends_with("_ms") || k == "batch" || k == "seconds"));
                map.values_mut().for_each(strip);
            }
            serde_json::Value::Array(items) => items.iter_mut().for_each(strip),
            _ => {}
        }
    }
    strip(&mut report);
    report
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("bodyspace-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn s(p: &Path) -> String {
    p.display().to_string()
}

#[test]
fn align_batch_and_the_core_give_the_same_report() {
    let (template, scan, landmarks) = subject();
    let dir = temp_dir("one-path");
    // As `bodyspace synth` writes a subject: millimetres, CAESAR .lnd.
    let scan_path = dir.join("scan_001.ply");
    let lnd_path = dir.join("landmarks_001.lnd");
    std::fs::write(&scan_path, write_ply(&scan.scaled(1000.0))).unwrap();
    std::fs::write(&lnd_path, write_lnd(&landmarks.scaled(1000.0), "001")).unwrap();
    let (scan_s, lnd_s, dir_s) = (s(&scan_path), s(&lnd_path), s(&dir));
    let (fit_s, out) = (s(&dir.join("fit.ply")), dir.join("out"));
    let out_s = s(&out);
    let from_align = bodyspace(&[
        "align",
        "--scan",
        &scan_s,
        "--landmarks",
        &lnd_s,
        "--out",
        &fit_s,
        "--max-iterations",
        "40",
    ]);
    bodyspace(&[
        "batch",
        "--scans",
        &dir_s,
        "--out",
        &out_s,
        "--jobs",
        "1",
        "--max-iterations",
        "40",
    ]);
    let from_batch: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("reports").join("scan_001.json")).unwrap())
            .unwrap();

    let scan_bytes = std::fs::read(&scan_path).unwrap();
    let lnd_bytes = std::fs::read(&lnd_path).unwrap();
    let fit = fit_subject_files(
        &template,
        None,
        (&scan_bytes, &s(&scan_path)),
        Some((&lnd_bytes, &s(&lnd_path))),
        None,
        &options(),
        &mut (),
    )
    .unwrap();
    let from_core = serde_json::to_value(&fit.report).unwrap();

    assert_eq!(from_align["landmarks"]["source"], "checked");
    assert_eq!(from_align["units"], "millimetres");
    assert!(from_align["quality"]["rms_mm"].as_f64().unwrap() < 2.5);
    let reference = comparable(from_core);
    assert_eq!(comparable(from_align), reference);
    assert_eq!(comparable(from_batch), reference);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_lnd_beside_a_metres_scan_fits_as_its_csv() {
    let (_, scan, landmarks) = subject();
    let dir = temp_dir("lnd-metres");
    let scan_path = dir.join("scan.ply");
    std::fs::write(&scan_path, write_ply(&scan)).unwrap();
    std::fs::write(dir.join("l.lnd"), write_lnd(&landmarks.scaled(1000.0), "1")).unwrap();
    std::fs::write(dir.join("l.csv"), csv(&landmarks)).unwrap();
    let fit = |file: &str| {
        bodyspace(&[
            "align",
            "--scan",
            &s(&scan_path),
            "--landmarks",
            &s(&dir.join(file)),
            "--out",
            &s(&dir.join("fit.ply")),
            "--max-iterations",
            "40",
        ])
    };
    let (lnd, csv) = (fit("l.lnd"), fit("l.csv"));
    assert_eq!(lnd["units"], "metres");
    let rms = |r: &serde_json::Value| r["quality"]["rms_mm"].as_f64().unwrap();
    assert!(rms(&lnd) < 2.5, "{}", rms(&lnd));
    // The .lnd keeps 3 decimals of a millimetre: the fits agree far below the printed digits.
    assert!(
        (rms(&lnd) - rms(&csv)).abs() < 0.01,
        "{} vs {}",
        rms(&lnd),
        rms(&csv)
    );
    assert_eq!(lnd["warp"]["used"], csv["warp"]["used"]);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn any_frame_and_units_give_the_same_fit_in_the_template_frame() {
    let (template, scan, landmarks) = subject();
    let turn = |axis: Vector3<f64>, degrees: f64| {
        Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(axis), degrees.to_radians())
    };
    // (name, rotation applied to the y-up body, units, offset in metres)
    let frames = [
        (
            "y-up m",
            Rotation3::identity(),
            Units::Metres,
            Vector3::zeros(),
        ),
        (
            "z-up mm",
            turn(Vector3::x(), 90.0),
            Units::Millimetres,
            Vector3::new(0.3, -0.2, 0.0),
        ),
        (
            "turned cm",
            turn(Vector3::y(), 140.0),
            Units::Centimetres,
            Vector3::new(-1.0, 0.4, 2.0),
        ),
        (
            "-x up m",
            turn(Vector3::z(), 90.0),
            Units::Metres,
            Vector3::new(0.0, 0.0, 0.5),
        ),
    ];
    let mut fits = Vec::new();
    for (name, rotation, units, offset) in frames {
        let k = 1.0 / units.scale_to_metres();
        let moved = |p: &Point3<f64>| (rotation * p + offset) * k;
        let input = SubjectInput {
            name: name.to_string(),
            scan: Mesh::new(
                scan.positions.iter().map(moved).collect(),
                scan.triangles.clone(),
            ),
            units: None,
            given: Some(GivenLandmarks {
                set: LandmarkSet {
                    landmarks: landmarks
                        .landmarks
                        .iter()
                        .map(|l| Landmark {
                            name: l.name.clone(),
                            position: moved(&l.position),
                        })
                        .collect(),
                    ..LandmarkSet::default()
                },
                units: None,
                file: String::new(),
            }),
        };
        let fit = fit_subject(&template, None, &input, None, &options(), &mut ()).unwrap();
        assert_eq!(fit.report.alignment.units, units, "{name}");
        let rms = fit.report.quality.as_ref().unwrap().rms_mm.unwrap();
        assert!(rms < 2.5, "{name}: RMS {rms} mm");
        fits.push((name, fit.positions_in_template_frame()));
    }
    // Upright in the template's frame: the stature along y, the same from every frame.
    let stature = |fit: &[Point3<f64>]| {
        fit.iter().map(|p| p.y).fold(f64::MIN, f64::max)
            - fit.iter().map(|p| p.y).fold(f64::MAX, f64::min)
    };
    let (_, reference) = &fits[0];
    let height = stature(reference);
    assert!((1.4..2.1).contains(&height), "stature {height} m");
    for (name, fit) in &fits[1..] {
        let mut d: Vec<f64> = fit
            .iter()
            .zip(reference)
            .map(|(a, b)| (a - b).norm())
            .collect();
        let mean = d.iter().sum::<f64>() / d.len() as f64;
        d.sort_by(f64::total_cmp);
        let p99 = d[d.len() * 99 / 100];
        let dh = (stature(fit) - height).abs();
        eprintln!(
            "{name}: {:.3} mm mean, {:.3} mm p99, {:.1} mm worst from the y-up fit; stature {:.3} mm apart",
            mean * 1e3,
            p99 * 1e3,
            d[d.len() - 1] * 1e3,
            dh * 1e3
        );
        // Floating point differs with the frame; the fit does not beyond rounding (0.000 mm p99
        // today: closest points that tie go by the mesh, not by rounding). When rounding chose,
        // this subject with the forearm's twist was 3.4 mm p99 and 71 mm at worst apart, and
        // without it 0.3 mm p99 by luck (docs/fine-alignment.md, history 2026-11-27).
        assert!(mean < 1e-5 && p99 < 1e-4 && dh < 1e-4, "{name}");
    }
}

/// Issue 31: ten correct landmarks once made `align` worse than none (20.8 against 14.1 mm of
/// correspondence error: it warped from the ten alone). The policy fills in the rest by the
/// estimate, keeping the given ones; and the estimate with given landmarks starts its
/// segment-wise fit where the one without them does, unless the given landmarks show that start
/// clearly wrong (`EstimateParams::segment_start_margin`). Sellion, both Acromions and Crotch had
/// given 13.83 mm against 13.04 mm with no file (subject 0), eight landmarks of the limbs 30.99
/// mm (docs/subject.md, "Partial files"). The partial files of 4–10 correct landmarks of
/// `PARTIAL_FILES`, on two subjects: never worse than no file beyond 0.5 mm. Correct, not exact:
/// the generator places them with its noise (2 mm per axis, ≈ 3.5 mm RMS), and since the head is
/// held by its nose tip (2026-12-03) the estimate's own head landmarks are as near (3–6 mm on the
/// development subjects): files with Sellion, Crotch and the Trochanterions given then cost
/// subject 1 +0.15 and +0.31 mm (its head 6.6 → 7.1 mm, its legs 10.4 → 10.9 mm; 17.14 mm with
/// no file). The bound was 0.2 mm; the failure it guards against cost +6.7 mm.
#[test]
fn a_partial_file_of_correct_landmarks_is_never_worse_than_none() {
    let (template, data) = base_template_and_data();
    for index in [0, 1] {
        let id = SubjectId {
            profile: PopulationProfile::HeldOut,
            seed: 5151,
            index,
        };
        let scanner = ScannerParams {
            vertical_step: 0.012,
            horizontal_step: 0.012,
            ..id.profile.scanner()
        };
        let (scan, landmarks, truth) = subject_in_metres(&data, &template, id, &scanner);
        let fit_with = |given: Option<LandmarkSet>| {
            correspondence_mm(&template, &scan, &truth, given, None, &options())
        };
        let (none, report) = fit_with(None);
        assert_eq!(report.landmarks.estimated, 73);
        for (name, names) in PARTIAL_FILES {
            let (error, report) = fit_with(Some(only(&landmarks, names)));
            eprintln!("subject {index}, {name}: {error:.2} mm, none: {none:.2} mm");
            assert_eq!(report.landmarks.given, names.len());
            assert_eq!(report.landmarks.used, 73, "{:?}", report.landmarks);
            assert!(
                error <= none + 0.5,
                "subject {index}, {name}: {error} mm, none {none} mm"
            );
        }
    }
}

/// Issue 31: a scan's stray pieces (here 20 specks, each a triangle 1 cm across floating 15–40 cm
/// beyond the body's box) are left out of the fit and of the landmark estimate, and the reports
/// say so; the fit is then the clean scan's. Left in, they widened the extents the estimate's
/// frame candidates are scaled by (a zoo subject's estimate failed outright) and counted in the
/// fit's RMS (20.6 against 1.2 mm, a good fit flagged `high_rms`).
#[test]
fn stray_pieces_are_left_out_of_the_fit_and_said() {
    let (template, scan, landmarks) = subject();
    let (lo, hi) = bounding_box(&scan.positions).unwrap();
    let mut stray = scan.clone();
    for k in 0..20 {
        let off = 0.15 + 0.0125 * k as f64;
        let side = if k % 2 == 0 { hi.x + off } else { lo.x - off };
        let at = Point3::new(side, lo.y + 0.08 * k as f64, (lo.z + hi.z) / 2.0);
        let base = stray.positions.len() as u32;
        stray.positions.extend([
            at,
            at + Vector3::new(0.0, 0.01, 0.0),
            at + Vector3::new(0.0, 0.0, 0.01),
        ]);
        stray.triangles.push([base, base + 1, base + 2]);
    }
    let fit = |mesh: &Mesh, given: bool| fit_scan(&template, mesh, given.then_some(&landmarks));
    for given in [true, false] {
        let (clean, dirty) = (fit(&scan, given), fit(&stray, given));
        assert!(clean.report.strays.is_none());
        let strays = dirty.report.strays.as_ref().expect("the specks are stray");
        assert_eq!((strays.pieces, strays.vertices), (20, 60), "given {given}");
        assert_eq!(
            clean.alignment.positions, dirty.alignment.positions,
            "given {given}: the fit is the clean scan's"
        );
        let quality = dirty.report.quality.as_ref().unwrap();
        assert!(!quality.flags.iter().any(|f| f.name() == "high_rms"));
        if !given {
            let estimate = dirty.report.landmarks.estimate.as_ref().unwrap();
            assert_eq!(estimate["strays"]["pieces"], 20);
        }
    }
}

#[test]
fn a_scan_wound_inwards_is_turned_and_fitted_as_the_same_scan_wound_outwards() {
    // A file whose triangles run clockwise seen from outside: every normal points into the body,
    // against the template's, and left so the estimate ended 129 mm off and the fit from the true
    // landmarks matched 4 % of the template (a zoo scan, 2026-12-07).
    let (template, scan, landmarks) = subject();
    let inwards = turned_where(&scan, |_| true);
    let fit = |mesh: &Mesh, given: bool| fit_scan(&template, mesh, given.then_some(&landmarks));
    for given in [true, false] {
        let (outwards, turned) = (fit(&scan, given), fit(&inwards, given));
        assert!(outwards.report.turned.is_none());
        let what = turned.report.turned.as_ref().expect("the scan is turned");
        assert!(
            what.words
                .starts_with("the scan's triangles faced into the body"),
            "{}",
            what.words
        );
        assert_eq!(
            outwards.alignment.positions, turned.alignment.positions,
            "given {given}: the fit is the scan's wound outwards"
        );
        if !given {
            let estimate = turned.report.landmarks.estimate.as_ref().unwrap();
            assert_eq!(
                estimate["turned"]["triangles"],
                scan.triangles.len(),
                "the estimate turned it too"
            );
        }
    }
}

#[test]
fn a_scan_whose_triangles_face_both_ways_is_fitted_as_the_same_scan_wound_outwards() {
    // Half the triangles turned at random, as a mesh stitched from patches or never oriented may
    // come. Left so (2026-12-07), this subject fitted from its true landmarks at 2.41 mm RMS
    // against 1.10 wound outwards (correspondence 11.77 against 8.98 mm), without landmarks at
    // 2.72 against 1.08 mm RMS (23.3 against 13.9 mm), both flagged for high RMS, folds and
    // scan left uncovered. Now within 0.003 / 0.063 mm RMS and 0.08 / 0.21 mm of correspondence:
    // what is left is the few triangles below and the estimate's chain, which a few changed
    // normals move.
    let (template, scan, landmarks, truth) = subject_with_truth();
    let both_ways = turned_where(&scan, |t| {
        (t as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 63 == 1
    });
    // Turned back, but for pieces too small to judge whose way the scramble left them (one
    // triangle has no neighbour to agree with) and those the rays misjudge: 11 of 16,519.
    let (mended, what) = face_out(&both_ways, &WindingParams::default()).unwrap();
    let wrong = mended
        .triangles
        .iter()
        .zip(&scan.triangles)
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        wrong <= scan.triangles.len() / 1000,
        "{wrong} triangles still turned"
    );
    assert!(what.against_neighbours > scan.triangles.len() / 3);
    let correspondence = |mesh: &Mesh, given: bool| {
        correspondence_mm(
            &template,
            mesh,
            &truth,
            given.then(|| landmarks.clone()),
            None,
            &options(),
        )
    };
    for given in [true, false] {
        let ((outward_mm, outwards), (mm, report)) = (
            correspondence(&scan, given),
            correspondence(&both_ways, given),
        );
        let what = report.turned.as_ref().expect("the scan is turned");
        assert!(
            what.words
                .contains("faced the other way from their neighbours"),
            "{}",
            what.words
        );
        let quality = |r: &SubjectReport| r.quality.clone().unwrap();
        let (q0, q) = (quality(&outwards), quality(&report));
        assert!(
            (q.rms_mm.unwrap() - q0.rms_mm.unwrap()).abs() < 0.1,
            "given {given}: RMS {:?} against {:?} wound outwards",
            q.rms_mm,
            q0.rms_mm
        );
        assert_eq!(q.flags, q0.flags, "given {given}");
        assert!(
            (mm - outward_mm).abs() < 0.3,
            "given {given}: correspondence {mm:.3} mm against {outward_mm:.3} mm wound outwards"
        );
    }
}

/// `scan` with the triangles `turn` picks wound the other way.
fn turned_where(scan: &Mesh, turn: impl Fn(usize) -> bool) -> Mesh {
    let triangles = scan.triangles.iter().enumerate();
    Mesh::new(
        scan.positions.clone(),
        triangles
            .map(|(t, &[a, b, c])| if turn(t) { [a, c, b] } else { [a, b, c] })
            .collect(),
    )
}

/// The quality report of `scan` fitted from `landmarks` (metres, the scan's frame) by the one path.
fn quality_with_landmarks(
    template: &Template,
    scan: &Mesh,
    landmarks: &LandmarkSet,
) -> bodyspace::align::QualityReport {
    let input = SubjectInput {
        name: "subject".to_string(),
        scan: scan.clone(),
        units: None,
        given: Some(GivenLandmarks {
            set: landmarks.clone(),
            units: None,
            file: String::new(),
        }),
    };
    let fitted = fit_subject(template, None, &input, None, &options(), &mut ()).unwrap();
    fitted.report.quality.unwrap()
}

#[test]
fn a_part_of_the_scan_the_fit_does_not_reach_is_flagged_and_named() {
    // A rod 24 cm long grows out of the left hand, joined to it (no stray piece): no template
    // part can follow it, so its far end stays uncovered by the fit, near the left arm.
    let (template, scan, landmarks) = subject();
    let at = |name: &str| landmarks.get(name).unwrap();
    let hand = at("Lt. Dactylion");
    let out = {
        let across = hand - at("Rt. Dactylion");
        Vector3::new(across.x, 0.0, across.z).normalize()
    };
    let start = scan
        .positions
        .iter()
        .enumerate()
        .min_by(|a, b| (*a.1 - hand).norm().total_cmp(&(*b.1 - hand).norm()))
        .unwrap()
        .0 as u32;
    let mut rod = scan.clone();
    let mut previous = [start, start];
    for k in 1..=24 {
        let p = scan.positions[start as usize] + out * (0.01 * k as f64);
        let base = rod.positions.len() as u32;
        rod.positions.extend([p, p + Vector3::new(0.0, 0.008, 0.0)]);
        rod.triangles.push([previous[0], base, previous[1]]);
        rod.triangles.push([previous[1], base, base + 1]);
        previous = [base, base + 1];
    }
    let fit = |mesh: &Mesh| quality_with_landmarks(&template, mesh, &landmarks);
    let (clean, q) = (fit(&scan), fit(&rod));
    assert!(
        !clean.flags.iter().any(|f| f.name() == "uncovered_scan"),
        "{clean:?}"
    );
    assert!(clean.uncovered_scan_vertices <= 6, "{clean:?}");
    assert!(
        q.flags.iter().any(|f| f.name() == "uncovered_scan"),
        "{:?}",
        (q.uncovered_scan_vertices, q.scan_vertices, &q.flags)
    );
    assert!(q.uncovered_scan_vertices >= 20, "{q:?}");
    let near = q.uncovered_near.as_deref().unwrap_or("");
    assert!(near.starts_with("left "), "{near}");
}

#[test]
fn a_limb_the_fit_leaves_off_the_scan_is_flagged_and_named() {
    // The scan's left foot cut away (every point within 6 cm of the heel–toe line): the template's
    // left foot, placed by the landmarks, finds no scan under it while the right one does. The
    // body's RMS hardly sees it (its measure runs from the scan to the template).
    let (template, scan, landmarks) = subject();
    let at = |name: &str| landmarks.get(name).unwrap();
    let (heel, toe) = (at("Lt. Calcaneous, Post."), at("Lt. Digit II"));
    let near_the_foot = |p: &Point3<f64>| {
        let along = (toe - heel).normalize();
        let t = (p - heel).dot(&along).clamp(0.0, (toe - heel).norm());
        (p - (heel + along * t)).norm() < 0.06
    };
    let keep: Vec<bool> = scan.positions.iter().map(|p| !near_the_foot(p)).collect();
    let footless = scan.with_vertices(&keep);
    assert!(footless.positions.len() < scan.positions.len() - 50);
    let fit = |mesh: &Mesh| quality_with_landmarks(&template, mesh, &landmarks);
    let clean = fit(&scan);
    assert!(clean.uneven_limbs.is_empty(), "{:?}", clean.uneven_limbs);
    assert!(!clean.flags.iter().any(|f| f.name() == "uneven_limb"));
    let q = fit(&footless);
    assert!(
        q.flags.iter().any(|f| f.name() == "uneven_limb"),
        "{:?}",
        (&q.flags, &q.uneven_limbs, q.rms_mm)
    );
    let limb = q.uneven_limbs.iter().find(|u| u.part == "lower leg");
    let limb = limb.unwrap_or_else(|| panic!("{:?}", q.uneven_limbs));
    assert!(
        limb.left_rms_mm > 2.5 * limb.right_rms_mm && limb.left_rms_mm > 10.0,
        "{limb:?}"
    );
}
