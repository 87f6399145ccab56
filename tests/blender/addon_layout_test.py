# Suggest Probes, headless: on a suite level imported through Import Scene, the
# operator lays out the same probes `probeproxy layout SCENE --out DIR` writes (names, capture
# points, influence boxes, proxies), shows the error map, and Undo brings the scene's own probes
# back.
#   blender -b --factory-startup --python-exit-code 1 --python addon_layout_test.py -- \
#       --addon-dir plugin/blender --module-dir build/plugin/python --cli build/plugin/cli/probeproxy \
#       --scene build/scenes/l_room/l_room.scene.json --work build/tests/blender/addon_layout

import json
import os
import shutil
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_harness import check, enable_addon, finish, import_scene, parse_args  # noqa: E402

# Blender keeps locations and custom vectors as 32-bit floats: metres to about 1e-6 here.
FLOAT32_M = 1e-4

args = parse_args("--addon-dir", "--module-dir", "--cli", "--scene", "--work")
native, scene_io = enable_addon(args.addon_dir, args.module_dir)
shutil.rmtree(args.work, ignore_errors=True)
os.makedirs(args.work)

# The CLI's layout of the scene file.
cli_out = os.path.join(args.work, "cli")
run = subprocess.run([args.cli, "layout", args.scene, "--out", cli_out, "--json"],
                     capture_output=True, text=True)
check(run.returncode == 0, "probeproxy layout exits 0: " + run.stderr.strip()[-300:])
cli_scene = native.module.read_scene(os.path.join(cli_out, "layout.scene.json"), world_frame=True)
cli_figures = json.load(open(os.path.join(cli_out, "layout.json")))

# The same scene in Blender: the layout's files go beside its scene file (<stem>_layout/).
import_scene(args.scene, scene_io)
own_probes = sorted(o.name for o in scene_io.probes(bpy.context.scene))
bpy.context.scene.probeproxy.scene_file = args.scene
bpy.ops.ed.undo_push(message="before Suggest Probes")
check(bpy.ops.probeproxy.suggest_probes("EXEC_DEFAULT", True) == {"FINISHED"},
      "Suggest Probes (with its undo step, as from the panel)")
settings = bpy.context.scene.probeproxy
check(settings.level_used == "1 scene-file mesh(es)",
      "the level went to the library as the scene's own file: " + settings.level_used)

suggested = sorted(scene_io.probes(bpy.context.scene), key=lambda o: o.probeproxy.order)
cli_probes = cli_scene["probes"]
check([o.name for o in suggested] == [p["name"] for p in cli_probes],
      "the CLI's probes, in order: %s" % [p["name"] for p in cli_probes])
k = scene_io.meters_per_bu(bpy.context.scene)
for obj, want in zip(suggested, cli_probes):
    got = scene_io.probe_dict(obj, k)
    far = max(abs(a - b) for a, b in zip(got["capture"], want["capture"]))
    check(far < FLOAT32_M, "%s: capture %s (CLI %s)" % (obj.name, got["capture"], want["capture"]))
    gi, wi = got["influence"], want["influence"]
    check(gi["kind"] == wi["kind"] == "box", "%s: a box influence" % obj.name)
    for key in ("center", "half_extents", "inner_half_extents"):
        far = max(abs(a - b) for a, b in zip(gi[key], wi[key]))
        check(far < FLOAT32_M, "%s: influence %s %s (CLI %s)" % (obj.name, key, gi[key], wi[key]))
    proxy = obj.probeproxy.proxy_object
    check(proxy is not None and len(proxy.data.polygons) > 0,
          "%s: its proxy as a mesh in Proxies" % obj.name)
    gp, wp = got["proxy"], want["proxy"]
    # The add-on keeps every box as a box with a rotation: the file's "obb" is that box.
    same_kind = {"obb": "box"}.get(wp["kind"], wp["kind"]) == gp["kind"]
    check(same_kind, "%s: a %s proxy (CLI %s)" % (obj.name, gp["kind"], wp["kind"]))
    if "mesh" in wp:
        mesh = os.path.normpath(os.path.join(os.path.dirname(args.scene), gp["mesh"]))
        check(os.path.basename(mesh) == os.path.basename(wp["mesh"]) and os.path.isfile(mesh),
              "%s: proxy mesh %s written, as the CLI's %s" % (obj.name, mesh, wp["mesh"]))
    else:
        for key in ("center", "half_extents", "rotation"):
            a, b = gp.get(key, [1, 0, 0, 0]), wp.get(key, [1, 0, 0, 0])  # unturned: no rotation
            far = max(abs(x - y) for x, y in zip(a, b))
            check(far < FLOAT32_M, "%s: proxy %s %s (CLI %s)" % (obj.name, key, a, b))

figures = cli_figures["survey"]
check(settings.layout_summary.startswith("%d probes: p95 %.1f deg" % (len(cli_probes), figures["p95_deg"])),
      "the panel's summary is the CLI's figures: " + settings.layout_summary)
# The floor the layout measured on stays with the scene: the next Validate, and Save Scene,
# carry the CLI's measured_with, so they measure the same floor.
measured = json.loads(settings.measured_with_json)
check(measured == cli_scene.get("measured_with") and measured.get("seed_points"),
      "the layout's measured_with kept: %s (CLI %s)" % (measured, cli_scene.get("measured_with")))
check(scene_io.scene_dict(bpy.context.scene).get("measured_with") == measured,
      "the scene the add-on hands over carries it")
check(bpy.ops.probeproxy.validate_volumes() == {"FINISHED"}, "Validate after Suggest Probes")
failing = [f.rule for f in settings.findings if f.severity != "info"]
check(not failing, "the layout validates as `probeproxy validate` does, by its own tolerance: %s"
      % failing)
image = bpy.data.images.get(os.path.basename(settings.layout_map))
check(image is not None and image.size[0] >= 800, "the error map is loaded for the panel: %s %s"
      % (settings.layout_map, tuple(image.size) if image else None))

check(bpy.ops.ed.undo() == {"FINISHED"}, "Undo")
check(sorted(o.name for o in scene_io.probes(bpy.context.scene)) == own_probes,
      "Undo brings the scene's own probes back: %s" % own_probes)
shutil.rmtree(os.path.splitext(os.path.splitext(args.scene)[0])[0] + "_layout", ignore_errors=True)
finish()
