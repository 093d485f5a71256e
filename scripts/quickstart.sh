#!/usr/bin/env bash
# Sets up, builds, and runs the main job on a bundled model: a 3D tree bent
# by tropism, drawn into a PNG image and a glTF mesh in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
mkdir -p out
./build/src/sylva run examples/ternary-tree/ternary-tree.l examples/ternary-tree/ternary-tree.v \
  -o out/ternary-tree.png -o out/ternary-tree.glb --string out/ternary-tree.str
echo "wrote out/ternary-tree.png, out/ternary-tree.glb and out/ternary-tree.str"
