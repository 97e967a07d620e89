//! The shape-space bindings in a real browser (`wasm-pack test --headless --chrome`): the calls
//! the worker makes on a slider move are incremental and land where a rebuild does (1e-6 m),
//! at base and after mapping the model to the fine template.
#![cfg(target_arch = "wasm32")]

use bodyspace::bindings::{
    build_shape_model, load_statismo_model, load_template, ShapeSpace, StatismoArrays,
};
use bodyspace::template::Template;
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

/// `n` bodies: the template scaled in height and girth by a few per cent, with a belly.
fn subjects(n: usize) -> Vec<f32> {
    let template = Template::embedded().unwrap_or_else(|e| panic!("{e}"));
    (0..n)
        .flat_map(|i| {
            let t = i as f64 / n as f64 - 0.5;
            let (tall, wide, belly) = (1.0 + 0.05 * t, 1.0 - 0.08 * t * t, 0.03 * (3.0 * t).sin());
            template
                .mesh()
                .positions
                .iter()
                .flat_map(move |p| {
                    let bump = (-((p.y - 1.05) / 0.12).powi(2)).exp() * p.z.max(0.0);
                    [
                        (p.x * wide) as f32,
                        (p.y * tall) as f32,
                        (p.z * wide + belly * bump) as f32,
                    ]
                })
                .collect::<Vec<f32>>()
        })
        .collect()
}

fn update(space: &mut ShapeSpace, whole: &[f64], torso: &[f64], rebuild: bool) -> (bool, u64) {
    let counts = [-1, -1, -1, torso.len() as i32, -1, -1];
    let json = space
        .morph(whole, torso, &counts, rebuild)
        .unwrap_or_else(|_| panic!("morph"));
    let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}"));
    (
        v["rebuilt"].as_bool().unwrap_or(false),
        v["deltas"].as_u64().unwrap_or(99),
    )
}

fn max_diff(a: &[f32], b: &[f32]) -> f32 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f32::max)
}

fn stature(space: &ShapeSpace) -> f64 {
    let json = space.measure_json().unwrap_or_else(|_| panic!("measure"));
    let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}"));
    // A list of {name, label, kind, value}, one per measurement, all 20 taken on the mean.
    let list = v.as_array().map(Vec::as_slice).unwrap_or_default();
    assert_eq!(list.len(), 20, "{json}");
    assert!(list.iter().all(|r| r["value"].is_number()), "{json}");
    list.iter()
        .find(|r| r["name"] == "stature")
        .and_then(|r| r["value"].as_f64())
        .unwrap_or(0.0)
}

#[wasm_bindgen_test]
fn slider_moves_are_rank_one_updates_at_base_and_at_fine() {
    let n = 5;
    let names = serde_json::to_string(&(0..n).map(|i| format!("s{i}")).collect::<Vec<_>>())
        .unwrap_or_default();
    let mut space = build_shape_model(&subjects(n), n as u32, &names, 1.0, false)
        .unwrap_or_else(|_| panic!("build"));
    let info: serde_json::Value =
        serde_json::from_str(&space.info_json().unwrap_or_else(|_| panic!("info")))
            .unwrap_or_else(|e| panic!("{e}"));
    let modes = |part: usize| {
        info["parts"][part]["variances"]
            .as_array()
            .map_or(0, Vec::len)
    };
    let mut whole = vec![0.5; modes(0)];
    let mut torso = vec![-0.5; modes(4)];
    assert!(whole.len() >= 2 && !torso.is_empty());

    assert_eq!(update(&mut space, &whole, &torso, true), (true, 0));
    for i in 0..100 {
        let (w, t) = (i % whole.len(), i % torso.len());
        if i % 2 == 0 {
            whole[w] = ((i % 7) as f64 - 3.0) * 0.8;
        } else {
            torso[t] = ((i % 5) as f64 - 2.0) * 1.1;
        }
        assert_eq!(update(&mut space, &whole, &torso, false), (false, 1));
    }
    let incremental = space.positions().to_vec();
    assert_eq!(incremental.len(), 3 * 13_380);
    assert_eq!(update(&mut space, &whole, &torso, true), (true, 0));
    let base = space.positions().to_vec();
    let drift = max_diff(&incremental, &base);
    assert!(drift < 1e-6, "incremental vs rebuild at base: {drift} m");
    let base_stature = stature(&space);
    assert!(base_stature > 1.4 && base_stature < 2.0);

    // An export body of the same coefficients has the shown body's positions and normals.
    let counts = [-1, -1, -1, torso.len() as i32, -1, -1];
    let export = space
        .reconstruct(&whole, &torso, &counts)
        .unwrap_or_else(|_| panic!("reconstruct"))
        .to_vec();
    assert!(max_diff(&export, &base) < 1e-6);
    let export_normals = space
        .normals_of(&export)
        .unwrap_or_else(|_| panic!("normals of"))
        .to_vec();
    assert!(max_diff(&export_normals, &space.normals().to_vec()) < 1e-6);
    assert!(space.normals_of(&export[..3]).is_err());

    // The same body at fine: the base vertices come first and do not move.
    let fine = load_template("fine").unwrap_or_else(|_| panic!("fine template"));
    let progress = js_sys::Function::new_with_args("f", "");
    space
        .use_resolution("fine", &fine, &progress)
        .unwrap_or_else(|_| panic!("fine"));
    assert_eq!(space.vertex_count(), 214_050);
    assert_eq!(space.resolution(), "fine");
    let at_fine = space.positions().to_vec();
    assert_eq!(at_fine.len(), 3 * 214_050);
    assert!(max_diff(&at_fine[..base.len()], &base) < 1e-6);
    assert!((stature(&space) - base_stature).abs() < 1e-6);
    assert_eq!(space.normals().length() as usize, at_fine.len());

    whole[0] = 2.5;
    assert_eq!(update(&mut space, &whole, &torso, false), (false, 1));
    torso[0] = -1.5;
    assert_eq!(update(&mut space, &whole, &torso, false), (false, 1));
    let moved = space.positions().to_vec();
    assert_eq!(update(&mut space, &whole, &torso, true), (true, 0));
    assert!(max_diff(&moved, &space.positions().to_vec()) < 1e-6);
    assert!(stature(&space) != base_stature);

    // Back to base keeps the coefficients; the GLB of the seven models opens with its magic.
    space
        .use_resolution("base", &fine, &progress)
        .unwrap_or_else(|_| panic!("base"));
    assert_eq!(space.vertex_count(), 13_380);
    assert!(max_diff(&space.positions().to_vec(), &moved[..3 * 13_380]) < 1e-6);
    assert_eq!(&space.parts_glb(20).to_vec()[..4], b"glTF");
}

/// The worker's statismo path without the HDF5 layer: the model's datasets out
/// (`statismoArrays`), copied in through the setters the h5wasm reader uses, opened again
/// (`loadStatismoModel`): the same mean body; a segment's datasets are refused as a body.
#[wasm_bindgen_test]
fn statismo_arrays_round_trip_and_a_segment_is_refused() {
    let positions = subjects(5);
    let names = serde_json::to_string(&["a", "b", "c", "d", "e"]).unwrap_or_default();
    let space =
        build_shape_model(&positions, 5, &names, 1.0, false).unwrap_or_else(|_| panic!("build"));
    let out = space
        .statismo_arrays("whole")
        .unwrap_or_else(|_| panic!("arrays"));
    let mut copy = StatismoArrays::new();
    copy.set_version(out.major_version(), out.minor_version());
    let (n, m, k, s) = (
        out.point_count(),
        out.cell_count(),
        out.mode_count(),
        out.subject_count(),
    );
    assert_eq!((k, s), (4, 5));
    copy.set_points(3, n, &out.points().to_vec())
        .unwrap_or_else(|_| panic!("points"));
    copy.set_cells(3, m, &out.cells().to_vec())
        .unwrap_or_else(|_| panic!("cells"));
    copy.set_mean(&out.mean().to_vec());
    copy.set_pca_basis(3 * n, k, &out.pca_basis().to_vec())
        .unwrap_or_else(|_| panic!("basis"));
    copy.set_pca_variance(&out.pca_variance().to_vec());
    copy.set_scores(k, s, &out.scores().to_vec())
        .unwrap_or_else(|_| panic!("scores"));
    assert!(copy.set_points(3, n + 1, &out.points().to_vec()).is_err());
    let back = load_statismo_model(&copy, "copy.h5").unwrap_or_else(|_| panic!("load"));
    assert!((stature(&back) - stature(&space)).abs() < 1e-6);

    let head = space
        .statismo_arrays("head")
        .unwrap_or_else(|_| panic!("head"));
    assert!(load_statismo_model(&head, "head.h5").is_err());
    assert!(space.statismo_arrays("tail").is_err());
}

/// A reading of the mean body from `measure_json`.
fn reading(space: &ShapeSpace, name: &str) -> f64 {
    let json = space.measure_json().unwrap_or_else(|_| panic!("measure"));
    let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}"));
    v.as_array()
        .and_then(|a| a.iter().find(|r| r["name"] == name))
        .and_then(|r| r["value"].as_f64())
        .unwrap_or_else(|| panic!("no {name} in {json}"))
}

#[wasm_bindgen_test]
fn fits_in_mixed_frames_and_units_build_the_upright_model() {
    // The app's batch hands over fits in their scans' frames: here y up in metres, CAESAR's
    // z up in millimetres, turned in centimetres and −x up. The model is the all-y-up one.
    let n = 5;
    let upright = subjects(n);
    let per_body = upright.len() / n;
    let (c, s) = (2.2f64.cos(), 2.2f64.sin());
    let mixed: Vec<f32> = upright
        .chunks_exact(per_body)
        .enumerate()
        .flat_map(|(k, body)| {
            body.chunks_exact(3)
                .flat_map(move |p| {
                    let (x, y, z) = (p[0] as f64, p[1] as f64, p[2] as f64);
                    let q = match k % 4 {
                        0 => [x, y, z],
                        1 => [1e3 * x + 50.0, -1e3 * z, 1e3 * y + 20.0],
                        2 => [
                            100.0 * (c * x + s * z) + 9.0,
                            100.0 * y,
                            100.0 * (c * z - s * x),
                        ],
                        _ => [-y, x, z + 0.3],
                    };
                    q.map(|v| v as f32)
                })
                .collect::<Vec<f32>>()
        })
        .collect();
    let names = serde_json::to_string(&(0..n).map(|i| format!("s{i}")).collect::<Vec<_>>())
        .unwrap_or_default();
    let a = build_shape_model(&upright, n as u32, &names, 1.0, false)
        .unwrap_or_else(|_| panic!("build"));
    let b =
        build_shape_model(&mixed, n as u32, &names, 1.0, false).unwrap_or_else(|_| panic!("build"));
    let (sa, sb) = (stature(&a), stature(&b));
    assert!((sa - sb).abs() < 1e-3, "stature {sa} vs {sb}");
    assert!((1.4..2.1).contains(&sb), "stature {sb}");
    let (ha, hb) = (reading(&a, "hip_girth"), reading(&b, "hip_girth"));
    assert!((ha - hb).abs() < 1e-3, "hip girth {ha} vs {hb}");
    let info = |space: &ShapeSpace| -> serde_json::Value {
        serde_json::from_str(&space.info_json().unwrap_or_else(|_| panic!("info")))
            .unwrap_or_else(|e| panic!("{e}"))
    };
    let (ia, ib) = (info(&a), info(&b));
    let variances = |i: &serde_json::Value| -> Vec<f64> {
        i["parts"][0]["variances"]
            .as_array()
            .map(|v| v.iter().filter_map(|x| x.as_f64()).collect())
            .unwrap_or_default()
    };
    let (va, vb) = (variances(&ia), variances(&ib));
    assert!(!va.is_empty() && va.len() == vb.len());
    for (x, y) in va.iter().zip(&vb) {
        assert!((x - y).abs() <= 1e-5 * va[0], "λ {x} vs {y}");
    }
}
