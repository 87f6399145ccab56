# What a level artist meets in the add-on, headless, on a box room made here:
#   blender -b --factory-startup --python tests/blender/addon_artist_test.py -- \
#       --addon-dir plugin/blender --module-dir build/plugin/python \
#       --cli build/plugin/cli/probeproxy --work DIR
# Asserts:
#   - Export refuses with a message when there are no probes, and when no folder is chosen,
#     and writes nothing;
#   - a stale selection does not narrow the level: with one of the room's two meshes selected,
#     Generate builds from both; with Level set to Selected, from the selected one only;
#   - moving or scaling the whole level with its probes and proxies is no hand edit: Generate
#     builds the proxies again;
#   - a hand edit of a generated proxy is exported as the artist's: the moved vertices are in
#     proxies.json, the kept candidate is `authored`, and Generate afterwards keeps the edit;
#   - a probe outside the level is a warning in the Findings list after Generate, and
#     `capture_outside_level` after Validate, as `probeproxy validate` gives it;
#   - a failed Generate clears the panel's "Last built from";
#   - with the .blend unsaved and Blender's working folder removed, Validate and Generate
#     still finish (the scene is anchored in Blender's temporary folder).

import json
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_harness import (check, clear_objects, empty_folder, enable_addon, finish,  # noqa: E402
                           inward_box, panel_findings, parse_args, select_only, validate_like_cli)

ROOM_MIN = (-3.0, -2.0, 0.0)  # metres, world frame (Z up)
ROOM_MAX = (3.0, 2.0, 3.0)
CAPTURE = (0.75, -0.5, 1.5)
LIFT = 0.5  # how far the hand edit moves the proxy's ceiling up, metres

args = parse_args("--addon-dir", "--module-dir", "--cli", "--work")
work = empty_folder(args.work)
native, scene_io = enable_addon(args.addon_dir, args.module_dir)
cli_path = os.path.abspath(args.cli)
os.chdir(work)  # an unsaved .blend anchors its scene (and hand-edited proxies) here
clear_objects()
settings = bpy.context.scene.probeproxy


def refused(operator, what, **kwargs):
    """Runs an operator that must refuse: CANCELLED, with an error message (Blender raises the
    error report as RuntimeError when the operator is called from Python)."""
    try:
        result = operator(**kwargs)
        message = ""
    except RuntimeError as e:
        result, message = {"CANCELLED"}, str(e)
    check(result == {"CANCELLED"} and message, "%s: refused with %r" % (what, message.strip()))
    return message



# The room in two meshes: the lower and the upper half (an artist's level is many objects).
lower = inward_box("room_lower", ROOM_MIN, (3.0, 2.0, 3.0))
floor_only = inward_box("floor_slab", (-3.0, -2.0, -0.2), (3.0, 2.0, 0.0))

# No probes: Export refuses, writes nothing.
no_probe_dir = os.path.join(work, "no_probes")
msg = refused(bpy.ops.probeproxy.export_proxies, "Export without probes", directory=no_probe_dir)
check("no probes" in msg, "the message says there are no probes")
check(not os.path.exists(os.path.join(no_probe_dir, "proxies.json")), "nothing written")

bpy.context.scene.cursor.location = CAPTURE
check(bpy.ops.probeproxy.add_probe() == {"FINISHED"}, "Add Probe")
probe = bpy.context.view_layer.objects.active
s = probe.probeproxy
s.half_extents = [(hi - lo) / 2 for lo, hi in zip(ROOM_MIN, ROOM_MAX)]
s.inner_half_extents = [h - 0.5 for h in s.half_extents]
s.influence_offset = [(lo + hi) / 2 - c for lo, hi, c in zip(ROOM_MIN, ROOM_MAX, CAPTURE)]
probe_name = probe.name

# No folder: Export refuses rather than writing into the working folder.
msg = refused(bpy.ops.probeproxy.export_proxies, "Export without a folder", directory="")
check("folder" in msg, "the message asks for a folder")
check(not os.path.exists(os.path.join(work, "proxies.json")), "nothing written here")

# A stale selection does not narrow the level.
select_only([lower])
check(settings.level_scope == "ALL", "Level: whole level by default")
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate with one mesh selected")
check(settings.level_used == "2 Blender mesh(es)",
      "the whole level was used, not the selection: " + settings.level_used)
settings.level_scope = "SELECTED"
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate, Level: Selected")
check(settings.level_used == "1 Blender mesh(es)",
      "Level: Selected used the selected mesh only: " + settings.level_used)
select_only([])
refused(bpy.ops.probeproxy.generate_proxies, "Generate, Level: Selected, nothing selected")
check(settings.level_used == "", "a failed Generate leaves no \"Last built from\": %r"
      % settings.level_used)
settings.level_scope = "ALL"
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate on the whole level")
result = json.loads(bpy.data.objects[probe_name].probeproxy.result_json)
check(result["planes"] == 6 and result["vertices"] == 8, "kept the room: %s, %d planes"
      % (result["candidate"], result["planes"]))

# Moving or scaling the whole level, probes and proxies with it, is no hand edit: Generate
# builds the proxy again (for the scaled room, a room twice the height), writes no edited mesh.
def move_everything(dx=0.0, factor=1.0):
    """Every object of the scene moved by dx along x, then scaled about the origin (Generate
    makes new proxy objects, so the list is taken anew each time)."""
    for o in bpy.context.scene.objects:
        if o.parent is None:
            o.location.x += dx
            o.location *= factor
            o.scale *= factor
    bpy.context.view_layer.update()


move_everything(dx=5.0)
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate after moving everything")
probe_settings = bpy.data.objects[probe_name].probeproxy
check(probe_settings.proxy_mode == "AUTO" and not any(
          f.endswith("_proxy_edited.obj") for f in os.listdir(work)),
      "moving the level with its proxies is no hand edit (proxy %s)" % probe_settings.proxy_mode)
move_everything(dx=-5.0, factor=2.0)
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate after scaling everything")
proxy = bpy.data.objects[probe_name + "_proxy"]
height = max((proxy.matrix_world @ v.co).z for v in proxy.data.vertices)
check(probe_settings.proxy_mode == "AUTO" and abs(height - 2 * ROOM_MAX[2]) <= 1e-3,
      "scaled 2x, the proxy is built again: ceiling at %.3f (the room's %.1f)"
      % (height, 2 * ROOM_MAX[2]))
move_everything(factor=0.5)
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate back at the room's size")

# Hand edit: lift the proxy's ceiling (its four top vertices) by LIFT, as in Edit Mode.
proxy = bpy.data.objects[probe_name + "_proxy"]
top = max(v.co.z for v in proxy.data.vertices)
moved = []
for v in proxy.data.vertices:
    if abs(v.co.z - top) < 1e-6:
        v.co.z += LIFT
        moved.append(tuple(proxy.matrix_world @ v.co))
proxy.data.update()
check(len(moved) == 4, "moved the proxy's 4 ceiling vertices up %.2f m" % LIFT)
out = os.path.join(work, "export")
check(bpy.ops.probeproxy.export_proxies(directory=out) == {"FINISHED"}, "Export after the edit")
with open(os.path.join(out, "proxies.json")) as f:
    exported = {p["name"]: p for p in json.load(f)["probes"]}[probe_name]
found = [m for m in moved
         if any(max(abs(a - b) for a, b in zip(m, v)) <= 1e-6 for v in exported["vertices"])]
check(len(found) == 4, "every moved vertex is in proxies.json (%d of 4, z %.2f)"
      % (len(found), top + LIFT))
check(exported["candidate"] == "authored", "exported as the artist's proxy: candidate %r"
      % exported["candidate"])
check(max(v[2] for v in exported["vertices"]) >= ROOM_MAX[2] + LIFT - 1e-6,
      "the exported ceiling is the edited one")
check(s.proxy_mode == "MESH" and os.path.exists(os.path.join(work, s.proxy_mesh)),
      "the probe's proxy is now the authored mesh %s" % s.proxy_mesh)
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate after the edit")
proxy = bpy.data.objects[probe_name + "_proxy"]
check(abs(max((proxy.matrix_world @ v.co).z for v in proxy.data.vertices)
          - (ROOM_MAX[2] + LIFT)) <= 1e-6, "Generate keeps the edit (the ceiling stays lifted)")

# A probe outside the level: a finding after Generate and after Validate, as the CLI says.
bpy.context.scene.cursor.location = (10.0, 0.0, 1.5)
check(bpy.ops.probeproxy.add_probe() == {"FINISHED"}, "Add a probe outside the room")
outside = bpy.context.view_layer.objects.active
outside.probeproxy.half_extents = (1.0, 1.0, 1.0)
outside.probeproxy.inner_half_extents = (0.5, 0.5, 0.5)
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate with it")
after_generate = [f for f in panel_findings() if f["probe"] == outside.name]
check(after_generate and all(f["severity"] == "warning" for f in after_generate),
      "Generate lists it in Findings as a warning: %r"
      % [f["message"] for f in after_generate])
saved = os.path.join(work, "artist.scene.json")
check(bpy.ops.probeproxy.save_scene(filepath=saved) == {"FINISHED"}, "Save Scene")
findings = validate_like_cli(cli_path, saved, "probe outside")
check(any(f["probe"] == outside.name and f["rule"] == "capture_outside_level"
          and f["severity"] == "warning" for f in findings),
      "Validate: capture_outside_level (warning) on the probe outside")

# Blender started in a folder that is gone, the .blend never saved: the operators work, with
# the scene anchored in Blender's temporary folder (a FileNotFoundError traceback before).
settings.scene_file = ""
for o in scene_io.probes(bpy.context.scene):
    o.probeproxy.proxy_mode = "AUTO"  # an authored mesh path would point into `work`
gone = os.path.join(work, "gone")
os.makedirs(gone)
os.chdir(gone)
os.rmdir(gone)
check(bpy.ops.probeproxy.validate_volumes() == {"FINISHED"}, "Validate from a removed folder")
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate from a removed folder")
os.chdir(work)
finish()
