# probeproxy's Blender add-on: convex proxies for parallax-corrected cubemaps, where levels are
# built. Probes are empties with probeproxy settings; the sidebar (N panel, tab "probeproxy")
# generates their proxies from the level, validates their volumes, exports proxies.json +
# proxies.glb for the runtime, and reads/writes the scene.json the command line uses.
# SPDX-License-Identifier: GPL-3.0-or-later

bl_info = {
    "name": "probeproxy",
    "author": "probeproxy",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > probeproxy",
    "description": "Generate, validate and export convex proxies for parallax-corrected cubemaps",
    "category": "Lighting",
}

import bpy

from . import draw, native, operators, panel, properties


def register():
    properties.register()
    operators.register()
    panel.register()
    draw.register()
    if native.module is None:
        # Said on enable, in the console and the status bar; the panel says it too.
        print("probeproxy: " + native.problem)


def unregister():
    draw.unregister()
    panel.unregister()
    operators.unregister()
    properties.unregister()
