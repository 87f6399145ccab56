#!/usr/bin/env bash
# keep_authored_checks.sh PROBEPROXY SUITE_DIR WORK
# `layout --keep-authored`: the artist's probes stay exactly as authored and only what
# fails gets new probes. The L-room's artist scene (each arm's bounding box as its proxy) fails
# at the corner where the arms meet: probes are added there, and the survey of the result has
# less floor over the tolerance and a lower p95 than the artist's scene alone. On the L-room's
# clean scene, which serves nearly all its floor, the result is never worse than the scene
# alone (an added probe that does not help is dropped). A scene without probes, or a baseline,
# is refused with one line.
set -eu
probeproxy=$1 suite=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

"$probeproxy" layout "$suite/l_room/l_room.artist.scene.json" --keep-authored \
  --out "$work/artist" >/dev/null 2>&1
"$probeproxy" survey "$suite/l_room/l_room.artist.scene.json" --tolerance-deg 5 --json \
  >"$work/artist_alone.json" 2>/dev/null
"$probeproxy" layout "$suite/l_room/l_room.scene.json" --keep-authored --out "$work/clean" \
  >/dev/null 2>&1
"$probeproxy" survey "$suite/l_room/l_room.scene.json" --tolerance-deg 5 --json \
  >"$work/clean_alone.json" 2>/dev/null
# Round the hall's pillars the cover proposes probes that, built and blended, do not help: they
# are dropped, and so are their proxy meshes. Those kept take the floor under the artist's
# volumes (which start 0.5 m up): the hall's p95 comes under the tolerance (15.6 deg alone;
# 7.4 when a cut in plan instead of under the artist's volumes left most floor in bands). The
# added probes' candidates are captured at the artist's height, 1.6 m, with no --capture-height
# named (at 0.6 m, named, they leave the hall at 9.0 deg).
"$probeproxy" layout "$suite/hall_pillars/hall_pillars.scene.json" --keep-authored \
  --out "$work/hall" >/dev/null 2>&1
"$probeproxy" layout "$suite/hall_pillars/hall_pillars.scene.json" --keep-authored \
  --capture-height 0.6 --out "$work/hall_low" >/dev/null 2>&1
"$probeproxy" survey "$suite/hall_pillars/hall_pillars.scene.json" --tolerance-deg 5 --json \
  >"$work/hall_alone.json" 2>/dev/null
python3 - "$suite/l_room" "$work" <<'PY' || fail "keep-authored figures"
import json, os, sys
suite, work = sys.argv[1], sys.argv[2]

def kept_as_authored(authored_file, layout_dir):
    authored = json.load(open(authored_file))["probes"]
    written = json.load(open(os.path.join(layout_dir, "layout.scene.json")))["probes"]
    for a, w in zip(authored, written):
        for key in ("name", "capture", "influence", "proxy"):
            assert a.get(key) == w.get(key), (a["name"], key, a.get(key), w.get(key))
        # The cubemaps are the same files, reached from the layout's folder.
        if "cubemap" in a:
            here = os.path.normpath(os.path.join(os.path.dirname(authored_file), a["cubemap"]))
            there = os.path.normpath(os.path.join(layout_dir, w["cubemap"]))
            assert here == there, (here, there)
    return authored, written

authored, written = kept_as_authored(os.path.join(suite, "l_room.artist.scene.json"),
                                     os.path.join(work, "artist"))
report = json.load(open(os.path.join(work, "artist", "layout.json")))
assert report["kept_probes"] == len(authored) == 3, report
assert report["added_probes"] >= 1 and len(written) == 3 + report["added_probes"], report
names = [p["name"] for p in written]
assert len(set(names)) == len(names), names
alone = json.load(open(os.path.join(work, "artist_alone.json")))
after = report["survey"]
assert after["over_tolerance_share"] < alone["over_tolerance_share"] - 0.01, (after, alone)
assert after["p95_deg"] < alone["p95_deg"], (after, alone)
assert after["uncovered_share"] == 0.0, after

authored, written = kept_as_authored(os.path.join(suite, "l_room.scene.json"),
                                     os.path.join(work, "clean"))
clean = json.load(open(os.path.join(work, "clean", "layout.json")))
clean_alone = json.load(open(os.path.join(work, "clean_alone.json")))
assert len(written) == len(authored) + clean["added_probes"], clean
assert clean["survey"]["over_tolerance_share"] <= clean_alone["over_tolerance_share"], clean
assert clean["survey"]["uncovered_share"] == 0.0, clean
if clean["added_probes"] > 0:
    assert clean["survey"]["over_tolerance_share"] < clean_alone["over_tolerance_share"], clean

hall = json.load(open(os.path.join(work, "hall", "layout.json")))
hall_alone = json.load(open(os.path.join(work, "hall_alone.json")))
assert hall["survey"]["over_tolerance_share"] <= hall_alone["over_tolerance_share"], hall
assert hall["survey"]["p95_deg"] <= 5.0, hall
# A height named is the height taken: candidates at 0.6 m, beside the artist's probes at 1.6 m,
# choose other ranges there, which leave the hall's p95 over the tolerance (9.0 deg).
low = json.load(open(os.path.join(work, "hall_low", "layout.json")))["survey"]
assert low["p95_deg"] > 5.0 > hall["survey"]["p95_deg"], (low, hall["survey"])

# Every proxy mesh written belongs to a probe of the scene written.
for run in ("artist", "clean", "hall"):
    folder = os.path.join(work, run)
    meshes = {p["proxy"]["mesh"] for p in json.load(open(os.path.join(folder, "layout.scene.json")))["probes"]
              if isinstance(p["proxy"], dict) and p["proxy"].get("kind") == "convex"}
    plys = {f for f in os.listdir(folder) if f.endswith(".ply")}
    assert plys == meshes, (run, plys, meshes)
PY

expect_error() {  # expected line, then the command's arguments
  local want=$1; shift
  if "$probeproxy" "$@" >"$work/out.txt" 2>"$work/err.txt"; then fail "accepted: $*"; fi
  grep -qF "$want" "$work/err.txt" || fail "for '$*' expected '$want', got: $(cat "$work/err.txt")"
  [ ! -e "$work/refused" ] || fail "a refused layout wrote its folder"
}
python3 - "$suite/l_room/l_room.scene.json" "$work/no_probes.scene.json" <<'PY'
import json, os, sys
scene = json.load(open(sys.argv[1]))
scene["probes"] = []
scene["level"] = [{"mesh": os.path.join(os.path.dirname(os.path.abspath(sys.argv[1])), "l_room.glb")}]
json.dump(scene, open(sys.argv[2], "w"))
PY
expect_error "no_probes.scene.json: --keep-authored: the scene has no probes to keep" \
  layout "$work/no_probes.scene.json" --keep-authored --out "$work/refused"
expect_error "option keep_authored: adds probes to the scene's own; it does not go with a baseline" \
  layout "$suite/l_room/l_room.scene.json" --keep-authored --baseline grid --out "$work/refused"
echo "keep-authored checks passed"
