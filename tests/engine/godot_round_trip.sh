#!/usr/bin/env bash
# The Godot round trip: `probeproxy build --out` exports a level, Debian's Godot 3
# (godot3-server, headless) runs the shipped importer (plugin/engines/godot/) to make
# ReflectionProbe nodes and save them as a binary scene (.scn: Godot 3's 32-bit floats, bit for
# bit), then loads that scene back in a second Godot process and checks every probe against
# proxies.json. The same probes saved as text (.tscn, where Godot 3 writes about six significant
# digits) with one extent grown by 1 m must fail the check, naming the extent. Prints the wall
# time.
#   godot_round_trip.sh PROBEPROXY SCENE_JSON|PROXIES_JSON OUT_DIR IMPORTER_DIR
# (a file named *proxies.json is imported as it is, without a build)
set -euo pipefail
probeproxy=$1 scene=$2 out=$3 importer=$4
godot=$(command -v godot3-server || true)
if [ -z "$godot" ]; then
  echo "godot3-server not found: scripts/setup.sh installs it" >&2
  exit 1
fi
start=$EPOCHREALTIME
rm -rf "$out" && mkdir -p "$out"
mkdir -p "$out/export"
case "$scene" in
  *proxies.json) cp "$scene" "$out/export/proxies.json" ;;
  *) "$probeproxy" build "$scene" --out "$out/export" > /dev/null ;;
esac
run() { "$godot" --no-window --path "$out" -s "$@" 2>&1 | grep -v "locale\|At: core/translation"; }
run "$importer/import_to_scene.gd" --args "$out/export/proxies.json" "$out/probes.scn" | tee "$out/import.log"
# Godot 3's default reflection atlas draws 16 probes: the importer says so past 16, and only then.
probes=$(grep -o "[0-9]* ReflectionProbe nodes" "$out/import.log" | cut -d' ' -f1)
if [ "$probes" -gt 16 ]; then
  grep -q "probeproxy: $probes probes, but Godot 3 draws only 16 .*: set it to " "$out/import.log"
elif grep -q "atlas_subdiv" "$out/import.log"; then
  echo "the importer warned of the atlas with $probes probes" >&2
  exit 1
fi
run "$importer/check_scene.gd" --args "$out/export/proxies.json" "$out/probes.scn" | tee "$out/check.log"
grep -q "probes, 0 mismatches" "$out/check.log"
# The check can fail: the first probe's extents grown by 1 m.
run "$importer/import_to_scene.gd" --args "$out/export/proxies.json" "$out/probes.tscn" > /dev/null
grep -q 'type="ReflectionProbe"' "$out/probes.tscn"
python3 - "$out/probes.tscn" "$out/tampered.tscn" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
def grow(m):
    x, y, z = (float(v) for v in m.group(1).split(","))
    return "extents = Vector3( %r, %r, %r )" % (x + 1.0, y, z)
open(sys.argv[2], "w").write(re.sub(r"extents = Vector3\(([^)]*)\)", grow, text, count=1))
PY
if run "$importer/check_scene.gd" --args "$out/export/proxies.json" "$out/tampered.tscn" > "$out/tampered.log"; then
  echo "the check passed a scene with a changed extent" >&2
  exit 1
fi
grep -q "MISMATCH .*extents" "$out/tampered.log"
end=$EPOCHREALTIME
awk -v s="$start" -v e="$end" -v n="$(basename "$scene")" 'BEGIN { printf "godot round trip %s: wall %.2f s\n", n, e - s }'
