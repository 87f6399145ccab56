#!/usr/bin/python3
"""Charts of `probeproxy bench --json` (speed against accuracy), PNG and SVG.

    /usr/bin/python3 scripts/bench_charts.py OUT/bench.json OUT [--levels corridor l_room]
    /usr/bin/python3 scripts/bench_charts.py --sweeps sweeps.json OUT

Writes, per level: `<level>_error_vs_cost` (mirror_floor p95 angular error, log scale,
against ns per lookup of the batched kernel, Pareto front drawn) and `<level>_error_vs_planes`
(the convex fits); across levels: `summary` (each method's p95 per level, and ns per lookup of
the batched kernels against the scalar seed ports). Uses Debian's python3-matplotlib with the
Agg backend; SVGs are byte-identical across runs (fixed hash salt, no date).
"""

import argparse
import json
import math
import os
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

plt.rcParams["svg.hashsalt"] = "probeproxy"
plt.rcParams["font.size"] = 9

METHODS = ["infinite", "cheap_k", "sphere", "aabb", "obb", "convex", "mixing_plane",
           "raster_convex", "pointcloud"]
MARKERS = dict(zip(METHODS, "o^sDPX*vh"))
# A p95 of exactly zero (an exact box) cannot sit on a log axis: it is drawn at this floor.
ERROR_FLOOR_DEG = 1e-4
# A candidate that misses more than this share of samples is drawn hollow and kept off the
# Pareto front: a low p95 over the samples it does hit is not a usable proxy.
MAX_MISS_RATE = 0.001
# Methods with one row per probe (the mixing step through the kept proxy, the point cloud):
# nothing to choose between, so the table shows them whatever their misses. Their cost is per
# corrected texel (mixing) or per shading point (pointcloud), not per batched lookup.
ONE_ROW_METHODS = {"mixing_plane", "raster_convex", "pointcloud"}
# Sweeps whose chart also draws the median (dashed).
SWEEPS_WITH_MEDIAN = {"concavity"}


def finite(v):
    return v is not None and isinstance(v, (int, float)) and math.isfinite(v)


def save(fig, out_dir, name):
    for ext, meta in (("png", {"Software": None}), ("svg", {"Date": None})):
        fig.savefig(os.path.join(out_dir, f"{name}.{ext}"), dpi=90, metadata=meta)
    plt.close(fig)


def pareto_front(points):
    """Points (cost, error) no other point beats on both, by increasing cost."""
    front, best = [], math.inf
    for cost, err, row in sorted(points, key=lambda p: (p[0], p[1])):
        if err < best:
            front.append((cost, err, row))
            best = err
    return front


def label(row):
    return f"{row['probe']}: {row.get('candidate', row['method'])}"


def label_front_apart(fig, ax, front):
    """Each point of the front named beside it; a label that would cover an earlier one moves
    a line down, then up, then two, until it covers none (front points cluster where cheap
    methods tie)."""
    fig.canvas.draw()  # the axes' scales and limits, as the labels will be placed
    renderer = fig.canvas.get_renderer()
    offsets = [4] + [4 + sign * 9 * k for k in range(1, 7) for sign in (-1, 1)]
    placed = []
    for cost, err, row in front:
        for i, dy in enumerate(offsets):
            text = ax.annotate(label(row), (cost, err), textcoords="offset points",
                               xytext=(5, dy), fontsize=7)
            box = text.get_window_extent(renderer).expanded(1.02, 1.1)
            if i == len(offsets) - 1 or not any(box.overlaps(other) for other in placed):
                break
            text.remove()
        placed.append(box)


def error_vs_cost(level, rows, out_dir):
    fig, ax = plt.subplots(figsize=(9.5, 5.5))
    probes = sorted({r["probe"] for r in rows})
    colors = {p: plt.cm.tab10(i % 10) for i, p in enumerate(probes)}
    usable = []
    for r in rows:
        if not (finite(r["ns_per_lookup"]) and finite(r["p95_deg"])):
            continue
        err = max(r["p95_deg"], ERROR_FLOOR_DEG)
        misses = finite(r["miss_rate"]) and r["miss_rate"] > MAX_MISS_RATE
        ax.scatter(r["ns_per_lookup"], err, marker=MARKERS.get(r["method"], "o"), s=30,
                   facecolors="none" if misses else colors[r["probe"]],
                   edgecolors=colors[r["probe"]], linewidths=1, zorder=3)
        if not misses:
            usable.append((r["ns_per_lookup"], err, r))
    front = pareto_front(usable)
    if front:
        ax.step([p[0] for p in front], [p[1] for p in front], where="post", color="0.3",
                linewidth=1.2, linestyle="--", zorder=2, label="Pareto front")
        label_front_apart(fig, ax, front)
    for p in probes:
        ax.scatter([], [], color=colors[p], marker="o", label=f"probe {p}")
    for m in METHODS:
        if any(r["method"] == m and finite(r["ns_per_lookup"]) and finite(r["p95_deg"])
               for r in rows):
            ax.scatter([], [], color="0.5", marker=MARKERS[m], label=m)
    ax.scatter([], [], facecolors="none", edgecolors="0.5",
               label=f"misses > {100 * MAX_MISS_RATE:g}% (off the front)")
    ax.set_yscale("log")
    ax.set_xscale("log")
    ax.set_xlabel("cost: ns per lookup (batched kernel, median, log);\n"
                  "mixing_plane, raster_convex: ns per texel of the corrected cubemap")
    ax.set_ylabel("p95 angular error on mirror_floor (degrees, log)")
    ax.set_title(f"{level}: error against cost of every method and proxy "
                 f"(p95 of 0 drawn at {ERROR_FLOOR_DEG:g} deg)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    save(fig, out_dir, f"{level}_error_vs_cost")


def error_vs_planes(level, rows, out_dir):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    probes = sorted({r["probe"] for r in rows})
    for i, p in enumerate(probes):
        fits = sorted((r["planes"], max(r["p95_deg"], ERROR_FLOOR_DEG)) for r in rows
                      if r["probe"] == p and r["method"] == "convex" and finite(r["p95_deg"])
                      and r.get("candidate", "") != "authored")
        if fits:
            ax.plot([f[0] for f in fits], [f[1] for f in fits], marker="o", markersize=3,
                    color=plt.cm.tab10(i % 10), label=f"probe {p}")
        box = [r for r in rows if r["probe"] == p and r.get("candidate") == "aabb"]
        if box and finite(box[0]["p95_deg"]):
            ax.axhline(max(box[0]["p95_deg"], ERROR_FLOOR_DEG), color=plt.cm.tab10(i % 10),
                       linestyle=":", linewidth=0.8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("planes of the convex fit (log)")
    ax.set_ylabel("p95 angular error on mirror_floor (degrees, log)")
    ax.set_title(f"{level}: error of the convex fits against their plane count\n"
                 "(dotted: the fitted axis-aligned box of the same probe)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    save(fig, out_dir, f"{level}_error_vs_planes")


def best_p95(rows, method):
    """Per probe the lowest p95 of the method's candidates (convex: at most 16 planes), then
    the median over the level's probes."""
    per_probe = {}
    for r in rows:
        if r["method"] != method or not finite(r["p95_deg"]):
            continue
        if r.get("candidate") == "authored" or (method == "convex" and r["planes"] > 16):
            continue
        if (method not in ONE_ROW_METHODS and finite(r["miss_rate"])
                and r["miss_rate"] > MAX_MISS_RATE):
            continue
        per_probe[r["probe"]] = min(per_probe.get(r["probe"], math.inf), r["p95_deg"])
    return statistics.median(per_probe.values()) if per_probe else None


def summary(by_level, rows, out_dir):
    levels = sorted(by_level)
    methods = [m for m in METHODS if any(r["method"] == m for r in rows)]
    # pointcloud gives no direction: it has a cost and a PSNR but no angular error.
    error_methods = [m for m in methods if any(r["method"] == m and finite(r["p95_deg"])
                                               for r in rows)]
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5), gridspec_kw={"width_ratios": [3, 2]})
    grid = [[best_p95(by_level[lv], m) for m in error_methods] for lv in levels]
    shown = [[math.log10(max(v, ERROR_FLOOR_DEG)) if v is not None else math.nan for v in line]
             for line in grid]
    image = left.imshow(shown, cmap="viridis", aspect="auto", vmin=-4, vmax=2.3)
    for i, line in enumerate(grid):
        for j, v in enumerate(line):
            text = "-" if v is None else (f"{v:.3f}" if v < 10 else f"{v:.0f}")
            left.text(j, i, text, ha="center", va="center", fontsize=7,
                      color="white" if v is None or v < 1 else "black")
    left.set_xticks(range(len(error_methods)), error_methods, rotation=30)
    left.set_yticks(range(len(levels)), levels)
    left.set_title("p95 angular error (deg) on mirror_floor, best fit per probe,\n"
                   "median over the level's probes (convex: at most 16 planes)")
    fig.colorbar(image, ax=left, label="log10 p95 (degrees)")

    batched = [statistics.median([r["ns_per_lookup"] for r in rows if r["method"] == m
                                  and finite(r["ns_per_lookup"])] or [math.nan]) for m in methods]
    scalar = [statistics.median([r["ns_per_lookup_scalar"] for r in rows if r["method"] == m
                                 and finite(r.get("ns_per_lookup_scalar"))] or [math.nan])
              for m in methods]
    x = range(len(methods))
    right.bar([i - 0.2 for i in x], scalar, width=0.4, label="scalar seed port", color="0.6")
    right.bar([i + 0.2 for i in x], batched, width=0.4, label="batched kernel", color="tab:blue")
    for i, (s, b) in enumerate(zip(scalar, batched)):
        if finite(s) and finite(b) and b > 0:
            right.text(i, max(s, b) * 1.1, f"{s / b:.1f}x", ha="center", fontsize=7)
    right.set_xticks(list(x), methods, rotation=30)
    right.set_yscale("log")
    right.set_ylabel("ns per lookup, log (median over all levels' rows);\n"
                     "mixing: per corrected texel, pointcloud: per shading point")
    right.set_title("cost per lookup; labels: batched speed-up\nover the scalar port, same run")
    right.legend(fontsize=7)
    fig.suptitle(f"probeproxy bench: every method on {len(levels)} level{'' if len(levels) == 1 else 's'}")
    fig.tight_layout()
    save(fig, out_dir, "summary")


def sweep_charts(sweeps_json, out_dir):
    """One chart per sweep: p95 (log) and miss rate against the swept parameter."""
    with open(sweeps_json) as f:
        sweeps = json.load(f)["sweeps"]
    for sweep in sweeps:
        fig, (err_ax, miss_ax) = plt.subplots(1, 2, figsize=(10, 4))
        # The concavity sweep's errors are exact zeros or degrees: floor them where the log
        # axis can show them, and draw the medians too (dashed).
        with_median = sweep["name"] in SWEEPS_WITH_MEDIAN
        floor = ERROR_FLOOR_DEG if with_median else 1e-12
        for i, series in enumerate(sweep["series"]):
            xs = [p["parameter"] for p in series["points"]]
            p95 = [max(p["p95_deg"], floor) if finite(p["p95_deg"]) else math.nan
                   for p in series["points"]]
            color = plt.cm.tab10(i % 10)
            err_ax.plot(xs, p95, marker="o", markersize=3, color=color, label=series["method"])
            if with_median:
                median = [max(p["median_deg"], floor) if finite(p["median_deg"]) else math.nan
                          for p in series["points"]]
                err_ax.plot(xs, median, linestyle="--", linewidth=1, color=color)
            miss_ax.plot(xs, [p["miss_rate"] for p in series["points"]], marker="o",
                         markersize=3, color=color, label=series["method"])
        for ax in (err_ax, miss_ax):
            ax.set_xlabel(sweep["parameter"])
            if sweep["name"] in ("origin", "resolution"):
                ax.set_xscale("log")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7)
        err_ax.set_yscale("log")
        err_ax.set_ylabel("p95 angular error (degrees, log; misses left out)"
                          + ("\nsolid p95, dashed median; 0 drawn at 1e-4" if with_median else ""))
        miss_ax.set_ylabel("miss rate (flagged misses / lookups)")
        fig.suptitle(f"where methods break: {sweep['name']} sweep")
        fig.tight_layout()
        save(fig, out_dir, f"sweep_{sweep['name']}")


def percent(v):
    return 100 * v if finite(v) else None


def markdown_table(by_level):
    """Per level and method: the median over probes of the best candidate's p95 (as in the
    summary chart), with its ns per lookup (batched, scalar), instructions and PSNR."""
    lines = ["| level | method | p95 deg | median deg | miss % | ns batched | ns scalar | "
             "speed-up | instr | PSNR dB |", "|---" * 10 + "|"]
    fmt = lambda v, f: "-" if not finite(v) else format(v, f)  # noqa: E731
    for level in sorted(by_level):
        for method in METHODS:
            best = {}
            for r in by_level[level]:
                if r["method"] != method or r.get("candidate") == "authored":
                    continue
                if method in ONE_ROW_METHODS:
                    best[r["probe"]] = r
                    continue
                if method == "convex" and r["planes"] > 16 or not finite(r["p95_deg"]):
                    continue
                if finite(r["miss_rate"]) and r["miss_rate"] > MAX_MISS_RATE:
                    continue
                if r["probe"] not in best or r["p95_deg"] < best[r["probe"]]["p95_deg"]:
                    best[r["probe"]] = r
            if not best:
                continue
            # The median probe by p95, or by PSNR for a method without angular error.
            key = "p95_deg" if any(finite(r["p95_deg"]) for r in best.values()) else "psnr_db"
            rows = sorted(best.values(),
                          key=lambda r: r[key] if finite(r[key]) else math.inf)
            mid = rows[len(rows) // 2]
            ratio = (mid["ns_per_lookup_scalar"] / mid["ns_per_lookup"]
                     if finite(mid.get("ns_per_lookup_scalar")) and finite(mid["ns_per_lookup"])
                     else None)
            name = method if method != "convex" else f"convex ({mid['planes']} planes)"
            if method in ("mixing_plane", "raster_convex"):
                name = f"{method} (kept {mid['candidate']})"
            lines.append(f"| {level} | {name} | {fmt(mid['p95_deg'], '.3f')} | "
                         f"{fmt(mid['median_deg'], '.3f')} | {fmt(percent(mid['miss_rate']), '.1f')} | "
                         f"{fmt(mid['ns_per_lookup'], '.2f')} | "
                         f"{fmt(mid.get('ns_per_lookup_scalar'), '.2f')} | {fmt(ratio, '.1f')} | "
                         f"{fmt(mid['instructions_per_lookup'], '.1f')} | "
                         f"{fmt(mid['psnr_db'], '.1f')} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("bench_json", help="bench.json, or sweeps.json with --sweeps")
    parser.add_argument("out_dir")
    parser.add_argument("--levels", nargs="*", help="per-level charts for these only")
    parser.add_argument("--table", action="store_true",
                        help="also print the per-level summary as a Markdown table")
    parser.add_argument("--sweeps", action="store_true",
                        help="the input is break_sweeps' JSON: chart each sweep")
    args = parser.parse_args()
    if args.sweeps:
        os.makedirs(args.out_dir, exist_ok=True)
        sweep_charts(args.bench_json, args.out_dir)
        return
    with open(args.bench_json) as f:
        rows = json.load(f)["results"]
    if not rows:
        sys.exit(f"{args.bench_json}: no results")
    os.makedirs(args.out_dir, exist_ok=True)
    by_level = {}
    for r in rows:
        by_level.setdefault(r["scene"], []).append(r)
    for level, level_rows in sorted(by_level.items()):
        if args.levels and level not in args.levels:
            continue
        error_vs_cost(level, level_rows, args.out_dir)
        error_vs_planes(level, level_rows, args.out_dir)
    summary(by_level, rows, args.out_dir)
    if args.table:
        print(markdown_table(by_level))


if __name__ == "__main__":
    main()
