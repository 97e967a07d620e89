//! Accuracy and speed of the landmark estimate (issue 11) on synthetic subjects in the poses and
//! frames of `tests/estimate_support` with the landmark files withheld.
//!
//! `cargo run --release --example landmarks_estimate -- [--n N] [--seed S] [--partial K]
//!  [--fine-iterations N] [--segment-iterations N] [--step MM] [--pose K] [--frame K]
//!  [--first K] [--profile tuning|held-out] [--align] [--rounds 2] [--perturb MM] [--knees] [--arms] [--acromions]
//!  [--true-for NAMES]
//!  [--quiet] [--params JSON]`
//!
//! `--params JSON` sets any of the estimate's parameters (`EstimateParams` fields, the rest
//! default), e.g. `--params '{"fine": {"scan_term_weight": 0}}'`.
//!
//! `--profile held-out` draws the subjects from the generator's `held-out` profile (shapes,
//! scanner and poses the estimate was not developed on: arms 20–60° from the body, arms down,
//! hands on hips, stances, head and trunk turns) instead of overriding the pose; the honest
//! figures. `--pose K`, `--frame K` fix the pose and frame (indices into `poses()`, `frames()`), `--first
//! K` starts at subject K. `--step MM` sets the virtual scanner's sampling step (default 3 mm; 2.6 mm makes scans of
//! ≈ 200K vertices).
//!
//! Subject i (1..=N) gets pose i mod 8 and frame (i / 8) mod 5 (indices into `poses()`, `frames()`).
//! Prints per subject the mean and worst landmark error, the wrists' and hands' mean and the time (and a `held-out` subject's
//! pose), then per landmark the mean and worst error over all subjects. `--partial K` gives the estimate K landmarks (spread over
//! the body, see `PARTIAL`) and measures the others. `--align` also aligns each subject with the
//! estimated and with the true landmarks (`align_scan`, defaults) and compares the mean
//! correspondence error and the scan→template RMS; `--rounds 2` aligns a second time from the
//! landmark vertices of the first alignment from the estimate. `--perturb MM` aligns from the true
//! landmarks each moved MM along the surface in a random direction instead of from the estimate:
//! what landmarks that far off cost the alignment; `--true-for NAMES` (comma-separated parts of
//! names, e.g. `Metacarpal,Dactylion`) aligns from the estimate with those landmarks replaced by
//! the true ones: what their error costs it. `--arms` gives each arm's bend, the upper arm's and
//! the forearm's length (true and estimated: acromion → epicondyles' midpoint → styloids'), the
//! forearm's turn about its own axis (the styloids' direction across it, estimate against
//! truth), the hand's direction (styloids → Dactylion) against the truth, the knuckles' turn
//! against the styloids about the forearm (true and estimated) and splits each elbow, wrist and hand landmark's error along the upper arm, along the
//! forearm and out of their plane (`--knees` the knees', `--acromions` the Acromions' split
//! lateral / up / forward in the trunk's frame). Also printed: the mean and worst error per landmark
//! group and Spearman's ρ between the confidence and the error (the confidence should fall as the
//! error grows: ρ < 0).

#[cfg(not(target_arch = "wasm32"))]
#[path = "../tests/estimate_support/mod.rs"]
mod support;

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use super::support::{case_scanned, frames, load, poses, Case, PARTIAL};
    use bodyspace::align::{align_scan, AlignInput, AlignParams};
    use bodyspace::estimate::confidence::spearman;
    use bodyspace::estimate::{estimate_landmarks, EstimateInput, EstimateParams};
    use bodyspace::landmarks::{LandmarkSet, CAESAR_LANDMARKS};
    use bodyspace::mesh::normals::vertex_normals;
    use bodyspace::synth::population::A_POSE_ARM_DEG;
    use bodyspace::synth::{PopulationProfile, ScannerParams, SubjectId};
    use bodyspace::template::Template;
    use nalgebra::Point3;
    use nalgebra::Vector3;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    pub fn main() {
        let mut n = 10u64;
        let mut seed = 2026u64;
        let mut partial = 0usize;
        let mut align = false;
        let mut quiet = false;
        let mut knees = false;
        let mut arms = false;
        let mut acromions = false;
        let mut true_for: Vec<String> = Vec::new();
        let mut params = EstimateParams::default();
        let mut scanner: Option<ScannerParams> = None;
        let mut profile = PopulationProfile::Tuning;
        let mut rounds = 1usize;
        let mut perturb = 0.0f64;
        let (mut pose_at, mut frame_at, mut first): (Option<usize>, Option<usize>, u64) =
            (None, None, 1);
        let mut args = std::env::args().skip(1);
        while let Some(a) = args.next() {
            match a.as_str() {
                "--n" => n = args.next().and_then(|v| v.parse().ok()).expect("--n N"),
                "--seed" => seed = args.next().and_then(|v| v.parse().ok()).expect("--seed S"),
                "--partial" => {
                    partial = args
                        .next()
                        .and_then(|v| v.parse().ok())
                        .expect("--partial K")
                }
                "--fine-iterations" => {
                    params.fine.max_iterations = args
                        .next()
                        .and_then(|v| v.parse().ok())
                        .expect("--fine-iterations N")
                }
                "--segment-iterations" => {
                    params.segment_iterations = args
                        .next()
                        .and_then(|v| v.parse().ok())
                        .expect("--segment-iterations N")
                }
                "--step" => {
                    let mm: f64 = args.next().and_then(|v| v.parse().ok()).expect("--step MM");
                    scanner = Some(ScannerParams {
                        vertical_step: mm / 1000.0,
                        horizontal_step: mm / 1000.0,
                        ..ScannerParams::default()
                    });
                }
                "--profile" => {
                    profile = args
                        .next()
                        .and_then(|v| PopulationProfile::from_name(&v))
                        .expect("--profile tuning|held-out")
                }
                "--rounds" => {
                    rounds = args
                        .next()
                        .and_then(|v| v.parse().ok())
                        .expect("--rounds N")
                }
                "--pose" => pose_at = args.next().and_then(|v| v.parse().ok()),
                "--frame" => frame_at = args.next().and_then(|v| v.parse().ok()),
                "--first" => first = args.next().and_then(|v| v.parse().ok()).expect("--first K"),
                "--params" => {
                    params = args
                        .next()
                        .and_then(|v| serde_json::from_str(&v).ok())
                        .expect("--params JSON (EstimateParams fields)")
                }
                "--align" => align = true,
                "--perturb" => {
                    perturb = args
                        .next()
                        .and_then(|v| v.parse().ok())
                        .expect("--perturb MM");
                    align = true;
                }
                "--quiet" => quiet = true,
                "--knees" => knees = true,
                "--arms" => arms = true,
                "--acromions" => acromions = true,
                "--true-for" => {
                    true_for = args
                        .next()
                        .expect("--true-for NAMES")
                        .split(',')
                        .map(str::to_string)
                        .collect()
                }
                other => panic!("unknown option {other}"),
            }
        }
        let (template, data) = load();
        let from = if perturb > 0.0 {
            format!("the true landmarks moved {perturb} mm")
        } else {
            "estimate".to_string()
        };
        let (poses, frames) = (poses(), frames());
        let scanner = scanner.unwrap_or(profile.scanner());
        // (error mm, confidence) of every estimated landmark, for the groups and the ranking.
        let mut all: Vec<(usize, f64, f64)> = Vec::new();
        let mut per_landmark = vec![(0.0f64, 0.0f64, 0usize); CAESAR_LANDMARKS.len()];
        let (mut sum_mean, mut worst, mut sum_ms, mut max_ms) = (0.0, 0.0f64, 0.0, 0.0f64);
        let (mut est_corr, mut true_corr, mut est_rms, mut true_rms) = (0.0, 0.0, 0.0, 0.0);
        for i in first..first + n {
            // The development subjects override the pose; the held-out ones keep their own.
            let pose = match (profile, pose_at) {
                (PopulationProfile::HeldOut, None) => None,
                (_, k) => Some(&poses[k.unwrap_or(i as usize % poses.len())]),
            };
            let frame = &frames[frame_at.unwrap_or((i as usize / poses.len()) % frames.len())];
            let id = SubjectId {
                profile,
                seed,
                index: i,
            };
            let c = case_scanned(&data, &template, id, pose, frame, &scanner);
            let given = LandmarkSet {
                landmarks: c
                    .landmarks
                    .landmarks
                    .iter()
                    .filter(|l| PARTIAL[..partial.min(PARTIAL.len())].contains(&l.name.as_str()))
                    .cloned()
                    .collect(),
                ..LandmarkSet::default()
            };
            let input = EstimateInput {
                template: &template,
                scan: &c.scan,
                given: &given,
                units: None,
                orientation: None,
            };
            let estimate = estimate_landmarks(&input, &params, &mut ()).unwrap();
            let to_mm = estimate.scale_to_metres * 1000.0;
            let mut errors = Vec::new();
            for (k, l) in c.landmarks.landmarks.iter().enumerate() {
                if estimate.given[k] {
                    continue;
                }
                let e = estimate.positions[k]
                    .map(|p| (p - l.position).norm() * to_mm)
                    .unwrap_or(f64::INFINITY);
                per_landmark[k].0 += e;
                per_landmark[k].1 = per_landmark[k].1.max(e);
                per_landmark[k].2 += 1;
                errors.push(e);
                all.push((k, e, estimate.confidence[k]));
            }
            let mean = errors.iter().sum::<f64>() / errors.len().max(1) as f64;
            let max = errors.iter().cloned().fold(0.0, f64::max);
            // The segment-wise fit's landmarks (before the fine fit), over the same landmarks.
            let segment_errors: Vec<f64> = c
                .landmarks
                .landmarks
                .iter()
                .enumerate()
                .filter(|(k, _)| !estimate.given[*k])
                .map(|(k, l)| (estimate.predicted[k] - l.position).norm() * to_mm)
                .collect();
            let segment_mean =
                segment_errors.iter().sum::<f64>() / segment_errors.len().max(1) as f64;
            let hand = group_errors(&all[all.len() - errors.len()..], HAND_GROUP);
            let hands = hand.iter().sum::<f64>() / hand.len().max(1) as f64;
            let ms = estimate.report.total_ms;
            sum_mean += mean;
            worst = worst.max(max);
            sum_ms += ms;
            max_ms = max_ms.max(ms);
            let r = &estimate.report;
            if !quiet {
                println!(
                    "subject {i:2} {:24} {:26} {:7} scan vertices: mean {mean:5.1} mm, worst {max:6.1} mm, wrists and hands {hands:5.1} mm, frame up {} facing {}, segment RMS {:.1} mm (mean {segment_mean:.1} mm), fit RMS {:.2} mm, flagged {}, {ms:6.0} ms (candidates {:.0}, segments {:.0}, fine {:.0})",
                    pose.map_or(profile.name(), |p| p.name),
                    frame.name,
                    c.scan.positions.len(),
                    r.frame.up_axis,
                    r.frame.facing_axis,
                    r.segment_rms_mm,
                    r.fit_rms_mm,
                    r.flagged.len(),
                    r.candidates_ms,
                    r.segments_ms,
                    r.fine_ms,
                );
            }
            if !quiet && pose.is_none() {
                let q = &c.subject.params.pose;
                println!(
                    "           pose: arms {:.0}° / {:.0}° from the body (left / right), elbows {:.0}° / {:.0}°, hips {:.0}° / {:.0}°, trunk {:.0}° turned {:.0}°",
                    q.left_shoulder_abduction + A_POSE_ARM_DEG,
                    q.right_shoulder_abduction + A_POSE_ARM_DEG,
                    q.left_elbow_flexion,
                    q.right_elbow_flexion,
                    q.left_hip_abduction,
                    q.right_hip_abduction,
                    q.trunk_flexion,
                    q.trunk_turn,
                );
            }
            if knees {
                print_knees(&c.landmarks, &estimate.positions, to_mm, "fit");
                let predicted: Vec<_> = estimate.predicted.iter().map(|p| Some(*p)).collect();
                print_knees(&c.landmarks, &predicted, to_mm, "segments");
            }
            if arms {
                print_arms(&c.landmarks, &estimate.positions, to_mm, "fit");
                let predicted: Vec<_> = estimate.predicted.iter().map(|p| Some(*p)).collect();
                print_arms(&c.landmarks, &predicted, to_mm, "segments");
            }
            if acromions {
                print_acromions(&c.landmarks, &estimate.positions, to_mm, "fit");
                let predicted: Vec<_> = estimate.predicted.iter().map(|p| Some(*p)).collect();
                print_acromions(&c.landmarks, &predicted, to_mm, "segments");
            }
            if align {
                let estimated = if perturb > 0.0 {
                    displaced(&template, &c, perturb / to_mm, i)
                } else {
                    let mut set = estimate.to_set();
                    if !true_for.is_empty() {
                        for l in &mut set.landmarks {
                            if true_for.iter().any(|n| l.name.contains(n.as_str())) {
                                if let Some(t) =
                                    c.landmarks.landmarks.iter().find(|t| t.name == l.name)
                                {
                                    l.position = t.position;
                                }
                            }
                        }
                    }
                    set
                };
                let (e, t) = compare_fits(
                    &template,
                    &c.scan,
                    &estimated,
                    &c.landmarks,
                    &c.truth,
                    rounds,
                );
                if !quiet {
                    println!(
                        "           fit from {from}: correspondence {:.2} mm, RMS {:.3} mm; from true landmarks: {:.2} mm, {:.3} mm",
                        e.0, e.1, t.0, t.1
                    );
                }
                est_corr += e.0;
                est_rms += e.1;
                true_corr += t.0;
                true_rms += t.1;
            }
        }
        let nf = n as f64;
        println!(
            "\n{n} subjects, {partial} given: mean landmark error {:.1} mm, worst {worst:.1} mm; time mean {:.0} ms, max {max_ms:.0} ms",
            sum_mean / nf,
            sum_ms / nf
        );
        if align {
            println!(
                "fit from {from}: correspondence {:.2} mm, RMS {:.3} mm; from true landmarks: {:.2} mm, {:.3} mm; ratio {:.2}",
                est_corr / nf,
                est_rms / nf,
                true_corr / nf,
                true_rms / nf,
                est_corr / true_corr
            );
        }
        let (errors, confidences): (Vec<f64>, Vec<f64>) =
            all.iter().map(|(_, e, c)| (*e, *c)).unzip();
        println!(
            "confidence against error: Spearman's rho {:.2} over {} estimated landmarks",
            spearman(&confidences, &errors),
            all.len()
        );
        println!("\n| group | mean (mm) | worst (mm) |\n| --- | --- | --- |");
        for (group, members) in GROUPS {
            let e = group_errors(&all, members);
            if !e.is_empty() {
                println!(
                    "| {group} | {:.1} | {:.1} |",
                    e.iter().sum::<f64>() / e.len() as f64,
                    e.iter().cloned().fold(0.0, f64::max)
                );
            }
        }
        println!("\n| landmark | mean (mm) | worst (mm) |\n| --- | --- | --- |");
        for (l, (sum, max, count)) in CAESAR_LANDMARKS.iter().zip(&per_landmark) {
            if *count > 0 {
                println!("| {} | {:.1} | {:.1} |", l.name, sum / *count as f64, max);
            }
        }
    }

    /// The true and the estimated position of the landmark `name`.
    fn true_and_estimated(
        truth: &LandmarkSet,
        estimated: &[Option<Point3<f64>>],
        name: &str,
    ) -> Option<(Point3<f64>, Option<Point3<f64>>)> {
        let k = truth.landmarks.iter().position(|l| l.name == name)?;
        Some((truth.landmarks[k].position, estimated[k]))
    }

    /// The error (mm) of each of `names` on `side` that has an estimate, along `axes`.
    fn split<'n>(
        truth: &LandmarkSet,
        estimated: &[Option<Point3<f64>>],
        side: &str,
        names: &[&'n str],
        axes: [Vector3<f64>; 3],
        to_mm: f64,
    ) -> Vec<(&'n str, [f64; 3])> {
        names
            .iter()
            .filter_map(|n| {
                let (p, q) = true_and_estimated(truth, estimated, &format!("{side} {n}"))?;
                let e = (q? - p) * to_mm;
                Some((*n, axes.map(|a| e.dot(&a))))
            })
            .collect()
    }

    /// Per knee, each knee landmark's error split along the leg (+ towards the ankle), across it
    /// (+ lateral) and front to back (+ forward), in mm, and the turn (degrees) of the estimated
    /// epicondyles about the leg's axis (the true ones' is 0); the leg's frame from the true
    /// landmarks (Trochanterion → the malleoli's midpoint, the lateral epicondyle's side, the
    /// knee crease behind).
    fn print_knees(truth: &LandmarkSet, estimated: &[Option<Point3<f64>>], to_mm: f64, what: &str) {
        let at = |name: &str| true_and_estimated(truth, estimated, name);
        for side in ["Rt.", "Lt."] {
            let t = |n: &str| at(&format!("{side} {n}")).map(|(p, _)| p);
            let (Some(hip), Some(lm), Some(mm), Some(lat), Some(med), Some(crease)) = (
                t("Trochanterion"),
                t("Lateral Malleolus"),
                t("Medial Malleolus"),
                t("Femoral Lateral Epicn"),
                t("Femoral Medial Epicn"),
                t("Knee Crease"),
            ) else {
                continue;
            };
            let ankle = nalgebra::center(&lm, &mm);
            let axis = (ankle - hip).normalize();
            let across = |v: nalgebra::Vector3<f64>| v - axis * v.dot(&axis);
            let lateral = across(lat - med).normalize();
            // Forward made square to lateral: the crease need not sit straight behind the
            // epicondyles' midpoint, and an oblique frame turned the true epicondyles by up to 20°.
            let back_to_front = across(nalgebra::center(&lat, &med) - crease);
            let forward = (back_to_front - lateral * back_to_front.dot(&lateral)).normalize();
            let mut line =
                format!("           {side} knee, {what} (along / lateral / forward mm):");
            let names = [
                "Knee Crease",
                "Femoral Lateral Epicn",
                "Femoral Medial Epicn",
            ];
            for (n, [a, b, c]) in split(
                truth,
                estimated,
                side,
                &names,
                [axis, lateral, forward],
                to_mm,
            ) {
                line += &format!(" {n} {a:+5.1} {b:+5.1} {c:+5.1};");
            }
            let lat_e = at(&format!("{side} Femoral Lateral Epicn")).and_then(|x| x.1);
            let med_e = at(&format!("{side} Femoral Medial Epicn")).and_then(|x| x.1);
            if let (Some(a), Some(b)) = (lat_e, med_e) {
                let v = across(a - b);
                let turn = v.dot(&forward).atan2(v.dot(&lateral)).to_degrees();
                line += &format!(" turn {turn:+.0}°");
            }
            println!("{line}");
        }
    }

    /// Per side, the Acromion's error in the trunk's frame from the true landmarks, in mm:
    /// lateral (+ away from the midline, along the true Acromions' line made square to up), up
    /// (+ towards the head, the ASIS' midpoint → Suprasternale) and forward (+ the way the body
    /// faces, Cervicale → Suprasternale made square to up), and the confidence's landmark
    /// distance.
    fn print_acromions(
        truth: &LandmarkSet,
        estimated: &[Option<Point3<f64>>],
        to_mm: f64,
        what: &str,
    ) {
        let t = |n: &str| true_and_estimated(truth, estimated, n).map(|(p, _)| p);
        let (Some(rt), Some(lt), Some(sternum), Some(cervicale), Some(ra), Some(la)) = (
            t("Rt. Acromion"),
            t("Lt. Acromion"),
            t("Suprasternale"),
            t("Cervicale"),
            t("Rt. ASIS"),
            t("Lt. ASIS"),
        ) else {
            return;
        };
        let up = (sternum - nalgebra::center(&ra, &la)).normalize();
        let square = |v: Vector3<f64>| (v - up * v.dot(&up)).normalize();
        let right = square(rt - lt);
        let forward = square(sternum - cervicale);
        let mut line = format!("           acromions, {what} (lateral / up / forward mm):");
        for (side, lateral) in [("Rt.", right), ("Lt.", -right)] {
            if let [(_, [a, b, c])] = split(
                truth,
                estimated,
                side,
                &["Acromion"],
                [lateral, up, forward],
                to_mm,
            )[..]
            {
                line += &format!(" {side} {a:+5.1} {b:+5.1} {c:+5.1};");
            }
        }
        println!("{line}");
    }

    /// Per arm, each elbow, wrist and hand landmark's error in the arm's frame from the true
    /// landmarks, in mm: along the upper arm (+ towards the elbow), along the forearm across the
    /// upper arm (+ towards the hand) and out of the plane of the two (upper arm × forearm).
    fn print_arms(truth: &LandmarkSet, estimated: &[Option<Point3<f64>>], to_mm: f64, what: &str) {
        let at = |name: &str| true_and_estimated(truth, estimated, name);
        for side in ["Rt.", "Lt."] {
            let t = |n: &str| at(&format!("{side} {n}")).map(|(p, _)| p);
            let (Some(acromion), Some(lat), Some(med), Some(rs), Some(us)) = (
                t("Acromion"),
                t("Humeral Lateral Epicn"),
                t("Humeral Medial Epicn"),
                t("Radial Styloid"),
                t("Ulnar Styloid"),
            ) else {
                continue;
            };
            let elbow = nalgebra::center(&lat, &med);
            let upper = (elbow - acromion).normalize();
            let fore = nalgebra::center(&rs, &us) - elbow;
            let bend = upper.angle(&fore).to_degrees();
            let across = (fore - upper * fore.dot(&upper)).normalize();
            let out = upper.cross(&across);
            // The forearm's turn about its own axis: the styloids' direction across it.
            let roll = match (
                at(&format!("{side} Radial Styloid")),
                at(&format!("{side} Ulnar Styloid")),
            ) {
                (Some((_, Some(e_rs))), Some((_, Some(e_us)))) => {
                    let axis = fore.normalize();
                    let flat = |v: Vector3<f64>| v - axis * v.dot(&axis);
                    let (t, e) = (flat(rs - us), flat(e_rs - e_us));
                    format!(
                        "{:+.0}°",
                        t.cross(&e).dot(&axis).atan2(t.dot(&e)).to_degrees()
                    )
                }
                _ => "-".into(),
            };
            // The estimate's own bend and lengths (acromion → elbow → wrist).
            let e = |n: &str| at(&format!("{side} {n}")).and_then(|(_, e)| e);
            let shape = match (
                e("Acromion"),
                e("Humeral Lateral Epicn"),
                e("Humeral Medial Epicn"),
                e("Radial Styloid"),
                e("Ulnar Styloid"),
            ) {
                (Some(ea), Some(el), Some(em), Some(ers), Some(eus)) => {
                    let e_elbow = nalgebra::center(&el, &em);
                    let e_fore = nalgebra::center(&ers, &eus) - e_elbow;
                    format!(
                        " (estimate {:.0}°), upper arm {:.0} mm (estimate {:.0}), forearm {:.0} mm (estimate {:.0})",
                        (e_elbow - ea).angle(&e_fore).to_degrees(),
                        (elbow - acromion).norm() * to_mm,
                        (e_elbow - ea).norm() * to_mm,
                        fore.norm() * to_mm,
                        e_fore.norm() * to_mm
                    )
                }
                _ => String::new(),
            };
            // The elbow's hinge (lateral − medial epicondyle) against its arm's plane: the
            // angle between them, true and estimated, each in its own arm's frame.
            let hinge_tilt = |a: Point3<f64>, l: Point3<f64>, m: Point3<f64>, w: Point3<f64>| {
                let e = nalgebra::center(&l, &m);
                let normal = (e - a).cross(&(w - e)).normalize();
                (l - m).normalize().dot(&normal).abs().acos().to_degrees()
            };
            let hinge = match (
                e("Acromion"),
                e("Humeral Lateral Epicn"),
                e("Humeral Medial Epicn"),
                e("Radial Styloid"),
                e("Ulnar Styloid"),
            ) {
                (Some(ea), Some(el), Some(em), Some(ers), Some(eus)) => format!(
                    ", hinge out of the arm's normal {:.0}° (estimate {:.0}°)",
                    hinge_tilt(acromion, lat, med, nalgebra::center(&rs, &us)),
                    hinge_tilt(ea, el, em, nalgebra::center(&ers, &eus))
                ),
                _ => String::new(),
            };
            // The hand's direction (mid-styloids → Dactylion), estimate against truth, and its
            // bend from the forearm.
            let hand = match (
                t("Dactylion"),
                e("Dactylion"),
                e("Radial Styloid"),
                e("Ulnar Styloid"),
            ) {
                (Some(td), Some(ed), Some(ers), Some(eus)) => {
                    let (th, eh) = (
                        td - nalgebra::center(&rs, &us),
                        ed - nalgebra::center(&ers, &eus),
                    );
                    format!(
                        ", hand {:.0}° off (bent {:.0}° from the forearm, estimate {:.0}°)",
                        th.angle(&eh).to_degrees(),
                        th.angle(&fore).to_degrees(),
                        eh.angle(&fore).to_degrees()
                    )
                }
                _ => String::new(),
            };
            // The hand's turn against the wrist about the forearm's axis: the knuckles' line
            // (Metacarpal Phal. II − V) against the styloids', true and estimated.
            let knuckles = |rs: Point3<f64>, us: Point3<f64>, m2: Point3<f64>, m5: Point3<f64>| {
                let axis = fore.normalize();
                let flat = |v: Vector3<f64>| v - axis * v.dot(&axis);
                let (a, b) = (flat(rs - us), flat(m2 - m5));
                a.cross(&b).dot(&axis).atan2(a.dot(&b)).to_degrees()
            };
            let knuckle = match (
                t("Metacarpal Phal. II"),
                t("Metacarpal Phal. V"),
                e("Radial Styloid"),
                e("Ulnar Styloid"),
                e("Metacarpal Phal. II"),
                e("Metacarpal Phal. V"),
            ) {
                (Some(m2), Some(m5), Some(ers), Some(eus), Some(em2), Some(em5)) => format!(
                    ", knuckles turned {:+.0}° from the styloids (estimate {:+.0}°)",
                    knuckles(rs, us, m2, m5),
                    knuckles(ers, eus, em2, em5)
                ),
                _ => String::new(),
            };
            let mut line = format!(
                "           {side} arm bent {bend:.0}°{shape}, forearm turned {roll}{hinge}{hand}{knuckle}, {what} (along upper / along forearm / out mm):"
            );
            let names = [
                "Humeral Lateral Epicn",
                "Humeral Medial Epicn",
                "Olecranon",
                "Radiale",
                "Radial Styloid",
                "Ulnar Styloid",
                "Metacarpal Phal. II",
                "Dactylion",
            ];
            for (n, [a, b, c]) in split(truth, estimated, side, &names, [upper, across, out], to_mm)
            {
                line += &format!("\n             {n:24} {a:+6.1} {b:+6.1} {c:+6.1}");
            }
            println!("{line}");
        }
    }

    /// Landmark groups for the summary: (name, substrings of the members' names). Every
    /// CAESAR landmark is in exactly one.
    /// The errors of `all` (landmark, error, confidence) whose landmark's name contains one of
    /// `members`.
    fn group_errors(all: &[(usize, f64, f64)], members: &[&str]) -> Vec<f64> {
        all.iter()
            .filter(|(k, _, _)| {
                members
                    .iter()
                    .any(|m| CAESAR_LANDMARKS[*k].name.contains(m))
            })
            .map(|(_, e, _)| *e)
            .collect()
    }

    /// The wrist and hand landmarks (issue 11's hand step is measured on them per subject).
    const HAND_GROUP: &[&str] = &["Styloid", "Metacarpal", "Dactylion"];

    const GROUPS: [(&str, &[&str]); 6] = [
        (
            "head and neck",
            &[
                "Sellion",
                "Infraorbitale",
                "Supramenton",
                "Tragion",
                "Gonion",
                "Nuchale",
                "Cervicale",
            ],
        ),
        (
            "torso and shoulders",
            &[
                "Clavicale",
                "Suprasternale",
                "Thelion",
                "Substernale",
                "10th Rib",
                "ASIS",
                "Iliocristale",
                "Trochanterion",
                "PSIS",
                "Waist",
                "Acromion",
                "Axilla",
                "Crotch",
            ],
        ),
        ("elbows", &["Olecranon", "Humeral", "Radiale"]),
        ("wrists and hands", HAND_GROUP),
        ("knees", &["Knee Crease", "Femoral"]),
        (
            "ankles and feet",
            &[
                "Metatarsal",
                "Malleolus",
                "Sphyrion",
                "Calcaneous",
                "Digit II",
            ],
        ),
    ];

    /// The true landmarks, each moved `distance` (scan units) along the surface in a random
    /// direction (seeded by the subject): what the alignment makes of landmarks placed that far
    /// off, the yardstick for the fit from the estimate (`--perturb MM`).
    fn displaced(template: &Template, c: &Case, distance: f64, subject: u64) -> LandmarkSet {
        let normals = vertex_normals(&c.truth, &template.mesh().triangles);
        let mut rng = ChaCha8Rng::seed_from_u64(subject);
        let mut set = c.landmarks.clone();
        for (l, (_, v)) in set.landmarks.iter_mut().zip(template.landmark_vertices()) {
            let n = normals[*v as usize];
            let r = Vector3::new(
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
            );
            let tangent = (r - n * n.dot(&r)).normalize();
            l.position += tangent * distance;
        }
        set
    }

    /// (mean correspondence error mm, scan→template RMS mm) of `align_scan` with the estimated
    /// and with the true landmarks; with `rounds` 2 the estimated run is repeated from the
    /// landmark vertices of its own fit.
    fn compare_fits(
        template: &Template,
        scan: &bodyspace::mesh::Mesh,
        estimated: &LandmarkSet,
        truth_landmarks: &LandmarkSet,
        truth: &[Point3<f64>],
        rounds: usize,
    ) -> ((f64, f64), (f64, f64)) {
        let run = |landmarks: &LandmarkSet, round: usize| {
            let input = AlignInput {
                template,
                base_template: None,
                scan,
                landmarks,
                units: None,
            };
            let mut a = align_scan(&input, &AlignParams::default(), &mut ()).unwrap();
            if round > 1 {
                let refit = LandmarkSet {
                    landmarks: template
                        .landmark_vertices()
                        .iter()
                        .map(|(name, v)| bodyspace::landmarks::Landmark {
                            name: name.clone(),
                            position: a.positions[*v as usize] / a.scale_to_metres,
                        })
                        .collect(),
                    ..LandmarkSet::default()
                };
                let input = AlignInput {
                    landmarks: &refit,
                    ..input
                };
                a = align_scan(&input, &AlignParams::default(), &mut ()).unwrap();
            }
            let truth_m: Vec<_> = truth.iter().map(|p| p * a.scale_to_metres).collect();
            a.compare_with_truth(template, &truth_m);
            let corr = a.report.correspondence.as_ref().unwrap().fitted.mean_mm;
            let rms = a.report.fine.as_ref().unwrap().scan_to_template.rms_mm;
            (corr, rms)
        };
        (run(estimated, rounds), run(truth_landmarks, 1))
    }
}

fn main() {
    #[cfg(not(target_arch = "wasm32"))]
    native::main();
}
