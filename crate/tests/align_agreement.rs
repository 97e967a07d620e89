//! The native half of the native-vs-WASM agreement check of fine alignment: the same case and
//! the same tolerance band as `align_wasm.rs` (run in a browser by scripts/test-wasm.sh).
#![cfg(not(target_arch = "wasm32"))]

mod align_support;

use bodyspace::align::{fine_align, FineAlignInput, FineAlignParams, SurfaceIndex};

#[test]
fn fine_align_lands_on_the_known_sphere_natively() {
    let (scan, template) = align_support::agreement_case();
    let index = SurfaceIndex::new(&scan).unwrap();
    let weights = vec![1.0; template.positions.len()];
    let result = fine_align(
        &FineAlignInput::of_mesh(&template, &index, &weights),
        &FineAlignParams::default(),
        &mut (),
    )
    .unwrap();
    align_support::check_agreement(&result.positions, result.report.scan_to_template.rms);
}
