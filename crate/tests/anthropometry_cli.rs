//! `bodyspace measure --model MODEL --distribution` and `bodyspace manikins` on the demo model:
//! JSON on stdout, the CSV files and PLY bodies written, and clear errors for bad input.
#![cfg(not(target_arch = "wasm32"))]

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
        19 * 19
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
        assert_eq!(m["measurements"].as_object().unwrap().len(), 19);
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
