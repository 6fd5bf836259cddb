#!/usr/bin/env bash
# Fuzzes every loader of user input (fuzz/, one libFuzzer target per loader): builds build-fuzz/
# with clang (libFuzzer, AddressSanitizer, UndefinedBehaviorSanitizer) and runs each target on a
# seed corpus made from presets/ and assets/. Prints each target's executions and time and exits
# non-zero on a finding (a crash, a sanitizer report, a leak, an unexpected exception, a unit
# slower than the timeout); the input is left as build-fuzz/crash-*, leak-* or timeout-*.
#   scripts/fuzz.sh                 the campaign: 1,000,000 executions per loader target, and one
#                                   hour of world_step (each of its units simulates a scene for up
#                                   to seconds: 10^6 of them would take days)
#   scripts/fuzz.sh --seconds 10    a bounded run per target (CI)
#   scripts/fuzz.sh ... TARGET...   only the named targets (json_text scene material_preset
#                                   tear_table obj_cloth closed_obj sharp_tags scene_overrides
#                                   world_step)
# The corpus each run grows is kept in build-fuzz/corpus/TARGET and reused by the next run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh

limit=(-runs=1000000)
if [ "${1:-}" = "--seconds" ]; then
  limit=(-max_total_time="${2:?--seconds needs a number}")
  shift 2
fi
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(json_text scene material_preset tear_table obj_cloth closed_obj sharp_tags scene_overrides world_step)
fi

CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWEFT_FUZZ=ON \
  -DWEFT_BUILD_TESTS=OFF > /dev/null
cmake --build build-fuzz --target "${targets[@]/#/fuzz_}"

# Seeds, per target (two runs of this script may fuzz different targets at once). A preset is
# loaded as NAME.json and must call itself NAME: the targets load "fuzz", so the preset seeds are
# renamed to reach past that check.
make_seeds() {
  local dir="build-fuzz/seeds/$1"
  rm -rf "$dir" && mkdir -p "$dir"
  case "$1" in
    json_text) find presets assets -name '*.json' -exec cp {} "$dir/" \; ;;
    scene) cp presets/scenes/*.json "$dir/" ;;
    material_preset | tear_table)
      local folder=materials
      if [ "$1" = tear_table ]; then folder=tear_tables; fi
      for f in presets/"$folder"/*.json; do
        sed -E '0,/"name": *"[^"]*"/s//"name": "fuzz"/' "$f" > "$dir/$(basename "$f")"
      done ;;
    obj_cloth) cp assets/meshes/*.obj fuzz/seeds/obj_cloth/*.obj "$dir/" ;;
    closed_obj) cp assets/tools/*.obj fuzz/seeds/closed_obj/*.obj "$dir/" ;;
    sharp_tags) cp assets/tools/*.sharp.json fuzz/seeds/sharp_tags/*.json "$dir/" ;;
    scene_overrides | world_step)
      # Each shipped scene as it is (its name alone), and the hand-made overrides; for the step,
      # also overrides that blow a run up (fuzz/seeds/world_step/).
      for f in presets/scenes/*.json; do basename "$f" .json > "$dir/$(basename "$f" .json).txt"; done
      cp fuzz/seeds/scene_overrides/*.txt "$dir/"
      if [ "$1" = world_step ]; then cp fuzz/seeds/world_step/*.txt "$dir/"; fi ;;
  esac
}

# A dictionary of the words a target's input is made of, where mutating bytes alone would take
# long to spell them: for the overrides, every key of the shipped scenes (a PATH is keys joined by
# dots) and the shape and motion names.
make_dictionary() {
  local dict="build-fuzz/seeds/$1.dict"
  case "$1" in
    scene_overrides | world_step)
      grep -ohE '"[A-Za-z_]+" *:' presets/scenes/*.json | sed -E 's/^"([A-Za-z_]+)".*/"\1"/' | sort -u > "$dict"
      printf '"%s"\n' sphere box capsule cylinder mesh static kinematic dynamic . = '[' ']' '{' '}' >> "$dict"
      echo "$dict" ;;
  esac
}

# The longest input each target tries, in bytes. The JSON formats' largest files are under 3 KB
# (a scene with obstacles); 4 KB leaves room for every field at once. The OBJ cloths in assets/
# are 10-21 KB of repeated `v`, `vt` and `f` lines and are cut to their first 8 KB (the small
# seeds in fuzz/seeds/ are whole meshes). Longer inputs reach no code a shorter one does not (the
# readers are linear in the input) and only slow the campaign down.
# Tools (closed OBJs) are 11-43 KB and cut to 8 KB like the cloths; the small closed solids in
# fuzz/seeds/closed_obj/ are whole. An override line is under 100 bytes; 1 KB holds 16 of them or
# a whole obstacle written as one value.
declare -A max_len=([json_text]=4096 [scene]=4096 [material_preset]=4096 [tear_table]=4096 [obj_cloth]=8192
                    [closed_obj]=8192 [sharp_tags]=4096 [scene_overrides]=1024 [world_step]=1024)
# A unit slower than this many seconds (wall clock) is a finding: a hang. The slowest legitimate
# input is a scene pinning a 1024 x 1024 grid (built to check the pins): 4 s of CPU under the
# sanitizers, half a minute of wall time on a loaded machine.
timeout=300
# No allocation stacks in reports: a quarter faster. Rerunning a finding's input
# (build-fuzz/fuzz/fuzz_TARGET build-fuzz/crash-...) prints them.
export ASAN_OPTIONS="${ASAN_OPTIONS:-malloc_context_size=0}"

failed=0
for target in "${targets[@]}"; do
  make_seeds "$target"
  dict_option=()
  dict=$(make_dictionary "$target")
  if [ -n "$dict" ]; then dict_option=(-dict="${dict#build-fuzz/}"); fi
  corpus="build-fuzz/corpus/$target"
  mkdir -p "$corpus"
  log="build-fuzz/fuzz_$target.log"
  status=0
  start=$(date +%s)
  target_limit=("${limit[@]}")
  if [ "$target" = world_step ] && [ "${limit[0]}" = -runs=1000000 ]; then target_limit=(-max_total_time=3600); fi
  (cd build-fuzz && exec "./fuzz/fuzz_$target" "${target_limit[@]}" -max_len="${max_len[$target]}" -timeout="$timeout" \
     "${dict_option[@]}" -print_final_stats=1 "corpus/$target" "seeds/$target") > "$log" 2>&1 &
  pid=$!
  wait "$pid" || status=$?
  rm -rf "/dev/shm/weft_fuzz_$pid" "${TMPDIR:-/tmp}/weft_fuzz_$pid"  # the targets' scratch files (fuzz/fuzz_file.h)
  runs=$(grep -oE '^stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' || echo '?')
  echo "fuzz_$target: $runs executions in $(( $(date +%s) - start )) s, max_len ${max_len[$target]} (exit $status)"
  if [ "$status" -ne 0 ]; then
    grep -E "ERROR|SUMMARY|Test unit written|uncaught" "$log" || true
    echo "fuzz_$target: a finding; the full log is $log" >&2
    failed=1
  fi
done
exit "$failed"
