//! The landmark estimate on the scanner zoo (issue 31): per scanner class and frame, whether the
//! frame comes out right (up and facing), the mean landmark error and the time, on subjects of
//! the `held-out` profile in their own poses with the landmark files withheld.
//!
//! `cargo run --release --example zoo_estimate -- [--n N] [--seed S] [--first K]
//!  [--class NAME[,NAME…]] [--frame NAME[,NAME…]] [--params JSON] [--worst K] [--quiet]`
//!
//! `--worst K` names each subject's K landmarks farthest from the truth, with their distances.
//!
//! `--params JSON` sets any of the estimate's parameters (`EstimateParams` fields, the rest
//! default), e.g. `--params '{"head_end_decisive": 0}'` (the frame from nearest points alone).
//! Each subject line also gives the shape's verdict on the head's end (`estimate::up`) and its
//! width ratios, whether or not it is decisive.
//!
//! Subjects `first..first + N` (default 1..=3) of seed `S` (default 4242); every class of
//! `ScannerClass::ALL` and every frame of `zoo_frames()` unless named. The frame is right when
//! the estimate's up is within 25.8° (cos 0.9) of the true up and its facing within 25.8° of the
//! true facing. Prints one line per subject and frame (with the self-check's verdict and its
//! reasons), then a Markdown table: class, frame,
//! subjects, frames right, mean landmark error (mean over subjects, worst subject), estimate time
//! (mean, worst) and the scans' vertex counts.

#[cfg(not(target_arch = "wasm32"))]
#[path = "../tests/estimate_support/mod.rs"]
mod support;

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use super::support::{
        estimate_bare, frame_cosines, landmark_errors, load, placed, zoo_frames, Zoo,
    };
    use bodyspace::estimate::facing::{cue_says, FacingCue};
    use bodyspace::estimate::up::head_end;
    use bodyspace::estimate::EstimateParams;
    use bodyspace::synth::population::A_POSE_ARM_DEG;
    use bodyspace::synth::{PopulationProfile, ScannerClass, SubjectId, ZooParams};
    use nalgebra::Vector3;

    /// One class × frame: per subject (right frame, mean error mm, ms, scan vertices).
    type Row = Vec<(bool, f64, f64, usize)>;

    pub fn main() {
        let (mut n, mut seed, mut first, mut quiet) = (3u64, 4242u64, 1u64, false);
        let mut worst = 0usize;
        let mut classes: Vec<ScannerClass> = ScannerClass::ALL.to_vec();
        let mut frame_names: Option<Vec<String>> = None;
        let mut params = EstimateParams::default();
        let mut args = std::env::args().skip(1);
        while let Some(a) = args.next() {
            match a.as_str() {
                "--n" => n = args.next().and_then(|v| v.parse().ok()).expect("--n N"),
                "--seed" => seed = args.next().and_then(|v| v.parse().ok()).expect("--seed S"),
                "--first" => first = args.next().and_then(|v| v.parse().ok()).expect("--first K"),
                "--class" => {
                    classes = args
                        .next()
                        .expect("--class NAME")
                        .split(',')
                        .map(|c| ScannerClass::from_name(c).expect("a scanner class"))
                        .collect()
                }
                "--frame" => {
                    frame_names = Some(
                        args.next()
                            .expect("--frame NAME")
                            .split(',')
                            .map(String::from)
                            .collect(),
                    )
                }
                "--quiet" => quiet = true,
                "--worst" => worst = args.next().and_then(|v| v.parse().ok()).expect("--worst K"),
                "--params" => {
                    params = serde_json::from_str(&args.next().expect("--params JSON"))
                        .expect("EstimateParams JSON")
                }
                other => panic!("unknown argument {other}"),
            }
        }
        let (template, data) = load();
        let frames: Vec<_> = zoo_frames()
            .into_iter()
            .filter(|f| {
                frame_names
                    .as_ref()
                    .is_none_or(|names| names.iter().any(|x| x == f.name))
            })
            .collect();
        let zoo = Zoo {
            data: &data,
            template: &template,
            scanner: PopulationProfile::HeldOut.scanner(),
            params: ZooParams::default(),
        };
        let mut table: Vec<(ScannerClass, &str, Row)> = Vec::new();
        for &class in &classes {
            let mut rows: Vec<Row> = vec![Vec::new(); frames.len()];
            for i in first..first + n {
                let id = SubjectId {
                    profile: PopulationProfile::HeldOut,
                    seed,
                    index: i,
                };
                let subject = zoo.scanned(id, class);
                let q = subject.params.pose;
                let pose = format!(
                    "arms {:.0}°/{:.0}°, elbows {:.0}°/{:.0}°",
                    q.left_shoulder_abduction + A_POSE_ARM_DEG,
                    q.right_shoulder_abduction + A_POSE_ARM_DEG,
                    q.left_elbow_flexion,
                    q.right_elbow_flexion
                );
                for (f, frame) in frames.iter().enumerate() {
                    let c = placed(&template, subject.clone(), frame);
                    let e = estimate_bare(&template, &c, &params);
                    let r = &e.report;
                    let to_mm = e.scale_to_metres * 1000.0;
                    let errors = landmark_errors(&c, &e.positions, to_mm);
                    let mean = errors.iter().sum::<f64>() / errors.len() as f64;
                    let (up, facing) = frame_cosines(frame, r.frame.up, r.frame.facing);
                    let right = up > 0.9 && facing > 0.9;
                    if !quiet {
                        // The shape's verdict on the head's end (`estimate::up`), decisive or not.
                        let shape = head_end(&c.scan.positions, &c.scan.triangles, 1.0).map_or(
                            "none".to_string(),
                            |h| {
                                format!(
                                    "head {} ratio {:.2} / feet {:.2}",
                                    if h.up.dot(&(frame.rotation * Vector3::z())) > 0.0 {
                                        "right"
                                    } else {
                                        "WRONG"
                                    },
                                    h.head_ratio,
                                    h.feet_ratio
                                )
                            },
                        );
                        // The feet's reach forward and the thighs' from the calves
                        // (`estimate::facing`), decisive or not, and whether each points the way
                        // the estimate's frame faces.
                        let facing = Vector3::from(r.frame.facing);
                        let said = |cue: FacingCue| {
                            head_end(&c.scan.positions, &c.scan.triangles, 1.0)
                                .and_then(|h| {
                                    cue_says(
                                        cue,
                                        &c.scan.positions,
                                        &c.scan.triangles,
                                        &h.up,
                                        &facing,
                                    )
                                })
                                .map_or("none".to_string(), |f| {
                                    format!(
                                        "{:.0} mm {}",
                                        f.reach * to_mm,
                                        if f.forward.dot(&facing) > 0.0 {
                                            "with the facing"
                                        } else {
                                            "AGAINST the facing"
                                        }
                                    )
                                })
                        };
                        let feet = said(FacingCue::Feet);
                        let legs = said(FacingCue::Legs);
                        let energies: Vec<String> = r
                            .candidates
                            .iter()
                            .map(|k| {
                                format!(
                                    "{}/{} {:.1} mm {:.0} %",
                                    k.frame.up_axis,
                                    k.frame.facing_axis,
                                    k.rms_mm,
                                    100.0 * k.matched
                                )
                            })
                            .collect();
                        let check = &r.self_check;
                        println!(
                            "{:10} {:24} subject {i} ({pose}) {:7} vertices: frame {} (up {} facing {}), mean {mean:6.1} mm, fit RMS {:.2} mm, {:6.0} ms; self-check {} ({}); shape: {shape}; feet: {feet}; legs: {legs}; candidates {}",
                            class.name(),
                            frame.name,
                            c.scan.positions.len(),
                            if right { "right" } else { "WRONG" },
                            r.frame.up_axis,
                            r.frame.facing_axis,
                            r.fit_rms_mm,
                            r.total_ms,
                            check.verdict.name(),
                            check.reasons.join("; "),
                            energies.join(", ")
                        );
                    }
                    if worst > 0 {
                        let mut named: Vec<(&str, f64)> = c
                            .landmarks
                            .landmarks
                            .iter()
                            .zip(&errors)
                            .map(|(l, e)| (l.name.as_str(), *e))
                            .collect();
                        named.sort_by(|a, b| b.1.total_cmp(&a.1));
                        let listed: Vec<String> = named
                            .iter()
                            .take(worst)
                            .map(|(name, e)| format!("{name} {e:.0}"))
                            .collect();
                        println!("    worst landmarks (mm): {}", listed.join(", "));
                    }
                    rows[f].push((right, mean, r.total_ms, c.scan.positions.len()));
                }
            }
            for (f, row) in rows.into_iter().enumerate() {
                table.push((class, frames[f].name, row));
            }
        }
        println!("\n| class | frame | subjects | frame right | landmarks mean (mm) | worst subject (mm) | time mean / worst (s) | scan vertices |");
        println!("| --- | --- | --- | --- | --- | --- | --- | --- |");
        for (class, frame, row) in &table {
            let k = row.len() as f64;
            let right = row.iter().filter(|r| r.0).count();
            let mean = row.iter().map(|r| r.1).sum::<f64>() / k;
            let worst = row.iter().map(|r| r.1).fold(0.0, f64::max);
            let ms = row.iter().map(|r| r.2).sum::<f64>() / k;
            let ms_worst = row.iter().map(|r| r.2).fold(0.0, f64::max);
            let vmin = row.iter().map(|r| r.3).min().unwrap_or(0);
            let vmax = row.iter().map(|r| r.3).max().unwrap_or(0);
            println!(
                "| {} | {frame} | {} | {right}/{} | {mean:.1} | {worst:.1} | {:.1} / {:.1} | {vmin}–{vmax} |",
                class.name(),
                row.len(),
                row.len(),
                ms / 1000.0,
                ms_worst / 1000.0
            );
        }
    }
}

fn main() {
    #[cfg(not(target_arch = "wasm32"))]
    native::main();
}
