#!/bin/sh
# Sylva's derive-only run in the calling convention of
# ../shared/tools/perf-compare.sh's SYLVA_DERIVE: MODEL STEPS [INPUT...],
# STEPS -1 for the model's derivation length. No string is written.
# SYLVA_THREADS: the derivation's threads (default: one per core).
set -eu
model=$1 steps=$2
shift 2
set -- "$model" "$@" --string none --threads "${SYLVA_THREADS:-0}"
if [ "$steps" -ge 0 ]; then set -- "$@" -n "$steps"; fi
exec "${SYLVA:?set SYLVA to the sylva binary}" run "$@"
