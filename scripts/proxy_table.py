#!/usr/bin/env python3
"""The proxy table of docs/building_proxies.md: for every level of the suite, per probe, the
kept proxy's kind, planes and mirror_floor error beside the artist box's and the plain hull's.

    scripts/proxy_table.py build/plugin/cli/probeproxy build/scenes [--out build/proxy-table]

Runs `probeproxy build --json --regenerate` on each level's scene file and prints a Markdown
table. The artist box is measured as the `authored` candidate: of the scene file itself where
it authors the box (box rooms), else of `<level>.artist.scene.json`, the same level with the
artist boxes, whose main scene file asks for "auto".
"""

import argparse
import json
import pathlib
import subprocess
import sys

LEVELS = ["corridor", "l_room", "u_corridors", "hall_pillars", "attic", "round_room",
          "courtyard", "tiny_closet", "hangar"]


def fmt(value, digits=3):
    return "-" if value is None else f"{value:.{digits}f}"


def build(probeproxy, scene, out):
    """`probeproxy build --json --regenerate`'s probes, or None (reported) when it fails."""
    run = subprocess.run([probeproxy, "build", str(scene), "--out", str(out), "--json", "--regenerate"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        print(f"{scene}: probeproxy build failed: {run.stderr.strip()}", file=sys.stderr)
        return None
    return json.loads(run.stdout)["probes"]


def authored_error(probe):
    return next((c["error"] for c in probe["candidates"] if c["kind"] == "authored"), {})


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("probeproxy")
    parser.add_argument("suite")
    parser.add_argument("--out", default=None, help="folder for each level's proxies")
    parser.add_argument("--levels", default=",".join(LEVELS))
    args = parser.parse_args()

    suite = pathlib.Path(args.suite)
    out = pathlib.Path(args.out) if args.out else suite.parent / "proxy-table"
    print("| level | probe | kept | planes | median deg | p95 deg | miss % | artist box median / p95 |"
          " hull planes | hull median / p95 | build ms |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for level in args.levels.split(","):
        probes = build(args.probeproxy, suite / level / f"{level}.scene.json", out / level)
        artist_scene = suite / level / f"{level}.artist.scene.json"
        artist_probes = build(args.probeproxy, artist_scene, out / f"{level}.artist") if artist_scene.exists() else probes
        if probes is None or artist_probes is None:
            return 1
        artist_boxes = {p["name"]: authored_error(p) for p in artist_probes}
        for probe in probes:
            by_kind = {c["kind"]: c for c in probe["candidates"]}
            kept = probe["proxy"]
            err = probe["error"]
            artist = artist_boxes.get(probe["name"], {})
            hull = by_kind.get("hull", {})
            hull_err = hull.get("error", {})
            print(f"| {level} | {probe['name']} | {kept['candidate']} ({kept['kind']}) | {kept['planes']} "
                  f"| {fmt(err['median_deg'])} | {fmt(err['p95_deg'])} | {fmt(100 * err['miss_rate'], 1)} "
                  f"| {fmt(artist.get('median_deg'))} / {fmt(artist.get('p95_deg'))} "
                  f"| {hull.get('planes', '-')} | {fmt(hull_err.get('median_deg'))} / {fmt(hull_err.get('p95_deg'))} "
                  f"| {probe['build_ms']:.0f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
