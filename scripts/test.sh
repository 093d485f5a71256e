#!/usr/bin/env bash
# Sets up, builds, and runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh -DSYLVA_BUILD_TESTS=ON
cd build
ctest --output-on-failure -j "$(nproc)"
