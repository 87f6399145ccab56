# Generate Proxies on a level authored in Blender (a box room made with bmesh in this script,
# not imported), and undo, headless:
#   blender -b --factory-startup --python tests/blender/addon_authored_test.py -- \
#       --addon-dir plugin/blender --module-dir build/plugin/python \
#       --cli build/plugin/cli/probeproxy --work DIR
# Asserts: the kept proxy is the room (6 planes, its corners within 1 mm of the room's, the
# mirror_floor p95 under the build's tolerance and misses under its limit); Save Scene writes the
# level beside the scene file and `probeproxy build` on it keeps the same proxy with the same
# error figures; Validate gives the CLI's findings on the saved scene; Undo
# after Generate removes the proxy meshes and the figures, Redo brings them back.

import json
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_harness import (check, clear_objects, empty_folder, enable_addon, finish,  # noqa: E402
                           inward_box, parse_args, select_only, validate_like_cli)

ROOM_MIN = (-3.0, -2.0, 0.0)  # metres, world frame (Z up)
ROOM_MAX = (3.0, 2.0, 3.0)
CAPTURE = (0.75, -0.5, 1.5)
TOLERANCE_DEG = 0.25  # the build's default (the CLI's --tolerance-deg)
MAX_MISS_RATE = 0.001  # the build's default

args = parse_args("--addon-dir", "--module-dir", "--cli", "--work")
work = empty_folder(args.work)
native, scene_io = enable_addon(args.addon_dir, args.module_dir)
cli_path = os.path.abspath(args.cli)
os.chdir(work)  # an unsaved .blend anchors its scene in the working folder
clear_objects()



room = inward_box("room", ROOM_MIN, ROOM_MAX)
bpy.context.scene.cursor.location = CAPTURE
check(bpy.ops.probeproxy.add_probe() == {"FINISHED"}, "Add Probe at the 3D cursor")
probe = bpy.context.view_layer.objects.active
s = probe.probeproxy
s.half_extents = [(hi - lo) / 2 for lo, hi in zip(ROOM_MIN, ROOM_MAX)]
s.inner_half_extents = [h - 0.5 for h in s.half_extents]
s.influence_offset = [(lo + hi) / 2 - c for lo, hi, c in zip(ROOM_MIN, ROOM_MAX, CAPTURE)]
probe_name = probe.name
select_only([room])

# Generate, then undo and redo it.
# Background Blender starts with undo off (ed.undo's poll says so); ed.undo_push turns it on.
# An operator called from Python pushes its undo step only when asked to (the third argument,
# undo=True), as a button press does.
bpy.ops.ed.undo_push(message="before Generate")
check(bpy.ops.probeproxy.generate_proxies("EXEC_DEFAULT", True) == {"FINISHED"},
      "Generate Proxies (with its undo step, as from the panel)")
settings = bpy.context.scene.probeproxy
check(settings.level_used == "1 Blender mesh(es)",
      "the level went to the library as Blender's triangles: " + settings.level_used)
check(bpy.data.objects.get(probe_name + "_proxy") is not None, "the proxy mesh exists")
check(bpy.ops.ed.undo() == {"FINISHED"}, "Undo")
check(bpy.data.objects.get(probe_name + "_proxy") is None
      and not bpy.data.objects[probe_name].probeproxy.result_json,
      "Undo after Generate removes the proxy mesh and the figures")
check(bpy.ops.ed.redo() == {"FINISHED"}, "Redo")
probe = bpy.data.objects[probe_name]
proxy = bpy.data.objects.get(probe_name + "_proxy")
check(proxy is not None and probe.probeproxy.proxy_object == proxy
      and bool(probe.probeproxy.result_json), "Redo brings the proxy mesh and the figures back")

# The kept proxy is the room.
result = json.loads(probe.probeproxy.result_json)
e = result["error"]
check(result["planes"] == 6 and result["vertices"] == 8,
      "kept %s (%s): %d planes, %d vertices" % (result["candidate"], result["kind"],
                                                result["planes"], result["vertices"]))
check(e["p95_deg"] is not None and e["p95_deg"] <= TOLERANCE_DEG,
      "mirror_floor p95 %r deg <= tolerance %r" % (e["p95_deg"], TOLERANCE_DEG))
check(e["miss_rate"] <= MAX_MISS_RATE, "miss rate %r <= %r" % (e["miss_rate"], MAX_MISS_RATE))
corners = {tuple(lo if i >> axis & 1 == 0 else hi
                 for axis, (lo, hi) in enumerate(zip(ROOM_MIN, ROOM_MAX))) for i in range(8)}
worst = max(min(max(abs(a - b) for a, b in zip(proxy.matrix_world @ v.co, c)) for c in corners)
            for v in proxy.data.vertices) if proxy else float("inf")
check(worst <= 1e-3, "every proxy vertex within 1 mm of a room corner (worst %.2e m)" % worst)

# Saved, the CLI reads the room back from the level file Save Scene wrote and agrees.
saved = os.path.join(work, "authored.scene.json")
check(bpy.ops.probeproxy.save_scene(filepath=saved) == {"FINISHED"}, "Save Scene")
check(os.path.exists(os.path.join(work, "authored_level.glb")), "level written beside it")
run = subprocess.run([cli_path, "build", saved, "--out", os.path.join(work, "cli"), "--json"],
                     capture_output=True, text=True)
check(run.returncode == 0, "probeproxy build on the saved scene: " + run.stderr.strip())
cli = json.loads(run.stdout or '{"probes": [{}]}')["probes"][0]
check({k: cli.get("proxy", {}).get(k) for k in ("kind", "candidate", "planes", "vertices")}
      == {k: result[k] for k in ("kind", "candidate", "planes", "vertices")},
      "the CLI keeps the same proxy: %r" % cli.get("proxy"))
# The exported glb holds the same float32 triangles in the same order, so the figures are
# the same bits; were they reordered, they would still have to be within the tolerance.
check(cli.get("error") == e, "the CLI's error figures equal Generate's (p95 %r)" % e["p95_deg"])
select_only([room])
validate_like_cli(cli_path, saved, "authored")
finish()
