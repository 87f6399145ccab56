# Draws every probe's volumes in the 3D view (a gpu draw handler, so nothing is added to the
# scene): the influence's outer range solid-coloured, its inner range dimmer, an authored box
# or sphere proxy in orange. World frame; the influence follows the probe's world matrix.

import math

import bpy
import gpu
from gpu_extras.batch import batch_for_shader
from mathutils import Matrix, Quaternion, Vector

from . import scene_io

_handle = None

_BOX_EDGES = [(0, 1), (1, 3), (3, 2), (2, 0), (4, 5), (5, 7), (7, 6), (6, 4),
              (0, 4), (1, 5), (2, 6), (3, 7)]


def _box_lines(center, half, rotation):
    m = Matrix.Translation(center) @ rotation.to_matrix().to_4x4()
    corners = [m @ Vector((sx * half[0], sy * half[1], sz * half[2]))
               for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
    return [corners[i] for e in _BOX_EDGES for i in e]


def _sphere_lines(center, radius, segments=48):
    lines = []
    for axes in ((0, 1), (1, 2), (0, 2)):
        for i in range(segments):
            for j in (i, i + 1):
                a = 2 * math.pi * j / segments
                p = Vector(center)
                p[axes[0]] += radius * math.cos(a)
                p[axes[1]] += radius * math.sin(a)
                lines.append(p)
    return lines


def _draw():
    context = bpy.context
    if context.scene is None or not context.scene.probeproxy.show_volumes:
        return
    outer, inner, proxy = [], [], []
    for obj in scene_io.probes(context.scene):
        s = obj.probeproxy
        inf = scene_io.influence_world(obj)  # what the library gets, in Blender units
        center = Vector(inf["center"])
        if s.influence_shape == "BOX":
            rotation = Quaternion(inf["rotation"])
            outer += _box_lines(center, inf["half_extents"], rotation)
            inner += _box_lines(center, inf["inner_half_extents"], rotation)
        else:
            outer += _sphere_lines(center, inf["radius"])
            inner += _sphere_lines(center, inf["inner_radius"])
        if s.proxy_mode == "BOX":
            proxy += _box_lines(Vector(s.proxy_center), s.proxy_half_extents,
                                Quaternion(s.proxy_rotation))
        elif s.proxy_mode == "SPHERE":
            proxy += _sphere_lines(s.proxy_center, s.proxy_radius)
    shader = gpu.shader.from_builtin("3D_UNIFORM_COLOR")
    gpu.state.blend_set("ALPHA")
    gpu.state.line_width_set(2.0)
    for lines, color in ((outer, (0.2, 0.8, 1.0, 0.9)), (inner, (0.2, 0.8, 1.0, 0.35)),
                         (proxy, (1.0, 0.55, 0.1, 0.9))):
        if lines:
            batch = batch_for_shader(shader, "LINES", {"pos": lines})
            shader.uniform_float("color", color)
            batch.draw(shader)
    gpu.state.line_width_set(1.0)
    gpu.state.blend_set("NONE")


def register():
    global _handle
    if not bpy.app.background:
        _handle = bpy.types.SpaceView3D.draw_handler_add(_draw, (), "WINDOW", "POST_VIEW")


def unregister():
    global _handle
    if _handle is not None:
        bpy.types.SpaceView3D.draw_handler_remove(_handle, "WINDOW")
        _handle = None
