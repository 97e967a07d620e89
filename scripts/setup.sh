#!/usr/bin/env bash
# Installs everything BodySpace needs from the package registries, skipping what is already there:
# Debian's chromium and chromium-driver, libhdf5-dev (statismo models in the native build); the wasm32 Rust target; wasm-pack (built by cargo,
# since its own binary download fails here; wasm-pack in turn builds the matching wasm-bindgen CLI
# with cargo on its first run and caches it); npm packages.
set -euo pipefail
cd "$(dirname "$0")/.."

export PATH="$HOME/.cargo/bin:$PATH"

need_apt=()
command -v chromium >/dev/null 2>&1 || need_apt+=(chromium)
command -v chromedriver >/dev/null 2>&1 || need_apt+=(chromium-driver)
# The native build reads and writes statismo HDF5 models through the HDF5 C library.
[ -f /usr/include/hdf5/serial/hdf5.h ] || need_apt+=(libhdf5-dev)
if [ ${#need_apt[@]} -gt 0 ]; then
  echo "setup: installing Debian packages: ${need_apt[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${need_apt[@]}" >/dev/null
fi

if ! rustup target list --installed | grep -q '^wasm32-unknown-unknown$'; then
  echo "setup: adding Rust target wasm32-unknown-unknown"
  rustup target add wasm32-unknown-unknown
fi
rustup component list --installed 2>/dev/null | grep -q '^clippy' || rustup component add clippy
rustup component list --installed 2>/dev/null | grep -q '^rustfmt' || rustup component add rustfmt

if ! command -v wasm-pack >/dev/null 2>&1; then
  echo "setup: building wasm-pack with cargo (about 3 minutes, once)"
  cargo install wasm-pack --locked
fi

if [ ! -d node_modules ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  echo "setup: installing npm packages"
  npm ci --no-audit --no-fund --loglevel=error
fi
