//! End-to-end: the model file round-trips and every kind of damage gives its documented error.

mod pca_support;

use bodyspace::model_file::file::{
    read_model, read_model_for, write_model, BasisPrecision, FORMAT_VERSION,
};
use bodyspace::pca::{build_body_model, BodyModel, BuildParams, Coefficients, PcaError};

fn model() -> BodyModel {
    let set = pca_support::training_set(8, 21);
    let params = BuildParams {
        quality: bodyspace::pca::QualityParams {
            specificity_samples: 10,
            ..Default::default()
        },
        ..BuildParams::default()
    };
    build_body_model(&set, &params).unwrap()
}

#[test]
fn f32_file_round_trips_bit_exactly() {
    let model = model();
    let bytes = write_model(&model, BasisPrecision::F32);
    let back = read_model_for(&bytes, &pca_support::template_identity()).unwrap();
    let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    for (a, b) in std::iter::once((&model.whole, &back.whole))
        .chain(model.segments.iter().zip(&back.segments))
    {
        assert_eq!(bits(&a.mean), bits(&b.mean));
        assert_eq!(bits(&a.basis), bits(&b.basis));
        assert_eq!(bits(&a.scores), bits(&b.scores));
        assert_eq!(a.vertex_indices, b.vertex_indices);
        for (x, y) in a.variances.iter().zip(&b.variances) {
            assert_eq!(x.to_bits(), y.to_bits());
        }
        assert_eq!(
            a.quality.generalization.len(),
            b.quality.generalization.len()
        );
    }
    assert_eq!(model.triangles, back.triangles);
    assert_eq!(model.segment_weights, back.segment_weights);
    assert_eq!(model.subjects, back.subjects);
    assert_eq!(model.template, back.template);
    assert_eq!(model.settings.gpa, back.settings.gpa);
    // Writing what was read gives the same bytes.
    assert!(write_model(&back, BasisPrecision::F32) == bytes);
}

#[test]
fn f16_file_is_smaller_and_reconstructs_within_tolerance() {
    let model = model();
    let full = write_model(&model, BasisPrecision::F32);
    let half = write_model(&model, BasisPrecision::F16);
    assert!(half.len() < full.len());
    let back = read_model(&half).unwrap();
    let c = Coefficients {
        whole: model
            .whole
            .coefficients_from_sigma(&vec![3.0; model.whole.mode_count()])
            .unwrap(),
        ..Coefficients::default()
    };
    let a = model.reconstruct(&c).unwrap();
    let b = back.reconstruct(&c).unwrap();
    let worst = a
        .iter()
        .zip(&b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    // 3σ on every mode; f16 keeps 11 significant bits of each basis entry: well under 0.1 mm.
    assert!(worst < 1e-4, "f16 error {worst} m");
}

#[test]
fn damaged_files_give_the_documented_errors() {
    let bytes = write_model(&model(), BasisPrecision::F32);

    let mut magic = bytes.clone();
    magic[0] = b'X';
    assert_eq!(read_model(&magic), Err(PcaError::BadMagic));
    assert_eq!(
        read_model(b"ply\nformat ascii 1.0\n"),
        Err(PcaError::BadMagic)
    );

    let mut version = bytes.clone();
    version[8..12].copy_from_slice(&(FORMAT_VERSION + 1).to_le_bytes());
    assert_eq!(
        read_model(&version),
        Err(PcaError::UnsupportedVersion {
            found: FORMAT_VERSION + 1,
            supported: FORMAT_VERSION
        })
    );

    for cut in [0, 5, 12, 40, bytes.len() / 2, bytes.len() - 1] {
        match read_model(&bytes[..cut]) {
            Err(PcaError::Truncated(_)) => {}
            other => panic!("cut at {cut}: {other:?}"),
        }
    }
    // Every prefix fails cleanly (no panic), and so does a flipped byte anywhere.
    for cut in (0..bytes.len()).step_by(97) {
        assert!(read_model(&bytes[..cut]).is_err());
    }
    let mut flipped = bytes.clone();
    let last = flipped.len() - 10;
    flipped[last] ^= 0x40;
    assert!(matches!(read_model(&flipped), Err(PcaError::Corrupted(_))));
    for at in (16..bytes.len()).step_by(131) {
        let mut f = bytes.clone();
        f[at] ^= 0xff;
        let _ = read_model(&f);
    }

    let mut other = pca_support::template_identity();
    other.hash = "ffff".into();
    let err = read_model_for(&bytes, &other).unwrap_err();
    assert!(matches!(err, PcaError::TemplateMismatch { .. }));
    assert!(err.to_string().contains("test-tube"));
}
