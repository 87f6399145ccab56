#!/usr/bin/python3
"""The per-engine table of docs/engines.md, measured: per level, `probeproxy layout` and a grid
baseline with the same number of probes (`--baseline grid --max-probes N`, aabb proxies), each
written scene surveyed under every engine model (`probeproxy survey --engine E --proxies
DIR/proxies.json`): what each engine renders from the presets the layout exports. Prints one
Markdown table per engine: p95, floor over 5 deg and uncovered floor (the share of the
reflection the engine leaves to its sky / ambient fallback) for the layout and the grid.

  /usr/bin/python3 scripts/engine_table.py build/plugin/cli/probeproxy build/corpus/scenes \
      [--levels downer toxic] [--engines godot3 unreal] [--work DIR]
"""
import argparse
import glob
import json
import os
import subprocess
import tempfile

ENGINES = ("generic", "unity", "unity-hdrp", "unreal", "godot3", "godot4", "bevy", "eevee")


def run_json(*command):
    done = subprocess.run(command, check=True, capture_output=True, text=True)
    return json.loads(done.stdout)


def survey(probeproxy, out, engine):
    report = run_json(probeproxy, "survey", os.path.join(out, "layout.scene.json"), "--engine",
                      engine, "--proxies", os.path.join(out, "proxies.json"), "--json")
    return report["p95_deg"], report["over_tolerance_share"], report["uncovered_share"]


def cell(figures):
    p95, over, uncovered = figures
    p95_text = "—" if p95 is None else "%.1f" % p95
    return "%s | %.1f%% | %.1f%%" % (p95_text, 100 * over, 100 * uncovered)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("probeproxy")
    parser.add_argument("scenes")
    parser.add_argument("--levels", nargs="*", default=[])
    parser.add_argument("--engines", nargs="*", default=list(ENGINES))
    parser.add_argument("--work", help="keep every run's output here")
    args = parser.parse_args()

    scenes = sorted(glob.glob(os.path.join(args.scenes, "*", "*.scene.json")))
    if args.levels:
        scenes = [s for s in scenes if os.path.basename(os.path.dirname(s)) in args.levels]
    rows = {engine: [] for engine in args.engines}
    with tempfile.TemporaryDirectory() as scratch:
        work = args.work or scratch
        os.makedirs(work, exist_ok=True)
        for scene in scenes:
            level = os.path.basename(os.path.dirname(scene))
            layout_out = os.path.join(work, level + "_layout")
            grid_out = os.path.join(work, level + "_grid")
            layout = run_json(args.probeproxy, "layout", scene, "--out", layout_out, "--json")
            run_json(args.probeproxy, "layout", scene, "--out", grid_out, "--json",
                     "--baseline", "grid", "--max-probes", str(layout["probes"]))
            for engine in args.engines:
                row = "| %s | %s | %s |" % (level, cell(survey(args.probeproxy, layout_out, engine)),
                                            cell(survey(args.probeproxy, grid_out, engine)))
                rows[engine].append(row)
                print(engine, row, flush=True)
    for engine in args.engines:
        print("\n**%s**\n" % engine)
        print("| level | layout p95 | layout over 5 deg | layout uncovered | grid p95 "
              "| grid over 5 deg | grid uncovered |")
        print("|---|---|---|---|---|---|---|")
        for row in rows[engine]:
            print(row)


if __name__ == "__main__":
    main()
