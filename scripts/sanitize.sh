#!/usr/bin/env bash
# Builds core and the input tests with AddressSanitizer and UndefinedBehaviorSanitizer
# (build-asan/, -DWEFT_SANITIZE=ON) and runs them: the readers of scenes, presets, meshes and
# sharp tags, the echo of values in messages, and the health check. Any sanitizer report fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWEFT_SANITIZE=ON > /dev/null
cmake --build build-asan --target weft_tests
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd build-asan && ctest --output-on-failure --parallel "$(nproc)"
