#!/usr/bin/env bash
# layout_scene_checks.sh PROBEPROXY SCENE WORK
# What a layout writes is what it measured ("what we export must be what we
# measured"): every probe of its scene names the proxy the layout measured (none is left `auto`
# for `build` to make again: a scene file holds no cheap_k), and `survey` on that scene gives
# the figures of the layout's own survey. On basement, an earlier layout wrote three probes
# as `auto` and its scene surveyed at 23.769 deg p95 and 21.32% over 5 deg, where layout.json
# said 23.765 and 21.45%.
set -eu
probeproxy=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$probeproxy" layout "$scene" --out "$work/layout" --json >/dev/null
"$probeproxy" survey "$work/layout/layout.scene.json" --json >"$work/survey.json"
python3 - "$work/layout/layout.scene.json" "$work/layout/layout.json" "$work/survey.json" <<'PY'
import json, sys
scene, layout, survey = (json.load(open(f)) for f in sys.argv[1:])
auto = [p["name"] for p in scene["probes"] if p["proxy"] == "auto"]
assert not auto, "probes the layout's scene leaves auto: %s" % auto
measured = layout["survey"]
for key in ("walkable_m2", "samples", "probes", "uncovered_share", "occluded_share"):
    assert survey[key] == measured[key], (key, survey[key], measured[key])
# The convex proxies go through a .ply file: the same planes, to rounding.
for key in ("median_deg", "p95_deg", "over_tolerance_share"):
    assert abs(survey[key] - measured[key]) <= 1e-6 * max(1.0, abs(measured[key])), \
        (key, survey[key], measured[key])
PY
echo "layout scene checks passed"
