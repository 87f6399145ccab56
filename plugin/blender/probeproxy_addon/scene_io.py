# Between Blender objects and the scene file's dict (docs/cli_and_formats.md "Scene file"), in the world frame
# (Z up, metres). Blender stores 32-bit floats; each number is written as the shortest decimal
# that reads back to the same 32-bit value, so 1.6 typed or imported comes back as 1.6, and an
# unedited scene gives the library the very numbers the file holds.
#
# Units: a Blender unit is `scene.unit_settings.scale_length` metres (Unit Scale; 0.01 for a
# level modelled in centimetres). Everything handed to the library is in metres, everything
# read back is turned into Blender units (`meters_per_bu`).
# Transforms: a probe's capture point, influence centre, rotation and extents follow the
# object's full world matrix (parents, any rotation mode, delta transforms, scale). The
# influence's centre offset and extents are in the probe's own frame, so they turn, move and
# scale with it. Authored proxy boxes and spheres are world-space shapes (the room's walls):
# they stay where they are when the capture point moves.

import array
import hashlib
import json
import os
import struct

import bpy
from mathutils import Matrix, Quaternion, Vector


def collection(scene, name):
    """The collection `name`, made and linked under the scene's when it is missing."""
    coll = bpy.data.collections.get(name)
    if coll is None:
        coll = bpy.data.collections.new(name)
    if coll.name not in scene.collection.children:
        scene.collection.children.link(coll)
    return coll


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


def meters_per_bu(scene):
    """Metres per Blender unit: the scene's Unit Scale, as typed (Blender stores 0.01 as the
    32-bit 0.0099999998; the shortest decimal of it is the 0.01 the artist meant)."""
    scale = f32(scene.unit_settings.scale_length)
    return scale if scale > 0 else 1.0


def to_meters(values, scale):
    """Blender-unit numbers (already shortest decimals) in metres; untouched at scale 1, so a
    metre scene gives the library the file's own numbers; else rounded to 1e-9 m, as the scene
    writer rounds."""
    if scale == 1.0:
        return list(values) if isinstance(values, list) else values
    if isinstance(values, list):
        return [round(v * scale, 9) for v in values]
    return round(values * scale, 9)


def per_meter(value, scale):
    """A per-Blender-unit factor (cheap_k's k) per metre; untouched at scale 1, else rounded
    to 12 significant digits, as the scene writer rounds it."""
    return value if scale == 1.0 else float("%.12g" % (value / scale))


def to_bu(values, scale):
    """Metres in Blender units."""
    if scale == 1.0:
        return values
    if isinstance(values, (int, float)):
        return values / scale
    return [v / scale for v in values]


def _rotate(q, v):
    """Quaternion [w, x, y, z] (unit) applied to a 3-vector, in doubles."""
    w, x, y, z = q
    tx = 2 * (y * v[2] - z * v[1])
    ty = 2 * (z * v[0] - x * v[2])
    tz = 2 * (x * v[1] - y * v[0])
    return [v[0] + w * tx + (y * tz - z * ty), v[1] + w * ty + (z * tx - x * tz),
            v[2] + w * tz + (x * ty - y * tx)]


def _inverse_rotate(q, v):
    return _rotate([q[0], -q[1], -q[2], -q[3]], v)


def _is_plain(obj):
    """No parent, no delta transforms, quaternion mode: the object's own numbers are its world
    transform, exactly as typed or imported."""
    return (obj.parent is None and obj.rotation_mode == "QUATERNION"
            and tuple(obj.delta_location) == (0, 0, 0)
            and tuple(obj.delta_rotation_quaternion) == (1, 0, 0, 0)
            and tuple(obj.delta_scale) == (1, 1, 1))


def probe_frame(obj):
    """The probe's world transform as (capture, rotation [w, x, y, z], scale), Blender units,
    from its full world matrix. A scale within 1e-6 of 1 is 1 (float noise through parents)."""
    m = obj.matrix_world
    capture = vec(m.translation)
    if _is_plain(obj):
        rotation = vec(obj.rotation_quaternion)
    else:
        rotation = vec(m.to_quaternion())  # Blender normalizes the scale out first
    scale = [abs(f32(c)) for c in m.to_scale()]
    scale = [1.0 if abs(c - 1.0) <= 1e-6 else c for c in scale]
    return capture, rotation, scale


def probe_rotation(obj):
    return probe_frame(obj)[1]


def influence_world(obj):
    """The influence volume in the world, Blender units: a dict with `center`, `rotation` and
    `half_extents` + `inner_half_extents` (box) or `radius` + `inner_radius` (sphere)."""
    s = obj.probeproxy
    capture, rotation, scale = probe_frame(obj)
    local = [o * c for o, c in zip(vec(s.influence_offset), scale)]
    offset = local if rotation == [1.0, 0.0, 0.0, 0.0] else vec(_rotate(rotation, local))
    out = {"center": add(capture, offset), "rotation": rotation}
    if s.influence_shape == "BOX":
        out["half_extents"] = [f32(h * c) for h, c in zip(vec(s.half_extents), scale)]
        out["inner_half_extents"] = [f32(h * c) for h, c in zip(vec(s.inner_half_extents), scale)]
    else:  # a sphere scales by its largest axis: an influence sphere has one radius
        out["radius"] = f32(f32(s.radius) * max(scale))
        out["inner_radius"] = f32(f32(s.inner_radius) * max(scale))
    return out


def is_probe(obj):
    return obj.probeproxy.is_probe


def probes(scene):
    return sorted((o for o in scene.objects if is_probe(o)),
                  key=lambda o: (o.probeproxy.order, o.name))


def probe_dict(obj, meters_per_unit=1.0, proxy_override=None):
    """The probe as the scene file's dict, world frame, metres (`meters_per_unit`: metres per
    Blender unit). `proxy_override`: a proxy entry to use instead of the object's settings."""
    s = obj.probeproxy
    k = meters_per_unit
    capture = probe_frame(obj)[0]
    inf = influence_world(obj)
    if s.influence_shape == "BOX":
        influence = {"kind": "box", "center": to_meters(inf["center"], k),
                     "half_extents": to_meters(inf["half_extents"], k),
                     "rotation": inf["rotation"],
                     "inner_half_extents": to_meters(inf["inner_half_extents"], k)}
    else:
        influence = {"kind": "sphere", "center": to_meters(inf["center"], k),
                     "radius": to_meters(inf["radius"], k),
                     "inner_radius": to_meters(inf["inner_radius"], k)}
    if proxy_override is not None:
        proxy = proxy_override
    elif s.proxy_mode == "AUTO":
        proxy = "auto"
    elif s.proxy_mode == "INFINITE":
        proxy = "infinite"
    elif s.proxy_mode == "BOX":
        rotation = vec(s.proxy_rotation)
        proxy = {"kind": "box", "center": to_meters(vec(s.proxy_center), k),
                 "half_extents": to_meters(vec(s.proxy_half_extents), k)}
        if rotation != [1.0, 0.0, 0.0, 0.0]:
            proxy["kind"] = "obb"
            proxy["rotation"] = rotation
    elif s.proxy_mode == "SPHERE":
        proxy = {"kind": "sphere", "center": to_meters(vec(s.proxy_center), k),
                 "radius": to_meters(f32(s.proxy_radius), k)}
    elif s.proxy_mode == "CHEAP_K":
        proxy = {"kind": "cheap_k", "k": per_meter(f32(s.proxy_k), k)}
    else:
        proxy = {"kind": "convex", "mesh": s.proxy_mesh}
    d = {"name": obj.name, "capture": to_meters(capture, k), "influence": influence,
         "proxy": proxy}
    d.update(json.loads(s.extra_json or "{}"))
    return d


def scene_anchor(scene):
    """The file the scene dict stands for: its scene file, or one beside the .blend."""
    settings = scene.probeproxy
    if settings.scene_file:
        return bpy.path.abspath(settings.scene_file)
    return os.path.join(_unsaved_folder(), "untitled.scene.json")


def _unsaved_folder():
    """Beside the .blend; for an unsaved one the working folder, or Blender's temporary folder
    where that is gone or not writable (Blender started from a folder the artist cannot write)."""
    if bpy.data.filepath:
        return os.path.dirname(bpy.data.filepath)
    try:
        folder = os.getcwd()
    except OSError:  # the folder Blender started in was removed
        return bpy.app.tempdir
    return folder if os.access(folder, os.W_OK) else bpy.app.tempdir


def scene_dict(scene, proxy_overrides=None):
    """The scene file's dict for the probes in `scene`, world frame (up Z, metres, whatever the
    scene's Unit Scale). `proxy_overrides`: probe name -> proxy entry (hand-edited proxies)."""
    level = json.loads(scene.probeproxy.level_json or "[]")
    if not level:  # a level authored in Blender: Save Scene writes it to this file
        level = [{"mesh": "level.glb"}]
    k = meters_per_bu(scene)
    overrides = proxy_overrides or {}
    d = {"probeproxy_scene": 1, "up": "Z", "meters_per_unit": 1.0, "level": level,
         "probes": [probe_dict(o, k, overrides.get(o.name)) for o in probes(scene)]}
    measured_with = json.loads(scene.probeproxy.measured_with_json or "{}")
    if measured_with:  # world frame, metres, as the module handed it over
        d["measured_with"] = measured_with
    return d


def set_probe_from_dict(obj, d, meters_per_unit=1.0):
    """Sets a probe object from a world-frame probe dict in metres (`meters_per_unit`: metres
    per Blender unit of the scene it goes into). The object's world matrix becomes the capture
    point and the influence's rotation, scale 1, whatever its parent."""
    k = meters_per_unit
    s = obj.probeproxy
    s.is_probe = True
    obj.rotation_mode = "QUATERNION"
    capture = to_bu(d["capture"], k)
    inf = d["influence"]
    rotation = inf.get("rotation", [1, 0, 0, 0]) if inf["kind"] == "box" else [1, 0, 0, 0]
    world = Matrix.Translation(capture) @ Quaternion(rotation).to_matrix().to_4x4()
    if obj.parent is None:
        obj.location = capture
        obj.rotation_quaternion = rotation
        obj.scale = (1, 1, 1)
    else:
        obj.matrix_world = world
    offset = [c - p for c, p in zip(to_bu(inf["center"], k), capture)]
    if [float(r) for r in rotation] != [1.0, 0.0, 0.0, 0.0]:
        offset = _inverse_rotate([float(r) for r in rotation], offset)
    s.influence_offset = offset
    if inf["kind"] == "box":
        s.influence_shape = "BOX"
        s.half_extents = to_bu(inf["half_extents"], k)
        s.inner_half_extents = to_bu(inf.get("inner_half_extents", inf["half_extents"]), k)
    else:
        s.influence_shape = "SPHERE"
        s.radius = to_bu(inf["radius"], k)
        s.inner_radius = to_bu(inf.get("inner_radius", inf["radius"]), k)
    proxy = d["proxy"]
    if proxy == "auto":
        s.proxy_mode = "AUTO"
    elif proxy == "infinite":
        s.proxy_mode = "INFINITE"
    elif proxy["kind"] in ("box", "obb"):
        s.proxy_mode = "BOX"
        s.proxy_center = to_bu(proxy["center"], k)
        s.proxy_half_extents = to_bu(proxy["half_extents"], k)
        s.proxy_rotation = proxy.get("rotation", [1, 0, 0, 0])
    elif proxy["kind"] == "sphere":
        s.proxy_mode = "SPHERE"
        s.proxy_center = to_bu(proxy["center"], k)
        s.proxy_radius = to_bu(proxy["radius"], k)
    elif proxy["kind"] == "cheap_k":
        s.proxy_mode = "CHEAP_K"
        s.proxy_k = proxy["k"] * k
    else:
        s.proxy_mode = "MESH"
        s.proxy_mesh = proxy["mesh"]
    extra = {k2: d[k2] for k2 in ("cubemap", "reflection_planes") if k2 in d}
    s.extra_json = json.dumps(extra)


def _append_triangles(evaluated, matrix, meters_per_unit, world, triangles):
    """Appends an evaluated mesh object's triangles, placed by `matrix`, to `world` (flat
    vertices) and `triangles` (indices into them)."""
    mesh = evaluated.to_mesh()
    try:
        mesh.calc_loop_triangles()
        co = array.array("f", [0.0]) * (len(mesh.vertices) * 3)
        mesh.vertices.foreach_get("co", co)
        tris = array.array("i", [0]) * (len(mesh.loop_triangles) * 3)
        mesh.loop_triangles.foreach_get("vertices", tris)
        first = len(world) // 3
        for i in range(0, len(co), 3):
            p = matrix @ Vector((co[i], co[i + 1], co[i + 2]))
            world.extend(p if meters_per_unit == 1.0 else [c * meters_per_unit for c in p])
        triangles.extend(tris if first == 0 else array.array("i", (t + first for t in tris)))
    finally:
        evaluated.to_mesh_clear()


def world_triangles(obj, depsgraph, meters_per_unit=1.0):
    """The evaluated mesh of `obj` (or, for a collection instance, of every mesh it instances
    that renders) as flat world-space vertices (float64, Blender units times
    `meters_per_unit`) and triangles."""
    world, triangles = array.array("d"), array.array("i")
    if is_collection_instance(obj):
        for instance in depsgraph.object_instances:
            parent = instance.parent
            member = instance.object
            if (instance.is_instance and parent is not None and parent.original == obj
                    and member.type == "MESH" and renders(member.original)):
                _append_triangles(member, instance.matrix_world.copy(), meters_per_unit, world,
                                  triangles)
    else:
        evaluated = obj.evaluated_get(depsgraph)
        _append_triangles(evaluated, evaluated.matrix_world, meters_per_unit, world, triangles)
    return world, triangles


def mesh_fingerprint(obj, probe):
    """A hash of a proxy object's own mesh data and of its placement relative to its probe (no
    depsgraph: a new object has none yet): changes with any vertex moved, added or removed, and
    with the proxy moved on its own; not when the level is moved or scaled with its probes and
    proxies (that is no edit of the proxy: Generate builds it again)."""
    mesh = obj.data
    co = array.array("f", [0.0]) * (len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", co)
    loops = array.array("i", [0]) * len(mesh.loops)
    mesh.loops.foreach_get("vertex_index", loops)
    h = hashlib.sha1(co.tobytes())
    h.update(loops.tobytes())
    relative = probe.matrix_world.inverted_safe() @ obj.matrix_world
    # Six digits: moving a whole level leaves the product equal but for rounding.
    h.update(" ".join("%.6g" % (c + 0.0) for row in relative for c in row).encode())
    return h.hexdigest()


def fingerprint(obj, depsgraph):
    vertices, triangles = world_triangles(obj, depsgraph)
    h = hashlib.sha1(vertices.tobytes())
    h.update(triangles.tobytes())
    return h.hexdigest()


def renders(obj):
    """Whether a render shows the object: its own Disable in Renders and its collections'. A
    mesh hidden from renders (a blocking volume, a helper) is no wall a reflection lands on."""
    return not obj.hide_render and not any(c.hide_render for c in obj.users_collection)


def is_collection_instance(obj):
    return (obj.type == "EMPTY" and obj.instance_type == "COLLECTION"
            and obj.instance_collection is not None)


def is_level_object(obj):
    """A mesh, or an instance of a collection (its meshes that render), that the view layer
    renders and that is no probe or proxy. A collection's own objects may be excluded from the
    view layer and still render where it is instanced."""
    s = obj.probeproxy
    return ((obj.type == "MESH" or is_collection_instance(obj)) and not s.is_probe
            and not s.is_proxy and renders(obj)
            and obj.name in bpy.context.view_layer.objects)  # not in an excluded collection


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
    k = meters_per_bu(context.scene)
    for obj in sorted(objects, key=lambda o: o.name):
        if obj.name in covered:
            continue
        vertices, triangles = world_triangles(obj, depsgraph, k)
        if len(triangles):
            parts.append({"name": obj.name, "vertices": vertices, "triangles": triangles})
            from_blender.append(obj.name)
    summary = []
    if from_files:
        summary.append("%d scene-file mesh(es)" % len(from_files))
    if from_blender:
        summary.append("%d Blender mesh(es)" % len(from_blender))
    return parts, ", ".join(summary) or "nothing"
