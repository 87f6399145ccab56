# The add-on without its compiled module: it still enables, and says in one line that the
# module is missing, with Blender's Python version and the install command.
#   blender -b --factory-startup --python tests/blender/addon_missing_module_test.py -- ADDON_DIR
import os
import sys

sys.path.insert(0, os.path.abspath(sys.argv[sys.argv.index("--") + 1]))
import addon_utils  # noqa: E402

module = addon_utils.enable("probeproxy_addon", default_set=True, handle_error=None)
from probeproxy_addon import native  # noqa: E402

python = "%d.%d" % sys.version_info[:2]
problems = []
if module is None:
    problems.append("the add-on did not enable")
if native.module is not None:
    problems.append("a probeproxy_py module was found; this test needs it absent")
for part in ("is missing", "Blender runs Python " + python, "scripts/install_addon.sh"):
    if part not in native.problem:
        problems.append("the message lacks %r: %s" % (part, native.problem))
print(native.problem)
sys.exit("\n".join(problems) if problems else 0)
