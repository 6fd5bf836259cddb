#!/usr/bin/env bash
# Regenerates ("blesses") the golden PNGs of the snapshot tests from what the renderer draws now:
# every test whose name contains "Snapshot" rewrites its golden instead of comparing with it.
# Look at the images (and `git diff --stat tests/`) before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${WEFT_BUILD_DIR:-build}"
bash scripts/build.sh
WEFT_BLESS=1 GALLIUM_DRIVER=llvmpipe "$BUILD_DIR/tests/weft_tests" --gtest_filter='*Snapshot*'
echo "weft: goldens rewritten; review them with: git status tests/"
