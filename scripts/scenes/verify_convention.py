#!/usr/bin/env python3
"""Proves the suite's renders follow the cube-face convention: verify_convention.py DIR

For every probe and face, each texel of `<probe>_position_<face>.exr` holds the world point
Cycles hit through that texel's centre. Its direction from the capture point must be the
direction core/cube/cube_face.h assigns to the texel:
    forward + (2u - 1) * right + (1 - 2v) * up,  u = (col + 0.5) / N,  v = (row + 0.5) / N.
A mirrored, rotated or transposed face, or a flipped row order, is off by at least a texel
(about 1.4 degrees at 64 px), far above the tolerance. Mirror views are checked the same way
against their JSON camera (position, forward, up, fov_x_deg) with `<view>_position.exr`.
Standard library only. Prints one line per failure; exit 1 on any.
"""

import json
import math
import sys
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(Path(__file__).resolve().parent))
import exr  # noqa: E402

# name: (forward, up, right), copied from core/cube/cube_face.h on purpose: this script
# must not share the generator's table, or a wrong table would check itself.
FACES = {
    "px": ((1, 0, 0), (0, 0, 1), (0, -1, 0)),
    "nx": ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
    "py": ((0, 1, 0), (0, 0, 1), (1, 0, 0)),
    "ny": ((0, -1, 0), (0, 0, 1), (-1, 0, 0)),
    "pz": ((0, 0, 1), (0, 1, 0), (-1, 0, 0)),
    "nz": ((0, 0, -1), (0, -1, 0), (-1, 0, 0)),
}
TOLERANCE_DEG = 0.05
# Levels whose probes see the sky (position 0); everywhere else every texel must hit.
OPEN_LEVELS = {"courtyard"}


def _angle_deg(a, b):
    dot = sum(x * y for x, y in zip(a, b))
    na = math.sqrt(sum(x * x for x in a))
    nb = math.sqrt(sum(x * x for x in b))
    return math.degrees(math.acos(max(-1.0, min(1.0, dot / (na * nb)))))


def check_image(path, origin, ray, allow_sky):
    """ray(col, row, w, h) -> expected direction. Returns (problems, worst angle, sky count)."""
    width, height, planes = exr.read(path)
    r, g, b = planes["R"], planes["G"], planes["B"]
    worst, sky = 0.0, 0
    for row in range(height):
        for col in range(width):
            i = row * width + col
            p = (r[i], g[i], b[i])
            if p == (0.0, 0.0, 0.0):
                sky += 1
                continue
            d = tuple(p[k] - origin[k] for k in range(3))
            worst = max(worst, _angle_deg(d, ray(col, row, width, height)))
    problems = []
    if worst > TOLERANCE_DEG:
        problems.append(f"{path}: a texel's hit is {worst:.3f} deg off its convention direction (tolerance {TOLERANCE_DEG})")
    if sky and not allow_sky:
        problems.append(f"{path}: {sky} texel(s) hit nothing in a closed level")
    if sky == width * height:
        problems.append(f"{path}: no texel hit the level")
    return problems, worst, sky


def cube_ray(face):
    f, up, right = FACES[face]

    def ray(col, row, w, h):
        u, v = (col + 0.5) / w, (row + 0.5) / h
        return tuple(f[k] + (2 * u - 1) * right[k] + (1 - 2 * v) * up[k] for k in range(3))

    return ray


def view_ray(view):
    f, up = view["forward"], view["up"]
    right = (f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0])
    tx = math.tan(math.radians(view["fov_x_deg"]) / 2)

    def ray(col, row, w, h):
        u, v = (col + 0.5) / w, (row + 0.5) / h
        ty = tx * h / w
        return tuple(f[k] + (2 * u - 1) * tx * right[k] + (1 - 2 * v) * ty * up[k] for k in range(3))

    return ray


def main(argv):
    if len(argv) != 2:
        print("usage: verify_convention.py SUITE_DIR", file=sys.stderr)
        return 2
    root = Path(argv[1])
    problems, checked, worst_all = [], 0, 0.0
    scenes = sorted(root.glob("*/*.scene.json"))
    # Each level's own scene file (its artist variant has the same probes and images).
    scenes = [s for s in scenes if s.parent.name != "broken" and s.name == f"{s.parent.name}.scene.json"]
    if not scenes:
        print(f"{root}: no rendered levels found")
        return 1
    for scene_path in scenes:
        level = scene_path.parent
        allow_sky = level.name in OPEN_LEVELS
        scene = json.loads(scene_path.read_text(encoding="utf-8"))
        for probe in scene["probes"]:
            for face in FACES:
                path = level / "cubemaps" / f"{probe['name']}_position_{face}.exr"
                found, worst, _ = check_image(path, probe["capture"], cube_ray(face), allow_sky)
                problems += found
                worst_all = max(worst_all, worst)
                checked += 1
        for view_path in sorted((level / "mirror_views").glob("*.json")):
            view = json.loads(view_path.read_text(encoding="utf-8"))
            path = view_path.with_name(f"{view['name']}_position.exr")
            found, worst, _ = check_image(path, view["position"], view_ray(view), allow_sky)
            problems += found
            worst_all = max(worst_all, worst)
            checked += 1
    for line in problems:
        print(line)
    print(f"verify_convention: {checked} images, worst texel {worst_all:.4f} deg, {len(problems)} problem(s)",
          file=sys.stderr if problems else sys.stdout)
    return 1 if problems else 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except (OSError, KeyError, ValueError) as exc:
        print(f"verify_convention: {exc}")
        sys.exit(1)
