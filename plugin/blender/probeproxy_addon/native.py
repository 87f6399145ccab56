# The compiled probeproxy module (plugin/python, pybind11). It is looked for beside the add-on
# (where scripts/install_addon.sh copies it), then on sys.path (the build tree in tests). When
# it is missing, or was built for another Python than Blender's, `module` is None and `problem`
# says why in one line, with both Python versions: the panel and the enable step show it.

import importlib
import sys

module = None
problem = ""

_BLENDER_PYTHON = "%d.%d" % sys.version_info[:2]


def _load():
    global module, problem
    errors = []
    for name in (__package__ + ".probeproxy_py", "probeproxy_py"):
        try:
            module = importlib.import_module(name)
            problem = ""
            return
        except ImportError as e:  # a wrong ABI shows up here too (undefined symbols, init name)
            errors.append(str(e))
    built = _built_for()
    problem = (
        "probeproxy's compiled module (probeproxy_py) %s; Blender runs Python %s. "
        "Build and install it with scripts/install_addon.sh. (%s)"
        % ("was built for Python " + built if built else "is missing", _BLENDER_PYTHON,
           errors[-1]))


def _built_for():
    """The Python a probeproxy_py file beside the add-on was built for, from its name."""
    import os
    import re
    here = os.path.dirname(__file__)
    for name in sorted(os.listdir(here)):
        m = re.match(r"probeproxy_py\.cpython-(\d)(\d+)", name)
        if m and "%s.%s" % (m.group(1), m.group(2)) != _BLENDER_PYTHON:
            return "%s.%s" % (m.group(1), m.group(2))
    return ""


_load()
