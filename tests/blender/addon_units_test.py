# Units and transforms as Blender means them, headless:
#   blender -b --factory-startup --python tests/blender/addon_units_test.py -- \
#       --addon-dir plugin/blender --module-dir build/plugin/python \
#       --cli build/plugin/cli/probeproxy --scene build/scenes/l_room/l_room.scene.json --work DIR
# Each case is compared with the same level authored in metres without parents:
#   - a centimetre scene (Unit Scale 0.01): Add Probe makes a 2 m volume (200 cm), and a
#     refused probe is named by its object, its capture point in centimetres; Import
#     Scene puts every length in centimetres,
#     the library gets the same metres, Generate keeps the same proxies with the same figures,
#     the proxy meshes are the same in metres, Save Scene reads back to the same metres (the
#     largest difference is printed) and Export writes the metre scene's proxies.json;
#   - cheap_k's k, a factor per length, is per centimetre in Blender and per metre in the file;
#   - a probe under a rotated parent: its influence turns with the parent;
#   - a scaled probe: its influence extents and centre offset scale with it;
#   - a probe in an Euler rotation mode: the same as its quaternion twin.

import json
import math
import os
import sys

import bpy
from mathutils import Matrix, Quaternion, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_harness import check, empty_folder, enable_addon, finish, import_scene, parse_args  # noqa: E402

args = parse_args("--addon-dir", "--module-dir", "--cli", "--scene", "--work")
work = empty_folder(args.work)
native, scene_io = enable_addon(args.addon_dir, args.module_dir)
scene = bpy.context.scene


def numbers(value):
    """Every number in a JSON-like value, in a fixed order."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return [float(value)]
    if isinstance(value, dict):
        return [n for k in sorted(value) for n in numbers(value[k])]
    if isinstance(value, list):
        return [n for v in value for n in numbers(v)]
    return []


def largest_difference(a, b):
    na, nb = numbers(a), numbers(b)
    if len(na) != len(nb):
        return float("inf")
    return max((abs(x - y) for x, y in zip(na, nb)), default=0.0)


def same_shape(a, b):
    """Equal apart from numbers."""
    if isinstance(a, dict) and isinstance(b, dict):
        return sorted(a) == sorted(b) and all(same_shape(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same_shape(x, y) for x, y in zip(a, b))
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return True
    return a == b


def results():
    return {o.name: json.loads(o.probeproxy.result_json) for o in scene_io.probes(scene)}


def proxy_vertices_m():
    k = scene_io.meters_per_bu(scene)
    out = {}
    for o in scene_io.probes(scene):
        obj = o.probeproxy.proxy_object
        out[o.name] = [[c * k for c in obj.matrix_world @ v.co] for v in obj.data.vertices] \
            if obj else []
    return out


# ------------------------------------------------------------------------------------------
# Metres (Unit Scale 1): the reference.
scene.unit_settings.scale_length = 1.0
import_scene(args.scene, scene_io)
metres = scene_io.scene_dict(scene)
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "metres: Generate")
metre_results, metre_vertices = results(), proxy_vertices_m()
metre_out = os.path.join(work, "metres_export")
check(bpy.ops.probeproxy.export_proxies(directory=metre_out) == {"FINISHED"}, "metres: Export")

# ------------------------------------------------------------------------------------------
# Centimetres (Unit Scale 0.01).
scene.unit_settings.scale_length = 0.01
import_scene(args.scene, scene_io)
first = scene_io.probes(scene)[0]
file_capture = metres["probes"][0]["capture"]
check(all(abs(a - 100 * b) <= 1e-4 for a, b in zip(first.location, file_capture)),
      "cm: the capture point is in centimetres in Blender: %r (file %r m)"
      % (tuple(first.location), file_capture))
level = [o for o in scene.objects if scene_io.is_level_object(o)]
dims = max(max(o.dimensions) for o in level)
check(dims > 100, "cm: the level mesh is in centimetres in Blender (largest side %.1f)" % dims)
# Add Probe in centimetres: a room-sized probe (2 m half-extents, 200 cm), not a 2 cm one.
check(bpy.ops.probeproxy.add_probe() == {"FINISHED"}, "cm: Add Probe")
added = bpy.context.view_layer.objects.active
check(all(abs(h - 200.0) <= 1e-3 for h in added.probeproxy.half_extents)
      and abs(added.probeproxy.radius - 200.0) <= 1e-3,
      "cm: the new probe's volume is 2 m (200 cm): %r" % (tuple(added.probeproxy.half_extents),))
# A probe whose capture point is outside its volume: the refusal names the object and says
# where in the scene's units, not `$.probes[N]` and metres.
added.probeproxy.influence_offset = (1000.0, 0.0, 0.0)  # 10 m off, in centimetres
added.location = (50.0, 0.0, 150.0)  # centimetres
try:
    bpy.ops.probeproxy.generate_proxies()
    refusal = ""
except RuntimeError as e:
    refusal = str(e)
check("probe '%s' captures at (50 cm, 0 m, 1.5 m)" % added.name in refusal
      and "$.probes" not in refusal,
      "cm: the refusal names the probe, in centimetres: %r" % refusal.strip())
bpy.data.objects.remove(added)
cm = scene_io.scene_dict(scene)
diff = largest_difference(cm, metres)
check(same_shape(cm, metres) and diff <= 1e-6,
      "cm: the library gets the metre scene's numbers (largest difference %.3g m)" % diff)
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "cm: Generate")
check(scene.probeproxy.level_used.endswith("scene-file mesh(es)"),
      "cm: the unchanged level goes as its files: " + scene.probeproxy.level_used)
cm_results = results()
for name, r in sorted(metre_results.items()):
    c = cm_results.get(name, {})
    check({k: c.get(k) for k in ("kind", "candidate", "planes", "vertices", "error")}
          == {k: r[k] for k in ("kind", "candidate", "planes", "vertices", "error")},
          "cm: %s keeps %s with the metre scene's figures (p95 %r)"
          % (name, r["candidate"], r["error"]["p95_deg"]))
vdiff = largest_difference(proxy_vertices_m(), metre_vertices)
check(vdiff <= 1e-5, "cm: proxy meshes are the metre scene's in metres (largest difference "
      "%.3g m, float32 centimetres)" % vdiff)
cm_out = os.path.join(work, "cm_export")
check(bpy.ops.probeproxy.export_proxies(directory=cm_out) == {"FINISHED"}, "cm: Export")
with open(os.path.join(metre_out, "proxies.json")) as f:
    metre_json = json.load(f)
with open(os.path.join(cm_out, "proxies.json")) as f:
    cm_json = json.load(f)
ediff = largest_difference(cm_json, metre_json)
check(same_shape(cm_json, metre_json) and ediff <= 1e-6,
      "cm: Export writes the metre scene's proxies.json (largest difference %.3g)" % ediff)

# Save Scene from the centimetre scene, beside the original (its relative paths stay), and read
# both back in metres.
saved = os.path.join(os.path.dirname(os.path.abspath(args.scene)), "addon_units_cm.scene.json")
check(bpy.ops.probeproxy.save_scene(filepath=saved) == {"FINISHED"}, "cm: Save Scene")
try:
    back = native.module.read_scene(saved, world_frame=True)
    original = native.module.read_scene(os.path.abspath(args.scene), world_frame=True)
    rdiff = largest_difference(back["probes"], original["probes"])
    print("centimetre round trip: largest difference %.3g m" % rdiff)
    check(same_shape(back["probes"], original["probes"]) and rdiff <= 1e-6,
          "cm round trip: Save Scene reads back to the file's metres (largest difference "
          "%.3g m)" % rdiff)
finally:
    os.remove(saved)

# cheap_k's k is per length: 0.25 per metre is 0.0025 per centimetre in Blender, and the
# library gets 0.25 again.
first = scene_io.probes(scene)[0]
entry = dict(metres["probes"][0], proxy={"kind": "cheap_k", "k": 0.25})
scene_io.set_probe_from_dict(first, entry, scene_io.meters_per_bu(scene))
check(first.probeproxy.proxy_mode == "CHEAP_K" and abs(first.probeproxy.proxy_k - 0.0025) <= 1e-9,
      "cm: cheap_k's k is per centimetre in Blender: %r" % first.probeproxy.proxy_k)
back_k = scene_io.probe_dict(first, scene_io.meters_per_bu(scene))["proxy"]
check(back_k == {"kind": "cheap_k", "k": 0.25}, "cm: cheap_k's k goes back per metre: %r" % back_k)

# ------------------------------------------------------------------------------------------
# Transforms, in metres: each probe compared with a twin authored without parents.
scene.unit_settings.scale_length = 1.0
import_scene(args.scene, scene_io)
probes = scene_io.probes(scene)
check(len(probes) >= 3, "three probes to transform")


def twin(name, location, rotation, settings_from, scale=(1, 1, 1)):
    """An unparented probe in quaternion mode with these world numbers and the settings of
    `settings_from`, extents and offset multiplied by `scale` (what a scaled probe means)."""
    obj = bpy.data.objects.new(name, None)
    scene.collection.objects.link(obj)
    src = settings_from.probeproxy
    s = obj.probeproxy
    s.is_probe = True
    obj.rotation_mode = "QUATERNION"
    obj.location = location
    obj.rotation_quaternion = rotation
    s.influence_shape = src.influence_shape
    s.influence_offset = [o * k for o, k in zip(src.influence_offset, scale)]
    s.half_extents = [h * k for h, k in zip(src.half_extents, scale)]
    s.inner_half_extents = [h * k for h, k in zip(src.inner_half_extents, scale)]
    s.radius, s.inner_radius = src.radius * max(scale), src.inner_radius * max(scale)
    s.proxy_mode = src.proxy_mode
    s.extra_json = src.extra_json  # cubemap and reflection planes
    bpy.context.view_layer.update()
    return obj


def compare(label, obj, reference, tolerance=1e-5):
    got = scene_io.probe_dict(obj)
    want = scene_io.probe_dict(reference)
    want["name"] = got["name"]
    d = largest_difference(got, want)
    check(same_shape(got, want) and d <= tolerance,
          "%s: the library gets the unparented twin's numbers (largest difference %.3g m)"
          % (label, d))
    return got


# A rotated parent: the probe keeps its world transform when parented, then the parent turns
# 90 degrees about Z around its own origin, taking the probe and its influence along.
p = probes[0]
p.probeproxy.influence_offset = (0.5, 0.25, -0.1)  # off-centre, so the turn moves the centre
before = scene_io.probe_dict(p)
parent = bpy.data.objects.new("parent", None)
scene.collection.objects.link(parent)
parent.location = (1.0, 2.0, 0.0)
parent.rotation_euler = (0.0, 0.0, math.radians(37.0))
bpy.context.view_layer.update()
p.parent = parent
p.matrix_parent_inverse = parent.matrix_world.inverted()
bpy.context.view_layer.update()
d = largest_difference(scene_io.probe_dict(p), before)
check(d <= 1e-5, "parented: the probe's world numbers are unchanged (%.3g)" % d)
parent.rotation_euler.z += math.radians(90.0)
bpy.context.view_layer.update()
turn = Quaternion((0, 0, 1), math.radians(90.0))
pivot = Vector(parent.location)
world_capture = pivot + turn @ (Vector(before["capture"]) - pivot)
world_rotation = turn @ Quaternion(before["influence"]["rotation"])
q = twin("p_twin", world_capture, world_rotation, p)
got = compare("rotated parent", p, q)
centre_turned = pivot + turn @ (Vector(before["influence"]["center"]) - pivot)
check((Vector(got["influence"]["center"]) - centre_turned).length <= 1e-5,
      "rotated parent: the influence centre turned with the parent")

# A scaled probe: the influence's extents and centre offset scale with the object.
p2 = probes[1]
p2.probeproxy.influence_offset = (0.5, -0.25, 0.0)
p2.scale = (2.0, 1.0, 0.5)
bpy.context.view_layer.update()
q2 = twin("p2_twin", p2.location, p2.rotation_quaternion, p2, scale=(2.0, 1.0, 0.5))
got2 = compare("scaled probe", p2, q2)
check(got2["influence"]["half_extents"] == [2 * h if i == 0 else (h / 2 if i == 2 else h)
                                            for i, h in enumerate(scene_io.vec(p2.probeproxy.half_extents))],
      "scaled probe: half-extents x2, x1, x0.5: %r" % (got2["influence"]["half_extents"],))

# An Euler rotation mode: the same as the quaternion it stands for.
p3 = probes[2]
p3.rotation_mode = "XYZ"
p3.rotation_euler = (0.0, 0.0, math.radians(30.0))
bpy.context.view_layer.update()
q3 = twin("p3_twin", p3.location, p3.rotation_euler.to_quaternion(), p3)
compare("Euler XYZ", p3, q3)

# The whole level builds and validates with the transformed probes (the library accepts them).
for o in (q, q2, q3):
    bpy.data.objects.remove(o)
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate with the transformed probes")

# A level modelled here in centimetres, saved: Blender's glTF exporter writes Blender units, so
# the scene file's unit is the Unit Scale, and `probeproxy build` on it keeps what Generate kept.
import subprocess  # noqa: E402

import bmesh  # noqa: E402

for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)
scene.probeproxy.level_json = "[]"
scene.probeproxy.scene_file = ""
scene.probeproxy.meters_per_unit = 1.0
scene.unit_settings.scale_length = 0.01
bm = bmesh.new()
bmesh.ops.create_cube(bm, size=1.0)
for v in bm.verts:  # a 6 x 4 x 3 m room, in centimetres
    v.co = [lo if c < 0 else hi for c, lo, hi in zip(v.co, (-300, -200, 0), (300, 200, 300))]
bmesh.ops.reverse_faces(bm, faces=bm.faces)
mesh = bpy.data.meshes.new("room_cm")
bm.to_mesh(mesh)
bm.free()
scene.collection.objects.link(bpy.data.objects.new("room_cm", mesh))
scene.cursor.location = (75.0, -50.0, 150.0)
check(bpy.ops.probeproxy.add_probe() == {"FINISHED"}, "cm room: Add Probe")
cm_probe = bpy.context.view_layer.objects.active
cm_probe.probeproxy.half_extents = (300.0, 200.0, 150.0)
cm_probe.probeproxy.inner_half_extents = (250.0, 150.0, 100.0)
cm_probe.probeproxy.influence_offset = (-75.0, 50.0, 0.0)
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "cm room: Generate")
generated = json.loads(cm_probe.probeproxy.result_json)
room_saved = os.path.join(work, "room_cm.scene.json")
check(bpy.ops.probeproxy.save_scene(filepath=room_saved) == {"FINISHED"}, "cm room: Save Scene")
with open(room_saved) as f:
    written = json.load(f)
check(written["meters_per_unit"] == 0.01 and written["probes"][0]["capture"] == [75, -50, 150],
      "cm room: the scene file is in centimetres (meters_per_unit %r, capture %r)"
      % (written["meters_per_unit"], written["probes"][0]["capture"]))
run = subprocess.run([os.path.abspath(args.cli), "build", room_saved, "--out",
                      os.path.join(work, "room_cm_cli"), "--json"], capture_output=True, text=True)
check(run.returncode == 0, "cm room: probeproxy build on it: " + run.stderr.strip())
cli = json.loads(run.stdout or '{"probes": [{}]}')["probes"][0]
check({k: cli.get("proxy", {}).get(k) for k in ("kind", "candidate", "planes")}
      == {k: generated[k] for k in ("kind", "candidate", "planes")}
      and cli.get("error") == generated["error"],
      "cm room: the CLI keeps Generate's proxy with its figures (p95 %r)"
      % generated["error"]["p95_deg"])
finish()
