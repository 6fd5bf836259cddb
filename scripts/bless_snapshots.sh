#!/usr/bin/env bash
# Regenerates ("blesses") the golden PNGs of the snapshot tests from what the renderer draws now:
# the preset-scene snapshot tests (tests/ui/scene_snapshot_test.cpp) rewrite their goldens
# and tests/ui/snapshots/RENDERER.txt, and the editor's screenshot (tests/editor/editor_panels_test.cpp)
# its golden, instead of comparing with them.
# Look at the images (and `git diff --stat tests/`) before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${WEFT_BUILD_DIR:-build}"
bash scripts/build.sh
WEFT_BLESS=1 GALLIUM_DRIVER=llvmpipe "$BUILD_DIR/tests/weft_tests" --gtest_filter='PresetScenes/SceneSnapshotTest.*:SceneSnapshotTest.*:EditorPanelsTest.EditorSnapshot*'
echo "weft: goldens rewritten; review them with: git status tests/"
