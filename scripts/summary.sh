#!/usr/bin/env bash
# Prints the test counts of each layer and the time of each phase from the
# logs scripts/timed.sh kept, ending with one "total: N passed, N failed" line.
set -euo pipefail
logs=test-results/logs

cargo_counts() { # passed and failed over every "test result:" line of a cargo log
  awk '/^test result:/ { for (i = 1; i <= NF; i++) { if ($(i) ~ /^passed;?$/) p += $(i-1); if ($(i) ~ /^failed;?$/) f += $(i-1) } }
       END { printf "%d %d\n", p, f }' "$1"
}
node_counts() { # TAP ("# pass N", Node 20 when piped) or spec ("ℹ pass N", Node 23+)
  awk '/^(# |ℹ )pass [0-9]+$/ { p += $3 } /^(# |ℹ )fail [0-9]+$/ { f += $3 } END { printf "%d %d\n", p, f }' "$1"
}

oracle_counts() { # scripts/oracle-linuxcnc.py: one "ok NAME" or "FAIL NAME" line per program
  awk '/^ok / { p++ } /^FAIL / { f++ } END { printf "%d %d\n", p, f }' "$1"
}

total_passed=0
total_failed=0
printf '\n== offsetlab test summary\n'
for layer in native:cargo oracle:oracle wasm-contract:cargo e2e:node; do
  name=${layer%%:*}
  kind=${layer##*:}
  log="$logs/$name.log"
  if [ ! -f "$log" ]; then
    printf '%-14s not run\n' "$name"
    continue
  fi
  read -r passed failed < <("${kind}_counts" "$log")
  printf '%-14s %4d passed, %d failed\n' "$name" "$passed" "$failed"
  total_passed=$((total_passed + passed))
  total_failed=$((total_failed + failed))
done
if [ -f "$logs/times.txt" ]; then
  printf '\n== phase times (seconds)\n'
  awk '{ printf "%-14s %5d\n", $1, $2; t += $2 } END { printf "%-14s %5d\n", "all", t }' "$logs/times.txt"
fi
printf '\ntotal: %d passed, %d failed\n' "$total_passed" "$total_failed"
