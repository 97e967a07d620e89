#!/usr/bin/env bash
# Fuzz campaign over every reader of user bytes (see docs/fuzzing.md): each target in turn, one
# process and one job (libFuzzer's default; the machine is shared), for FUZZ_RUNS executions.
#
#   npm run fuzz                                   # every target, 1,000,000 executions each
#   FUZZ_RUNS=100000 FUZZ_TARGETS="obj bsm" npm run fuzz
#
# Seeds are read from crate/fuzz/corpus/<target>/ (committed); new inputs go to
# crate/fuzz/work/<target>/ (not committed), crashes to crate/fuzz/artifacts/<target>/.
# Prints executions, time and libFuzzer's final coverage (cov: edges, ft: features) per target.
set -uo pipefail
cd "$(dirname "$0")/../crate/fuzz"

RUNS=${FUZZ_RUNS:-1000000}
TARGETS=${FUZZ_TARGETS:-"ply_ascii ply_binary obj stl_ascii stl_binary gzip lnd landmarks_csv landmarks_json bsm"}
MAX_LEN=${FUZZ_MAX_LEN:-65536}

if ! command -v cargo-fuzz >/dev/null 2>&1; then
  echo "installing cargo-fuzz from crates.io ..."
  cargo install cargo-fuzz --locked || exit 1
fi
if ! rustup toolchain list | grep -q '^nightly'; then
  echo "cargo-fuzz needs nightly Rust: rustup toolchain install nightly" >&2
  exit 1
fi

# -O: optimised; -a: debug assertions, so integer overflow panics instead of wrapping.
cargo +nightly fuzz build -O -a || exit 1

mkdir -p logs
summary=()
failed=0
for t in $TARGETS; do
  mkdir -p "work/$t" "corpus/$t"
  log="logs/$t.log"
  echo "== $t: $RUNS executions"
  start=$(date +%s.%N)
  cargo +nightly fuzz run -O -a "$t" "work/$t" "corpus/$t" -- \
    -runs="$RUNS" -timeout=1 -rss_limit_mb=2048 -max_len="$MAX_LEN" -print_final_stats=1 \
    >"$log" 2>&1
  status=$?
  end=$(date +%s.%N)
  secs=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.0f", b - a }')
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  # libFuzzer's own time for the runs (the wall time above also counts a rebuild, if any).
  fuzz_secs=$(grep -o 'Done [0-9]* runs in [0-9]* second' "$log" | grep -o 'in [0-9]*' | grep -o '[0-9]*' | tail -1)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  rss=$(grep -o 'stat::peak_rss_mb: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -1)
  if [ $status -ne 0 ]; then
    failed=1
    result="FAILED (exit $status; see crate/fuzz/$log and crate/fuzz/artifacts/$t/)"
    grep -m3 -E 'ERROR|panicked|SUMMARY' "$log" | sed 's/^/   /'
  else
    result="ok"
  fi
  line=$(printf '%-15s %10s %6ss %6ss %8s/s %6s MB  %-22s %s' "$t" "${execs:-?}" "${fuzz_secs:-?}" "$secs" \
    "${rate:-?}" "${rss:-?}" "${cov:-cov: ?}" "$result")
  echo "$line"
  summary+=("$line")
done

echo
echo "target          executions   fuzz   wall    execs/s  peak RSS  coverage (final)       result"
printf '%s\n' "${summary[@]}"
exit $failed
