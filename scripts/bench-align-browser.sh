#!/usr/bin/env bash
# Alignment in the browser worker (issue 5's speed goals: base ≤ 3 s, fine ≤ 15 s on a 200K-vertex
# scan) and the same natively. Synthesises its own subject with `bodyspace synth` (subject 1 of
# seed 2026, scanner step 2.43 mm: ≈ 201K scan vertices, the size of the demo population's
# largest scan), builds the WASM core (WASM_FEATURES as scripts/build-wasm.sh; default
# +simd128) and the app, serves it, and aligns at base (ALIGN_RUNS, default 3) and fine
# (ALIGN_FINE_RUNS, default 2) in Chromium through the app's Align button (ALIGN_RESOLUTIONS
# picks them, default "base fine").
# The same subject's scan alone is then dropped ESTIMATE_RUNS times (default 3) for the landmark
# estimate in the app's landmark worker (issue 11: ≤ 5 s in the browser, ≤ 2 s natively), and
# estimated natively by `bodyspace landmarks`. ALIGN_RESOLUTIONS=none runs the estimate alone.
# SIMD or not: `WASM_FEATURES= bash scripts/bench-align-browser.sh`, then without the variable.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
port="${BENCH_PORT:-4181}"
work="$(mktemp -d)"
trap 'kill "${server:-0}" 2>/dev/null || true; rm -rf "$work"' EXIT

cargo build --quiet --release --manifest-path crate/Cargo.toml --bin bodyspace
bin=crate/target/release/bodyspace
"$bin" synth --n 1 --seed 2026 --step 2.43 --out "$work/subject" >/dev/null
scan="$work/subject/scan_001.ply"
landmarks="$work/subject/landmarks_001.lnd"
truth="$work/subject/truth_001.ply"

bash scripts/build-wasm.sh
npx vite build --logLevel warn --outDir "$work/dist"
node node_modules/vite/bin/vite.js preview --outDir "$work/dist" --host 127.0.0.1 --port "$port" --strictPort >"$work/server.log" 2>&1 &
server=$!
for _ in $(seq 1 100); do
  curl -sf "http://127.0.0.1:$port/" >/dev/null && break
  sleep 0.2
done

echo
echo "== machine"
lscpu | grep -E '^(Model name|CPU\(s\)|Thread|Core|Socket)' || true
echo "nproc: $(nproc); load average: $(cut -d' ' -f1-3 /proc/loadavg); WASM target features: $(cat web/pkg/target-features 2>/dev/null || echo unknown)"
resolutions="${ALIGN_RESOLUTIONS:-base fine}"
[ "$resolutions" = none ] && resolutions=""
for resolution in $resolutions; do
  echo
  echo "== browser worker, $resolution template"
  runs="${ALIGN_RUNS:-3}"
  [ "$resolution" = fine ] && runs="${ALIGN_FINE_RUNS:-2}"
  node bench/align-bench.mjs "http://127.0.0.1:$port/" "$scan" "$landmarks" "$resolution" "$runs"
done

[ -n "$resolutions" ] && echo && echo "== native (release, $(nproc) threads for the correspondence search), same subject"
for resolution in $resolutions; do
  "$bin" align --resolution "$resolution" --scan "$scan" --landmarks "$landmarks" --truth "$truth" \
    --out "$work/fit-$resolution.ply" --report "$work/report-$resolution.json" >/dev/null
  node -e '
    const r = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
    const f = r.fine, base = f.stages ? ` (base stage ${f.stages.base.elapsed_ms.toFixed(0)})` : "";
    console.log(`${r.template_resolution}: scan ${f.scan_vertices} vertices; RBF ${r.rough_ms.toFixed(0)} ms, index ${r.index_ms.toFixed(0)} ms, ` +
      `fine ${f.elapsed_ms.toFixed(0)} ms${base}, total ${r.total_ms.toFixed(0)} ms; ${f.iterations} iterations; ` +
      `RMS ${f.scan_to_template.rms_mm.toFixed(3)} mm; correspondence ${r.correspondence.fitted.mean_mm.toFixed(2)} mm`);
  ' "$work/report-$resolution.json"
done

echo
echo "== landmark estimate of the bare scan: browser, the landmark worker"
node bench/estimate-bench.mjs "http://127.0.0.1:$port/" "$scan" "${ESTIMATE_RUNS:-3}"
echo "== landmark estimate: native (release), same scan"
for run in $(seq 1 "${ESTIMATE_RUNS:-3}"); do
  "$bin" landmarks --scan "$scan" --out "$work/landmarks.csv" | node -e '
    let s = ""; process.stdin.on("data", (d) => (s += d)).on("end", () => { const r = JSON.parse(s);
      console.log(`${r.total_ms.toFixed(0)} ms (candidates ${r.candidates_ms.toFixed(0)}, segments ${r.segments_ms.toFixed(0)}, fine ${r.fine_ms.toFixed(0)}); fit RMS ${r.fit_rms_mm.toFixed(2)} mm`); });'
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
