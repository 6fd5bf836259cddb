#!/usr/bin/env bash
# The main job: install, build, then open the editor on the default scene where a display exists;
# with no display, run the default scene headless and write its results (metrics, OBJ and PNG
# frames rendered through EGL) under ./out.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
SCENE=presets/scenes/hanging-sheet.json
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  status=0
  ./build/app/weft edit "$SCENE" || status=$?
  # 2: the editor could not open (not built yet, or no usable display): fall back to headless.
  if [ "$status" -ne 2 ]; then exit "$status"; fi
  echo "weft: falling back to a headless run" >&2
fi
./build/app/weft run "$SCENE" --out out/hanging-sheet --obj --png "$@"
