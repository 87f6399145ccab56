"""Reference mirror views: the image the C++ side must reconstruct from a probe's cubemap.

The floor under the view becomes a perfect mirror only for these renders, so the cubemaps
still show it as the emissive checker the probe really sees.
"""

import math
from contextlib import contextmanager

from . import materials, render


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


@contextmanager
def mirrored(objects, mirror):
    saved = [(obj, list(obj.data.materials)) for obj in objects]
    for obj in objects:
        materials.assign(obj, mirror)
    try:
        yield
    finally:
        for obj, mats in saved:
            obj.data.materials.clear()
            for m in mats:
                obj.data.materials.append(m)


def _place(cam, view, probe):
    position = view.position(probe.floor_z)
    forward, up = view.forward(), view.up()
    render.place_camera(cam, position, _cross(forward, up), up, forward, math.radians(view.fov_x_deg))
    return position, forward, up


def render_view(scene, cam, view, probe, floors, mirror, out_dir, width, height, samples, filter_width):
    position, forward, up = _place(cam, view, probe)
    image = out_dir / f"{view.name}.exr"
    with mirrored(floors, mirror):
        render.render_exr(scene, image, width, height, samples, filter_width)
    return {
        "name": view.name,
        "probe": probe.name,
        "image": image.name,
        "width": width,
        "height": height,
        "position": list(position),
        "forward": list(forward),
        "up": list(up),
        "fov_x_deg": view.fov_x_deg,
        "mirror_plane": {"point": [position[0], position[1], probe.floor_z], "normal": [0.0, 0.0, 1.0]},
    }


def render_position(scene, cam, view, probe, out_dir, width, height):
    """The same camera's first hits (floor not mirrored), to prove the camera model: run
    under materials.position_override."""
    _place(cam, view, probe)
    render.render_exr(scene, out_dir / f"{view.name}_position.exr", width, height, 1, materials.POSITION_FILTER_WIDTH)
