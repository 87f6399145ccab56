"""Command line and per-level driver: build, export, render, write the scene file.

A level is generated into `<out>/<level>.partial` and renamed into place only when complete,
so an interrupted or failed run never leaves a level that looks finished.
"""

import argparse
import importlib
import json
import shutil
import time
from pathlib import Path

from . import broken
from .levels import LEVELS


def parse_args(argv):
    parser = argparse.ArgumentParser(
        prog="generate_suite.py",
        description="Generate probeproxy's test levels (run inside headless Blender, arguments after --).",
    )
    parser.add_argument("--out", required=True, type=Path, help="output folder, one sub-folder per level")
    parser.add_argument("--levels", default=",".join(LEVELS), help=f"comma-separated subset of: {','.join(LEVELS)}")
    parser.add_argument("--size", type=int, help="cubemap face size in pixels (default 64, 256 with --large)")
    parser.add_argument("--samples", type=int, help="Cycles samples per cubemap face (default 16, 64 with --large)")
    parser.add_argument("--large", action="store_true", help="bigger renders for inspection and charts")
    args = parser.parse_args(argv)
    levels = [name.strip() for name in args.levels.split(",") if name.strip()]
    unknown = [name for name in levels if name not in LEVELS]
    if unknown or not levels:
        parser.error(f"unknown level(s) {', '.join(unknown) or '(none given)'}; choose from {', '.join(LEVELS)}")
    args.levels = levels
    args.size = args.size or (256 if args.large else 64)
    args.samples = args.samples or (64 if args.large else 16)
    if args.size < 1 or args.samples < 1:
        parser.error("--size and --samples must be positive")
    args.view_size = (384, 256) if args.large else (96, 64)
    # Mirror views are compared pixel by pixel against reconstructions: less noise than faces.
    args.view_samples = max(32, 2 * args.samples)
    return args


def _replace_dir(staging, final):
    if final.exists():
        shutil.rmtree(final)
    staging.rename(final)


def generate_level(name, args):
    staging = args.out / f"{name}.partial"
    if staging.exists():
        shutil.rmtree(staging)
    staging.mkdir(parents=True)
    try:
        if name == "broken":
            count = broken.write_all(staging)
        else:
            from . import level_render  # imports bpy: only inside Blender

            module = importlib.import_module(f".levels.{name}", __package__)
            count = level_render.generate(name, module, staging, args)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    _replace_dir(staging, args.out / name)
    return count


def main(argv):
    args = parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    timings = {}
    start = time.monotonic()
    for name in args.levels:
        t0 = time.monotonic()
        count = generate_level(name, args)
        timings[name] = time.monotonic() - t0
        print(f"[suite] {name}: {timings[name]:.1f} s, {count} files", flush=True)
    total = time.monotonic() - start
    print(f"[suite] done: {len(timings)} level(s) in {total:.1f} s -> {args.out}", flush=True)
    print("[suite] timings " + json.dumps({k: round(v, 2) for k, v in timings.items()}), flush=True)
