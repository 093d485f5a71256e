#!/usr/bin/env bash
# Sets up, builds, and runs the main job on a bundled model: the Anabaena
# filament of the L+C thesis, derived 500 steps, string written to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
mkdir -p out
./build/src/sylva run examples/anabaena/anabaena.l --steps 500 --string out/anabaena.str
echo "wrote out/anabaena.str ($(wc -w < out/anabaena.str) modules)"
