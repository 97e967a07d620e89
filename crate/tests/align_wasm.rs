//! The WASM half of the native-vs-WASM agreement check of fine alignment: the same case and
//! the same tolerance band as `align_agreement.rs` (native), run in a real browser by scripts/test-wasm.sh.
#![cfg(target_arch = "wasm32")]

mod align_support;

use bodyspace::align::{fine_align, FineAlignInput, FineAlignParams, SurfaceIndex};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

#[wasm_bindgen_test]
fn fine_align_lands_on_the_known_sphere_in_wasm() {
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
