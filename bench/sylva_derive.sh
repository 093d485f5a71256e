#!/bin/sh
# Sylva's derive-only run in the calling convention of
# ../shared/tools/perf-compare.sh's SYLVA_DERIVE: MODEL STEPS [INPUT...],
# STEPS -1 for the model's derivation length. No string is written.
set -eu
model=$1 steps=$2
shift 2
if [ "$steps" -ge 0 ]; then
  exec "${SYLVA:?set SYLVA to the sylva binary}" run "$model" "$@" -n "$steps" --string none
fi
exec "${SYLVA:?set SYLVA to the sylva binary}" run "$model" "$@" --string none
