#!/usr/bin/env bash
# Benchmarks; builds release artefacts first and prints tables (figures in docs/benchmarks.md).
#   parse  a 300,000-triangle binary PLY (i) in the real core worker inside Chromium, through the
#          built app, and (ii) natively
#   shape  morphing the demo shape model at base and fine, six segments stitched: slider moves
#          (rank-1 updates), full rebuilds and the round trip to the vertex buffers, in the
#          worker inside Chromium and natively (crate/examples/pca_bench.rs morph)
#   align  alignment vs trimesh nricp_amberg (scripts/bench-align.sh), and of a ≈ 201K-vertex
#          scan in the browser worker at base and fine, and the landmark
#          estimate of that scan alone (scripts/bench-align-browser.sh)
#   anthro measurements of one body, a body from measurements, the population and boundary
#          manikins of the demo model in the worker inside Chromium (bench/anthropometry-bench.mjs),
#          and natively: bodies from measurements (random targets inside the 5–95 % range;
#          held-out subjects), distributions and boundary manikins
#          (crate/examples/anthropometry_bench.rs)
#   measure measurements of fitted held-out subjects against their truth and the ISO 20685-1
#          verdict: `bodyspace synth --profile held-out` (MEASURE_N subjects, default 8, seed
#          MEASURE_SEED, default 6161), each fitted from its true landmarks, from ten of them and
#          without landmarks, at `base` and then at `fine` (MEASURE_FINE=0 skips it), and the
#          scanner zoo (`--zoo`, 16 subjects: one per class, seed MEASURE_ZOO_SEED, default 6868) at `base`; fit
#          and truth measured by the same code (crate/examples/measure_accuracy.rs)
#   batch  20 synthetic subjects (`bodyspace synth --n 20 --seed 7`, as the CLI batch benchmark)
#          picked at once in the app: wall time to the built model with the worker pool and with
#          one worker (bench/batch-bench.mjs; BATCH_RUNS rounds, default 2)
# BENCH_PARTS picks some (default: "parse shape anthro measure align batch"); RUNS / SHAPE_RUNS set the repetitions.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
parts="${BENCH_PARTS:-parse shape anthro measure align batch}"
runs="${RUNS:-7}"
port="${BENCH_PORT:-4179}"
work="$(mktemp -d)"
trap 'kill "${server:-0}" 2>/dev/null || true; rm -rf "$work"' EXIT
wants() { [[ " $parts " == *" $1 "* ]]; }

bash scripts/build-wasm.sh
npx vite build --logLevel warn

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
echo "nproc: $(nproc); load average: $(cut -d' ' -f1-3 /proc/loadavg)"

if wants parse; then
  node bench/make-ply.mjs "$work/torus-300k.ply"
  echo
  echo "== parse: browser"
  node bench/browser-bench.mjs "http://127.0.0.1:$port/" "$work/torus-300k.ply" "$runs"
  echo
  echo "== parse: native"
  cargo run --quiet --release --manifest-path bench/native/Cargo.toml --target-dir crate/target -- \
    "$work/torus-300k.ply" "$runs"
fi
if wants shape; then
  echo
  echo "== shape model (public/models/demo.bsm): morphing in the worker (WASM in Chromium)"
  node bench/shape-bench.mjs "http://127.0.0.1:$port/" "${SHAPE_RUNS:-30}"
  echo
  echo "== shape model: morphing natively (release)"
  cargo run --quiet --release --manifest-path crate/Cargo.toml --example pca_bench -- morph
fi
if wants anthro; then
  echo
  echo "== anthropometry (public/models/demo.bsm) in the worker (WASM in Chromium)"
  node bench/anthropometry-bench.mjs "http://127.0.0.1:$port/" "${SHAPE_RUNS:-30}"
  echo
  echo "== anthropometry: bodies from measurements, distributions, boundary manikins (native)"
  echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  cargo run --quiet --release --manifest-path crate/Cargo.toml --example anthropometry_bench
fi
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
if wants measure; then
  echo
  echo "== measurements of fits against the truth, ISO 20685-1 (held-out; base, fine; the zoo)"
  cargo build --quiet --release --manifest-path crate/Cargo.toml --bin bodyspace --example measure_accuracy
  crate/target/release/bodyspace synth --n "${MEASURE_N:-8}" --seed "${MEASURE_SEED:-6161}" \
    --profile held-out --out "$work/measure" >/dev/null
  crate/target/release/bodyspace synth --n 16 --zoo --seed "${MEASURE_ZOO_SEED:-6868}" \
    --profile held-out --out "$work/measure-zoo" >/dev/null
  echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  crate/target/release/examples/measure_accuracy "$work/measure" --from all
  if [ "${MEASURE_FINE:-1}" != 0 ]; then
    crate/target/release/examples/measure_accuracy "$work/measure" --from all --resolution fine
  fi
  crate/target/release/examples/measure_accuracy "$work/measure-zoo" --from all
  echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
fi
if wants align; then
  echo
  echo "== alignment vs trimesh nricp_amberg"
  bash scripts/bench-align.sh
  echo
  echo "== alignment in the browser worker (≈ 201K-vertex synthetic subject, base and fine)"
  bash scripts/bench-align-browser.sh
fi
if wants batch; then
  echo
  echo "== batch in the browser: 20 synthetic subjects, worker pool vs one worker"
  cargo build --quiet --release --manifest-path crate/Cargo.toml --bin bodyspace
  crate/target/release/bodyspace synth --n 20 --seed 7 --out "$work/batch" >/dev/null
  echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  node bench/batch-bench.mjs "http://127.0.0.1:$port/" "$work/batch" "${BATCH_RUNS:-2}"
  echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
fi
