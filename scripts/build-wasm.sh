#!/usr/bin/env bash
# Builds the Rust core to WebAssembly into web/pkg (the worker's only import of the core).
# Skips the build when web/pkg is newer than every source of the crate and was built with the
# same target features. WASM_FEATURES sets them (default "+simd128"; WASM_FEATURES= builds
# without SIMD, into its own target directory so the default build's artefacts stay).
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
flags="${RUSTFLAGS:-}"
if [ -n "$features" ]; then flags="$flags -C target-feature=$features"; fi
if [ "$features" != "+simd128" ]; then
  export CARGO_TARGET_DIR="$PWD/crate/target/wasm-features-${features:-none}"
fi
RUSTFLAGS="$flags" \
  wasm-pack build crate --release --target web --out-dir ../web/pkg --out-name bodyspace --no-pack
printf '%s' "$features" >"$record"
