#!/usr/bin/python3
"""Proof in pixels: a real renderer shows the exported probes, and the walls say where each
reflection came from.

Every level surface is coloured by its own world position and the floor is a mirror, so each
mirror pixel shows the level point the engine's probe lookup returned (a blend of them where
probes blend). The true reflection is the camera ray mirrored at the floor, cast to the level.
The angle between the two, seen from the floor point, is the renderer's error at that pixel,
in degrees, with no shading model and no reference image. Beside it, the error the engine
model (`survey --engine E`'s rules, geometry/engines/) predicts for that pixel: the same angle
to the weight-averaged point the model's lookups show (probeproxy_py.engine_reflections).

For a level (a scene file) and its cameras (scripts/render_check/cameras/<level>.json), three
sets of probes, each laid out by the CLI for the engine:
  layout   `probeproxy layout SCENE --engine E`
  grid     `probeproxy layout SCENE --baseline grid --max-probes N --engine E` (N: layout's)
  default  the layout's probes as the engine does by default (EEVEE: the parallax box is the
           influence box: parallax_distance 1)
Writes OUT/<set>/ (the CLI's files, the frames), OUT/render_check.json (figures per set) and
OUT/render_check_<camera>.png (rendered and predicted error per set, survey's colour scale).

  /usr/bin/python3 scripts/render_check.py build/plugin/cli/probeproxy \\
      build/scenes/l_room/l_room.scene.json scripts/render_check/cameras/l_room.json \\
      --module-dir build/plugin/python --out out/render_check/l_room [--capture-height H]
Exit 0 when it ran (the figures say how the engines did), 1 with --require-agreement when the
model and the renderer disagree, 2 on bad input.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(HERE, "render_check"))
import position_code  # noqa: E402
MIRROR_NORMAL_Z = 0.7  # as eevee_frames.py
WIDTH, HEIGHT = 320, 180  # as eevee_frames.py's default
MIN_WEIGHT = 0.02      # a mirror pixel with less probe weight shows the (black) sky: uncovered
OVER_DEG = 5.0
# Each renderer: the proxies.json preset its probes are made from, and what its default is.
PRESETS = {"eevee": "eevee_reflection_cubemap", "godot3": "godot_reflection_probe"}
DEFAULTS = {"eevee": ("parallax_distance", 1.0),   # no custom parallax: parallax = influence
            "godot3": ("box_projection", False)}   # a ReflectionProbe's box projection is off
FLOOR_TILE = 1.0    # metres: the mirror floor's objects in Godot (split_floor)
AGREE_DEG = 1.0     # the model against the pixels: median |rendered - predicted| per pixel
AGREE_SHARE = 0.05  # and the shares of mirror pixels over 5 deg


def run_json(*command):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("render_check: %s failed: %s" % (" ".join(command[:3]), done.stderr.strip()))
    return json.loads(done.stdout)


def lay_out(args, out, region):
    """The three probe sets' proxies.json, as rendered: within `region` when the cameras
    file gives one."""
    height = () if args.capture_height is None else ("--capture-height", repr(args.capture_height))
    layout = run_json(args.probeproxy, "layout", args.scene, "--engine", args.engine,
                      "--out", os.path.join(out, "layout"), "--json", *height)
    run_json(args.probeproxy, "layout", args.scene, "--engine", args.engine, "--baseline", "grid",
             "--max-probes", str(layout["probes"]), "--out", os.path.join(out, "grid"), "--json",
             *height)
    exports = {}
    for name in ("layout", "grid"):
        with open(os.path.join(out, name, "proxies.json")) as f:
            exports[name] = json.load(f)
    # The engine's default on the layout's probes, for the renderer and the model alike.
    exports["default"] = json.loads(json.dumps(exports["layout"]))
    field, value = DEFAULTS[args.engine]
    for probe in exports["default"]["probes"]:
        preset = probe.get("engines", {}).get(PRESETS[args.engine])
        if preset is not None:
            preset[field] = value
    sets = []
    for name, export in exports.items():
        if region is not None:
            export["probes"] = [p for p in export["probes"]
                                if reaches(p.get("engines", {}).get(PRESETS[args.engine]),
                                           region)]
        path = os.path.join(out, name, "rendered.proxies.json")
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            json.dump(export, f, indent=1)
        sets.append((name, path))
    return sets


def reaches(preset, region):
    """Whether a probe's preset (its bounding sphere) meets the region's box: a map's region is
    rendered with those probes only, for the renderer and the model alike."""
    if preset is None:
        return False
    if "location" in preset:  # EEVEE: world axes, the box centred on the location
        centre, radius = np.array(preset["location"]), np.linalg.norm(preset["scale"])
    else:  # Godot: its axes, world (x, y, z) = Godot (x, -z, y)
        x, y, z = preset["origin"]
        centre, radius = np.array([x, -z, y]), 0.5 * np.linalg.norm(preset["size"])
    nearest = np.clip(centre, region["lo"], region["hi"])
    return float(np.linalg.norm(nearest - centre)) <= radius


def render_eevee(args, proxies, out, geometry):
    command = ["xvfb-run", "-a", args.blender, "-b", "--factory-startup", "--python-exit-code",
               "1", "--python", os.path.join(HERE, "render_check", "eevee_frames.py"), "--",
               "--module-dir", args.module_dir, "--addon-dir", os.path.join(ROOT, "plugin",
                                                                           "blender"),
               "--scene", args.scene, "--proxies", proxies, "--cameras", args.cameras,
               "--out", out] + ([] if geometry else ["--no-geometry"])
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("render_check: EEVEE failed:\n" + done.stdout[-2000:] + done.stderr[-2000:])
    with open(os.path.join(out, "frames.json")) as f:
        return json.load(f)


def godot_point(p):
    """World (Z up) to Godot's axes (Y up)."""
    return [p[0], p[2], -p[1]]


def godot3_reflection_atlas(probe_count):
    """(atlas_size, atlas_subdiv) for Godot 3's project settings, so that every probe is drawn.
    The atlas has a slot per probe it draws, atlas_subdiv rounded up to a power of 4
    (RasterizerSceneGLES3::reflection_atlas_set_subdivision): the default 8 gives 16 slots, and
    a probe that finds none is not drawn. Each slot keeps the default's 512 px, up to Godot's
    8192 px atlas."""
    slots = 16
    while slots < probe_count:
        slots *= 4
    return min(8192, 512 * math.isqrt(slots)), slots


def split_floor(vertices, triangles, tile):
    """The level with its mirror floor cut into triangles no longer than `tile` a side.
    Godot 3 gives an object the first 8 probes paired with it (RasterizerSceneGLES3::
    _setup_light: `reflection_count < maxobj`), so one floor mesh under a hundred boxes
    shows eight of them; godot_frames.gd makes an object of each tile's pieces, as a real
    level's floor is many meshes. Longest edges are halved: the pieces keep the plane."""
    vertices = [tuple(v) for v in vertices]
    out = []
    todo = [tuple(t) for t in triangles]
    while todo:
        t = todo.pop()
        a, b, c = (np.array(vertices[i]) for i in t)
        n = np.cross(b - a, c - a)
        length = np.linalg.norm(n)
        edges = [np.linalg.norm(b - a), np.linalg.norm(c - b), np.linalg.norm(a - c)]
        if length == 0.0 or n[2] / length <= MIRROR_NORMAL_Z or max(edges) <= tile:
            out.append(list(t))
            continue
        k = int(np.argmax(edges))  # the edge from t[k] to t[k + 1]
        i, j, o = t[k], t[(k + 1) % 3], t[(k + 2) % 3]
        vertices.append(tuple(0.5 * (np.array(vertices[i]) + np.array(vertices[j]))))
        m = len(vertices) - 1
        todo += [(i, m, o), (m, j, o)]
    return [list(v) for v in vertices], out


def render_godot(args, proxies, out, geometry):
    """Godot 3 (godot3-runner, GLES3 under xvfb-run): one process for every pass, frames as
    EEVEE's; the position and normal passes only with `geometry`."""
    import probeproxy_py  # main() put its folder on the path
    os.makedirs(out, exist_ok=True)
    with open(proxies) as f:
        probe_count = sum(1 for p in json.load(f)["probes"]
                          if p.get("engines", {}).get(PRESETS["godot3"]) is not None)
    atlas_size, atlas_slots = godot3_reflection_atlas(probe_count)
    with open(os.path.join(out, "project.godot"), "w") as f:
        f.write('config_version=4\n[application]\nconfig/name="render_check"\n'
                '[rendering]\nquality/driver/driver_name="GLES3"\n'
                'quality/reflections/atlas_size=%d\nquality/reflections/atlas_subdiv=%d\n'
                'environment/default_clear_color=Color( 0, 0, 0, 1 )\n'
                % (atlas_size, atlas_slots))
    vertices, triangles = probeproxy_py.level_triangles(args.scene)
    vertices, triangles = split_floor(np.array(vertices, dtype=float), triangles, FLOOR_TILE)
    lo, size = position_code.bounds(vertices)
    with open(args.cameras) as f:
        cameras = json.load(f)["cameras"]
    spec = {"level": {"vertices": [godot_point(v) for v in vertices], "triangles": triangles},
            "cameras": [{"name": c["name"], "eye": godot_point(c["eye"]),
                         "target": godot_point(c["target"]), "hfov_deg": c.get("fov_deg", 70.0)}
                        for c in cameras],
            "width": WIDTH, "height": HEIGHT, "far": float(np.linalg.norm(size)), "lo": lo,
            "size": size, "importer": os.path.join(ROOT, "plugin", "engines", "godot"),
            "floor_tile": FLOOR_TILE, "out": out}
    coded = position_code.codes(size)
    passes = [("position", {}), ("normal", {})] if geometry else []
    passes += [("white", {"proxies": proxies})] + [
        ("code_%d_%g" % (a, p), {"proxies": proxies, "code": {"axis": a, "period": p}})
        for a, p in coded]
    start = time.time()
    path = os.path.join(out, "frames.spec.json")
    with open(path, "w") as f:
        json.dump(spec | {"passes": [extra | {"name": name, "pass": name.split("_")[0]}
                                     for name, extra in passes]}, f)
    done = subprocess.run(["xvfb-run", "-a", "godot3-runner", "--path", out, "-s",
                           os.path.join(HERE, "render_check", "godot_frames.gd"), "--args",
                           path], capture_output=True, text=True)
    raw = [os.path.join(out, "%s_%s.rgbah" % (c["name"], name))
           for c in cameras for name, _ in passes]
    if done.returncode != 0 or not all(os.path.isfile(r) for r in raw):
        sys.exit("render_check: Godot failed:\n" + done.stdout[-2000:] + done.stderr[-2000:])
    seconds = time.time() - start
    for c in cameras:
        frames = {}
        for name, _ in passes:
            path = os.path.join(out, "%s_%s.rgbah" % (c["name"], name))
            with open(path, "rb") as f:
                rgba = np.frombuffer(f.read(), dtype=np.float16).reshape(HEIGHT, WIDTH, 4)
            frames[name] = rgba[..., :3].astype(np.float32)
            os.remove(path)
        np.savez_compressed(os.path.join(out, c["name"] + ".npz"), **frames)
    meta = {"renderer": "godot3", "lo": lo, "size": size, "codes": coded, "cameras": cameras,
            "width": WIDTH, "height": HEIGHT, "seconds": seconds,
            "probes": [p["name"] for p in json.load(open(proxies))["probes"]
                       if p.get("engines", {}).get(PRESETS["godot3"]) is not None]}
    with open(os.path.join(out, "frames.json"), "w") as f:
        json.dump(meta, f, indent=1)
    return meta


def decode_axis(frames, meta, axis, white):
    """One axis of the shown point: the coarse code, refined by each period's phase while
    the blend kept it (a blend of points far apart on that period averages its phase away)."""
    lo, size = meta["lo"][axis], meta["size"][axis]
    estimate = None
    for code_axis, period in meta["codes"]:
        if code_axis != axis:
            continue
        code = frames["code_%d_%g" % (axis, period)] / white[..., None]
        if estimate is None:
            estimate = lo + (code[..., 0] - 1.0) * size
        c, s = 2.0 * code[..., 1] - 1.0, 2.0 * code[..., 2] - 1.0
        kept = np.hypot(c, s) > 0.5
        fine = np.arctan2(s, c) / (2.0 * math.pi) * period
        refined = fine + period * np.round((estimate - fine) / period)
        estimate = np.where(kept, refined, estimate)
    return estimate


def angle_deg(a, b):
    cos = np.sum(a * b, axis=-1) / np.maximum(
        np.linalg.norm(a, axis=-1) * np.linalg.norm(b, axis=-1), 1e-12)
    return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))


def mirror_view(args, meta, camera, frames):
    """A camera's mirror pixels: mask, floor points, normals, the decoded shown points and
    the rendered weight."""
    white = frames["white"][..., 0]
    normal = frames["normal"] * 2.0 - 1.0
    mirror = normal[..., 2] > MIRROR_NORMAL_Z
    if not mirror.any():
        print("render_check: %s: camera %s sees no floor (no surface facing up): move it" % (
            args.camera_file, camera["name"]), file=sys.stderr)
        sys.exit(2)
    x = frames["position"] + np.array(meta["lo"])
    safe = np.where(white > 1e-6, white, 1.0)
    shown = np.stack([decode_axis(frames, meta, a, safe) for a in range(3)], axis=-1)
    return {"mirror": mirror, "points": x[mirror], "normals": normal[mirror],
            "eye": camera["eye"], "shown": shown[mirror], "white": white[mirror]}


def predicted_decode(texels, meta):
    """The point the decoder reads from the pixel the model predicts: each code's colours
    blended with the model's weights, then decoded as the renderer's frames are. Where a
    pixel blends points far apart, the phase codes average to neither (decode_axis keeps the
    coarse code there): comparing the decoded model with the decoded frame measures the
    renderer, not the code."""
    pixel = np.repeat(np.arange(len(texels)), [len(t) for t in texels])
    flat = np.array([t for ts in texels for t in ts], dtype=float).reshape(-1, 4)
    weight, points = flat[:, 0], flat[:, 1:]

    def blended(values):
        out = np.zeros((len(texels),) + values.shape[1:])
        np.add.at(out, pixel, weight.reshape((-1,) + (1,) * (values.ndim - 1)) * values)
        return out

    white = blended(np.ones(len(weight)))
    codes = {"code_%d_%g" % (a, p): blended(position_code.colour(points, meta["lo"],
                                                                  meta["size"], a, p))
             for a, p in meta["codes"]}
    safe = np.where(white > 0.0, white, 1.0)
    decoded = np.stack([decode_axis(codes, meta, a, safe) for a in range(3)], axis=-1)
    decoded[~(white > 0.0)] = np.nan
    return decoded


def set_pixels(module, args, proxies, views, meta):
    """Per camera's mirror pixels: rendered and predicted error (nan where uncovered) and the
    two weights. The model runs once for all cameras (the level loads once)."""
    points = np.concatenate([v["points"] for v in views])
    model = module.engine_reflections(
        args.scene, proxies, args.engine, [tuple(p) for p in points],
        [tuple(n) for v in views for n in v["normals"]],
        [tuple(v["eye"]) for v in views for _ in range(len(v["points"]))])
    true_hit = np.array([h if h is not None else (np.nan,) * 3 for h in model["true_hit"]])
    predicted = predicted_decode(model["texels"], meta)
    predicted_weight = np.array(model["surface_weight"])
    shown = np.concatenate([v["shown"] for v in views])
    white = np.concatenate([v["white"] for v in views])
    rendered_error = angle_deg(shown - points, true_hit - points)
    predicted_error = angle_deg(predicted - points, true_hit - points)
    sky = np.isnan(true_hit[:, 0])
    rendered_error[sky | ~(white > MIN_WEIGHT)] = np.nan
    predicted_error[sky | ~(predicted_weight > MIN_WEIGHT)] = np.nan
    pixels, start = [], 0
    for v in views:
        end = start + len(v["points"])
        pixels.append({"mirror": v["mirror"], "rendered": rendered_error[start:end],
                       "predicted": predicted_error[start:end], "white": white[start:end],
                       "predicted_weight": predicted_weight[start:end]})
        start = end
    return pixels


def figures(errors):
    """Median, p95 and share over 5 deg of the pixels a probe reaches; and of all mirror pixels
    the share not right: over 5 deg, or showing no probe (the world where the level stands)."""
    shown = ~np.isnan(errors)
    valid = errors[shown]
    not_right = float(np.mean(~shown | (np.where(shown, errors, 0.0) > OVER_DEG)))
    if valid.size == 0:
        return {"median_deg": None, "p95_deg": None, "over_5_share": None,
                "not_right_share": not_right}
    return {"median_deg": float(np.median(valid)), "p95_deg": float(np.percentile(valid, 95)),
            "over_5_share": float(np.mean(valid > OVER_DEG)), "not_right_share": not_right}


def level_survey(out, name):
    """The layout's own level-wide figures for the engine (survey's floor and cameras, the
    angle seen from the capture point): beside the pixels, not the same measure."""
    path = os.path.join(out, name, "layout.json")
    if not os.path.isfile(path):
        return None
    with open(path) as f:
        survey = json.load(f)["survey"]
    return {k: survey[k] for k in ("p95_deg", "over_tolerance_share", "uncovered_share")}


def set_figures(pixels):
    rendered = np.concatenate([p["rendered"] for p in pixels])
    predicted = np.concatenate([p["predicted"] for p in pixels])
    both = ~np.isnan(rendered) & ~np.isnan(predicted)
    white = np.concatenate([p["white"] for p in pixels])
    weight = np.concatenate([p["predicted_weight"] for p in pixels])
    r, p = figures(rendered), figures(predicted)
    return {"mirror_pixels": int(rendered.size),
            "rendered": r | {"uncovered_share": float(np.mean(np.isnan(rendered)))},
            "predicted": p | {"uncovered_share": float(np.mean(np.isnan(predicted)))},
            "median_abs_difference_deg": float(np.median(np.abs(rendered[both] - predicted[both])))
            if both.any() else None,
            "over_5_share_difference": (r["over_5_share"] - p["over_5_share"])
            if r["over_5_share"] is not None and p["over_5_share"] is not None else None,
            "median_weight_difference": float(np.median(np.abs(white - weight)))}


RENDERER_NAMES = {"eevee": "EEVEE", "godot3": "Godot 3"}


def picture(module, path, camera, rows, width, height, engine):
    """Per set: rendered error | predicted error, survey's colour scale, with a legend."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import BoundaryNorm, ListedColormap
    scale = module.survey_scale()
    edges = [e for e, _ in scale] + [180.0]
    cmap = ListedColormap([tuple(c / 255.0 for c in rgb) for _, rgb in scale])
    cmap.set_bad((0.12, 0.12, 0.12))
    norm = BoundaryNorm(edges, cmap.N)
    fig, axes = plt.subplots(len(rows), 2, figsize=(12, 3.6 * len(rows) + 0.8), squeeze=False)
    for row, (name, pixels, fig_r, fig_p) in enumerate(rows):
        for col, (kind, figs) in enumerate((("rendered", fig_r), ("predicted", fig_p))):
            image = np.full((height, width), np.nan)
            image[pixels["mirror"]] = pixels[kind]
            ax = axes[row][col]
            ax.imshow(np.ma.masked_invalid(image), cmap=cmap, norm=norm,
                      interpolation="nearest")
            over = figs["over_5_share"]
            unseen = float(np.mean(np.isnan(pixels[kind])))
            ax.set_title("%s, %s by %s: median %s deg, %s over 5 deg%s" % (
                name, kind, RENDERER_NAMES[engine] if kind == "rendered" else "the model",
                "-" if figs["median_deg"] is None else "%.2f" % figs["median_deg"],
                "-" if over is None else "%.0f%%" % (100 * over),
                ", %.0f%% no probe" % (100 * unseen) if unseen > 0 else ""), fontsize=9)
            ax.set_xticks([]), ax.set_yticks([])
    bar = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=axes, orientation=
                       "horizontal", fraction=0.04, pad=0.03, ticks=edges[:-1])
    bar.set_label("reflection error at the mirror pixel, degrees (dark grey: not a mirror, "
                  "or no probe: the sky)")
    fig.suptitle("camera %s: eye %s, looking at %s" % (camera["name"], camera["eye"],
                                                       camera["target"]))
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("probeproxy")
    parser.add_argument("scene")
    parser.add_argument("cameras")
    parser.add_argument("--module-dir", required=True, help="where probeproxy_py is built")
    parser.add_argument("--engine", choices=sorted(PRESETS), default="eevee",
                        help="the renderer: eevee (Blender) or godot3 (godot3-runner)")
    parser.add_argument("--blender", default="blender")
    parser.add_argument("--capture-height", type=float,
                        help="the layout's and the grid's --capture-height (default: layout's)")
    parser.add_argument("--out", required=True)
    parser.add_argument("--max-cameras", type=int, default=None,
                        help="the first N cameras of the file only (a quicker check)")
    parser.add_argument("--require-agreement", action="store_true",
                        help="exit 1 unless, for every set, the median absolute difference "
                        "between rendered and predicted per-pixel error is under %g deg and the "
                        "shares over 5 deg are within %g points" % (AGREE_DEG, 100 * AGREE_SHARE))
    args = parser.parse_args()
    for path in (args.scene, args.cameras):
        if not os.path.isfile(path):
            print("render_check: %s: no such file" % path, file=sys.stderr)
            return 2
    args.scene, args.cameras = os.path.abspath(args.scene), os.path.abspath(args.cameras)
    args.module_dir = os.path.abspath(args.module_dir)
    sys.path.insert(0, args.module_dir)
    import probeproxy_py as module
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    with open(args.cameras) as f:
        camera_file = json.load(f)
    cameras, region = camera_file["cameras"][:args.max_cameras], camera_file.get("region")
    # The renderers read the cameras used, from the output folder.
    args.camera_file, args.cameras = args.cameras, os.path.join(out, "cameras.json")
    with open(args.cameras, "w") as f:
        json.dump(camera_file | {"cameras": cameras}, f, indent=1)
    report = {"scene": args.scene, "engine": args.engine, "sets": {}}
    rows = {c["name"]: [] for c in cameras}
    geometry = {}  # per camera: where its rays land, the same for every set of probes
    for name, proxies in lay_out(args, out, region):
        render = render_eevee if args.engine == "eevee" else render_godot
        meta = render(args, proxies, os.path.join(out, name, "frames"), not geometry)
        views = []
        for camera in cameras:
            frames = dict(np.load(os.path.join(out, name, "frames", camera["name"] + ".npz")))
            if camera["name"] not in geometry:
                geometry[camera["name"]] = {k: frames[k] for k in ("position", "normal")}
            views.append(mirror_view(args, meta, camera, frames | geometry[camera["name"]]))
        pixels = set_pixels(module, args, proxies, views, meta)
        for camera, p in zip(cameras, pixels):
            rows[camera["name"]].append((name, p, figures(p["rendered"]),
                                         figures(p["predicted"])))
        report["sets"][name] = set_figures(pixels) | {
            "proxies": os.path.relpath(proxies, out), "survey": level_survey(out, name),
            "probes": len(meta["probes"]), "render_seconds": render_seconds(meta)}
    for camera in cameras:
        picture(module, os.path.join(out, "render_check_%s.png" % camera["name"]), camera,
                rows[camera["name"]], meta["width"], meta["height"], args.engine)
    with open(os.path.join(out, "render_check.json"), "w") as f:
        json.dump(report, f, indent=1)
    for name, s in report["sets"].items():
        r, p = s["rendered"], s["predicted"]
        print("%-8s rendered: median %s p95 %s over 5 %s uncovered %.0f%% not right %s | "
              "predicted: over 5 %s uncovered %.0f%% not right %s | median |diff| %s deg" % (
                  name, fmt(r["median_deg"]), fmt(r["p95_deg"]), pct(r["over_5_share"]),
                  100 * r["uncovered_share"], pct(r["not_right_share"]), pct(p["over_5_share"]),
                  100 * p["uncovered_share"], pct(p["not_right_share"]),
                  fmt(s["median_abs_difference_deg"])))
    if args.require_agreement:
        disagree = [name for name, s in report["sets"].items() if not agrees(s)]
        if disagree:
            print("render_check: the model and %s disagree on %s (over %g deg median, or %g "
                  "points of the share over 5 deg)" % (args.engine, ", ".join(disagree),
                                                       AGREE_DEG, 100 * AGREE_SHARE))
            return 1
    return 0


def render_seconds(meta):
    """The renderer's seconds for a set: EEVEE times each pass, Godot its one process."""
    seconds = meta["seconds"]
    return round(sum(seconds.values()) if isinstance(seconds, dict) else seconds, 1)


def agrees(s):
    d, share = s["median_abs_difference_deg"], s["over_5_share_difference"]
    wrong = s["rendered"]["not_right_share"] - s["predicted"]["not_right_share"]
    return (d is not None and d < AGREE_DEG and share is not None and abs(share) <= AGREE_SHARE
            and abs(wrong) <= AGREE_SHARE)


def fmt(v):
    return "-" if v is None else "%.2f" % v


def pct(v):
    return "-" if v is None else "%.1f%%" % (100 * v)


if __name__ == "__main__":
    sys.exit(main())
