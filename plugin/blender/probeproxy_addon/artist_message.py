# The library's messages as the artist's Blender scene says them: its messages name scene-file
# places (`$.probes[0]`), metres and the file it was handed, which an artist in a centimetre
# scene, or with an unsaved .blend, never wrote.

import re

import bpy

from . import scene_io

_PROBE_PATH = re.compile(r"\$\.probes\[(\d+)\]((?:\.[a-z_]+|\[\d+\])*): ")
_POINT_IN_METRES = re.compile(r"\((-?[0-9.eE+-]+), (-?[0-9.eE+-]+), (-?[0-9.eE+-]+)\) m\b")


def artist_message(scene, text):
    """The library's message as the artist's scene says it: no file the add-on made up for an
    unsaved scene, a probe by its object's name rather than its place in the scene file
    (`$.probes[0]`), points in the scene's units rather than metres."""
    if not scene.probeproxy.scene_file:
        text = text.replace(scene_io.scene_anchor(scene) + ": ", "")
    names = [o.name for o in scene_io.probes(scene)]

    def probe_named(m):
        index, member = int(m.group(1)), m.group(2)
        if index >= len(names):
            return m.group(0)
        rest = text[m.end():]
        if rest.startswith("probe '%s'" % names[index]) and not member:
            return ""  # the message names it already
        return "probe '%s'%s: " % (names[index], " (%s)" % member.lstrip(".") if member else "")

    text = _PROBE_PATH.sub(probe_named, text)
    units = scene.unit_settings
    if units.system != "NONE" and units.scale_length != 1.0:
        def in_scene_units(m):
            return "(%s)" % ", ".join(
                bpy.utils.units.to_string(units.system, "LENGTH", float(v), precision=4)
                for v in m.groups())
        text = _POINT_IN_METRES.sub(in_scene_units, text)
    return text
