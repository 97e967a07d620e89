#!/usr/bin/env bash
# Accuracy and speed of alignment (RBF warp + fine alignment) against the peer,
# trimesh.registration.nricp_amberg, on the same N synthetic subjects (default 2; the peer takes
# ~1–2 min per subject on the 2-core machine). The peer starts from OUR RBF-warped template with
# the same landmark anchors (see bench/peer/nricp.py); then both fits' correspondence split as a
# shape model sees it (common to all subjects / each one's own, leave one out;
# crate/examples/correspondence_split.rs, the same code for both). Python packages go into a venv under
# .bodyspace-cache/venv, installed here (never at test time).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
n="${ALIGN_BENCH_N:-2}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

cargo build --quiet --release --manifest-path crate/Cargo.toml --bin bodyspace --example align_accuracy --example correspondence_split
crate/target/release/bodyspace synth --n "$n" --seed 1 --out "$work/synth" >/dev/null
mkdir -p "$work/export"

venv=.bodyspace-cache/venv
if [ ! -x "$venv/bin/python" ] || ! "$venv/bin/python" -c 'import trimesh, scipy, rtree' 2>/dev/null; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet "trimesh>=4,<6" scipy numpy rtree
fi

echo
echo "== ours (bodyspace, defaults)"
crate/target/release/examples/align_accuracy "$work/synth" --n "$n" --export "$work/export" | tee "$work/ours.txt"
echo
echo "== peer (trimesh.registration.nricp_amberg, default steps, same start and landmarks)"
"$venv/bin/python" bench/peer/nricp.py "$work/synth" "$work/export" "$n" | tee "$work/peer.txt"

echo
echo "== fine alignment: ours vs peer, mean over $n subjects"
read -r _ _ ours_rms _ _ _ ours_corr _ < <(grep '^ *mean' "$work/ours.txt")
ours_ms="$(grep '^ *mean' "$work/ours.txt" | awk '{print $(NF-3) + $(NF-2) + $(NF-1) + $NF}')"
read -r _ peer_rms peer_corr peer_s < <(grep '^ *mean' "$work/peer.txt")
printf '%-32s %14s %22s %12s\n' "method" "scan→tmpl RMS" "correspondence (mean)" "time"
printf '%-32s %11.3f mm %19.2f mm %10.2f s\n' "bodyspace (RBF + fine)" "$ours_rms" "$ours_corr" "$(awk "BEGIN{print $ours_ms/1000}")"
printf '%-32s %11.3f mm %19.2f mm %10.2f s\n' "trimesh nricp_amberg" "$peer_rms" "$peer_corr" "$peer_s"
awk "BEGIN{printf \"speed-up: %.0fx\n\", $peer_s*1000/$ours_ms}"

echo
echo "== correspondence as the shape model sees it: ours, then the peer ($n subjects)"
crate/target/release/examples/correspondence_split "$work/synth" "$work/export" --n "$n" --prefix fitted
crate/target/release/examples/correspondence_split "$work/synth" "$work/export" --n "$n" --prefix peer
