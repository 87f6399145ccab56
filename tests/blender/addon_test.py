# The Blender add-on, headless, against the CLI on the same suite level:
#   blender -b --factory-startup --python tests/blender/addon_test.py -- \
#       --addon-dir plugin/blender --module-dir build/plugin/python \
#       --cli build/plugin/cli/probeproxy --scene build/scenes/l_room/l_room.scene.json --work DIR
# Enables the add-on from the source tree with the built module, imports the scene through
# Import Scene, runs every operator and asserts: Validate's findings equal `probeproxy
# validate --json`'s (same order, same values) and select the offending probes; Generate's
# kinds, plane counts and error figures equal `probeproxy build --json`'s exactly (authored
# proxies kept, and --regenerate);
# Export writes the CLI's proxies.json and proxies.glb byte for byte; Save Scene of the
# unedited scene gives the scene file's own bytes; a probe moved and an influence range changed
# in Blender, saved, reads back in the CLI as Blender shows it and builds and validates as
# Blender did. Exits non-zero if any check failed, naming each.

import filecmp
import json
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_harness import (check, empty_folder, enable_addon, finish, import_scene,  # noqa: E402
                           parse_args, validate_like_cli)

args = parse_args("--addon-dir", "--module-dir", "--cli", "--scene", "--work")


def cli_build(scene, out, *extra):
    run = subprocess.run([args.cli, "build", scene, "--out", out, "--json", *extra],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("probeproxy build failed: " + run.stderr)
    return {p["name"]: p for p in json.loads(run.stdout)["probes"]}


def blender_results():
    out = {}
    for obj in bpy.data.objects:
        if obj.probeproxy.is_probe:
            out[obj.name] = json.loads(obj.probeproxy.result_json)
    return out


def compare_builds(cli, blender, label):
    check(sorted(cli) == sorted(blender), label + ": same probes")
    for name in sorted(cli):
        c, b = cli[name], blender.get(name, {})
        for key in ("kind", "candidate", "planes", "vertices"):
            check(c["proxy"][key] == b.get(key), "%s %s: proxy %s %r == %r" % (
                label, name, key, c["proxy"][key], b.get(key)))
        check(c["error"] == b.get("error"), "%s %s: error figures equal (p95 %r)" % (
            label, name, c["error"]["p95_deg"]))
        cands = [{k: x[k] for k in ("kind", "planes", "error")} for x in c["candidates"]]
        check(cands == b.get("candidates"), "%s %s: %d candidates equal" % (
            label, name, len(cands)))
        proxy = bpy.data.objects.get(name + "_proxy")
        check(proxy is not None and proxy.name in bpy.data.collections["Proxies"].objects
              and bpy.data.objects[name].probeproxy.proxy_object == proxy,
              "%s %s: proxy mesh in the Proxies collection, linked to its probe" % (label, name))


def same_bytes(a, b, what):
    check(filecmp.cmp(a, b, shallow=False), what + ": %s == %s byte for byte" % (a, b))


work = empty_folder(args.work)

native, scene_io = enable_addon(args.addon_dir, args.module_dir)
level = import_scene(args.scene, scene_io)

# Validate on the imported level: the CLI's findings, the offending probes selected.
validate_like_cli(args.cli, args.scene, "imported")
for o in bpy.context.view_layer.objects:
    o.select_set(o in level)

# Generate, authored proxies kept (the CLI's default), then regenerated.
settings = bpy.context.scene.probeproxy
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate Proxies")
check(settings.level_used.endswith("scene-file mesh(es)") and "Blender" not in settings.level_used,
      "unchanged imported level built from the scene's files: " + settings.level_used)
compare_builds(cli_build(args.scene, os.path.join(work, "cli_kept")), blender_results(),
               "kept")
settings.regenerate = True
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate Proxies (regenerate)")
cli_regen = os.path.join(work, "cli_regenerate")
compare_builds(cli_build(args.scene, cli_regen, "--regenerate"), blender_results(),
               "regenerate")

# Export: the CLI's files, byte for byte.
blender_out = os.path.join(work, "blender_export")
check(bpy.ops.probeproxy.export_proxies(directory=blender_out) == {"FINISHED"}, "Export")
for name in ("proxies.json", "proxies.glb"):
    same_bytes(os.path.join(cli_regen, name), os.path.join(blender_out, name), "Export " + name)

# Save Scene, unedited: the canonical bytes of the scene file (the library's writer; the suite's
# files are laid out by the generator), written beside it so its relative paths stay the same.
saved = os.path.join(os.path.dirname(os.path.abspath(args.scene)), "addon_test_saved.scene.json")
check(bpy.ops.probeproxy.save_scene(filepath=saved) == {"FINISHED"}, "Save Scene")
try:
    canonical = native.module.scene_json(native.module.read_scene(args.scene),
                                         os.path.abspath(args.scene))
    with open(saved) as f:
        check(f.read() == canonical, "Save Scene unedited: the scene file's canonical bytes")
finally:
    os.remove(saved)

# Edit in Blender, save, read back through the CLI.
probe = scene_io.probes(bpy.context.scene)[0]
probe.location.x += 0.25
probe.location.y -= 0.125
s = probe.probeproxy
if s.influence_shape == "BOX":
    s.half_extents[0] += 0.5
    s.inner_half_extents[0] = min(s.inner_half_extents[0], s.half_extents[0])
else:
    s.radius += 0.5
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate Proxies after the edit")
edited = os.path.join(os.path.dirname(os.path.abspath(args.scene)), "addon_test_edited.scene.json")
check(bpy.ops.probeproxy.save_scene(filepath=edited) == {"FINISHED"}, "Save Scene after the edit")
try:
    shown = scene_io.probe_dict(probe)
    back = {p["name"]: p for p in native.module.read_scene(edited, world_frame=True)["probes"]}
    check(back[probe.name]["capture"] == shown["capture"],
          "edited capture reads back as Blender shows it: %r" % (shown["capture"],))
    check(back[probe.name]["influence"] == shown["influence"],
          "edited influence reads back as Blender shows it")
    compare_builds(cli_build(edited, os.path.join(work, "cli_edited"), "--regenerate"),
                   blender_results(), "edited")
    validate_like_cli(args.cli, edited, "edited")
finally:
    os.remove(edited)

finish()
