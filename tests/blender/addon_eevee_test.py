# EEVEE Probes and EEVEE Probes from File, headless:
#   blender -b --factory-startup --python tests/blender/addon_eevee_test.py -- \
#       --addon-dir plugin/blender --module-dir build/plugin/python \
#       --cli build/plugin/cli/probeproxy --scene build/scenes/l_room/l_room.scene.json --work DIR
# Against `probeproxy build SCENE --out DIR`'s proxies.json:
#   - EEVEE Probes makes one Reflection Cubemap per probe whose every Blender property is the
#     export's preset (numbers to float32, strings equal), and reads back into that preset;
#   - undo removes them, redo brings them back; a second run updates them in place;
#   - in a centimetre scene (Unit Scale 0.01) the same presets in metres, lengths in centimetres;
#   - EEVEE Probes from File on the CLI's proxies.json gives the same light probes;
#   - each bake sees from 5 cm (a capture point near a wall) to the level's size;
#   - a file that is not a proxies.json is one error line naming it, and changes nothing.

import json
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_harness import check, empty_folder, enable_addon, finish, import_scene, parse_args  # noqa: E402

args = parse_args("--addon-dir", "--module-dir", "--cli", "--scene", "--work")
work = empty_folder(args.work)
native, scene_io = enable_addon(args.addon_dir, args.module_dir)
from probeproxy_addon import eevee_probes  # noqa: E402

run = subprocess.run([args.cli, "build", args.scene, "--out", os.path.join(work, "cli")],
                     capture_output=True, text=True)
check(run.returncode == 0, "probeproxy build: " + run.stderr.strip())
cli_export = os.path.join(work, "cli", "proxies.json")
with open(cli_export) as f:
    expected = eevee_probes.presets_in_export(json.load(f))
check(len(expected) > 0, "the CLI's export has %d EEVEE presets" % len(expected))

FLOAT32 = 2.0 ** -23


def differences(got, want):
    """The largest relative difference of the numbers, and the fields that differ otherwise."""
    largest, other = 0.0, []
    for field in eevee_probes.DATA_FIELDS + ("location", "rotation_xyzw", "scale"):
        g, w = got[field], want[field]
        if isinstance(w, list):
            for a, b in zip(g, w):
                largest = max(largest, abs(a - b) / max(1.0, abs(b)))
        elif isinstance(w, (int, float)) and not isinstance(w, bool):
            largest = max(largest, abs(g - w) / max(1.0, abs(w)))
        elif g != w:
            other.append("%s %r != %r" % (field, g, w))
    return largest, other


def check_light_probes(label, meters_per_bu):
    made = eevee_probes.light_probes(bpy.context.scene)
    check(sorted(made) == sorted(expected), "%s: one Reflection Cubemap per preset (%d)" % (
        label, len(made)))
    worst, wrong = 0.0, []
    for name, obj in made.items():
        check(obj.type == "LIGHT_PROBE" and obj.data.type == "CUBEMAP",
              "%s: %s is a Reflection Cubemap" % (label, obj.name))
        largest, other = differences(eevee_probes.preset_of_light_probe(obj, meters_per_bu),
                                     expected[name])
        worst, wrong = max(worst, largest), wrong + other
    level = [o for o in bpy.context.scene.objects if scene_io.is_level_object(o)]
    size = eevee_probes.level_size_m(level, meters_per_bu)
    check(all(abs(o.data.clip_start * meters_per_bu - eevee_probes.CLIP_START_M) < 1e-6 and
              o.data.clip_end * meters_per_bu >= size * (1 - 1e-6) for o in made.values()),
          "%s: each bake sees from %g m to the level's size (%.2f m)" % (
              label, eevee_probes.CLIP_START_M, size))
    # Blender keeps floats; a quaternion and a scale come back through a 4x4 matrix.
    check(worst <= 16 * FLOAT32 and not wrong,
          "%s: the light probes read back into the export's presets (largest relative "
          "difference %.2g, float32 eps %.2g) %s" % (label, worst, FLOAT32, "; ".join(wrong)))
    return made


import_scene(os.path.abspath(args.scene), scene_io)
bpy.ops.ed.undo_push(message="before EEVEE Probes")
check(bpy.ops.probeproxy.eevee_probes("EXEC_DEFAULT", True) == {"FINISHED"}, "EEVEE Probes")
made = check_light_probes("EEVEE Probes", 1.0)
first = {name: obj.data.name for name, obj in made.items()}

check(bpy.ops.ed.undo() == {"FINISHED"}, "Undo")
check(not eevee_probes.light_probes(bpy.context.scene), "Undo removes the light probes")
check(bpy.ops.ed.redo() == {"FINISHED"}, "Redo")
check_light_probes("Redo", 1.0)

check(bpy.ops.probeproxy.eevee_probes() == {"FINISHED"}, "EEVEE Probes again")
again = check_light_probes("EEVEE Probes again", 1.0)
check({name: obj.data.name for name, obj in again.items()} == first,
      "a second run updates the same light probes in place (no .001 copies)")

# A centimetre scene: the same presets, every length in centimetres.
bpy.context.scene.unit_settings.scale_length = 0.01
import_scene(os.path.abspath(args.scene), scene_io)
for obj in list(eevee_probes.light_probes(bpy.context.scene).values()):
    bpy.data.objects.remove(obj)
check(bpy.ops.probeproxy.eevee_probes() == {"FINISHED"}, "EEVEE Probes in a centimetre scene")
made = check_light_probes("centimetre scene", 0.01)
name, obj = sorted(made.items())[0]
check(abs(obj.location.x - expected[name]["location"][0] / 0.01) <= 1e-3,
      "centimetre scene: %s's location in centimetres (%.3f)" % (obj.name, obj.location.x))
bpy.context.scene.unit_settings.scale_length = 1.0

# From the CLI's file.
for obj in list(eevee_probes.light_probes(bpy.context.scene).values()):
    bpy.data.objects.remove(obj)
check(bpy.ops.probeproxy.eevee_probes_from_file(filepath=cli_export) == {"FINISHED"},
      "EEVEE Probes from File")
check_light_probes("from the CLI's proxies.json", 1.0)

# Not a proxies.json: one line, nothing changed.
bad = os.path.join(work, "not_proxies.json")
with open(bad, "w") as f:
    f.write('{"probes": []}')
before = sorted(eevee_probes.light_probes(bpy.context.scene))
try:
    result = bpy.ops.probeproxy.eevee_probes_from_file(filepath=bad)
    message = ""
except RuntimeError as e:  # background Blender raises an operator's error report
    result, message = {"CANCELLED"}, str(e)
check(result == {"CANCELLED"} and bad in message and "not a probeproxy proxies.json" in message,
      "a JSON that is not a proxies.json is refused, naming it: " + message.strip())
check(sorted(eevee_probes.light_probes(bpy.context.scene)) == before,
      "the refused file changed nothing")

finish()
