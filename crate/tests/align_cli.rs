//! `bodyspace align` end to end (RBF warp, then fine alignment) on the embedded template deformed
//! by a known smooth map, with ground truth.

use std::path::PathBuf;
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

#[test]
fn full_align_fits_the_scan_and_keeps_correspondences() {
    let dir = std::env::temp_dir().join(format!("bodyspace-align-full-{}", std::process::id()));
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
    let report: PathBuf = dir.join("report.json");

    let out = Command::new(env!("CARGO_BIN_EXE_bodyspace"))
        .arg("align")
        .arg("--scan")
        .arg(dir.join("scan.ply"))
        .arg("--landmarks")
        .arg(dir.join("landmarks.csv"))
        .arg("--truth")
        .arg(dir.join("truth.ply"))
        .args(["--max-iterations", "40"])
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
    let r: serde_json::Value = serde_json::from_slice(&std::fs::read(&report).unwrap()).unwrap();
    let fine = &r["fine"];
    assert_eq!(
        fine["template_vertices"].as_u64().unwrap() as usize,
        template.mesh().positions.len()
    );
    let iterations = fine["iterations"].as_u64().unwrap();
    assert!((1..=40).contains(&iterations), "{iterations} iterations");
    let s2t = fine["scan_to_template"]["rms_mm"].as_f64().unwrap();
    assert!(s2t < 1.5, "scan-to-template RMS {s2t} mm");
    let ce = &r["correspondence_error"];
    let (before, after) = (
        ce["rough_mean_mm"].as_f64().unwrap(),
        ce["mean_mm"].as_f64().unwrap(),
    );
    assert!(
        after < before + 0.5,
        "correspondence error {before} → {after} mm"
    );
    let fitted = std::fs::read(dir.join("fit.ply")).unwrap();
    assert!(fitted.starts_with(b"ply"));
    let _ = std::fs::remove_dir_all(&dir);
}
