#!/bin/sh
# Runs every Sylva benchmark, each in a process of its own so that the
# peak_RSS_MB counter (getrusage's ru_maxrss, a per-process maximum) belongs to
# that benchmark alone. Extra arguments go to every sylva_bench run, e.g.
#   bench/run.sh --benchmark_repetitions=3
# Environment: BUILD_DIR (default build-bench), FILTER (a regex: only the
# benchmarks it matches).
set -eu
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build-bench}
BENCH="$BUILD_DIR/bench/sylva_bench"
if [ ! -x "$BENCH" ]; then
  echo "build it first: cmake -S . -B $BUILD_DIR -G Ninja -DSYLVA_BUILD_BENCHMARKS=ON -DSYLVA_BUILD_TESTS=OFF -DCMAKE_BUILD_TYPE=Release && ninja -C $BUILD_DIR sylva_bench" >&2
  exit 1
fi
"$BENCH" --benchmark_list_tests=true | grep -E -- "${FILTER:-.}" | while read -r name; do
  # Names carry '/': match this one exactly.
  pattern=$(printf '%s' "$name" | sed 's/[][\.*^$+?(){}|]/\\&/g')
  "$BENCH" --benchmark_filter="^${pattern}\$" "$@" 2>&1 | grep -E -- "$name|ERROR|error" || true
done
