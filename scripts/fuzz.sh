#!/usr/bin/env bash
# Fuzzes the loaders' first contact with raw bytes (fuzz/): builds build-fuzz/ with clang
# (libFuzzer, AddressSanitizer, UndefinedBehaviorSanitizer) and runs each target on a seed corpus
# made from presets/ and assets/. Prints each target's executions and exits non-zero on a finding
# (the crashing input is left as build-fuzz/crash-*).
#   scripts/fuzz.sh                 the campaign: 1,000,000 executions per target
#   scripts/fuzz.sh --seconds 10    a bounded run per target (CI)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh

limit=(-runs=1000000)
if [ "${1:-}" = "--seconds" ]; then limit=(-max_total_time="${2:?--seconds needs a number}"); fi

CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWEFT_FUZZ=ON \
  -DWEFT_BUILD_TESTS=OFF > /dev/null
cmake --build build-fuzz --target fuzz_json_text fuzz_obj_cloth

seeds=build-fuzz/seeds
rm -rf "$seeds" && mkdir -p "$seeds/json_text" "$seeds/obj_cloth"
find presets assets -name '*.json' -size -64k -exec cp {} "$seeds/json_text/" \;
find assets -name '*.obj' -size -64k -exec cp {} "$seeds/obj_cloth/" \;

for target in json_text obj_cloth; do
  corpus="build-fuzz/corpus/$target"
  mkdir -p "$corpus"
  log="build-fuzz/fuzz_$target.log"
  status=0
  (cd build-fuzz && "./fuzz/fuzz_$target" "${limit[@]}" -max_len=65536 -print_final_stats=1 \
     "corpus/$target" "seeds/$target") > "$log" 2>&1 || status=$?
  echo "fuzz_$target: $(grep -E '^Done [0-9]+ runs' "$log" || echo 'no summary') (exit $status)"
  if [ "$status" -ne 0 ]; then
    grep -E "ERROR|SUMMARY|Test unit written" "$log" || true
    echo "fuzz_$target: a finding; the full log is $log" >&2
    exit 1
  fi
done
