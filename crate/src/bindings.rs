//! The one layer that exposes the core to JavaScript (wasm32 only): flat typed arrays in and out,
//! errors as `JsError` with messages a person can act on. Validates at the boundary, trusts inside.

use wasm_bindgen::prelude::*;

/// The core's version, so the front end can show what it runs.
#[wasm_bindgen(js_name = coreVersion)]
pub fn core_version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
