# Validate Volumes on a level with findings (the suite's deliberately broken scenes, the
# L-room with the artist's boxes), headless:
#   blender -b --factory-startup --python tests/blender/addon_validate_test.py -- \
#       --addon-dir plugin/blender --module-dir build/plugin/python \
#       --cli build/plugin/cli/probeproxy --scene build/scenes/broken/probe_outside.scene.json
# Imports the scene through Import Scene and asserts that the findings in the panel equal
# `probeproxy validate --json`'s (same order, same values), that there are some, that exactly
# the offending probes are selected (the first finding's active), and that the module's
# validate_scene returns the CLI's findings too, and only the named rules' under options
# {"rules": [...]}; a refused option raises InputError, a missing level mesh InputError with
# the library's one line.

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_harness import (check, enable_addon, finish, import_scene, parse_args,  # noqa: E402
                           validate_like_cli)

args = parse_args("--addon-dir", "--module-dir", "--cli", "--scene")
scene = os.path.abspath(args.scene)
native, scene_io = enable_addon(args.addon_dir, args.module_dir)
import_scene(scene, scene_io)
expected = validate_like_cli(args.cli, scene, os.path.basename(scene))
check(len(expected) > 0, "the level has findings")
direct = native.module.validate_scene(native.module.read_scene(scene), scene)
check(direct == expected, "module validate_scene on the scene file: the CLI's findings")


def raised(work):
    try:
        work()
    except ValueError as e:  # InputError is a ValueError
        return e
    return None


data = native.module.read_scene(scene)
e = raised(lambda: native.module.validate_scene(data, scene, options={"grid": 0}))
check(isinstance(e, native.module.InputError) and str(e) == "option grid: 0 is outside [0.01, 10]",
      "an option the CLI refuses raises the job's InputError, the CLI's line: %s" % e)
# rules: only floor_not_covered is measured; the mesh and capture checks always run.
always = {"capture_outside_proxy", "capture_outside_influence", "floor_not_covered"}
only = native.module.validate_scene(data, scene, options={"rules": ["floor_not_covered"]})
kept = [f for f in expected
        if f["rule"] in always or (f["rule"].startswith("proxy_") and
                                   f["rule"] != "proxy_error_over_tolerance")]
check(only == kept, "options rules: the findings of the rules named and the gating checks: %s"
      % [f["rule"] for f in only])
e = raised(lambda: native.module.validate_scene(data, scene, options={"rules": ["leaks"]}))
check(isinstance(e, native.module.InputError) and
      str(e).startswith("option rules: unknown rule 'leaks' (rules: capture_outside_level, "),
      "an unknown rule raises InputError listing the rules: %s" % e)
data["level"] = ["no_such_level.obj"]
e = raised(lambda: native.module.validate_scene(data, scene))
missing = os.path.join(os.path.dirname(scene), "no_such_level.obj")
check(isinstance(e, native.module.InputError) and str(e) == missing + ": mesh file not found",
      "a missing level mesh raises InputError naming the file: %s" % e)
finish()
