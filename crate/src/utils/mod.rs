//! Small platform helpers the algorithms share, so that no algorithm file carries `cfg` branches
//! for wasm32:
//!
//! * [`clock`] — milliseconds on a clock that exists on native builds and in the browser.
//! * [`parallel`] — per-item loops that run on all cores natively (rayon) and in order on wasm32.

pub mod clock;
pub mod parallel;

pub use clock::now_ms;
