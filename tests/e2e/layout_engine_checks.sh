#!/usr/bin/env bash
# layout_engine_checks.sh PROBEPROXY SCENE WORK
# A layout made for every engine (`layout --engine all`) exports, per engine, the presets it
# measured: `survey --engine E --proxies proxies.json` on the layout's scene gives layout.json's
# figures for E exactly; of each kind of box the best trial (the least floor over the
# tolerance, left to the fallback or shown by probes that cannot see what it reflects, then the
# lowest p95) is finished with its probes' entries, and the kept policy is the best finished one;
# the same run twice writes the same bytes.
set -eu
probeproxy=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
for run in a b; do
  "$probeproxy" layout "$scene" --engine all --out "$work/$run" --json >/dev/null
done
cmp "$work/a/proxies.json" "$work/b/proxies.json"
cmp "$work/a/layout.scene.json" "$work/b/layout.scene.json"
python3 - "$probeproxy" "$work/a" <<'PY'
import json, math, subprocess, sys
probeproxy, out = sys.argv[1:]
layout = json.load(open(out + "/layout.json"))
engines = layout["engines"]
assert sorted(engines) == sorted(["unity", "unity-hdrp", "unreal", "godot3", "godot4", "bevy",
                                  "eevee"]), sorted(engines)
presets = json.load(open(out + "/proxies.json"))
for name, entry in engines.items():
    measured = entry["survey"]
    assert measured["engine"] == name, measured
    report = subprocess.run([probeproxy, "survey", out + "/layout.scene.json", "--engine", name,
                             "--proxies", out + "/proxies.json", "--json"],
                            check=True, capture_output=True, text=True).stdout
    survey = json.loads(report)
    for key, value in measured.items():
        if key in ("seconds", "scene"):
            continue
        assert survey[key] == value, (name, key, survey[key], value)
    def rank(t):
        p95 = t["p95_deg"] if t["p95_deg"] is not None else math.inf
        return (t["over_tolerance_share"] + t["uncovered_share"] + t["occluded_share"], p95)
    keys = ("clip_to_influence", "fade_scale", "clear_the_floor", "cube_about_capture",
            "influence_inside")
    boxes = ("clip_to_influence", "cube_about_capture", "influence_inside")
    finished = [t for t in entry["tried"] if "finished" in t]
    for t in finished:
        kind = [u for u in entry["tried"] if all(u[k] == t[k] for k in boxes)]
        assert rank(t) == min(map(rank, kind)), (name, t)
    assert len(finished) == len({tuple(t[k] for k in boxes) for t in entry["tried"]}), name
    kept = next(t for t in finished if all(t[k] == entry[k] for k in keys))
    assert rank(kept["finished"]) == min(rank(t["finished"]) for t in finished), name
print("layout engine checks passed:", ", ".join(
    "%s %.1f%%" % (n, 100 * e["survey"]["over_tolerance_share"]) for n, e in engines.items()))
PY
