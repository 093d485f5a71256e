#!/usr/bin/env bash
# Installs what Sylva needs to build and test on Debian 12 (run as root or with sudo).
set -euo pipefail

PACKAGES=(
  g++ cmake ninja-build       # toolchain; g++ also compiles models at run time
  libcli11-dev                # command line
  libgtest-dev libgmock-dev   # tests
  libbenchmark-dev            # bench/
  pkg-config libcairo2-dev libosmesa6-dev libpng-dev   # vector drawings, offscreen OpenGL, PNG
  libegl-dev libgl1-mesa-dri                           # --gpu: headless OpenGL through EGL (surfaceless: llvmpipe)
  libssl-dev                                           # SHA-256 in provenance records (libcrypto)
  libtinygltf-dev nlohmann-json3-dev libstb-dev        # glTF
  libgraphicsmagick1-dev                               # texture images (PNG, SGI .rgb ...)
  libassimp-dev poppler-utils ghostscript              # tests read meshes, PDFs and PostScript back
  libcpp-httplib-dev                                   # the studio's web server
  libsundials-dev libeigen3-dev                        # stiff integration (CVODE), linear algebra in tests
  libtomlplusplus-dev                                  # experiment plans (TOML)
  libopenmpi-dev openmpi-bin                           # experiments on a cluster (MPI; mpirun in the tests)
  chromium                                             # the studio's browser tests (headless)
  clang libclang-rt-14-dev                             # the sanitizer build and the fuzz targets (libFuzzer)
)
# The studio's page is bundled with Node.js packages (web/package.json): Debian's
# nodejs and npm unless the machine has them already.
command -v node >/dev/null || PACKAGES+=(nodejs)
command -v npm >/dev/null || PACKAGES+=(npm)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# three.js, esbuild and playwright-core, as package-lock.json pins them (again
# whenever the lock file changes).
cd "$(dirname "$0")/../web"
if ! cmp -s package-lock.json node_modules/.installed-lock.json; then
  npm ci --no-audit --no-fund --loglevel=error
  cp package-lock.json node_modules/.installed-lock.json
fi
