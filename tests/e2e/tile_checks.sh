#!/usr/bin/env bash
# tile_checks.sh PROBEPROXY SUITE WORK
# `layout --tile-size` judges the capture points a tile of the floor at a time, each tile's
# candidates packed and read back as from another process (candidate_wire.h): on a level of two
# storeys and a hall with pillars, 4 m tiles give the untiled layout, every file the same bytes
# and layout.json the same figures but for its timings and the tiles' own counts.
set -eu
probeproxy=$1 suite=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
for level in u_corridors hall_pillars; do
  for tile in 0 4; do
    "$probeproxy" layout "$suite/$level/$level.scene.json" --out "$work/${level}_$tile" \
      --tile-size $tile --json >/dev/null
  done
  [ "$(ls "$work/${level}_0")" = "$(ls "$work/${level}_4")" ] || fail "$level: other files in tiles"
  for f in $(ls "$work/${level}_0"); do
    [ "$f" = layout.json ] && continue
    cmp -s "$work/${level}_0/$f" "$work/${level}_4/$f" || fail "$level: $f differs in tiles"
  done
  python3 - "$work/${level}_0/layout.json" "$work/${level}_4/layout.json" <<'PY' || fail "$level: layout.json"
import json, sys
whole, tiled = (json.load(open(f)) for f in sys.argv[1:])
assert "candidate_tiles" not in whole
assert tiled.pop("candidate_tiles") > 1 and tiled.pop("candidate_wire_bytes") > 0
def figures(d):
    if isinstance(d, dict):
        return {k: figures(v) for k, v in d.items() if not k.endswith(("seconds", "_ms"))}
    return [figures(x) for x in d] if isinstance(d, list) else d
assert figures(whole) == figures(tiled), "figures differ"
PY
done
echo "tile checks passed"
