#!/usr/bin/env bash
# bare_level_checks.sh PROBEPROXY SUITE_DIR WORK
# `layout` on each suite level's bare .glb (no spawn points, no probes) finds the walkable
# floor itself (geometry/floor/floor_seed.h) and lays it out: the floor it surveys is the one
# `survey` walks on the level's scene, seeded from its probes (both storeys of the U, which no
# stair joins). And `survey` of the scene the layout wrote measures that same floor, with the
# seeds and player the layout recorded in it (measured_with): every figure of layout.json's, to
# the last bit.
set -u
probeproxy=$1 suite=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail=0
for level in corridor l_room u_corridors hall_pillars attic round_room courtyard tiny_closet; do
  if ! "$probeproxy" layout "$suite/$level/$level.glb" --out "$work/$level" --json >"$work/$level.json" 2>"$work/$level.err"; then
    echo "FAIL $level: $(tail -n 1 "$work/$level.err")"; fail=1; continue
  fi
  "$probeproxy" survey "$suite/$level/$level.scene.json" --json --out "$work/${level}_scene" >"$work/${level}_scene.json" 2>/dev/null
  "$probeproxy" survey "$work/$level/layout.scene.json" --json >"$work/${level}_again.json" 2>/dev/null
  python3 - "$level" "$work/$level.json" "$work/${level}_scene.json" "$work/${level}_again.json" <<'PY' || fail=1
import json, sys
level, bare, scene, again = sys.argv[1], *(json.load(open(f)) for f in sys.argv[2:5])
differ = [k for k, v in bare["survey"].items() if k != "seconds" and again.get(k) != v]
ok = (bare["seeded_from"] == "the level's floor regions" and bare["probes"] >= 1
      and abs(bare["survey"]["walkable_m2"] - scene["walkable_m2"]) <= 1e-6 and not differ)
print("%s %s: %d probes from %d seed(s), floor %.2f m^2 (the scene's %.2f); survey of the "
      "layout's scene differs in %s" % (
    "ok  " if ok else "FAIL", level, bare["probes"], len(bare["seed_points"]),
    bare["survey"]["walkable_m2"], scene["walkable_m2"], differ or "nothing"))
sys.exit(0 if ok else 1)
PY
done
exit $fail
