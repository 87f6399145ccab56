"""Cycles settings shared by every render, and the one camera that is moved between shots.

Settings aim at reproducible, nearly noise-free linear images: CPU, fixed seed, no
denoiser, no adaptive sampling, no clamping (it would cut world positions above the clamp),
no stamp metadata (it carries the date and render time, which would make runs differ).
"""

import os
import sys
from contextlib import contextmanager

import bpy
from mathutils import Matrix

from . import exr_metadata


def configure(scene):
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.seed = 0
    cycles.use_animated_seed = False
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    # Emission-only scenes need no diffuse bounces; the mirror floor needs glossy ones
    # (more than one so a mirror seen in a mirror, e.g. two floors at one height, resolves).
    cycles.max_bounces = 4
    cycles.diffuse_bounces = 0
    cycles.glossy_bounces = 4
    cycles.transmission_bounces = 0
    cycles.volume_bounces = 0
    cycles.transparent_max_bounces = 0
    cycles.pixel_filter_type = "BLACKMAN_HARRIS"
    cycles.use_auto_tile = True
    cycles.tile_size = 256

    render = scene.render
    # Keeps the synced scene between the many small renders of a level; only the camera
    # and overrides change between them.
    render.use_persistent_data = True
    render.use_motion_blur = False
    render.resolution_percentage = 100
    render.pixel_aspect_x = render.pixel_aspect_y = 1.0
    render.film_transparent = False
    render.use_compositing = False
    render.use_sequencer = False
    render.use_stamp = False
    for prop in render.bl_rna.properties:
        if prop.identifier.startswith("use_stamp"):
            setattr(render, prop.identifier, False)
    render.metadata_input = "SCENE"

    settings = render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_mode = "RGB"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"
    settings.use_preview = False

    view = scene.view_settings
    view.view_transform = "Standard"
    view.look = "None"
    view.exposure = 0.0
    view.gamma = 1.0
    scene.display_settings.display_device = "sRGB"
    scene.sequencer_colorspace_settings.name = "Linear"


def make_camera(scene):
    data = bpy.data.cameras.new("camera")
    data.type = "PERSP"
    data.sensor_fit = "HORIZONTAL"
    data.shift_x = data.shift_y = 0.0
    # The closet's walls are 0.4 m from its probe; nothing may be clipped away.
    data.clip_start = 0.001
    data.clip_end = 10000.0
    cam = bpy.data.objects.new("camera", data)
    scene.collection.objects.link(cam)
    scene.camera = cam
    return cam


def place_camera(cam, position, right, up, forward, fov_x_rad):
    """A Blender camera looks down its local -Z with +Y up, so its rotation's columns are
    (right, up, -forward)."""
    back = tuple(-c for c in forward)
    cam.matrix_world = Matrix(
        (
            (right[0], up[0], back[0], position[0]),
            (right[1], up[1], back[1], position[1]),
            (right[2], up[2], back[2], position[2]),
            (0.0, 0.0, 0.0, 1.0),
        )
    )
    cam.data.angle = fov_x_rad


def render_exr(scene, path, width, height, samples, filter_width):
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.cycles.samples = samples
    scene.cycles.filter_width = filter_width
    scene.render.filepath = str(path)
    scene.render.use_file_extension = False
    with quiet_stdout():
        bpy.ops.render.render(write_still=True)
    if not path.is_file() or path.stat().st_size == 0:
        raise RuntimeError(f"Cycles wrote no image to {path}")
    exr_metadata.strip_timings(path)


@contextmanager
def quiet_stdout():
    """Cycles prints a dozen progress lines per render (and the glTF exporter one per object)
    on stdout; hundreds of renders would bury the suite's own messages in a CTest log.
    Failures still surface: they raise, and the traceback goes to stderr."""
    sys.stdout.flush()
    saved = os.dup(1)
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    try:
        yield
    finally:
        os.dup2(saved, 1)
        os.close(saved)
        os.close(devnull)
