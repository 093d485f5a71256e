#!/usr/bin/env bash
# Sets up, builds, and runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh -DSYLVA_BUILD_TESTS=ON
(cd build && ctest --output-on-failure -j "$(nproc)")

# The sanitizer job: the front ends and every input-file reader built with
# clang, AddressSanitizer and UndefinedBehaviorSanitizer, each fuzz target run
# a fixed number of times from its seed corpus (fuzz/README.md).
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Release -DSYLVA_BUILD_TESTS=OFF \
  -DSYLVA_BUILD_FUZZERS=ON >/dev/null
ninja -C build-fuzz fuzzers
(cd build-fuzz && ctest --output-on-failure -L fuzz -j "$(nproc)")
