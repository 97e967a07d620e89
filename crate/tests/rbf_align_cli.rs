//! `bodyspace align --rough-only` end to end: the embedded template warped onto a known
//! non-linear deformation of itself, written in CAESAR's frame (millimetres, z-up).
#![cfg(not(target_arch = "wasm32"))]

mod rbf_support;

use std::path::PathBuf;
use std::process::Command;

use bodyspace::io::{read_scan, write_ply};
use bodyspace::mesh::Mesh;
use bodyspace::template::Template;

fn temp_dir(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("bodyspace-align-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Writes scan.ply and landmarks.csv (all but `leave_out`) of the deformed template; returns
/// the true position of every template vertex on the scan.
fn write_subject(dir: &std::path::Path, leave_out: &[&str]) -> Vec<nalgebra::Point3<f64>> {
    let template = Template::embedded().unwrap();
    let truth: Vec<_> = template
        .mesh()
        .positions
        .iter()
        .map(rbf_support::subject)
        .collect();
    let scan = Mesh::new(truth.clone(), template.mesh().triangles.clone());
    std::fs::write(dir.join("scan.ply"), write_ply(&scan)).unwrap();
    let mut csv = String::from("name,x,y,z\n");
    for l in template.landmark_positions().landmarks {
        if leave_out.contains(&l.name.as_str()) {
            continue;
        }
        let q = rbf_support::subject(&l.position);
        csv += &format!("\"{}\",{},{},{}\n", l.name, q.x, q.y, q.z);
    }
    std::fs::write(dir.join("landmarks.csv"), csv).unwrap();
    truth
}

fn align(dir: &std::path::Path, extra: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_bodyspace"))
        .arg("align")
        .arg("--scan")
        .arg(dir.join("scan.ply"))
        .arg("--landmarks")
        .arg(dir.join("landmarks.csv"))
        .arg("--rough-only")
        .arg("--out")
        .arg(dir.join("warped.ply"))
        .args(extra)
        .output()
        .unwrap()
}

#[test]
fn rough_only_writes_the_warped_template_and_a_report() {
    let dir = temp_dir("ok");
    let truth = write_subject(&dir, &["Rt. Dactylion"]);
    let out = align(&dir, &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let warp = &report["warp"];
    assert_eq!(warp["used"].as_array().unwrap().len(), 72 + 12);
    assert_eq!(warp["skipped"], serde_json::json!(["Rt. Dactylion"]));
    assert_eq!(warp["kernel"], "thin-plate");
    assert_eq!(report["units"], "millimetres");
    assert!(report["fine"].is_null());
    let after = warp["max_residual_after_mm"].as_f64().unwrap();
    assert!(after < 1e-8 * 2000.0, "landmark residual {after} mm");
    assert!(warp["max_residual_before_mm"].as_f64().unwrap() > 20.0);
    // The pipeline works in metres: template (m) → scan (m) is about the identity scale.
    assert!((warp["similarity"]["scale"].as_f64().unwrap() - 1.0).abs() < 0.15);

    let bytes = std::fs::read(dir.join("warped.ply")).unwrap();
    let warped = read_scan(&bytes, "warped.ply").unwrap();
    assert_eq!(warped.positions.len(), truth.len());
    // Written as f32 PLY, in scan millimetres: measured 4.7 mm mean (default c = 0.1 m).
    let mean = warped
        .positions
        .iter()
        .zip(&truth)
        .map(|(a, b)| (a - b).norm())
        .sum::<f64>()
        / truth.len() as f64;
    assert!(mean < 6.0, "mean vertex error {mean} mm");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_arguments_exit_2_with_one_line() {
    let dir = temp_dir("bad");
    write_subject(&dir, &[]);
    for (args, needle) in [
        (&["--kernel", "cubic"][..], "unknown kernel"),
        (
            &["--kernel=gaussian", "--kernel-param=-1"][..],
            "Gaussian width",
        ),
        (&["--resolution", "huge"][..], "--resolution"),
    ] {
        let out = align(&dir, args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains(needle) && err.lines().count() == 1,
            "{args:?}: {err}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
