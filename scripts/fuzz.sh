#!/usr/bin/env bash
# Runs the cargo-fuzz targets (fuzz/) one after the other, each for SECONDS
# (default 60) on one core, and prints each target's last libFuzzer status
# line (executions, cov, ft, corpus). Not part of `make test`.
#
#   scripts/fuzz.sh                 # parse, run, macros and link, 60 s each
#   scripts/fuzz.sh 600 run         # the run target for ten minutes
#
# Needs the nightly toolchain and cargo-fuzz (`cargo install cargo-fuzz`).
# Corpora grow in fuzz/corpus/<target>/ (seeded from tests/data by
# fuzz/seeds.py), crashes land in fuzz/artifacts/<target>/ and logs in
# fuzz/logs/; none of these are committed. A crash input replays with
# `cargo +nightly fuzz run -O -a -s none <target> <file>`; it then belongs
# in tests/fuzz_regressions.rs.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(parse run macros link)

command -v cargo-fuzz >/dev/null || { echo "fuzz.sh: cargo-fuzz is missing (cargo install cargo-fuzz)" >&2; exit 2; }
# Safe Rust: no sanitizer (twice the speed), but debug assertions and
# overflow checks on (-a), as in the native tests.
flags=(-O -a -s none)
(cd fuzz && cargo +nightly fuzz build "${flags[@]}")
python3 fuzz/seeds.py fuzz/target/seeds >/dev/null
mkdir -p fuzz/logs

status=0
for t in "${targets[@]}"; do
  case $t in
    link) dict=fuzz/link.dict; max_len=16384 ;;
    *) dict=fuzz/gcode.dict; max_len=4096 ;;
  esac
  mkdir -p "fuzz/corpus/$t" "fuzz/artifacts/$t" "fuzz/target/seeds/$t"
  log="fuzz/logs/$t.log"
  echo "== $t: ${seconds}s (log $log)"
  # One process, one core (no -jobs/-workers: libFuzzer then runs in this
  # process and leaves the other core to whatever else is building).
  if (cd fuzz && cargo +nightly fuzz run "${flags[@]}" "$t" "corpus/$t" "target/seeds/$t" -- \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -max_len="$max_len" \
      -dict="../$dict" -print_final_stats=1) >"$log" 2>&1; then
    grep -aE '^#[0-9]+[[:space:]]+(DONE|pulse|NEW|REDUCE)' "$log" | tail -1 || true
    grep -E '^stat::(number_of_executed_units|peak_rss_mb)' "$log" || true
  else
    status=1
    echo "   $t FAILED: see $log and fuzz/artifacts/$t/"
    grep -E 'panicked|ERROR|Test unit written' "$log" | head -5 || true
  fi
done
exit $status
