#!/usr/bin/env bash
# Installs, builds and runs the whole test suite with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
cd "${WEFT_BUILD_DIR:-build}"
ctest --output-on-failure --parallel "$(nproc)" "$@"
