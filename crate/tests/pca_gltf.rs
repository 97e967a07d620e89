//! End-to-end: the GLB export carries the mean and σ-scaled modes as morph targets.

mod pca_support;

use bodyspace::pca::gltf::model_glb;
use bodyspace::pca::{build_body_model, BuildParams, Coefficients};

#[test]
fn glb_morph_targets_reproduce_sigma_steps() {
    let set = pca_support::training_set(8, 31);
    let params = BuildParams {
        compute_quality: false,
        ..BuildParams::default()
    };
    let model = build_body_model(&set, &params).unwrap();
    let glb = model_glb(&model, 20);
    let word =
        |at: usize| u32::from_le_bytes([glb[at], glb[at + 1], glb[at + 2], glb[at + 3]]) as usize;
    assert_eq!(&glb[..4], b"glTF");
    assert_eq!(word(4), 2);
    assert_eq!(word(8), glb.len());
    let json_len = word(12);
    assert_eq!(&glb[16..20], b"JSON");
    let doc: serde_json::Value = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    let bin_at = 20 + json_len;
    assert_eq!(&glb[bin_at + 4..bin_at + 8], b"BIN\0");
    let bin = &glb[bin_at + 8..bin_at + 8 + word(bin_at)];

    let m = model.whole.mode_count();
    let prim = &doc["meshes"][0]["primitives"][0];
    assert_eq!(prim["targets"].as_array().unwrap().len(), m);
    assert_eq!(
        doc["meshes"][0]["extras"]["targetNames"]
            .as_array()
            .unwrap()
            .len(),
        m
    );
    let read = |accessor: usize| -> Vec<f32> {
        let view = &doc["bufferViews"]
            [doc["accessors"][accessor]["bufferView"].as_u64().unwrap() as usize];
        let (o, l) = (
            view["byteOffset"].as_u64().unwrap() as usize,
            view["byteLength"].as_u64().unwrap() as usize,
        );
        bin[o..o + l]
            .chunks_exact(4)
            .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
            .collect()
    };
    let mean = read(prim["attributes"]["POSITION"].as_u64().unwrap() as usize);
    let target = read(prim["targets"][0]["POSITION"].as_u64().unwrap() as usize);
    // Mean + 2·target = the model at +2σ on mode 1 (a morph weight of 2).
    let c = Coefficients {
        whole: model.whole.coefficients_from_sigma(&[2.0]).unwrap(),
        ..Coefficients::default()
    };
    let expected = model.reconstruct(&c).unwrap();
    for ((e, m0), t) in expected.iter().zip(&mean).zip(&target) {
        assert!((e - (m0 + 2.0 * t) as f64).abs() < 1e-5);
    }
    let indices = prim["indices"].as_u64().unwrap() as usize;
    assert_eq!(
        doc["accessors"][indices]["count"].as_u64().unwrap() as usize,
        3 * model.triangles.len()
    );
}
