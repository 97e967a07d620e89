//! The bindings in a real browser (`wasm-pack test --headless --chrome`): files built here as
//! bytes go through the same calls the worker makes, and the numbers that come out are checked.
#![cfg(target_arch = "wasm32")]

use bodyspace::bindings::{
    caesar_landmark_names, core_version, pair_subject_files_js, parse_landmarks, parse_scan,
};
use wasm_bindgen_test::*;

mod cube;

wasm_bindgen_test_configure!(run_in_browser);

/// A binary little-endian PLY of a unit square in the z = 0 plane, in millimetres ×1000 so the
/// core detects millimetres: 4 vertices, 2 triangles, one boundary loop, one component.
fn square_ply_mm() -> Vec<u8> {
    let mut bytes = b"ply\nformat binary_little_endian 1.0\nelement vertex 4\n\
property float x\nproperty float y\nproperty float z\nelement face 2\n\
property list uchar int vertex_indices\nend_header\n"
        .to_vec();
    for p in [
        [0.0f32, 0.0, 0.0],
        [1000.0, 0.0, 0.0],
        [1000.0, 1600.0, 0.0],
        [0.0, 1600.0, 0.0],
    ] {
        for v in p {
            bytes.extend_from_slice(&v.to_le_bytes());
        }
    }
    for t in [[0i32, 1, 2], [0, 2, 3]] {
        bytes.push(3);
        for i in t {
            bytes.extend_from_slice(&i.to_le_bytes());
        }
    }
    bytes
}

/// The `version` of `[package]` in a Cargo.toml's text.
fn package_version(manifest: &str) -> Option<&str> {
    let mut in_package = false;
    for line in manifest.lines().map(str::trim) {
        if line.starts_with('[') {
            in_package = line == "[package]";
        } else if in_package {
            if let Some(value) = line.strip_prefix("version") {
                return Some(
                    value
                        .trim_start()
                        .strip_prefix('=')?
                        .trim()
                        .trim_matches('"'),
                );
            }
        }
    }
    None
}

/// The app's status line shows `Core <coreVersion()> ready`: it must be the version in
/// crate/Cargo.toml (read here as text, not through cargo's own environment variable).
#[wasm_bindgen_test]
fn core_version_is_the_crate_version() {
    let manifest = package_version(include_str!("../Cargo.toml"))
        .unwrap_or_else(|| panic!("crate/Cargo.toml has no [package] version"));
    let version = core_version();
    assert_eq!(version, manifest);
    let parts: Vec<&str> = version.split('.').collect();
    assert!(
        parts.len() == 3
            && parts
                .iter()
                .all(|p| !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit())),
        "{version:?} is not MAJOR.MINOR.PATCH"
    );
}

#[wasm_bindgen_test]
fn caesar_names_are_the_73_in_lnd_order() {
    let names = caesar_landmark_names();
    assert_eq!(names.len(), 73);
    assert_eq!(names[0], "Sellion");
    assert_eq!(names[72], "Crotch");
}

#[wasm_bindgen_test]
fn a_binary_ply_comes_out_as_flat_arrays_and_a_summary() {
    let scan = parse_scan(&square_ply_mm(), "square.ply").unwrap_or_else(|_| panic!("readable"));
    assert_eq!(scan.vertex_count(), 4);
    assert_eq!(scan.triangle_count(), 2);
    let positions = scan.positions().to_vec();
    assert_eq!(positions.len(), 12);
    assert_eq!(&positions[6..9], &[1000.0, 1600.0, 0.0]);
    assert_eq!(scan.triangles().to_vec(), vec![0, 1, 2, 0, 2, 3]);
    let normals = scan.normals().to_vec();
    assert_eq!(normals.len(), 12);
    for n in normals.chunks(3) {
        assert!((n[2].abs() - 1.0).abs() < 1e-6, "normal {n:?} is not ±z");
    }
    let summary: serde_json::Value =
        serde_json::from_str(&scan.summary_json().unwrap_or_else(|_| panic!("json")))
            .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(summary["vertices"], 4);
    assert_eq!(summary["triangles"], 2);
    assert_eq!(summary["units_detected"], "millimetres");
    assert!((summary["scale_to_metres"].as_f64().unwrap_or(0.0) - 0.001).abs() < 1e-12);
    assert!((summary["bbox_max"][1].as_f64().unwrap_or(0.0) - 1.6).abs() < 1e-6);
    assert_eq!(summary["boundary_loops"], 1);
    assert_eq!(summary["components"], 1);
}

/// A unit cube as OBJ (metres) whose triangles face out, but every other one turned to face in:
/// a file whose triangles face both ways.
fn cube_facing_both_ways_obj() -> String {
    let (corners, triangles) = cube::cube([1.0; 3]);
    let mut obj = String::new();
    for [x, y, z] in corners {
        obj += &format!("v {x} {y} {z}\n");
    }
    for (t, [a, b, c]) in triangles.into_iter().enumerate() {
        let [b, c] = if t % 2 == 0 { [c, b] } else { [b, c] };
        obj += &format!("f {} {} {}\n", a + 1, b + 1, c + 1);
    }
    obj
}

#[wasm_bindgen_test]
fn a_scan_facing_both_ways_says_so_per_triangle_and_is_shaded_as_one_surface() {
    let scan = parse_scan(cube_facing_both_ways_obj().as_bytes(), "cube.obj")
        .unwrap_or_else(|_| panic!("readable"));
    let facing = scan.triangle_facing().to_vec();
    let expected: Vec<i8> = (0..12).map(|t| if t % 2 == 0 { -1 } else { 1 }).collect();
    assert_eq!(facing, expected);
    // Each corner's normal points away from the centre, as a cube wound one way has it.
    let positions = scan.positions().to_vec();
    for (p, n) in positions.chunks(3).zip(scan.normals().to_vec().chunks(3)) {
        let out: f32 = (0..3).map(|k| (p[k] - 0.5) * n[k]).sum();
        assert!(out > 0.25, "normal {n:?} at {p:?} does not point out");
    }
}

#[wasm_bindgen_test]
fn an_lnd_comes_out_with_canonical_names_and_a_report() {
    let lnd = "SUBJECT_ID = 1\r\nSTD_LAND = 73\r\nSTANDARD =\r\nAUX =\r\n\
  1    1    1   0.5    1.0 1600.0  110.0 Sellion\r\n\
  5 -999 -999   0.0    0.0    0.0    0.0 Rt. Tragion\r\n\
 29    1    1   0.5 -180.0 1450.0    2.5 Rt. Acromio\r\n\
END =\r\n";
    let json = parse_landmarks(lnd.as_bytes(), "s.lnd").unwrap_or_else(|_| panic!("readable"));
    let parsed: serde_json::Value = serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        parsed["names"],
        serde_json::json!(["Sellion", "Rt. Acromion"])
    );
    assert_eq!(
        parsed["positions"],
        serde_json::json!([1.0, 1600.0, 110.0, -180.0, 1450.0, 2.5])
    );
    assert_eq!(parsed["units"], "millimetres");
    assert_eq!(
        parsed["report"]["found"],
        serde_json::json!(["Sellion", "Rt. Acromion"])
    );
    assert_eq!(
        parsed["report"]["missing"].as_array().map(Vec::len),
        Some(71)
    );
    assert_eq!(parsed["report"]["unknown"], serde_json::json!([]));
}

#[wasm_bindgen_test]
fn dropped_files_pair_by_base_name_as_the_cli_pairs_them() {
    let names = [
        "b.ply",
        "scan_7.stl.gz",
        "landmarks_7.csv",
        "b.lnd",
        "b.obj",
        "lone.json",
        "truth_7.ply",
    ]
    .map(String::from)
    .to_vec();
    let json = pair_subject_files_js(names).unwrap_or_else(|_| panic!("pairs"));
    let parsed: serde_json::Value = serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        parsed,
        serde_json::json!({
            "subjects": [
                {"subject": "b", "scan": 0, "landmarks": 3},
                {"subject": "scan_7", "scan": 1, "landmarks": 2},
            ],
            "duplicates": [{"file": 4, "kept": 0}],
            "not_scans": [6],
            "unpaired": [5],
        })
    );
}

#[wasm_bindgen_test]
fn a_truncated_ply_is_an_error_naming_the_file() {
    let bytes = square_ply_mm();
    let cut = &bytes[..bytes.len() - 20];
    let error = match parse_scan(cut, "cut.ply") {
        Ok(_) => panic!("a truncated file must not parse"),
        Err(e) => wasm_bindgen::JsValue::from(e),
    };
    let message = js_sys::Reflect::get(&error, &"message".into())
        .ok()
        .and_then(|m| m.as_string())
        .unwrap_or_default();
    assert!(message.starts_with("cut.ply: "), "message was {message:?}");
}

#[wasm_bindgen_test]
fn an_empty_file_and_a_blank_name_are_errors() {
    assert!(parse_scan(&[], "empty.ply").is_err());
    assert!(parse_scan(&square_ply_mm(), " ").is_err());
    assert!(parse_landmarks(b"", "empty.csv").is_err());
}

#[wasm_bindgen_test]
fn written_landmarks_read_back_in_each_format_with_the_absent_one_missing() {
    use bodyspace::bindings::write_landmarks;
    let names = "Sellion\nCrotch\nCervicale";
    let positions = [
        10.5,
        1700.25,
        -20.0,
        f64::NAN,
        f64::NAN,
        f64::NAN,
        1.0,
        1500.0,
        -80.0,
    ];
    for format in ["lnd", "csv", "json"] {
        let bytes = write_landmarks(names, &positions, format, "S1")
            .unwrap_or_else(|_| panic!("{format} written"));
        let parsed: serde_json::Value = serde_json::from_str(
            &parse_landmarks(&bytes, &format!("a.{format}"))
                .unwrap_or_else(|_| panic!("{format} read back")),
        )
        .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            parsed["names"],
            serde_json::json!(["Sellion", "Cervicale"]),
            "{format}"
        );
        assert_eq!(
            parsed["positions"][1],
            serde_json::json!(1700.25),
            "{format}"
        );
        assert!(
            parsed["report"]["missing"]
                .as_array()
                .unwrap()
                .iter()
                .any(|n| n == "Crotch"),
            "{format}"
        );
    }
    assert!(write_landmarks("Sellion", &[1.0, f64::NAN, 2.0], "lnd", "S1").is_err());
    assert!(write_landmarks(names, &positions, "xml", "S1").is_err());
}
