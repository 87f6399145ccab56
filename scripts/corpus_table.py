#!/usr/bin/python3
"""The corpus tables of docs/cli_and_formats.md, measured: per real map (scripts/corpus/), what it holds
(triangles, load time, walkable floor, spawn points) and what a player sees across its walkable
floor (`probeproxy survey`) with the spawn probes looked up three ways: through the build's
`aabb` candidate (what box projection gives an engine user), through the kept proxies, and with
no correction. Prints two Markdown tables (--table maps or survey: one of them, as the docs'
generated blocks take them; maps surveys only through the kept proxies, for the floor area);
with --maps DIR also writes the error maps of the maps named by --pictures into DIR (aabb and
kept only).

  /usr/bin/python3 scripts/corpus_table.py build/plugin/cli/probeproxy build/corpus/scenes \
      [--table maps|survey] [--maps scripts/charts/corpus --pictures downer toxic skyway]
"""
import argparse
import glob
import json
import os
import shutil
import subprocess
import tempfile

ROWS = [("aabb", "aabb candidate (box projection)"), ("scene", "kept proxies"),
        ("infinite", "no correction")]


def run_json(command):
    done = subprocess.run(command, check=True, capture_output=True, text=True)
    return json.loads(done.stdout)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("probeproxy")
    parser.add_argument("scenes")
    parser.add_argument("--maps")
    parser.add_argument("--pictures", nargs="*", default=[])
    parser.add_argument("--tolerance-deg", default="5")
    parser.add_argument("--table", choices=["maps", "survey", "both"], default="both")
    args = parser.parse_args()
    rows_wanted = [r for r in ROWS if args.table != "maps" or r[0] == "scene"]

    scenes = sorted(glob.glob(os.path.join(args.scenes, "*", "*.scene.json")))
    holds, seen = [], []
    for scene_file in scenes:
        name = os.path.basename(scene_file)[: -len(".scene.json")]
        scene = json.load(open(scene_file))
        level = scene["level"][0]
        pk3 = os.path.normpath(os.path.join(os.path.dirname(scene_file), level["mesh"]))
        info = run_json([args.probeproxy, "level-info", pk3, "--map", level["map"]])
        rows = {}
        for proxy, _ in rows_wanted:
            pictures = args.maps and name in args.pictures and proxy != "infinite"
            with tempfile.TemporaryDirectory() as out:
                # Without --out the survey draws no error map: only the figures are wanted.
                rows[proxy] = run_json([args.probeproxy, "survey", scene_file, "--json",
                                        "--proxy", proxy, "--tolerance-deg", args.tolerance_deg]
                                       + (["--out", out] if pictures else []))
                if pictures:
                    for png in sorted(glob.glob(os.path.join(out, "*.png"))):
                        target = os.path.join(args.maps, "corpus_%s_%s_%s" % (
                            name, proxy if proxy != "scene" else "kept",
                            os.path.basename(png).split("_survey_")[-1]))
                        shutil.copyfile(png, target)
        holds.append((name, info, rows["scene"]))
        seen.append((name, rows))

    if args.table != "survey":
        print("| map | triangles | sky triangles | load ms | walkable m^2 | spawn points |")
        print("|---|---|---|---|---|---|")
        for name, info, survey in holds:
            print("| %s | %d | %d | %.1f | %.0f | %d |" % (
                name, info["triangles"], info["sky_triangles"], info["load_ms"],
                survey["walkable_m2"], len(info["spawn_points"])))
    if args.table == "maps":
        return
    if args.table == "both":
        print()
    print("| map | probes | proxies | p95 deg | floor over %s deg | uncovered | occluded | s |"
          % args.tolerance_deg)
    print("|---|---|---|---|---|---|---|---|")
    for name, rows in seen:
        for proxy, label in ROWS:
            r = rows[proxy]
            p95 = "-" if r["p95_deg"] is None else "%.1f" % r["p95_deg"]
            print("| %s | %d | %s | %s | %.1f%% | %.1f%% | %.1f%% | %.1f |" % (
                name, r["probes"], label, p95, 100 * r["over_tolerance_share"],
                100 * r["uncovered_share"], 100 * r["occluded_share"], r["seconds"]))


if __name__ == "__main__":
    main()
