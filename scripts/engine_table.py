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
right (the three shares together, what the engine choice minimises); then one summary table, an
engine a row and a level a column (floor over 5 deg, layout / grid and their ratio; the floor
not right, layout / grid), with the levels where the layout has at most half the grid's floor
over 5 deg and under 30%; then, with the generic layout measured, what a studio importing it
gets in each engine, a level a row. With --jsonl FILE each level's figures are also appended
there as they come; --from-jsonl FILE prints the tables of such a file without running anything;
--without-generic skips the first run (and the tables' first column); --resume reads each run
whose folder under --work already holds its layout.json instead of running it again.

  /usr/bin/python3 scripts/engine_table.py build/plugin/cli/probeproxy build/corpus/scenes \
      [--levels downer toxic] [--engines unity godot3] [--work DIR] [--jsonl FILE] \
      [--without-generic] [--resume] [--capture-height H]
  /usr/bin/python3 scripts/engine_table.py - - --from-jsonl FILE
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


def run_layout(probeproxy, scene, out, resume, *options):
    """`layout SCENE --out OUT --json OPTIONS`; with resume, the layout.json an earlier run left
    in OUT (the file is what --json prints), so an interrupted table picks up where it stopped."""
    written = os.path.join(out, "layout.json")
    if resume and os.path.exists(written):
        with open(written) as f:
            return json.load(f)
    return run_json(probeproxy, "layout", scene, "--out", out, "--json", *options)


def level_figures(probeproxy, scene, work, engines, generic=True, resume=False, layout_options=()):
    plain, engine, grid = (os.path.join(work, kind) for kind in ("plain", "engine", "grid"))
    names = ",".join(engines)
    tuned = run_layout(probeproxy, scene, engine, resume, "--engine", names, *layout_options)
    baseline = run_layout(probeproxy, scene, grid, resume, "--baseline", "grid", "--max-probes",
                          str(tuned["probes"]), "--engine", names, *layout_options)
    # The same probes as `layout` alone writes them: the engine stage changes only the presets
    # (and with one engine named, its survey is that engine's, so the generic one comes from here).
    layout = run_layout(probeproxy, scene, plain, resume, *layout_options) if generic else None
    out = {"probes": tuned["probes"], "grid_probes": baseline["probes"],
           "generic": layout and figures(layout["survey"]), "engines": {}}
    for engine in engines:
        today = run_json(probeproxy, "survey", os.path.join(plain, "layout.scene.json"),
                         "--engine", engine, "--proxies", os.path.join(plain, "proxies.json"),
                         "--json") if generic else None
        out["engines"][engine] = {
            "today": today and figures(today),
            "layout": figures(tuned["engines"][engine]["survey"]),
            "grid": figures(baseline["engines"][engine]["survey"]),
            "policy": {k: tuned["engines"][engine][k]
                       for k in ("clip_to_influence", "fade_scale", "clear_the_floor",
                                 "cube_about_capture", "influence_inside")},
            "left_out": len(tuned["engines"][engine]["left_out"]),
            "other_box": len(tuned["engines"][engine]["other_box"]),
            "raised": len(tuned["engines"][engine].get("priority", {})),
            "centred": len(tuned["engines"][engine].get("at_box_centre", []))}
    return out


def cell(f):
    if f is None:
        return "not measured"
    p95 = "—" if f["p95"] is None else "%.1f" % f["p95"]
    return "%.1f%% / %.1f%% / %.1f%% / %s" % (100 * f["over"], 100 * f["occluded"],
                                              100 * f["uncovered"], p95)


def ratio(a, b):
    return a / b if b > 0 else float("nan")


def meets_goal(e):
    """At most half the grid's floor over 5 deg, and under 30%."""
    return e["layout"]["over"] <= 0.5 * e["grid"]["over"] and e["layout"]["over"] < 0.3


def print_level_tables(results, engines):
    for engine in engines:
        print("\n**%s** (floor over 5 deg / occluded / uncovered / p95 deg)\n" % engine)
        print("| level | generic layout's presets | layout for %s | same-count grid for %s "
              "| probes: layout for %s (left out, other box) / grid | over 5 deg, layout / grid "
              "| not right, layout / grid |" % (engine, engine, engine))
        print("|---|---|---|---|---|---|---|")
        for level, r in results.items():
            e = r["engines"][engine]
            extra = "".join(", %d %s" % (e.get(k, 0), word)
                            for k, word in (("raised", "raised"), ("centred", "at box centre"))
                            if e.get(k, 0))
            probes = "%d (%d, %d%s) / %d" % (e["layout"]["probes"], e["left_out"],
                                            e["other_box"], extra, e["grid"]["probes"])
            print("| %s | %s | %s | %s | %s | %.2f | %.2f |" % (
                level, cell(e["today"]), cell(e["layout"]), cell(e["grid"]), probes,
                ratio(e["layout"]["over"], e["grid"]["over"]),
                ratio(not_right(e["layout"]), not_right(e["grid"]))))


def print_summary(results, engines):
    """One row per engine, one column per level: floor over 5 deg, layout / grid (ratio); below
    it the floor not right, layout / grid, %; and the levels where the goal holds."""
    levels = list(results)
    print("\n| engine | %s | maps at most half the grid's and under 30%% |" % " | ".join(levels))
    print("|---|%s---|" % ("---|" * len(levels)))
    for engine in engines:
        cells, met = [], []
        for level in levels:
            e = results[level]["engines"][engine]
            lo, go = 100 * e["layout"]["over"], 100 * e["grid"]["over"]
            cells.append("%.1f / %.1f (%.2f)<br>%.0f / %.0f" % (
                lo, go, ratio(lo, go), 100 * not_right(e["layout"]), 100 * not_right(e["grid"])))
            if meets_goal(e):
                met.append(level)
        print("| `%s` | %s | %d of %d%s |" % (engine, " | ".join(cells), len(met), len(levels),
                                             " (%s)" % ", ".join(met) if met else ""))


def print_today_table(results, engines):
    """What a studio imports today, a level a row: the generic layout's own floor over 5 deg (its
    convex proxies, Lagarde's blend), then per engine its presets' floor over 5 deg / floor not
    right, % (in brackets the floor not right under the layout made for the engine)."""
    if any(r["generic"] is None for r in results.values()):
        return
    print("\n| level | generic (own proxies, Lagarde) | %s |"
          % " | ".join("`%s`" % e for e in engines))
    print("|---|---|%s" % ("---|" * len(engines)))
    for level, r in results.items():
        cells = ["%.0f / %.0f (%.0f)" % (100 * e["today"]["over"], 100 * not_right(e["today"]),
                                         100 * not_right(e["layout"]))
                 for e in (r["engines"][name] for name in engines)]
        print("| %s | %.1f | %s |" % (level, 100 * r["generic"]["over"], " | ".join(cells)))


def print_tables(results, engines):
    print_level_tables(results, engines)
    print_summary(results, engines)
    print_today_table(results, engines)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("probeproxy")
    parser.add_argument("scenes")
    parser.add_argument("--levels", nargs="*", default=[])
    parser.add_argument("--work", help="keep every run's output here")
    parser.add_argument("--jsonl", help="append each level's figures to this file")
    parser.add_argument("--engines", nargs="*", default=list(ENGINES))
    parser.add_argument("--from-jsonl", help="print the tables of figures a --jsonl run saved")
    parser.add_argument("--without-generic", action="store_true",
                        help="skip the generic layout's presets (one layout run less per level)")
    parser.add_argument("--resume", action="store_true",
                        help="read a run whose --work folder holds its layout.json, not run it")
    parser.add_argument("--capture-height", type=float,
                        help="every layout's and grid's --capture-height (default: layout's)")
    args = parser.parse_args()
    layout_options = () if args.capture_height is None else (
        "--capture-height", repr(args.capture_height))

    if args.from_jsonl:
        with open(args.from_jsonl) as f:
            results = {r.pop("level"): r for r in map(json.loads, f)}
        print_tables(results, args.engines)
        return
    scenes = sorted(glob.glob(os.path.join(args.scenes, "*", "*.scene.json")))
    if args.levels:
        scenes = [s for s in scenes if os.path.basename(os.path.dirname(s)) in args.levels]
    results = {}
    with tempfile.TemporaryDirectory() as scratch:
        for scene in scenes:
            level = os.path.basename(os.path.dirname(scene))
            work = os.path.join(args.work or scratch, level)
            results[level] = level_figures(args.probeproxy, scene, work, args.engines,
                                           not args.without_generic, args.resume, layout_options)
            if args.jsonl:
                with open(args.jsonl, "a") as f:
                    f.write(json.dumps({"level": level, **results[level]}) + "\n")
    print_tables(results, args.engines)


if __name__ == "__main__":
    main()
