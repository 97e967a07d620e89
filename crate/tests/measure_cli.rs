//! `bodyspace measure`: one fit as JSON in any frame and units, a folder of fits as CSV, with
//! `--model` the percentiles among the demo model's training subjects, and a clear error for a
//! bad input; `measure --model MODEL --distribution` and `bodyspace manikins` on the demo model:
//! JSON on stdout, the CSV files and PLY bodies written.
#![cfg(not(target_arch = "wasm32"))]

use bodyspace::io::write_ply;
use bodyspace::mesh::Mesh;
use bodyspace::template::Template;
use nalgebra::Point3;
use std::process::Command;

fn run(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_bodyspace"))
        .args(args)
        .output()
        .expect("run bodyspace");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn measure_a_fit_and_a_folder() {
    let dir = std::env::temp_dir().join(format!("bodyspace-measure-cli-{}", std::process::id()));
    let fits = dir.join("fits");
    std::fs::create_dir_all(&fits).unwrap();
    let template = Template::embedded().unwrap();
    let mesh = template.mesh();
    std::fs::write(fits.join("a.ply"), write_ply(mesh)).unwrap();
    // The same body as a CAESAR-like fit: millimetres, z up, moved.
    let caesar = Mesh::new(
        mesh.positions
            .iter()
            .map(|p| Point3::new(1000.0 * p.x + 50.0, -1000.0 * p.z, 1000.0 * p.y + 3.0))
            .collect(),
        mesh.triangles.clone(),
    );
    std::fs::write(fits.join("b.ply"), write_ply(&caesar)).unwrap();

    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/../public/models/demo.bsm");
    let a = fits.join("a.ply");
    let (ok, out, err) = run(&["measure", "--mesh", a.to_str().unwrap(), "--model", model]);
    assert!(ok, "{err}");
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    let stature = json["measurements"]["stature"].as_f64().unwrap();
    assert!(
        (stature - 1.6659).abs() < 1e-3,
        "template stature {stature}"
    );
    assert_eq!(json["measurements"].as_object().unwrap().len(), 20);
    for (name, p) in json["percentiles"].as_object().unwrap() {
        let p = p.as_f64().unwrap_or(-1.0);
        assert!((0.0..=100.0).contains(&p), "{name} percentile {p}");
    }

    let csv = dir.join("population.csv");
    let (ok, _, err) = run(&[
        "measure",
        "--fits",
        fits.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<Vec<&str>> = text.lines().map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 3);
    assert_eq!(rows[0][0], "subject");
    assert_eq!(rows[0].len(), 21);
    assert_eq!((rows[1][0], rows[2][0]), ("\"a\"", "\"b\""));
    // Frame and units do not change a measurement (f32 millimetres round to ≈0.1 mm).
    for ((name, x), y) in rows[0].iter().zip(&rows[1]).zip(&rows[2]).skip(1) {
        let (x, y): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
        assert!(
            (x - y).abs() < 2e-4 * x.abs().max(1.0),
            "{name}: {x} vs {y}"
        );
    }

    let (ok, _, err) = run(&[
        "measure",
        "--mesh",
        dir.join("missing.ply").to_str().unwrap(),
    ]);
    assert!(!ok && err.contains("missing.ply"), "{err}");
    std::fs::write(
        dir.join("small.ply"),
        write_ply(&Mesh::new(mesh.positions[..10].to_vec(), vec![])),
    )
    .unwrap();
    let (ok, _, err) = run(&["measure", "--mesh", dir.join("small.ply").to_str().unwrap()]);
    assert!(!ok && err.contains("10 vertices"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn distribution_and_manikins_from_the_command_line() {
    let dir = std::env::temp_dir().join(format!("bodyspace-anthro-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/../public/models/demo.bsm");
    let csv = dir.join("distribution.csv");
    let (ok, out, err) = run(&[
        "measure",
        "--model",
        model,
        "--distribution",
        "--samples",
        "40",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(json["samples"]["bodies"], 40);
    assert_eq!(json["training"]["bodies"], 100);
    let stature = &json["samples"]["measures"][0];
    assert_eq!(stature["name"], "stature");
    assert_eq!(stature["percentiles"].as_array().unwrap().len(), 5);
    assert_eq!(
        json["samples"]["correlation"].as_array().unwrap().len(),
        20 * 20
    );
    let table = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(table.lines().count(), 1 + 100 + 40);
    assert!(table
        .lines()
        .nth(101)
        .unwrap()
        .starts_with("\"sample_0001\","));

    let out_dir = dir.join("manikins");
    let (ok, out, err) = run(&[
        "manikins",
        "--model",
        model,
        "--measure",
        "stature",
        "--measure",
        "waist_girth",
        "--coverage",
        "0.9",
        "--samples",
        "120",
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    let manikins = json["manikins"].as_array().unwrap();
    assert_eq!(manikins.len(), 8);
    for m in manikins {
        let name = m["name"].as_str().unwrap();
        let ply = std::fs::read(out_dir.join(format!("{name}.ply"))).unwrap();
        assert!(ply.starts_with(b"ply"));
        assert_eq!(m["measurements"].as_object().unwrap().len(), 20);
    }
    let rows = std::fs::read_to_string(out_dir.join("manikins.csv")).unwrap();
    assert_eq!(rows.lines().count(), 9);

    // Bad input: one clear line, exit status 2.
    for (args, expect) in [
        (
            vec![
                "manikins",
                "--model",
                model,
                "--measure",
                "stature",
                "--out",
                "x",
            ],
            "2, 3 or 4",
        ),
        (
            vec![
                "manikins",
                "--model",
                model,
                "--measure",
                "stature",
                "--measure",
                "waist",
                "--out",
                "x",
            ],
            "unknown measurement",
        ),
        (vec!["measure", "--distribution"], "--model"),
    ] {
        let (ok, _, err) = run(&args);
        assert!(!ok);
        assert!(err.contains(expect), "{args:?}: {err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
