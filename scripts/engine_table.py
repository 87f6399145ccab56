#!/usr/bin/python3
"""The per-engine tables of docs/engines.md, measured. Per level, three runs:
  - `probeproxy layout` (no engine): the generic layout, its proxies.json the presets `build`
    would write; each engine's figures from `survey --engine E --proxies` on it (what a studio
    imports today);
  - `probeproxy layout --engine all`: the same probes, each engine's presets chosen for it:
    its policy, and per probe one of the boxes its build fitted, or none (layout.json
    "engines");
  - `probeproxy layout --baseline grid --max-probes N --engine all`: a grid of box-projected
    probes with the layout's count, each engine's presets chosen the same way.
Prints one Markdown table per engine: floor over 5 deg, occluded floor (shown by probes that
cannot see what it reflects), uncovered floor (left to the engine's sky / ambient fallback) and
p95 for the three, and the layout-to-grid ratios of the floor over 5 deg and of the floor not
right (the three shares together, what the engine choice minimises). With --jsonl FILE each level's figures are also appended there as they come.

  /usr/bin/python3 scripts/engine_table.py build/plugin/cli/probeproxy build/corpus/scenes \
      [--levels downer toxic] [--engines unity godot3] [--work DIR] [--jsonl FILE]
"""
import argparse
import glob
import json
import os
import subprocess
import tempfile

ENGINES = ("unity", "unity-hdrp", "unreal", "godot3", "godot4", "bevy", "eevee")


def run_json(*command):
    done = subprocess.run(command, check=True, capture_output=True, text=True)
    return json.loads(done.stdout)


def figures(survey):
    return {"p95": survey["p95_deg"], "over": survey["over_tolerance_share"],
            "occluded": survey["occluded_share"], "uncovered": survey["uncovered_share"],
            "probes": survey["probes"]}


def not_right(f):
    return f["over"] + f["occluded"] + f["uncovered"]


def level_figures(probeproxy, scene, work, engines):
    plain, engine, grid = (os.path.join(work, kind) for kind in ("plain", "engine", "grid"))
    layout = run_json(probeproxy, "layout", scene, "--out", plain, "--json")
    names = ",".join(engines)
    tuned = run_json(probeproxy, "layout", scene, "--out", engine, "--json", "--engine", names)
    baseline = run_json(probeproxy, "layout", scene, "--out", grid, "--json", "--baseline",
                        "grid", "--max-probes", str(layout["probes"]), "--engine", names)
    out = {"probes": layout["probes"], "grid_probes": baseline["probes"],
           "generic": figures(layout["survey"]), "engines": {}}
    for engine in engines:
        today = run_json(probeproxy, "survey", os.path.join(plain, "layout.scene.json"),
                         "--engine", engine, "--proxies", os.path.join(plain, "proxies.json"),
                         "--json")
        out["engines"][engine] = {
            "today": figures(today),
            "layout": figures(tuned["engines"][engine]["survey"]),
            "grid": figures(baseline["engines"][engine]["survey"]),
            "policy": {k: tuned["engines"][engine][k]
                       for k in ("clip_to_influence", "fade_scale", "clear_the_floor",
                                 "cube_about_capture", "influence_inside")},
            "left_out": len(tuned["engines"][engine]["left_out"]),
            "other_box": len(tuned["engines"][engine]["other_box"]),
            "raised": len(tuned["engines"][engine].get("priority", {}))}
    return out


def cell(f):
    p95 = "—" if f["p95"] is None else "%.1f" % f["p95"]
    return "%.1f%% / %.1f%% / %.1f%% / %s" % (100 * f["over"], 100 * f["occluded"],
                                              100 * f["uncovered"], p95)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("probeproxy")
    parser.add_argument("scenes")
    parser.add_argument("--levels", nargs="*", default=[])
    parser.add_argument("--work", help="keep every run's output here")
    parser.add_argument("--jsonl", help="append each level's figures to this file")
    parser.add_argument("--engines", nargs="*", default=list(ENGINES))
    args = parser.parse_args()

    scenes = sorted(glob.glob(os.path.join(args.scenes, "*", "*.scene.json")))
    if args.levels:
        scenes = [s for s in scenes if os.path.basename(os.path.dirname(s)) in args.levels]
    results = {}
    with tempfile.TemporaryDirectory() as scratch:
        for scene in scenes:
            level = os.path.basename(os.path.dirname(scene))
            work = os.path.join(args.work or scratch, level)
            results[level] = level_figures(args.probeproxy, scene, work, args.engines)
            if args.jsonl:
                with open(args.jsonl, "a") as f:
                    f.write(json.dumps({"level": level, **results[level]}) + "\n")
    for engine in args.engines:
        print("\n**%s** (floor over 5 deg / occluded / uncovered / p95 deg)\n" % engine)
        print("| level | generic layout's presets | layout for %s | same-count grid for %s "
              "| probes: layout for %s (left out, other box) / grid | over 5 deg, layout / grid "
              "| not right, layout / grid |" % (engine, engine, engine))
        print("|---|---|---|---|---|---|---|")
        for level, r in results.items():
            e = r["engines"][engine]
            ratio = e["layout"]["over"] / e["grid"]["over"] if e["grid"]["over"] > 0 else float("nan")
            probes = "%d (%d, %d%s) / %d" % (
                e["layout"]["probes"], e["left_out"], e["other_box"],
                ", %d raised" % e["raised"] if e["raised"] else "", e["grid"]["probes"])
            wrong = not_right(e["layout"]) / not_right(e["grid"]) if not_right(e["grid"]) > 0 \
                else float("nan")
            print("| %s | %s | %s | %s | %s | %.2f | %.2f |" % (
                level, cell(e["today"]), cell(e["layout"]), cell(e["grid"]), probes, ratio, wrong))


if __name__ == "__main__":
    main()
