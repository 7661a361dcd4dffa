#!/usr/bin/env bash
# Runs one phase of the build or the tests, keeps its output in
# test-results/logs/NAME.log and says how long it took:
#   scripts/timed.sh NAME COMMAND [ARGS...]
set -euo pipefail
name=$1
shift
logs=test-results/logs
mkdir -p "$logs"
printf '\n==> %s: %s\n' "$name" "$*"
start=$(date +%s)
status=0
"$@" 2>&1 | tee "$logs/$name.log" || status=$?
seconds=$(( $(date +%s) - start ))
printf '%s %s\n' "$name" "$seconds" >> "$logs/times.txt"
if [ "$status" -ne 0 ]; then
  printf '<== %s FAILED (exit %s) after %ss\n' "$name" "$status" "$seconds"
  exit "$status"
fi
printf '<== %s: %ss\n' "$name" "$seconds"
