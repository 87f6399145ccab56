"""Cubemap faces rendered with Cycles in the one face convention of core/cube/cube_face.h.

The table is a copy of that header's: a face is the un-mirrored photograph of a 90-degree
camera looking along `forward` with `up` at the top, so right = forward x up.
"""

import math

from . import render

#         name  forward           up                right
FACES = (
    ("px", (1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, -1.0, 0.0)),
    ("nx", (-1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, 1.0, 0.0)),
    ("py", (0.0, 1.0, 0.0), (0.0, 0.0, 1.0), (1.0, 0.0, 0.0)),
    ("ny", (0.0, -1.0, 0.0), (0.0, 0.0, 1.0), (-1.0, 0.0, 0.0)),
    ("pz", (0.0, 0.0, 1.0), (0.0, 1.0, 0.0), (-1.0, 0.0, 0.0)),
    ("nz", (0.0, 0.0, -1.0), (0.0, -1.0, 0.0), (-1.0, 0.0, 0.0)),
)


def _check_table():
    for name, f, u, r in FACES:
        cross = (f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2], f[0] * u[1] - f[1] * u[0])
        if cross != r:
            raise AssertionError(f"cube face {name}: right is not forward x up")


_check_table()


def render_cube(scene, cam, capture, pattern_path, size, samples, filter_width):
    for name, forward, up, right in FACES:
        render.place_camera(cam, capture, right, up, forward, math.pi / 2.0)
        path = pattern_path.parent / pattern_path.name.replace("{face}", name)
        render.render_exr(scene, path, size, size, samples, filter_width)
