#!/bin/sh
# Runs fuzz targets one after another for a long run by hand:
#   fuzz/run_long.sh BUILD_DIR WORK_DIR RUNS SECONDS TARGET...
# Each target runs RUNS executions (or until SECONDS pass, when the run is
# interrupted and its figures printed), niced, its findings kept in
# WORK_DIR/corpus/TARGET and its log in WORK_DIR/TARGET.log. A crash, hang or
# sanitizer report leaves its input in WORK_DIR and the next target starts.
set -u
build=$1 work=$2 runs=$3 seconds=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
for target in "$@"; do
  mkdir -p "$work/corpus/$target"
  dict=
  [ -f "$here/dictionaries/$target.dict" ] && dict="-dict=$here/dictionaries/$target.dict"
  (cd "$work" && timeout -s INT "$seconds" nice -n 10 "$build/fuzz/${target}_fuzzer" -runs="$runs" -seed=1 \
      -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 $dict "corpus/$target" "$here/corpus/$target" \
      > "$target.log" 2>&1)
  echo "$target: exit $? $(grep -E '^stat::number_of_executed_units|^#[0-9]+' "$work/$target.log" | tail -1)"
done
