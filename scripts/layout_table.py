#!/usr/bin/python3
"""The layout table of docs/layout.md, measured on both sets of the corpus: per map,
`probeproxy layout` against the grid baseline (`--baseline grid`, aabb proxies) with the same
number of probes, both surveyed (`probeproxy survey`'s figures, in layout.json), and a check that
`probeproxy survey DIR/layout.scene.json` gives layout.json's figures exactly (the scene carries
the floor it was measured on). With --reach, also the probe count the grid needs to reach the
layout's p95 (grids of 2x and 4x the layout's count; "> 4x" when none does). With --validate,
`probeproxy validate` of each layout with its defaults: its exit code and findings by rule.
With --worst, what the layout's worst 5% of floor (at its p95 or over) reaches: the sky, a
surface within 2 m, a surface inside its heaviest probe's proxy, and that probe's share.
Prints one Markdown table per set and a line of each set's worst figures; --jsonl keeps a row per
map. With --maps also copies the error maps of the levels named by --pictures into DIR as
<level>_layout.png and <level>_grid.png.

The tuning set is what the layout's choices were made on; the validation set was never tuned on:
judge a change by the validation set. At the layout's default tolerance (5 degrees) "over
tolerance" is the share of the walkable floor over 5 degrees.

  /usr/bin/python3 scripts/layout_table.py build/plugin/cli/probeproxy \
      --set tuning=build/corpus/scenes --set validation=build/corpus/validation \
      [--maps docs/images/layout --pictures downer toxic skyway] [--levels downer toxic] \
      [--reach] [--validate] [--worst] [--work DIR] [--jsonl FILE]
"""
import argparse
import glob
import json
import os
import shutil
import subprocess
import tempfile

GRID_FACTORS = (2, 4)


class LayoutFailed(Exception):
    pass


def layout_json(probeproxy, scene, out, *extra):
    done = subprocess.run([probeproxy, "layout", scene, "--out", out, "--json", *extra],
                          capture_output=True, text=True)
    if done.returncode != 0:
        raise LayoutFailed("exit %d: %s" % (done.returncode, done.stderr.strip().splitlines()[-1]
                                            if done.stderr.strip() else ""))
    with open(os.path.join(out, "layout.json")) as f:
        return json.load(f)


def figures(report):
    s = report["survey"]
    return report["probes"], s["p95_deg"], s["over_tolerance_share"], s["uncovered_share"]


def run(*command):
    return subprocess.run(command, capture_output=True, text=True)


def survey_agrees(probeproxy, layout_folder, report):
    """Whether `survey` of the written scene gives layout.json's figures, bit for bit."""
    surveyed = run(probeproxy, "survey", os.path.join(layout_folder, "layout.scene.json"), "--json")
    if surveyed.returncode != 0:
        return False
    again = json.loads(surveyed.stdout)
    mine = report["survey"]
    return all(again.get(k) == v for k, v in mine.items() if k != "seconds")


def validate_summary(probeproxy, layout_folder):
    checked = run(probeproxy, "validate", os.path.join(layout_folder, "layout.scene.json"), "--json")
    findings = json.loads(checked.stdout)["findings"] if checked.stdout.strip() else []
    by_rule = {}
    for f in findings:
        by_rule[f["rule"]] = by_rule.get(f["rule"], 0) + 1
    return checked.returncode, by_rule


def measure(args, scene, work):
    level = os.path.basename(os.path.dirname(scene))
    out = os.path.join(work, level)
    layout = layout_json(args.probeproxy, scene, out + "_layout")
    probes, p95, over, uncovered = figures(layout)
    grid = layout_json(args.probeproxy, scene, out + "_grid", "--baseline", "grid",
                       "--max-probes", str(probes))
    gprobes, gp95, gover, guncovered = figures(grid)
    row = {"level": level, "probes": probes, "p95_deg": p95, "over_share": over,
           "uncovered_share": uncovered, "seconds": layout["layout_seconds"],
           "grid_probes": gprobes, "grid_p95_deg": gp95, "grid_over_share": gover,
           "grid_uncovered_share": guncovered,
           "p95_ratio": p95 / gp95 if gp95 > 0 else float("nan"),
           "walkable_m2": layout["survey"]["walkable_m2"],
           "worst_floor": layout["survey"].get("worst_floor"),
           "grid_worst_floor": grid["survey"].get("worst_floor"),
           "survey_agrees": survey_agrees(args.probeproxy, out + "_layout", layout)}
    if args.reach:
        row["grid_probes_to_reach"] = "> %dx" % GRID_FACTORS[-1]
        for factor in GRID_FACTORS:
            denser = layout_json(args.probeproxy, scene, out + "_grid%d" % factor,
                                 "--baseline", "grid", "--max-probes", str(factor * probes))
            if figures(denser)[1] <= p95:
                row["grid_probes_to_reach"] = str(figures(denser)[0])
                break
    if args.validate:
        row["validate_exit"], row["validate_findings"] = validate_summary(args.probeproxy,
                                                                          out + "_layout")
    if args.maps and level in args.pictures:
        os.makedirs(args.maps, exist_ok=True)
        # layout_survey.png, grid_survey.png; per storey where the level has several.
        for kind in ("layout", "grid"):
            for path in sorted(glob.glob(os.path.join(out + "_" + kind, "*_survey*.png"))):
                storey = os.path.basename(path).split("_survey")[1]
                shutil.copyfile(path, os.path.join(args.maps, "%s_%s%s" % (level, kind, storey)))
    return row


def print_row(row, args):
    cells = ["%s" % row["level"], "%d" % row["probes"], "%.1f" % row["p95_deg"],
             "%.1f%%" % (100 * row["over_share"]), "%.2f%%" % (100 * row["uncovered_share"]),
             "%.0f" % row["seconds"], "%d" % row["grid_probes"], "%.1f" % row["grid_p95_deg"],
             "%.1f%%" % (100 * row["grid_over_share"]), "%.2f" % row["p95_ratio"],
             "yes" if row["survey_agrees"] else "**no**"]
    if args.worst:
        w = row["worst_floor"]
        top = w["probes"][0] if w and w["probes"] else None
        cells += ["%.0f%%" % (100 * w["sky_share"]), "%.0f%%" % (100 * w["near_hit_share"]),
                  "%.0f%%" % (100 * w["hit_inside_proxy_share"]),
                  "%s %.0f%%" % (top["name"], 100 * top["share"]) if top else "-"]
    if args.reach:
        cells.append(row["grid_probes_to_reach"])
    if args.validate:
        findings = ", ".join("%s %d" % kv for kv in sorted(row["validate_findings"].items()))
        cells.append("%d%s" % (row["validate_exit"], (" (" + findings + ")") if findings else ""))
    print("| " + " | ".join(cells) + " |", flush=True)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("probeproxy")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=FOLDER",
                        help="a set of scenes (FOLDER/<map>/<map>.scene.json); repeatable")
    parser.add_argument("--levels", nargs="*", default=[])
    parser.add_argument("--maps")
    parser.add_argument("--pictures", nargs="*", default=[])
    parser.add_argument("--reach", action="store_true")
    parser.add_argument("--worst", action="store_true",
                        help="what the layout's worst 5%% of floor reaches (survey's worst_floor)")
    parser.add_argument("--validate", action="store_true")
    parser.add_argument("--work", help="keep every run's output here (to validate the layouts)")
    parser.add_argument("--jsonl", help="append one JSON row per map to this file")
    args = parser.parse_args()
    if not args.set:
        parser.error("give at least one --set NAME=FOLDER")

    header = ("| map | layout probes | layout p95 | layout over 5 deg | layout uncovered "
              "| layout seconds | grid probes | grid p95 | grid over 5 deg | p95 ratio "
              "| survey of the scene agrees |")
    if args.worst:
        header += (" worst 5%: sky | worst 5%: hit within 2 m | worst 5%: hit inside the proxy "
                   "| worst 5%: heaviest probe |")
    if args.reach:
        header += " grid probes to reach layout's p95 |"
    if args.validate:
        header += " validate exit (findings) |"
    with tempfile.TemporaryDirectory() as scratch:
        for named in args.set:
            name, folder = named.split("=", 1)
            scenes = sorted(glob.glob(os.path.join(folder, "*", "*.scene.json")))
            if args.levels:
                scenes = [s for s in scenes
                          if os.path.basename(os.path.dirname(s)) in args.levels]
            if not scenes:
                continue
            work = os.path.join(args.work or scratch, name)
            os.makedirs(work, exist_ok=True)
            print("\n%s set:\n" % name)
            print(header)
            print("|" + "---|" * header.count(" |"))
            rows = []
            for scene in scenes:
                try:
                    row = measure(args, scene, work)
                except LayoutFailed as failed:  # a map the layout refuses is a row, not the end
                    level = os.path.basename(os.path.dirname(scene))
                    print("| %s | **failed**: %s |" % (level, failed), flush=True)
                    continue
                row["set"] = name
                rows.append(row)
                print_row(row, args)
                if args.jsonl:
                    with open(args.jsonl, "a") as f:
                        f.write(json.dumps(row) + "\n")
            if not rows:
                continue
            print("\n%s set, worst map: p95 ratio %.2f, %.1f%% over 5 deg, %.2f%% uncovered; "
                  "survey agrees on %d of %d" % (
                      name, max(r["p95_ratio"] for r in rows),
                      100 * max(r["over_share"] for r in rows),
                      100 * max(r["uncovered_share"] for r in rows),
                      sum(r["survey_agrees"] for r in rows), len(rows)), flush=True)


if __name__ == "__main__":
    main()
