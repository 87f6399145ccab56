#!/usr/bin/env bash
# Builds probeproxy's Python module and installs the Blender add-on, with the module, into the
# user's Blender add-ons folder, then enables it (saved in Blender's preferences):
#   scripts/install_addon.sh            uses the `blender` on PATH and build/
# The module must match the Python inside Blender (Debian's Blender 3.4 runs the system
# Python 3.11); this script checks that before copying anything.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${PROBEPROXY_BUILD_DIR:-$here/build}"
blender="${BLENDER:-blender}"

# Only the module: the tests, benchmarks and the Blender suite are not needed to install. On a
# fresh clone that is a build of the library (minutes): say so, and show CMake's progress.
echo "install_addon: building probeproxy's Python module in $build (a few minutes on a fresh clone)"
"$here/scripts/setup.sh" module | awk '/^\[ *[0-9]+%\]/ { print "  " $0; fflush() }'
echo "install_addon: asking Blender for its Python and add-ons folder"

ask() {  # runs a Python expression in Blender, prints its value
  "$blender" -b --factory-startup --python-expr "import sys, bpy; print('probeproxy:', $1)" 2>/dev/null |
    sed -n 's/^probeproxy: //p'
}
blender_python=$(ask "'cpython-%d%d' % sys.version_info[:2]")
addons=$(ask "bpy.utils.user_resource('SCRIPTS', path='addons', create=True)")
module=$(ls "$build"/plugin/python/probeproxy_py.cpython-*.so)
case "$(basename "$module")" in
  *"$blender_python"*) ;;
  *) echo "install_addon: $(basename "$module") does not match Blender's Python ($blender_python)" >&2
     exit 2 ;;
esac

target="$addons/probeproxy_addon"
rm -rf "$target"
mkdir -p "$target"
cp "$here"/plugin/blender/probeproxy_addon/*.py "$target/"
cp "$module" "$target/"
# OpenImageIO's module, which the Python module loads from beside itself for its first image.
cp "$build/core/libprobeproxy_image_codec.so" "$target/"
"$blender" -b --python-expr "import addon_utils, bpy
m = addon_utils.enable('probeproxy_addon', default_set=True, handle_error=None)
from probeproxy_addon import native
print('probeproxy:', native.problem or 'module ' + native.module.python_version)
bpy.ops.wm.save_userpref()" 2>/dev/null | sed -n 's/^probeproxy: //p'
echo "installed the probeproxy add-on in $target (enabled; View3D > Sidebar > probeproxy)"
