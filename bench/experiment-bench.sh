#!/bin/bash
# Runs per second of `sylva experiment` on 1 and 2 local processes and on 2
# MPI ranks (one run at a time each), interleaved over ROUNDS rounds, with
# the models compiled beforehand. Run by hand:
#   bench/experiment-bench.sh [build/src/sylva] [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
SYLVA=${1:-build/src/sylva}
ROUNDS=${2:-3}
PLAN=bench/experiment/runs-per-second.toml
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
"$SYLVA" experiment "$PLAN" -j 2 --no-progress 2>/dev/null   # compiles the -D sets once
runs=$(($(wc -l < /tmp/sylva-experiment-bench.csv) - 1))
seconds() { local start end; start=$(date +%s.%N); "$@" > /dev/null 2>&1; end=$(date +%s.%N); awk "BEGIN { print $end - $start }"; }
rate() { awk "BEGIN { printf \"%.1f\", $runs / $1 }"; }
for round in $(seq "$ROUNDS"); do
  one=$(seconds "$SYLVA" experiment "$PLAN" -j 1 --no-progress)
  two=$(seconds "$SYLVA" experiment "$PLAN" -j 2 --no-progress)
  mpi=$(seconds mpirun --oversubscribe -n 2 "$SYLVA" experiment "$PLAN")
  echo "round $round: $runs runs; 1 process $(rate "$one") runs/s, 2 processes $(rate "$two") runs/s," \
       "2 MPI ranks $(rate "$mpi") runs/s"
done
