#!/usr/bin/env bash
# Builds the Rust core to WebAssembly into web/pkg (the worker's only import of the core).
# Skips the build when web/pkg is newer than every source of the crate and was built with the
# same target features. WASM_FEATURES sets them (default "+simd128"; WASM_FEATURES= builds
# without SIMD, into its own target directory so the default build's artefacts stay).
#
# The features go to the wasm32 target only (CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS):
# through RUSTFLAGS they also reached host builds — on a fresh machine wasm-pack's `cargo install`
# of wasm-bindgen-cli — where every crate warned "'+simd128' is not a recognized feature for this
# target". A RUSTFLAGS set by the caller is moved there too (cargo ignores the target's flags
# while RUSTFLAGS is set), so it still reaches the core as before.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
features="${WASM_FEATURES-+simd128}"
stamp=web/pkg/bodyspace_bg.wasm
record=web/pkg/target-features
if [ -f "$stamp" ] && [ "$(cat "$record" 2>/dev/null)" = "$features" ] &&
  [ -z "$(find crate/src crate/Cargo.toml crate/Cargo.lock -newer "$stamp" -print -quit 2>/dev/null)" ]; then
  echo "build:wasm: web/pkg is up to date (target features: ${features:-none})"
  exit 0
fi
flags="${CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS:-} ${RUSTFLAGS:-}"
if [ -n "$features" ]; then flags="$flags -C target-feature=$features"; fi
unset RUSTFLAGS
export CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="$flags"
if [ "$features" != "+simd128" ]; then
  export CARGO_TARGET_DIR="$PWD/crate/target/wasm-features-${features:-none}"
fi
wasm-pack build crate --release --target web --out-dir ../web/pkg --out-name bodyspace --no-pack
printf '%s' "$features" >"$record"
