//! `bodyspace align` end to end (RBF warp, then fine alignment) on the embedded template deformed
//! by a known smooth map, with ground truth.

use std::path::{Path, PathBuf};
use std::process::Command;

use bodyspace::io::write_ply;
use bodyspace::mesh::Mesh;
use bodyspace::template::Template;
use nalgebra::{Point3, Vector3};

fn subject(p: &Point3<f64>) -> Point3<f64> {
    // A wider, slightly taller body with a smooth belly-like bulge, moved and in metres.
    let bulge = 0.02 * (-((p.y - 1.0).powi(2)) / 0.02).exp();
    Point3::new(
        p.x * 1.06,
        p.y * 1.03 + 0.01,
        p.z * 1.04 + bulge * p.z.signum().max(0.0),
    ) + Vector3::new(0.05, 0.0, -0.03)
}

/// Writes the subject (the embedded base template deformed by [`subject`]: scan, landmarks CSV,
/// ground truth) into a fresh directory named after `name`.
fn write_subject(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("bodyspace-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let template = Template::embedded().unwrap();
    let truth: Vec<_> = template.mesh().positions.iter().map(subject).collect();
    let scan = Mesh::new(truth.clone(), template.mesh().triangles.clone());
    std::fs::write(dir.join("scan.ply"), write_ply(&scan)).unwrap();
    std::fs::write(
        dir.join("truth.ply"),
        write_ply(&Mesh::new(truth.clone(), vec![])),
    )
    .unwrap();
    let mut csv = String::from("name,x,y,z\n");
    for l in template.landmark_positions().landmarks {
        let q = subject(&l.position);
        csv += &format!("\"{}\",{},{},{}\n", l.name, q.x, q.y, q.z);
    }
    std::fs::write(dir.join("landmarks.csv"), csv).unwrap();
    dir
}

/// Runs `bodyspace align` on the subject in `dir` with `extra` arguments; returns the report.
fn align(dir: &Path, extra: &[&str]) -> serde_json::Value {
    let report = dir.join("report.json");
    let out = Command::new(env!("CARGO_BIN_EXE_bodyspace"))
        .arg("align")
        .arg("--scan")
        .arg(dir.join("scan.ply"))
        .arg("--landmarks")
        .arg(dir.join("landmarks.csv"))
        .arg("--truth")
        .arg(dir.join("truth.ply"))
        .args(extra)
        .arg("--out")
        .arg(dir.join("fit.ply"))
        .arg("--report")
        .arg(&report)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&std::fs::read(&report).unwrap()).unwrap()
}

/// The fit's mean correspondence error is no worse than the RBF warp's (within 0.5 mm).
fn assert_correspondence_kept(r: &serde_json::Value) {
    let ce = &r["correspondence"];
    let (before, after) = (
        ce["rough"]["mean_mm"].as_f64().unwrap(),
        ce["fitted"]["mean_mm"].as_f64().unwrap(),
    );
    assert!(
        after < before + 0.5,
        "correspondence error {before} → {after} mm"
    );
}

#[test]
fn full_align_fits_the_scan_and_keeps_correspondences() {
    let dir = write_subject("align-full");
    let template = Template::embedded().unwrap();
    let r = align(&dir, &["--max-iterations", "40"]);
    let fine = &r["fine"];
    assert_eq!(
        fine["template_vertices"].as_u64().unwrap() as usize,
        template.mesh().positions.len()
    );
    let iterations = fine["iterations"].as_u64().unwrap();
    assert!((1..=40).contains(&iterations), "{iterations} iterations");
    let s2t = fine["scan_to_template"]["rms_mm"].as_f64().unwrap();
    assert!(s2t < 1.5, "scan-to-template RMS {s2t} mm");
    assert_correspondence_kept(&r);
    assert_eq!(r["params"]["preset"], "paper");
    let parts: Vec<&str> = r["correspondence"]["parts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["part"].as_str().unwrap())
        .collect();
    assert_eq!(parts, ["head", "torso", "arms", "hands", "legs", "feet"]);
    let fitted = std::fs::read(dir.join("fit.ply")).unwrap();
    assert!(fitted.starts_with(b"ply"));
    // The anchored preset, with b set on top of it.
    let r = align(
        &dir,
        &[
            "--max-iterations",
            "40",
            "--preset",
            "anchored",
            "--b",
            "0.2",
        ],
    );
    assert_eq!(r["params"]["preset"], "anchored");
    assert_eq!(r["params"]["fine"]["b"], 0.2);
    assert_eq!(r["params"]["fine"]["tangential_weight"], 0.1);
    assert_eq!(r["params"]["pose_parts"], true);
    assert_correspondence_kept(&r);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn fine_resolution_aligns_coarse_to_fine_in_fine_template_order() {
    let dir = write_subject("align-fine");
    let r = align(
        &dir,
        &[
            "--resolution",
            "fine",
            "--max-iterations",
            "20",
            "--fine-iterations",
            "2",
        ],
    );
    assert_eq!(r["template_resolution"], "fine");
    assert_eq!(r["coarse_to_fine"], true);
    let fine = &r["fine"];
    assert_eq!(fine["template_vertices"], 214_050);
    let stages = &fine["stages"];
    let base_iterations = stages["base"]["iterations"].as_u64().unwrap();
    assert!((1..=20).contains(&base_iterations));
    assert!((1..=2).contains(&stages["fine_iterations"].as_u64().unwrap()));
    assert_eq!(
        fine["iterations"].as_u64().unwrap(),
        base_iterations + stages["fine_iterations"].as_u64().unwrap()
    );
    let (base_rms, fine_rms) = (
        stages["base"]["scan_to_template"]["rms_mm"]
            .as_f64()
            .unwrap(),
        fine["scan_to_template"]["rms_mm"].as_f64().unwrap(),
    );
    assert!(fine_rms <= base_rms + 0.01, "{base_rms} → {fine_rms} mm");
    // The ground truth has the base vertices, which come first at fine.
    assert_eq!(r["correspondence"]["fitted"]["vertices"], 13_380);
    assert_correspondence_kept(&r);
    let fitted = std::fs::read(dir.join("fit.ply")).unwrap();
    let fitted = bodyspace::io::read_scan(&fitted, "fit.ply").unwrap();
    assert_eq!(fitted.positions.len(), 214_050);
    let _ = std::fs::remove_dir_all(&dir);
}
