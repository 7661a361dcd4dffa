#!/usr/bin/env bash
# Wall-clock time of a command, best and median of N runs, in milliseconds
# (docs/performance.md, target 6): scripts/best-of.sh N COMMAND [ARG...]
set -eu
n=$1
shift
times=()
for _ in $(seq "$n"); do
  start=$(date +%s%N)
  "$@" >/dev/null 2>&1 || true
  end=$(date +%s%N)
  times+=($(((end - start) / 100000)))
done
printf '%s\n' "${times[@]}" | sort -n |
  awk '{t[NR] = $1} END {printf "best %.1f ms, median %.1f ms (%d runs)\n", t[1] / 10, t[int((NR + 1) / 2)] / 10, NR}'
