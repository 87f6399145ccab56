#!/usr/bin/env bash
# split_probe_checks.sh PROBEPROXY SUITE_DIR WORK
# validate's split_probe finding. One probe in the L-room's corner serves the whole L
# with the box of the x arm as its proxy: the y arm's reflections miss it, and no single convex
# proxy serves both arms from the corner. A second probe in the y arm, with the y arm's box,
# serves that arm exactly: the finding must name a point in the y arm and a p95 within the
# tolerance, far below the probe's own. The suite's clean L-room scene gets no such finding.
set -eu
probeproxy=$1 suite=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

python3 - "$suite/l_room" "$work/one_probe.scene.json" <<'PY'
import json, os, sys
folder, out = sys.argv[1], sys.argv[2]
scene = json.load(open(os.path.join(folder, "l_room.scene.json")))
scene["level"] = [{"mesh": os.path.abspath(os.path.join(folder, "l_room.glb"))}]
scene["probes"] = [{
    "name": "whole_l", "capture": [2.0, 2.0, 1.6],
    "influence": {"kind": "box", "center": [5.0, 5.0, 1.5], "half_extents": [5.0, 5.0, 1.5],
                  "rotation": [1.0, 0.0, 0.0, 0.0], "inner_half_extents": [4.0, 4.0, 1.5]},
    "proxy": {"kind": "box", "center": [5.0, 2.0, 1.5], "half_extents": [5.0, 2.0, 1.5]}}]
json.dump(scene, open(out, "w"), indent=1)
PY
"$probeproxy" validate "$work/one_probe.scene.json" --tolerance-deg 5 --json \
  >"$work/one_probe.json" 2>/dev/null || true
"$probeproxy" validate "$suite/l_room/l_room.scene.json" --tolerance-deg 5 --json \
  >"$work/clean.json" 2>/dev/null || true
python3 - "$work" <<'PY' || fail "split_probe"
import json, os, re, sys
work = sys.argv[1]
findings = json.load(open(os.path.join(work, "one_probe.json")))["findings"]
own = [f for f in findings if f["rule"] == "proxy_error_over_tolerance"]
split = [f for f in findings if f["rule"] == "split_probe"]
assert len(own) == 1 and len(split) == 1, findings
assert split[0]["value"] <= 5.0 and split[0]["value"] < 0.1 * own[0]["value"], (own, split)
x, y, z = map(float, re.search(r"at \(([-\d.]+), ([-\d.]+), ([-\d.]+)\)", split[0]["hint"]).groups())
assert 0.0 < x < 4.0 and 4.0 < y < 10.0 and 0.0 < z < 3.0, (x, y, z)
assert "from %.2f to" % own[0]["value"] in split[0]["message"], split[0]["message"]
clean = json.load(open(os.path.join(work, "clean.json")))["findings"]
assert not [f for f in clean if f["rule"] == "split_probe"], clean
PY
# --rules without split_probe: the same proxy error, and no search for a second probe.
"$probeproxy" validate "$work/one_probe.scene.json" --tolerance-deg 5 --json \
  --rules proxy_error_over_tolerance >"$work/no_split.json" 2>/dev/null || true
python3 - "$work" <<'PY' || fail "split_probe left out by --rules"
import json, os, sys
rules = [f["rule"] for f in json.load(open(os.path.join(sys.argv[1], "no_split.json")))["findings"]]
assert rules == ["proxy_error_over_tolerance"], rules
PY
echo "split_probe checks passed"
