#!/usr/bin/python3
"""The layout table of docs/layout.md, measured: per level, `probeproxy layout` against the
grid baseline (`--baseline grid`, aabb proxies) with the same number of probes, both surveyed
(`probeproxy survey`'s figures, in layout.json); then the probe count the grid needs to reach
the layout's p95 (grids of 2x and 4x the layout's count; "> 4x" when none does). Prints a
Markdown table; with --maps DIR also copies the error maps of the levels named by --pictures
into DIR as <level>_layout.png and <level>_grid.png.

At the layout's default tolerance (5 degrees) "over tolerance" is the share of the walkable
floor over 5 degrees.

  /usr/bin/python3 scripts/layout_table.py build/plugin/cli/probeproxy build/corpus/scenes \
      [--maps docs/images/layout --pictures downer toxic skyway] [--levels downer toxic] \
      [--work DIR]
"""
import argparse
import glob
import json
import os
import shutil
import subprocess
import tempfile

GRID_FACTORS = (2, 4)


def layout_json(probeproxy, scene, out, *extra):
    subprocess.run([probeproxy, "layout", scene, "--out", out, "--json", *extra], check=True,
                   capture_output=True, text=True)
    with open(os.path.join(out, "layout.json")) as f:
        return json.load(f)


def figures(report):
    s = report["survey"]
    return report["probes"], s["p95_deg"], s["over_tolerance_share"], s["uncovered_share"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("probeproxy")
    parser.add_argument("scenes")
    parser.add_argument("--levels", nargs="*", default=[])
    parser.add_argument("--maps")
    parser.add_argument("--pictures", nargs="*", default=[])
    parser.add_argument("--work", help="keep every run's output here (to validate the layouts)")
    args = parser.parse_args()

    scenes = sorted(glob.glob(os.path.join(args.scenes, "*", "*.scene.json")))
    if args.levels:
        scenes = [s for s in scenes if os.path.basename(os.path.dirname(s)) in args.levels]
    print("| level | layout probes | layout p95 | layout over 5 deg | layout seconds "
          "| grid probes | grid p95 | grid over 5 deg | p95 ratio | grid probes to reach "
          "layout's p95 |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as scratch:
        work = args.work or scratch
        os.makedirs(work, exist_ok=True)
        for scene in scenes:
            level = os.path.basename(os.path.dirname(scene))
            out = os.path.join(work, level)
            layout = layout_json(args.probeproxy, scene, out + "_layout")
            probes, p95, over, _ = figures(layout)
            grid = layout_json(args.probeproxy, scene, out + "_grid", "--baseline", "grid",
                               "--max-probes", str(probes))
            gprobes, gp95, gover, _ = figures(grid)
            reach = "> %dx" % GRID_FACTORS[-1]
            for factor in GRID_FACTORS:
                denser = layout_json(args.probeproxy, scene, out + "_grid%d" % factor,
                                     "--baseline", "grid", "--max-probes",
                                     str(factor * probes))
                if figures(denser)[1] <= p95:
                    reach = str(figures(denser)[0])
                    break
            ratio = p95 / gp95 if gp95 > 0 else float("nan")
            print("| %s | %d | %.1f | %.1f%% | %.0f | %d | %.1f | %.1f%% | %.2f | %s |" %
                  (level, probes, p95, 100 * over, layout["layout_seconds"], gprobes, gp95,
                   100 * gover, ratio, reach), flush=True)
            if args.maps and level in args.pictures:
                os.makedirs(args.maps, exist_ok=True)
                # layout_survey.png, grid_survey.png; per storey where the level has several.
                for kind in ("layout", "grid"):
                    for path in sorted(glob.glob(os.path.join(out + "_" + kind, "*_survey*.png"))):
                        storey = os.path.basename(path).split("_survey")[1]
                        shutil.copyfile(path, os.path.join(args.maps,
                                                           "%s_%s%s" % (level, kind, storey)))


if __name__ == "__main__":
    main()
