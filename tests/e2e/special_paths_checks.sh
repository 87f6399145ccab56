#!/usr/bin/env bash
# special_paths_checks.sh PROBEPROXY EXPECT_FAILURE SCENE WORK
# Paths that are not regular files where probeproxy reads or writes one, and option values at
# the edge of what a double holds, on a suite scene (SCENE, whose first probe has a cubemap):
#  - a FIFO as the scene file of every verb, as --proxies, as an OBJ's material library and as
#    a .gltf's buffer file; /dev/zero as --proxies: one line, exit 2, never a hang;
#  - a folder where build's proxies.json, a corrected face or blend's weights picture goes:
#    refused before any file is written;
#  - a --plane normal of 1e-320 or 1e308 is a direction: the same faces as the unit normal;
#  - the layout baselines print no "nan".
set -u
probeproxy=$1 expect_failure=$2 scene=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
fail=0
probe=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['probes'][0]['name'])" "$scene")
expect() {  # name, pattern, arguments...
  local name=$1 pattern=$2
  shift 2
  if ! timeout 60 "$expect_failure" 2 "$pattern" "$work/none" -- "$probeproxy" "$@" >"$work/$name.log"; then
    echo "FAIL $name:"; cat "$work/$name.log"; fail=1
  else
    echo "ok   $name: $(grep -A1 -- '--- stderr:' "$work/$name.log" | tail -n 1)"
  fi
}

fifo="$work/fifo.scene.json"
mkfifo "$fifo"
is_fifo="^probeproxy: error: .*fifo\.scene\.json: JSON file is a FIFO, not a regular file$"
expect build_fifo_scene "$is_fifo" build "$fifo" --out "$work/none"
expect export_fifo_scene "$is_fifo" export "$fifo" --out "$work/none"
expect validate_fifo_scene "$is_fifo" validate "$fifo"
expect survey_fifo_scene "$is_fifo" survey "$fifo" --out "$work/none"
expect layout_fifo_scene "$is_fifo" layout "$fifo" --out "$work/none"
expect bench_fifo_scene "$is_fifo" bench "$fifo" --out "$work/none" --no-instructions
expect blend_fifo_scene "$is_fifo" blend "$fifo" --at 0,0,1.6 --weights-png "$work/none/w.png"
expect correct_fifo_scene "$is_fifo" correct "$fifo" --probe p --camera 1,1,1.7 --out "$work/none/c_{face}.exr"
expect survey_fifo_proxies "$is_fifo" survey "$scene" --proxies "$fifo" --out "$work/none"
expect survey_device_proxies "^probeproxy: error: /dev/zero: JSON file is a device, not a regular file$" \
  survey "$scene" --proxies /dev/zero --out "$work/none"

mkdir -p "$work/obj"
printf 'mtllib room.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$work/obj/room.obj"
mkfifo "$work/obj/room.mtl"
cat >"$work/obj/room.scene.json" <<'EOF'
{"probeproxy_scene": 1, "up": "Z", "level": ["room.obj"], "probes": [{"name": "p",
 "capture": [0.2, 0.2, 1], "influence": {"kind": "sphere", "center": [0, 0, 0], "radius": 10},
 "proxy": "auto"}]}
EOF
expect obj_fifo_material_library \
  "^probeproxy: error: .*obj/room\.mtl: OBJ material library is a FIFO, not a regular file$" \
  validate "$work/obj/room.scene.json"
mkdir -p "$work/gltf"
cat >"$work/gltf/room.gltf" <<'EOF'
{"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}], "meshes": [{"primitives":
 [{"attributes": {"POSITION": 0}}]}], "buffers": [{"byteLength": 36, "uri": "room.bin"}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}], "accessors": [{"bufferView": 0,
 "componentType": 5126, "count": 3, "type": "VEC3"}]}
EOF
mkfifo "$work/gltf/room.bin"
sed 's/room\.obj/room.gltf/' "$work/obj/room.scene.json" >"$work/gltf/room.scene.json"
expect gltf_fifo_buffer \
  "^probeproxy: error: .*gltf/room\.gltf: malformed mesh: glTF buffer 0 file 'room\.bin' is not a regular file$" \
  validate "$work/gltf/room.scene.json"

# Folders where a file goes: nothing written, not even the files before it.
mkdir -p "$work/build/proxies.json"
expect build_folder_at_proxies_json \
  "^probeproxy: error: .*build/proxies\.json: exists and is not a file; refusing to overwrite it" \
  build "$scene" --out "$work/build" --face-size 16 --samples 64
mkdir -p "$work/correct/c_nz.exr"
expect correct_folder_at_a_face "^probeproxy: error: .*correct/c_nz\.exr: output is a folder, not a regular file$" \
  correct "$scene" --probe "$probe" --camera 1,0,1.7 --out "$work/correct/c_{face}.exr"
mkdir -p "$work/blend/w.png"
expect blend_folder_at_the_weights_picture "^probeproxy: error: .*blend/w\.png: output is a folder, not a regular file$" \
  blend "$scene" --at 1,0,1.6 --out "$work/blend/b_{face}.exr" --weights-png "$work/blend/w.png"
for folder in build correct blend; do
  left=$(find "$work/$folder" -type f | wc -l)
  [ "$left" -eq 0 ] || { echo "FAIL $folder: $left files written before the refusal"; fail=1; }
done
expect plane_of_a_zero_normal "^probeproxy: error: --plane: the normal NX,NY,NZ is zero, expected a direction$" \
  correct "$scene" --probe "$probe" --camera 1,0,1.7 --plane 0,0,0,0,0,0 --out "$work/none/c_{face}.exr"

# A normal of 1e-320 (subnormal) or 1e308 along z is the unit normal: the same bytes.
for normal in 0,0,1 0,0,1e-320 0,0,1e308; do
  if ! "$probeproxy" correct "$scene" --probe "$probe" --camera 1,0,1.7 --plane "0,0,0,$normal" \
      --out "$work/plane_$normal/c_{face}.exr" >/dev/null 2>"$work/plane.err"; then
    echo "FAIL correct --plane 0,0,0,$normal: $(cat "$work/plane.err")"; fail=1
  fi
done
for normal in 0,0,1e-320 0,0,1e308; do
  for face in px nx py ny pz nz; do
    cmp -s "$work/plane_0,0,1/c_$face.exr" "$work/plane_$normal/c_$face.exr" ||
      { echo "FAIL --plane normal $normal: face $face differs from the unit normal's"; fail=1; }
  done
done

for baseline in grid spawn; do
  out=$("$probeproxy" layout "$scene" --baseline "$baseline" --out "$work/layout_$baseline" 2>&1)
  if [ $? -ne 0 ] || grep -qi "nan" <<<"$out"; then
    echo "FAIL layout --baseline $baseline: $(head -n 2 <<<"$out")"; fail=1
  fi
done
exit $fail
