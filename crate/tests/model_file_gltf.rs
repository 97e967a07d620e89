//! End-to-end: the GLB export carries the mean and σ-scaled modes as morph targets.

mod pca_support;

use bodyspace::model_file::gltf::model_glb;
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

/// Splits a GLB into its JSON document and BIN chunk, checking the container and that every
/// accessor's view lies in the buffer with the byte length its count and type need.
fn checked_glb(glb: &[u8]) -> (serde_json::Value, Vec<u8>) {
    let word =
        |at: usize| u32::from_le_bytes([glb[at], glb[at + 1], glb[at + 2], glb[at + 3]]) as usize;
    assert_eq!(&glb[..4], b"glTF");
    assert_eq!(word(4), 2);
    assert_eq!(word(8), glb.len());
    let json_len = word(12);
    assert_eq!(json_len % 4, 0);
    assert_eq!(&glb[16..20], b"JSON");
    let doc: serde_json::Value = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    let bin_at = 20 + json_len;
    let bin_len = word(bin_at);
    assert_eq!(&glb[bin_at + 4..bin_at + 8], b"BIN\0");
    assert_eq!(bin_at + 8 + bin_len, glb.len());
    let buffer_len = doc["buffers"][0]["byteLength"].as_u64().unwrap() as usize;
    assert!(buffer_len <= bin_len && bin_len - buffer_len < 4);
    for accessor in doc["accessors"].as_array().unwrap() {
        let view = &doc["bufferViews"][accessor["bufferView"].as_u64().unwrap() as usize];
        let offset = view["byteOffset"].as_u64().unwrap() as usize;
        let length = view["byteLength"].as_u64().unwrap() as usize;
        assert_eq!(offset % 4, 0);
        assert!(offset + length <= buffer_len);
        let components = match accessor["type"].as_str().unwrap() {
            "VEC3" => 3,
            "SCALAR" => 1,
            other => panic!("accessor type {other}"),
        };
        assert_eq!(
            length,
            4 * components * accessor["count"].as_u64().unwrap() as usize
        );
    }
    (doc, glb[bin_at + 8..bin_at + 8 + bin_len].to_vec())
}

#[test]
fn the_seven_models_export_as_seven_meshes_with_their_own_morph_targets() {
    use bodyspace::model_file::gltf::{parts_glb, SEGMENTS_OFFSET_M};
    use bodyspace::template::Segment;
    let set = pca_support::training_set(8, 31);
    let params = BuildParams {
        compute_quality: false,
        modes: Some(3),
        ..BuildParams::default()
    };
    let model = build_body_model(&set, &params).unwrap();
    let glb = parts_glb(&model, 20);
    let (doc, bin) = checked_glb(&glb);
    let meshes = doc["meshes"].as_array().unwrap();
    assert_eq!(meshes.len(), 7);
    assert_eq!(doc["scenes"][0]["nodes"], serde_json::json!([0, 1]));
    assert_eq!(doc["nodes"][1]["translation"][0], SEGMENTS_OFFSET_M as f64);
    assert_eq!(doc["nodes"][1]["children"].as_array().unwrap().len(), 6);
    let read = |accessor: u64| -> Vec<f32> {
        let view = &doc["bufferViews"][doc["accessors"][accessor as usize]["bufferView"]
            .as_u64()
            .unwrap() as usize];
        let o = view["byteOffset"].as_u64().unwrap() as usize;
        let l = view["byteLength"].as_u64().unwrap() as usize;
        bin[o..o + l]
            .chunks_exact(4)
            .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
            .collect()
    };
    let parts = std::iter::once(("whole", &model.whole))
        .chain(Segment::ALL.iter().map(|s| (s.name(), model.segment(*s))));
    for (mesh, (name, part)) in meshes.iter().zip(parts) {
        assert_eq!(mesh["name"], name);
        let prim = &mesh["primitives"][0];
        let position = prim["attributes"]["POSITION"].as_u64().unwrap();
        let count = doc["accessors"][position as usize]["count"]
            .as_u64()
            .unwrap();
        assert_eq!(count as usize, part.vertex_count(), "{name}");
        let targets = prim["targets"].as_array().unwrap();
        assert_eq!(targets.len(), part.mode_count(), "{name}");
        assert_eq!(
            mesh["extras"]["targetNames"].as_array().unwrap().len(),
            part.mode_count()
        );
        for t in targets {
            let a = t["POSITION"].as_u64().unwrap() as usize;
            assert_eq!(doc["accessors"][a]["count"].as_u64().unwrap(), count);
        }
        // Indices stay inside the part's own vertices and form whole triangles.
        let indices = prim["indices"].as_u64().unwrap() as usize;
        let n = doc["accessors"][indices]["count"].as_u64().unwrap() as usize;
        assert!(n > 0 && n % 3 == 0, "{name}: {n} indices");
        let view =
            &doc["bufferViews"][doc["accessors"][indices]["bufferView"].as_u64().unwrap() as usize];
        let o = view["byteOffset"].as_u64().unwrap() as usize;
        assert!(bin[o..o + 4 * n]
            .chunks_exact(4)
            .all(|c| (u32::from_le_bytes([c[0], c[1], c[2], c[3]]) as u64) < count));
        // Mean + 2·target 1 = this part's model at +2σ on its first mode.
        let mean = read(position);
        let target = read(targets[0]["POSITION"].as_u64().unwrap());
        let b = part.coefficients_from_sigma(&[2.0]).unwrap();
        let expected = part.reconstruct(&b).unwrap();
        for ((e, m0), t) in expected.iter().zip(&mean).zip(&target) {
            assert!((e - (m0 + 2.0 * t) as f64).abs() < 1e-5, "{name}");
        }
    }
    // The whole-body-only export passes the same structure check.
    checked_glb(&model_glb(&model, 20));
}
