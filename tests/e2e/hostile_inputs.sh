#!/usr/bin/env bash
# hostile_inputs.sh PROBEPROXY HOSTILE_DIR WORK
# Every verb over every hostile scene of tests/e2e/hostile/: each run must end in
# exit 0 (valid input) or exit 2 with exactly one line on stderr and no output folder left
# behind; exit 3 (an internal error), a crash or a hang (timeout 60 s) fails the test.
set -u
probeproxy=$1 hostile=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail=0
run() {  # name, out folder, arguments...
  local name=$1 out=$2
  shift 2
  rm -rf "$out"
  timeout 60 "$probeproxy" "$@" >"$work/stdout" 2>"$work/stderr"
  local code=$?
  local lines
  lines=$(wc -l <"$work/stderr")
  if [ "$code" -eq 2 ]; then
    if [ "$lines" -ne 1 ] || [ -e "$out" ]; then
      echo "FAIL $name: exit 2 with $lines stderr lines$( [ -e "$out" ] && echo ', output left behind')"
      fail=1
    fi
  elif [ "$code" -ne 0 ] && [ "$code" -ne 1 ]; then
    echo "FAIL $name: exit $code: $(head -c 300 "$work/stderr")"
    fail=1
  fi
  echo "$code $name: $(head -n 1 "$work/stderr")"
}
for scene in "$hostile"/*.scene.json; do
  n=$(basename "$scene" .scene.json)
  run "build $n" "$work/build_$n" build "$scene" --out "$work/build_$n" --face-size 16 --samples 64
  run "export $n" "$work/export_$n" export "$scene" --out "$work/export_$n" --face-size 16 --samples 64
  run "validate $n" "$work/none" validate "$scene" --samples 64
  run "survey $n" "$work/survey_$n" survey "$scene" --out "$work/survey_$n" --grid 0.5
  run "bench $n" "$work/bench_$n" bench "$scene" --out "$work/bench_$n" --no-instructions \
    --repetitions 1 --samples 64
  run "blend $n" "$work/blend_$n" blend "$scene" --at 0,0,1.6 --weights-png "$work/blend_$n/w.png"
  run "correct $n" "$work/correct_$n" correct "$scene" --probe p --camera 1,1,1.7 \
    --out "$work/correct_$n/c_{face}.exr"
done
# Output folders that cannot be made, for every verb that writes one; a path holding a newline.
room="$hostile/room.scene.json"
run "build unwritable" /proc/x build "$room" --out /proc/x
run "survey unwritable" /proc/x survey "$room" --out /proc/x
run "bench unwritable" /proc/x bench "$room" --out /proc/x --no-instructions
run "correct unwritable" /proc/x correct "$room" --probe p --camera 1,1,1.7 --out '/proc/x/c_{face}.exr'
run "blend unwritable" /proc/x blend "$room" --at 0,0,1.6 --weights-png /proc/x/w.png
run "demo unwritable" /proc/x demo --out /proc/x --no-bench
newline="$work/$(printf 'a\nb').scene.json"
run "build newline path" "$work/newline" build "$newline" --out "$work/newline"
exit $fail
