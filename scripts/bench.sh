#!/usr/bin/env bash
# Benchmark: parse a 300,000-triangle binary PLY (i) in the real core worker inside Chromium,
# through the built app, and (ii) natively; the shape model; alignment against the peer; and
# alignment of a ≈ 201K-vertex scan in the browser worker at base and fine
# (scripts/bench-align-browser.sh). Builds release artefacts first. Prints tables.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
runs="${RUNS:-7}"
port="${BENCH_PORT:-4179}"
work="$(mktemp -d)"
trap 'kill "${server:-0}" 2>/dev/null || true; rm -rf "$work"' EXIT

bash scripts/build-wasm.sh
npx vite build --logLevel warn
node bench/make-ply.mjs "$work/torus-300k.ply"

# node directly (not npx), so that $! is the server itself and the trap stops it.
node node_modules/vite/bin/vite.js preview --host 127.0.0.1 --port "$port" --strictPort >"$work/server.log" 2>&1 &
server=$!
for _ in $(seq 1 100); do
  curl -sf "http://127.0.0.1:$port/" >/dev/null && break
  sleep 0.2
done

echo
echo "== machine"
lscpu | grep -E '^(Model name|CPU\(s\)|Thread|Core|Socket)' || true
echo "nproc: $(nproc)"
echo
echo "== browser"
node bench/browser-bench.mjs "http://127.0.0.1:$port/" "$work/torus-300k.ply" "$runs"
echo
echo "== native"
cargo run --quiet --release --manifest-path bench/native/Cargo.toml --target-dir crate/target -- \
  "$work/torus-300k.ply" "$runs"
echo
echo "== shape model (public/models/demo.bsm), stitched reconstruction in the worker"
node bench/shape-bench.mjs "http://127.0.0.1:$port/" "${SHAPE_RUNS:-30}"
echo "== alignment vs trimesh nricp_amberg"
bash scripts/bench-align.sh
echo
echo "== alignment in the browser worker (≈ 201K-vertex synthetic subject, base and fine)"
bash scripts/bench-align-browser.sh
