//! `bodyspace info` end to end: the real binary on temporary files, its JSON and its exit codes.

use std::path::PathBuf;
use std::process::Command;

use bodyspace::io::write_ply;
use bodyspace::mesh::Mesh;
use nalgebra::Point3;

mod cube;

fn temp_dir(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("bodyspace-info-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A closed cube 1800 mm tall (so: millimetres, 0 loops, 1 component).
fn cube_mm() -> Mesh {
    let (corners, triangles) = cube::cube([400.0, 1800.0, 300.0]);
    Mesh::new(corners.into_iter().map(Point3::from).collect(), triangles)
}

#[test]
fn info_prints_one_json_object_with_landmarks() {
    let dir = temp_dir("ok");
    let scan = dir.join("cube.ply");
    std::fs::write(&scan, write_ply(&cube_mm())).unwrap();
    let marks = dir.join("marks.csv");
    std::fs::write(
        &marks,
        "name,x,y,z\nSellion,1,1700,2\n\"Rt. Acromio\",3,4,5\nbelly,0,0,0\n",
    )
    .unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_bodyspace"))
        .arg("info")
        .arg(&scan)
        .arg("--landmarks")
        .arg(&marks)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["vertices"], 8);
    assert_eq!(json["triangles"], 12);
    assert_eq!(json["units_detected"], "millimetres");
    assert_eq!(json["boundary_loops"], 0);
    assert_eq!(json["components"], 1);
    assert_eq!(json["winding"], "outward");
    let max: Vec<f64> = serde_json::from_value(json["bbox_max"].clone()).unwrap();
    assert!(
        (max[0] - 0.4).abs() < 1e-6 && (max[1] - 1.8).abs() < 1e-6 && (max[2] - 0.3).abs() < 1e-6
    );
    assert_eq!(json["bbox_min"], serde_json::json!([0.0, 0.0, 0.0]));
    assert_eq!(
        json["landmarks_found"],
        serde_json::json!(["Sellion", "Rt. Acromion"])
    );
    assert_eq!(json["landmarks_missing"].as_array().unwrap().len(), 71);
    assert_eq!(json["landmarks_unknown"], serde_json::json!(["belly"]));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn info_on_a_bad_file_exits_2_with_one_line() {
    let dir = temp_dir("bad");
    let scan = dir.join("broken.ply");
    let mut bytes = write_ply(&cube_mm());
    bytes.truncate(bytes.len() - 30);
    std::fs::write(&scan, bytes).unwrap();
    for args in [vec![scan.clone()], vec![dir.join("absent.obj")]] {
        let out = Command::new(env!("CARGO_BIN_EXE_bodyspace"))
            .arg("info")
            .args(&args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
        let stderr = String::from_utf8(out.stderr).unwrap();
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
    let out = Command::new(env!("CARGO_BIN_EXE_bodyspace"))
        .arg("info")
        .arg(&scan)
        .output()
        .unwrap();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(
        stderr.contains("broken.ply: header declares 12 faces but the file ends after 9"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
