# Blender's own Reflection Cubemap light probes from the EEVEE presets a build or a layout
# exports (proxies.json's "eevee_reflection_cubemap", docs/engines.md), and back: what an artist
# bakes and renders in EEVEE is what probeproxy measured for it.
#
# The preset is in Blender's frame (Z up, metres) and names Blender's own properties: the
# object's location (the capture point, also the centre of both volumes), rotation and scale
# (the influence box's half-extents or the ellipsoid's radii), the light probe's influence type
# and distance, falloff, and a custom parallax box, a uniformly scaled copy of the influence.

import bpy
from mathutils import Quaternion, Vector

from . import scene_io

PRESET = "eevee_reflection_cubemap"
COLLECTION = "EEVEE Probes"
SUFFIX = "_eevee"
# What a preset sets on the light probe data, beside the object's transform.
DATA_FIELDS = ("influence_type", "influence_distance", "falloff", "use_custom_parallax",
               "parallax_type", "parallax_distance")
# A capture point may stand a few centimetres from a wall: Blender's default clip start (0.8 m)
# would bake through it.
CLIP_START_M = 0.05


def presets_in_export(export):
    """{probe name: EEVEE preset} of a proxies.json's probes that have one (a probe whose kept
    proxy is open or flat has none: the file says why)."""
    return {p["name"]: p["engines"][PRESET] for p in export["probes"]
            if p.get("engines", {}).get(PRESET) is not None}


def make_light_probe(scene, name, preset, meters_per_bu, clip_end_m=None):
    """The Reflection Cubemap `name` + "_eevee" set from `preset` (made, or updated in place so
    that a bake the artist started keeps its object). Lengths become Blender units. The bake
    sees from CLIP_START_M to `clip_end_m` (the level's size: the default 40 m clips a hall)."""
    obj = bpy.data.objects.get(name + SUFFIX)
    if obj is None or obj.type != "LIGHT_PROBE" or obj.data.type != "CUBEMAP":
        data = bpy.data.lightprobes.new(name + SUFFIX, "CUBE")  # type "CUBEMAP" once made
        obj = bpy.data.objects.new(name + SUFFIX, data)
        scene_io.collection(scene, COLLECTION).objects.link(obj)
    obj["probeproxy_probe"] = name
    obj.location = Vector(preset["location"]) / meters_per_bu
    x, y, z, w = preset["rotation_xyzw"]
    obj.rotation_mode = "QUATERNION"
    obj.rotation_quaternion = Quaternion((w, x, y, z))
    obj.scale = Vector(preset["scale"]) / meters_per_bu
    for field in DATA_FIELDS:
        setattr(obj.data, field, preset[field])
    obj.data.clip_start = CLIP_START_M / meters_per_bu
    if clip_end_m is not None:
        obj.data.clip_end = max(clip_end_m, CLIP_START_M * 2.0) / meters_per_bu
    return obj


def preset_of_light_probe(obj, meters_per_bu):
    """The preset a Reflection Cubemap object stands for, in the export's terms (metres)."""
    q = obj.matrix_world.to_quaternion()
    preset = {"location": [c * meters_per_bu for c in obj.matrix_world.translation],
              "rotation_xyzw": [q.x, q.y, q.z, q.w],
              "scale": [c * meters_per_bu for c in obj.matrix_world.to_scale()]}
    for field in DATA_FIELDS:
        preset[field] = getattr(obj.data, field)
    return preset


def level_size_m(objects, meters_per_bu):
    """The diagonal of the objects' world bounds, in metres (None without objects)."""
    corners = [o.matrix_world @ Vector(c) for o in objects for c in o.bound_box]
    if not corners:
        return None
    lo = Vector([min(c[a] for c in corners) for a in range(3)])
    hi = Vector([max(c[a] for c in corners) for a in range(3)])
    return (hi - lo).length * meters_per_bu


def light_probes(scene):
    """The scene's Reflection Cubemaps made from probes: {probe name: object}."""
    return {o["probeproxy_probe"]: o for o in scene.objects
            if o.type == "LIGHT_PROBE" and "probeproxy_probe" in o}


def make_light_probes(scene, presets, meters_per_bu, clip_end_m=None):
    """One Reflection Cubemap per preset; the ones made from probes no longer in `presets`
    go. Returns the objects, in the presets' order."""
    made = [make_light_probe(scene, name, preset, meters_per_bu, clip_end_m)
            for name, preset in presets.items()]
    for name, obj in light_probes(scene).items():
        if name not in presets:
            data = obj.data
            bpy.data.objects.remove(obj)
            if data.users == 0:
                bpy.data.lightprobes.remove(data)
    return made
