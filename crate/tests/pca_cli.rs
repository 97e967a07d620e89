//! End-to-end: `bodyspace build-model`, `project` and `reconstruct` on fits made from the embedded
//! template (scaled in height and girth, randomly posed).
#![cfg(not(target_arch = "wasm32"))]

use bodyspace::cli::model::write_ply;
use bodyspace::pca::random::NormalRng;
use bodyspace::template::Template;
use nalgebra::{Rotation3, Vector3};
use std::path::Path;
use std::process::Command;

fn run(args: &[&str]) -> (bool, serde_json::Value, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_bodyspace"))
        .args(args)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    let json = serde_json::from_str(&stdout).unwrap_or(serde_json::Value::Null);
    (
        out.status.success(),
        json,
        String::from_utf8_lossy(&out.stderr).to_string(),
    )
}

fn make_fits(dir: &Path, n: usize) -> Vec<Vec<f32>> {
    let template = Template::embedded().unwrap();
    let mesh = template.mesh();
    let mut rng = NormalRng::new(5);
    (0..n)
        .map(|i| {
            let tall = 1.0 + 0.04 * rng.next_normal();
            let wide = 1.0 + 0.08 * rng.next_normal();
            let rot = Rotation3::from_euler_angles(
                0.05 * rng.next_normal(),
                0.5 * rng.next_normal(),
                0.0,
            );
            let shift = Vector3::new(rng.next_normal(), 0.0, rng.next_normal());
            let flat: Vec<f32> = mesh
                .positions
                .iter()
                .flat_map(|p| {
                    let q = rot * nalgebra::Point3::new(p.x * wide, p.y * tall, p.z * wide) + shift;
                    [q.x as f32, q.y as f32, q.z as f32]
                })
                .collect();
            write_ply(&dir.join(format!("fit{i:02}.ply")), &flat, &mesh.triangles).unwrap();
            flat
        })
        .collect()
}

#[test]
fn build_project_reconstruct_round_trip() {
    let dir = std::env::temp_dir().join(format!("bodyspace-pca-cli-{}", std::process::id()));
    let fits = dir.join("fits");
    std::fs::create_dir_all(&fits).unwrap();
    make_fits(&fits, 6);
    let model = dir.join("model.bsm");
    let csv = dir.join("csv");
    let (ok, summary, err) = run(&[
        "build-model",
        "--fits",
        fits.to_str().unwrap(),
        "--out",
        model.to_str().unwrap(),
        "--variance",
        "1.0",
        "--csv",
        csv.to_str().unwrap(),
        "--specificity-samples",
        "5",
        "--gltf",
        dir.join("model.glb").to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    assert_eq!(summary["subjects"], 6);
    // Two shape parameters (height, girth) vary; everything else is rigid pose, removed by GPA.
    let modes = summary["models"]["whole"]["modes"].as_u64().unwrap();
    assert!((2..=5).contains(&modes), "{modes} modes");
    assert_eq!(&std::fs::read(dir.join("model.glb")).unwrap()[..4], b"glTF");
    let quality = std::fs::read_to_string(csv.join("quality.csv")).unwrap();
    assert!(quality.starts_with("model,modes,compactness"));

    // A fixed mode count overrides the variance cut in every model and is recorded.
    let fixed = dir.join("fixed.bsm");
    let (ok, summary, err) = run(&[
        "build-model",
        "--fits",
        fits.to_str().unwrap(),
        "--out",
        fixed.to_str().unwrap(),
        "--modes",
        "1",
        "--no-quality",
    ]);
    assert!(ok, "{err}");
    for part in ["whole", "head", "left_arm", "torso", "right_leg"] {
        assert_eq!(summary["models"][part]["modes"], 1, "{part}: {summary}");
    }
    let header = bodyspace::model_file::file::read_model(&std::fs::read(&fixed).unwrap()).unwrap();
    assert_eq!(header.settings.modes, Some(1));
    let (ok, _, err) = run(&[
        "build-model",
        "--fits",
        fits.to_str().unwrap(),
        "--out",
        fixed.to_str().unwrap(),
        "--modes",
        "0",
    ]);
    assert!(!ok && err.contains("--modes"), "{err}");

    // The model file as GLB: whole body + six segments, one mesh each.
    let glb = dir.join("parts.glb");
    let (ok, exported, err) = run(&[
        "export-gltf",
        "--model",
        model.to_str().unwrap(),
        "--out",
        glb.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    assert_eq!(exported["meshes"].as_array().unwrap().len(), 7);
    assert_eq!(exported["meshes"][4]["name"], "torso");
    let bytes = std::fs::read(&glb).unwrap();
    assert_eq!(&bytes[..4], b"glTF");
    assert_eq!(exported["bytes"], bytes.len());

    let fit = fits.join("fit03.ply");
    let (ok, projected, err) = run(&[
        "project",
        "--model",
        model.to_str().unwrap(),
        "--mesh",
        fit.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    // All modes kept: the fit is reproduced to f32 precision (metres).
    assert!(
        projected["residual_m"].as_f64().unwrap() < 1e-4,
        "{projected}"
    );
    let coefficients = dir.join("c.json");
    std::fs::write(&coefficients, projected.to_string()).unwrap();

    let body = dir.join("body.ply");
    let (ok, rebuilt, err) = run(&[
        "reconstruct",
        "--model",
        model.to_str().unwrap(),
        "--coefficients",
        coefficients.to_str().unwrap(),
        "--out",
        body.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    // Every segment carries the same body's coefficients: the seams close.
    assert!(
        rebuilt["seam"]["max_jump"].as_f64().unwrap() < 1e-4,
        "{rebuilt}"
    );
    let stature = rebuilt["measurements"]["stature"].as_f64().unwrap();
    assert!(stature > 1.0 && stature < 2.5, "stature {stature}");
    // The template (≈1.67 m) measures ≈0.79 m bust, 0.75 m waist, 0.96 m hip (convex hull);
    // the fits are scaled by a few per cent.
    for (girth, low, high) in [
        ("bust_girth", 0.6, 1.0),
        ("waist_girth", 0.5, 0.9),
        ("hip_girth", 0.8, 1.2),
    ] {
        let g = rebuilt["measurements"][girth].as_f64().unwrap_or(0.0);
        assert!(g > low && g < high, "{girth} girth {g}");
    }
    assert!(body.metadata().unwrap().len() > 100_000);

    let (ok, sigma, err) = run(&[
        "reconstruct",
        "--model",
        model.to_str().unwrap(),
        "--coefficients",
        "2",
        "--segment",
        "torso=-1",
        "--sigma",
        "--out",
        body.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    assert!(sigma["seam"]["max_jump"].as_f64().unwrap() > 1e-3);

    // Damaged inputs: one line on stderr, exit status 2.
    let bad = dir.join("bad.bsm");
    std::fs::write(&bad, b"BSPCAMDL\x07\0\0\0").unwrap();
    let (ok, _, err) = run(&[
        "project",
        "--model",
        bad.to_str().unwrap(),
        "--mesh",
        fit.to_str().unwrap(),
    ]);
    assert!(!ok && err.contains("version 7"), "{err}");
    let (ok, _, err) = run(&[
        "reconstruct",
        "--model",
        model.to_str().unwrap(),
        "--coefficients",
        "1,x",
        "--out",
        body.to_str().unwrap(),
    ]);
    assert!(!ok && err.contains("not a number"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// `export-statismo` (whole body, a segment, a bad segment name) and the `.h5` read back by
/// `info`, `reconstruct` and `export-gltf` as the `.bsm` is; a segment file is refused as a body.
#[test]
fn export_statismo_and_every_model_command_reads_the_h5() {
    let dir = std::env::temp_dir().join(format!("bodyspace-statismo-cli-{}", std::process::id()));
    let fits = dir.join("fits");
    std::fs::create_dir_all(&fits).unwrap();
    make_fits(&fits, 6);
    let path = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let (bsm, h5, head) = (path("model.bsm"), path("model.h5"), path("head.h5"));
    let (ok, _, err) = run(&[
        "build-model",
        "--fits",
        fits.to_str().unwrap(),
        "--out",
        &bsm,
        "--variance",
        "1.0",
        "--no-quality",
    ]);
    assert!(ok, "{err}");
    let export = |out: &str, segment: Option<&str>| {
        let mut args = vec!["export-statismo", "--model", &bsm, "--out", out];
        args.extend(segment.map(|s| ["--segment", s]).iter().flatten());
        run(&args)
    };
    let (ok, from_bsm, err) = run(&["info", &bsm]);
    assert!(ok, "{err}");
    let modes = &from_bsm["parts"][0]["modes"];
    assert!(modes.as_u64() > Some(1));
    let (ok, json, err) = export(&h5, None);
    assert!(ok, "{err}");
    assert_eq!(json["points"], 13380);
    assert_eq!(&json["modes"], modes);
    let (ok, json, err) = export(&head, Some("head"));
    assert!(ok, "{err}");
    let head_points = json["points"].as_u64().unwrap();
    let (ok, _, err) = export(&head, Some("tail"));
    assert!(!ok && err.contains("unknown segment"), "{err}");

    let (ok, info, err) = run(&["info", &h5]);
    assert!(ok, "{err}");
    assert_eq!(info["subjects"], 6);
    assert_eq!(&info["parts"][0]["modes"], modes);
    assert_eq!(info["parts"][1]["vertices"].as_u64(), Some(head_points));
    let reconstruct = |model: &str, out: &str| {
        let (ok, json, err) = run(&[
            "reconstruct",
            "--model",
            model,
            "--coefficients",
            "1.5,-1",
            "--sigma",
            "--out",
            &path(out),
        ]);
        assert!(ok, "{err}");
        json["measurements"]["stature"].as_f64().unwrap()
    };
    assert!((reconstruct(&bsm, "a.ply") - reconstruct(&h5, "b.ply")).abs() < 1e-6);
    let (ok, _, err) = run(&["export-gltf", "--model", &h5, "--out", &path("m.glb")]);
    assert!(ok, "{err}");
    let (ok, _, err) = run(&["info", &head]);
    assert!(!ok && err.contains("head segment"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}
