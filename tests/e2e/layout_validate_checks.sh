#!/usr/bin/env bash
# layout_validate_checks.sh PROBEPROXY SCENE WORK
# What a layout writes is what it measured ("what we export must be what we measured"): every
# probe of its scene names the proxy the layout measured (none is left `auto` for `build` to
# make again: a scene file holds no cheap_k), and `survey` on that scene gives the figures of the
# layout's own survey, on the floor and player its measured_with records. On basement, an
# earlier layout wrote three probes as `auto` and its scene surveyed at 23.769 deg p95 and
# 21.32% over 5 deg, where layout.json said 23.765 and 21.45%.
#
# And a layout passes validate ("every layout validates clean"): every rule but those
# that measure a proxy's accuracy probe by probe (proxy_error_over_tolerance and split_probe
# build every probe's proxy again, tens of minutes on a corpus map; the layout keeps its proxies
# by the proxy rule's own test, layout_proxy.h, and layout_checks.sh runs them on the suite), the
# mesh and capture checks included. On downer, an earlier layout had a blend weight that
# turned at 0.021 per cm (weight_jump) and, with the proxy choice before its float
# merge, a proxy mesh with an edge bent inwards by 1.2 deg (proxy_concave_edge).
# Laid out for the player the layout's volume steps were tuned with (0.45 m step, 1.8 m head
# room, eyes at 1.7 m), not the BSP's Quake 3 player: there downer has a 0.3 m strip beside a
# stair it does not see (a band pulled in past its own width clears it) and a crowd of five
# bands two fills left (each dropped in turn). One finding is left and listed here until the
# fades clear it (docs/layout.md, "Known limits"): probe_113's weight turns at 0.024 per cm
# where two bands' far ends meet, and the widening that ends it turns a cell beside it from
# 0.0181 to 0.0182 per cm, which the fade step refuses. Any other finding fails.
set -eu
probeproxy=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$probeproxy" layout "$scene" --out "$work/layout" --json \
  --step-height 0.45 --head-clearance 1.8 --eye-height 1.7 >/dev/null
"$probeproxy" validate "$work/layout/layout.scene.json" --tolerance-deg 5 \
  --rules capture_outside_level,influence_leak,reflected_camera_outside_proxy,too_many_overlaps,inner_ranges_overlap,weight_jump,floor_not_covered \
  --json >"$work/validate.json" || true  # exit 1 on findings: listed below
python3 - "$work/validate.json" <<'PY'
import json, sys
findings = json.load(open(sys.argv[1]))["findings"]
found = {(f["rule"], f["probe"]) for f in findings}
assert found <= {("weight_jump", "probe_113")}, [
    "%s %s: %s" % (f["rule"], f["probe"], f["message"]) for f in findings
    if (f["rule"], f["probe"]) != ("weight_jump", "probe_113")]
PY
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
echo "layout scene and validate checks passed"
