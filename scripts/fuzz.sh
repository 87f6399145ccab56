#!/usr/bin/env bash
# Fuzzing probeproxy's readers and command line with libFuzzer (tests/fuzz/ holds the targets).
#   scripts/fuzz.sh build [--command-line]
#                                         configure and build the fuzz tree (clang, ASan, UBSan)
#                                         and write every target's seed corpus; with
#                                         --command-line the command_line target too, in a tree
#                                         of its own without the sanitizers (<tree>/command_line;
#                                         the whole library: about ten minutes more on 2 cores)
#   scripts/fuzz.sh run TARGET LIMIT      fuzz one target; LIMIT is `--runs N` or `--seconds S`
#   scripts/fuzz.sh all LIMIT             every target in turn, one summary line each
#   scripts/fuzz.sh regressions           every kept input of tests/fuzz/regressions/, once
#   scripts/fuzz.sh targets               the target names
# The tree is $PROBEPROXY_FUZZ_DIR (default build/fuzz); $PROBEPROXY_FUZZ_SEED fixes libFuzzer's
# random seed (CTest's short runs use 1; unset, each run draws its own). Each target's corpus grows in
# <tree>/corpus/<target>/ across runs; a crash, hang, leak or sanitizer report stops the run,
# leaves the input in <tree>/findings/<target>/ and makes the script exit 1. The summary line:
#   <target>: <executions> executions in <s> s, <edges> edges, <corpus> inputs, <findings> findings
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tree="${PROBEPROXY_FUZZ_DIR:-$here/build/fuzz}"
export LSAN_OPTIONS="suppressions=$here/tests/fuzz/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1"
targets=(scene_file runtime_export bsp pk3 level_gltf level_glb level_obj level_ply level_off
         cubemap_image cubemap_faces candidate_wire proxy_build_wire)
# The command line, where it was built (scripts/fuzz.sh build --command-line).
cli_tree=$tree/command_line
[ -x "$cli_tree/tests/fuzz/fuzz_command_line" ] && targets+=(command_line)

# Dictionaries by target: the tokens a mutation is unlikely to find byte by byte.
dictionary() {
  case "$1" in
    scene_file | runtime_export | level_gltf) echo "$here/tests/fuzz/dictionaries/json.dict" ;;
    bsp | pk3) echo "$here/tests/fuzz/dictionaries/bsp.dict" ;;
    level_obj) echo "$here/tests/fuzz/dictionaries/obj.dict" ;;
    level_ply) echo "$here/tests/fuzz/dictionaries/ply.dict" ;;
    level_off) echo "$here/tests/fuzz/dictionaries/off.dict" ;;
    cubemap_image) echo "$here/tests/fuzz/dictionaries/hdr.dict" ;;
    cubemap_faces) echo "$here/tests/fuzz/dictionaries/png.dict" ;;
    command_line) echo "$here/tests/fuzz/dictionaries/command_line.dict" ;;
    *) echo "" ;;
  esac
}

# Seeds beyond the generated ones: the suite's and the corpus' files where this checkout has
# them (build/scenes, build/corpus), the broken variants kept in tests/e2e/hostile/, the
# inputs kept as regressions.
copy_seeds() {
  local seeds=$tree/seeds target
  for target in "${targets[@]}" command_line; do mkdir -p "$seeds/$target"; done
  cp "$here"/tests/fuzz/seeds/command_line/* "$seeds/command_line/"
  shopt -s nullglob
  local f
  for f in "$here"/tests/e2e/hostile/*.scene.json "$here"/build/scenes/*/*.scene.json \
           "$here"/build/corpus/scenes/*/*.scene.json; do
    cp "$f" "$seeds/scene_file/$(basename "$(dirname "$f")")_$(basename "$f")"
  done
  for f in "$here"/tests/fuzz/seeds/runtime_export/*.json "$here"/build/tests/corpus/*/proxies.json; do
    cp "$f" "$seeds/runtime_export/$(basename "$(dirname "$f")")_$(basename "$f")"
  done
  for target in candidate_wire proxy_build_wire; do
    for f in "$here/tests/fuzz/seeds/$target"/*; do cp "$f" "$seeds/$target/"; done
  done
  for f in "$here"/build/scenes/*/*.glb; do cp "$f" "$seeds/level_glb/"; done
  for f in "$here"/tests/e2e/hostile/*.ply; do cp "$f" "$seeds/level_ply/"; done
  for f in "$here"/tests/e2e/hostile/*.off; do cp "$f" "$seeds/level_off/"; done
  # The smallest real map, if the corpus is unpacked: real lumps, real patches.
  local map
  map=$(ls -S "$here"/build/corpus/*/maps/*.bsp 2>/dev/null | tail -n 1 || true)
  [ -n "$map" ] && cp "$map" "$seeds/bsp/"
  for target in "${targets[@]}"; do
    for f in "$here/tests/fuzz/regressions/$target"/*; do cp "$f" "$seeds/$target/"; done
  done
}

build() {
  local options=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14
    -DPROBEPROXY_FUZZ=ON -DPROBEPROXY_BUILD_TESTS=OFF -DPROBEPROXY_BUILD_BENCHMARKS=OFF
    -DPROBEPROXY_WITH_BLENDER=OFF)
  cmake -S "$here" -B "$tree" "${options[@]}" -DPROBEPROXY_FUZZ_COMMAND_LINE=OFF >/dev/null
  cmake --build "$tree" -j"$(nproc)" --target fuzz_targets
  if [ "${1:-}" = --command-line ]; then
    cmake -S "$here" -B "$cli_tree" "${options[@]}" -DPROBEPROXY_FUZZ_SANITIZE=OFF \
      -DPROBEPROXY_FUZZ_COMMAND_LINE=ON >/dev/null
    cmake --build "$cli_tree" -j"$(nproc)" --target fuzz_command_line
  fi
  rm -rf "$tree/seeds"
  "$tree/tests/fuzz/write_fuzz_seeds" "$tree/seeds"
  copy_seeds
}

# run TARGET --runs N | --seconds S
run() {
  local target=$1 kind=$2 amount=$3
  local binary=$tree/tests/fuzz/fuzz_$target
  [ "$target" = command_line ] && binary=$cli_tree/tests/fuzz/fuzz_command_line
  [ -x "$binary" ] || { echo "fuzz: $binary not built: run scripts/fuzz.sh build" >&2; exit 2; }
  local corpus=$tree/corpus/$target findings=$tree/findings/$target log=$tree/logs/$target.log
  mkdir -p "$corpus" "$findings" "$tree/logs"
  local limit=(-runs="$amount")
  [ "$kind" = --seconds ] && limit=(-max_total_time="$amount")
  local dict
  dict=$(dictionary "$target")
  # One process, one core: -jobs would share the machine with the other targets. 2 GiB of
  # RSS and 10 s per input: past either the reader lacks a limit, which is a finding.
  local start=$SECONDS code=0
  # A command line runs a verb on a level: a layout takes half a second, a slow option minutes.
  local timeout=10
  [ "$target" = command_line ] && timeout=120
  "$binary" "${limit[@]}" ${dict:+-dict="$dict"} -rss_limit_mb=2048 -malloc_limit_mb=2048 \
    -timeout=$timeout -max_len=65536 -seed="${PROBEPROXY_FUZZ_SEED:-0}" -print_final_stats=1 -artifact_prefix="$findings/" \
    "$corpus" "$tree/seeds/$target" >"$log" 2>&1 || code=$?
  local seconds=$((SECONDS - start))
  local runs edges inputs found
  runs=$(grep -ao 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  edges=$(grep -ao 'cov: [0-9]*' "$log" | tail -n 1 | grep -o '[0-9]*' || echo 0)
  inputs=$(find "$corpus" -type f | wc -l)
  found=$(find "$findings" -type f | wc -l)
  echo "$target: ${runs:-0} executions in $seconds s, ${edges:-0} edges, $inputs inputs, $found findings"
  if [ "$code" -ne 0 ]; then
    echo "fuzz: $target stopped with exit $code; see $log and $findings/" >&2
    grep -a -m 3 -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error)' "$log" >&2 || true
    return 1
  fi
}

regressions() {
  local target f code=0
  for target in "${targets[@]}"; do
    for f in "$here/tests/fuzz/regressions/$target"/*; do
      [ -e "$f" ] || continue
      local binary=$tree/tests/fuzz/fuzz_$target
      [ "$target" = command_line ] && binary=$cli_tree/tests/fuzz/fuzz_command_line
      [ -x "$binary" ] || continue
      "$binary" -runs=1 "$f" >/dev/null 2>&1 || { echo "FAIL $target $f" >&2; code=1; }
    done
  done
  return $code
}

case "${1:-}" in
  build) build "${2:-}" ;;
  run) run "$2" "$3" "$4" ;;
  all)
    status=0
    for t in "${targets[@]}"; do run "$t" "$2" "$3" || status=1; done
    exit $status
    ;;
  regressions) regressions ;;
  targets) printf '%s\n' "${targets[@]}" ;;
  *) sed -n '2,12p' "$0" >&2; exit 2 ;;
esac
