# What the add-on's headless Blender tests share: arguments, checks that print ok/FAIL and
# count failures, enabling the add-on from the source tree with the built module, importing a
# scene through Import Scene, and Validate Volumes compared with `probeproxy validate --json`.

import argparse
import json
import os
import shutil
import subprocess
import sys

import bmesh
import bpy

failures = []


def parse_args(*names):
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser()
    for name in names:
        parser.add_argument(name, required=True)
    return parser.parse_args(argv)


def empty_folder(path):
    """`path`, absolute, emptied of an earlier run's files."""
    path = os.path.abspath(path)
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def finish():
    if failures:
        print("%d check(s) failed:\n  " % len(failures) + "\n  ".join(failures))
        sys.exit(1)
    print("all checks passed")


def enable_addon(addon_dir, module_dir):
    """Enables the add-on from `addon_dir` with the module built in `module_dir`; returns the
    add-on's native and scene_io modules."""
    sys.path.insert(0, os.path.abspath(addon_dir))
    sys.path.insert(0, os.path.abspath(module_dir))
    import addon_utils
    module = addon_utils.enable("probeproxy_addon", default_set=True, handle_error=None)
    check(module is not None, "add-on enabled")
    from probeproxy_addon import native, scene_io
    check(native.module is not None, "compiled module loaded: " + (native.problem or "ok"))
    check(hasattr(bpy.ops.probeproxy, "generate_proxies"), "operators under bpy.ops.probeproxy")
    return native, scene_io


def clear_objects():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)


def inward_box(name, lo, hi):
    """A closed box mesh object from corner lo to hi, faces pointing inward (the side a probe
    inside sees), linked into the scene."""
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=1.0)
    for v in bm.verts:
        v.co = [a if c < 0 else b for c, a, b in zip(v.co, lo, hi)]
    bmesh.ops.reverse_faces(bm, faces=bm.faces)
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def import_scene(path, scene_io):
    """Import Scene into an empty scene; returns the level objects, selected."""
    clear_objects()
    check(bpy.ops.probeproxy.import_scene(filepath=path) == {"FINISHED"}, "Import Scene")
    level = [o for o in bpy.data.objects if scene_io.is_level_object(o)]
    check(len(level) > 0 and all(o.probeproxy.level_index >= 0 for o in level),
          "level meshes imported by Blender's importer (%d objects)" % len(level))
    select_only(level)
    return level


def select_only(objects):
    for o in bpy.context.view_layer.objects:
        o.select_set(o in objects)


def cli_findings(cli, scene):
    """`probeproxy validate SCENE --json`'s findings (exit 0 clean, 1 findings)."""
    run = subprocess.run([cli, "validate", scene, "--json"], capture_output=True, text=True)
    if run.returncode not in (0, 1):
        sys.exit("probeproxy validate failed: " + run.stderr)
    findings = json.loads(run.stdout)["findings"]
    check(run.returncode == (1 if any(f["severity"] != "info" for f in findings) else 0),
          "validate exit code %d agrees with its findings" % run.returncode)
    return findings


def panel_findings():
    """The findings Validate Volumes stored for the panel, as the CLI's dicts."""
    out = []
    for f in bpy.context.scene.probeproxy.findings:
        out.append({"probe": f.probe, "rule": f.rule, "severity": f.severity,
                    "value": json.loads(f.value), "limit": json.loads(f.limit),
                    "message": f.message, "hint": f.hint})
    return out


def validate_like_cli(cli, scene, label):
    """Validate Volumes on what is selected, against `probeproxy validate --json` on `scene`:
    the same findings in the same order with the same values, and exactly the offending
    probes selected, one of them active. Returns the findings."""
    expected = cli_findings(cli, scene)
    check(bpy.ops.probeproxy.validate_volumes() == {"FINISHED"}, label + ": Validate Volumes")
    got = panel_findings()
    check(got == expected, "%s: findings equal `probeproxy validate --json`'s (%d: %s)" % (
        label, len(expected), ", ".join(f["rule"] for f in expected) or "clean"))
    named = {f["probe"] for f in expected}
    selected = {o.name for o in bpy.context.selected_objects}
    check(selected == named, "%s: the offending probes are selected (%s)" % (
        label, ", ".join(sorted(selected)) or "none"))
    active = bpy.context.view_layer.objects.active
    if expected:
        check(active is not None and active.name == expected[0]["probe"],
              "%s: the first finding's probe is active" % label)
    return expected
