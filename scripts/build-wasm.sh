#!/usr/bin/env bash
# Builds the Rust core to WebAssembly into web/pkg (the worker's only import of the core).
# Skips the build when web/pkg is newer than every source of the crate.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
stamp=web/pkg/bodyspace_bg.wasm
if [ -f "$stamp" ] && [ -z "$(find crate/src crate/Cargo.toml crate/Cargo.lock -newer "$stamp" -print -quit 2>/dev/null)" ]; then
  echo "build:wasm: web/pkg is up to date"
  exit 0
fi
RUSTFLAGS="${RUSTFLAGS:-} -C target-feature=+simd128" \
  wasm-pack build crate --release --target web --out-dir ../web/pkg --out-name bodyspace --no-pack
