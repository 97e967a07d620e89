//! The bindings in a real browser (`wasm-pack test --headless --chrome`).
#![cfg(target_arch = "wasm32")]

use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

#[wasm_bindgen_test]
fn core_version_is_the_crate_version() {
    assert_eq!(
        bodyspace::bindings::core_version(),
        env!("CARGO_PKG_VERSION")
    );
}
