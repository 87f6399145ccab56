# Between Blender objects and the scene file's dict (README "Scene file"), in the world frame
# (Z up, metres: Blender's). Blender stores 32-bit floats; each number is written as the
# shortest decimal that reads back to the same 32-bit value, so 1.6 typed or imported comes
# back as 1.6, and an unedited scene gives the library the very numbers the file holds.

import array
import hashlib
import json
import os
import struct

import bpy
from mathutils import Matrix, Quaternion, Vector


def f32(value):
    """The shortest decimal that is the same 32-bit float as `value`."""
    single = struct.unpack("f", struct.pack("f", value))[0]
    for digits in range(1, 10):
        text = "%.*g" % (digits, single)
        if struct.unpack("f", struct.pack("f", float(text)))[0] == single:
            return float(text)
    return single


def vec(values):
    return [f32(v) for v in values]


def add(a, b):
    # Sums of two short decimals, rounded as the scene writer rounds (1e-9 of a unit).
    return [round(x + y, 9) for x, y in zip(vec(a), vec(b))]


def is_probe(obj):
    return obj.probeproxy.is_probe


def probes(scene):
    return sorted((o for o in scene.objects if is_probe(o)),
                  key=lambda o: (o.probeproxy.order, o.name))


def probe_rotation(obj):
    if obj.rotation_mode == "QUATERNION":
        return vec(obj.rotation_quaternion)
    return vec(obj.matrix_world.to_quaternion())


def probe_dict(obj):
    s = obj.probeproxy
    capture = vec(obj.matrix_world.translation)
    center = add(capture, s.influence_offset)
    if s.influence_shape == "BOX":
        influence = {"kind": "box", "center": center, "half_extents": vec(s.half_extents),
                     "rotation": probe_rotation(obj),
                     "inner_half_extents": vec(s.inner_half_extents)}
    else:
        influence = {"kind": "sphere", "center": center, "radius": f32(s.radius),
                     "inner_radius": f32(s.inner_radius)}
    if s.proxy_mode == "AUTO":
        proxy = "auto"
    elif s.proxy_mode == "INFINITE":
        proxy = "infinite"
    elif s.proxy_mode == "BOX":
        rotation = vec(s.proxy_rotation)
        proxy = {"kind": "box", "center": vec(s.proxy_center),
                 "half_extents": vec(s.proxy_half_extents)}
        if rotation != [1.0, 0.0, 0.0, 0.0]:
            proxy["kind"] = "obb"
            proxy["rotation"] = rotation
    elif s.proxy_mode == "SPHERE":
        proxy = {"kind": "sphere", "center": vec(s.proxy_center), "radius": f32(s.proxy_radius)}
    else:
        proxy = {"kind": "convex", "mesh": s.proxy_mesh}
    d = {"name": obj.name, "capture": capture, "influence": influence, "proxy": proxy}
    d.update(json.loads(s.extra_json or "{}"))
    return d


def scene_anchor(scene):
    """The file the scene dict stands for: its scene file, or one beside the .blend."""
    settings = scene.probeproxy
    if settings.scene_file:
        return bpy.path.abspath(settings.scene_file)
    folder = os.path.dirname(bpy.data.filepath) if bpy.data.filepath else os.getcwd()
    return os.path.join(folder, "untitled.scene.json")


def scene_dict(scene):
    """The scene file's dict for the probes in `scene`, world frame (up Z, metres)."""
    level = json.loads(scene.probeproxy.level_json or "[]")
    if not level:  # a level authored in Blender: Save Scene writes it to this file
        level = [{"mesh": "level.glb"}]
    return {"probeproxy_scene": 1, "up": "Z", "meters_per_unit": 1.0, "level": level,
            "probes": [probe_dict(o) for o in probes(scene)]}


def set_probe_from_dict(obj, d):
    """Sets a probe object from a world-frame probe dict."""
    s = obj.probeproxy
    s.is_probe = True
    obj.rotation_mode = "QUATERNION"
    obj.location = d["capture"]
    inf = d["influence"]
    s.influence_offset = [c - p for c, p in zip(inf["center"], d["capture"])]
    if inf["kind"] == "box":
        s.influence_shape = "BOX"
        s.half_extents = inf["half_extents"]
        s.inner_half_extents = inf.get("inner_half_extents", inf["half_extents"])
        obj.rotation_quaternion = inf.get("rotation", [1, 0, 0, 0])
    else:
        s.influence_shape = "SPHERE"
        s.radius = inf["radius"]
        s.inner_radius = inf.get("inner_radius", inf["radius"])
        obj.rotation_quaternion = (1, 0, 0, 0)
    proxy = d["proxy"]
    if proxy == "auto":
        s.proxy_mode = "AUTO"
    elif proxy == "infinite":
        s.proxy_mode = "INFINITE"
    elif proxy["kind"] in ("box", "obb"):
        s.proxy_mode = "BOX"
        s.proxy_center = proxy["center"]
        s.proxy_half_extents = proxy["half_extents"]
        s.proxy_rotation = proxy.get("rotation", [1, 0, 0, 0])
    elif proxy["kind"] == "sphere":
        s.proxy_mode = "SPHERE"
        s.proxy_center = proxy["center"]
        s.proxy_radius = proxy["radius"]
    else:
        s.proxy_mode = "MESH"
        s.proxy_mesh = proxy["mesh"]
    extra = {k: d[k] for k in ("cubemap", "reflection_planes") if k in d}
    s.extra_json = json.dumps(extra)


def world_triangles(obj, depsgraph):
    """The evaluated mesh of `obj` as flat world-space vertices (float64) and triangles."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        mesh.calc_loop_triangles()
        co = array.array("f", [0.0]) * (len(mesh.vertices) * 3)
        mesh.vertices.foreach_get("co", co)
        tris = array.array("i", [0]) * (len(mesh.loop_triangles) * 3)
        mesh.loop_triangles.foreach_get("vertices", tris)
        m = evaluated.matrix_world
        world = array.array("d")
        for i in range(0, len(co), 3):
            world.extend(m @ Vector((co[i], co[i + 1], co[i + 2])))
        return world, tris
    finally:
        evaluated.to_mesh_clear()


def fingerprint(obj, depsgraph):
    vertices, triangles = world_triangles(obj, depsgraph)
    h = hashlib.sha1(vertices.tobytes())
    h.update(triangles.tobytes())
    return h.hexdigest()


def is_level_object(obj):
    s = obj.probeproxy
    return obj.type == "MESH" and not s.is_probe and not s.is_proxy


def level_parts(context, objects):
    """The level the library builds from: each scene-file mesh whose imported objects are all
    among `objects` and unchanged goes as the file itself (so the figures are the CLI's, to
    the bit); every other object goes as its evaluated world-space triangles."""
    depsgraph = context.evaluated_depsgraph_get()
    by_index = {}
    for obj in context.scene.objects:
        if is_level_object(obj) and obj.probeproxy.level_index >= 0:
            by_index.setdefault(obj.probeproxy.level_index, []).append(obj)
    chosen = set(o.name for o in objects)
    parts, from_files, from_blender = [], [], []
    covered = set()
    for index in sorted(by_index):
        group = by_index[index]
        if all(o.name in chosen and fingerprint(o, depsgraph) == o.probeproxy.level_fingerprint
               for o in group):
            parts.append({"scene_level": index})
            from_files.append(index)
            covered.update(o.name for o in group)
    for obj in sorted(objects, key=lambda o: o.name):
        if obj.name in covered:
            continue
        vertices, triangles = world_triangles(obj, depsgraph)
        if len(triangles):
            parts.append({"name": obj.name, "vertices": vertices, "triangles": triangles})
            from_blender.append(obj.name)
    summary = []
    if from_files:
        summary.append("%d scene-file mesh(es)" % len(from_files))
    if from_blender:
        summary.append("%d Blender mesh(es)" % len(from_blender))
    return parts, ", ".join(summary) or "nothing"
