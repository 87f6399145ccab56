"""A 12 x 12 m courtyard with 5 m walls and no ceiling: the sky is seen by the probes.

Rays that leave over the walls hit nothing; the level has no geometry there to build a
proxy from, so this is the case where a proxy must be closed by something other than the
level (and where the position cubemaps hold zeros for sky texels).
"""

from .. import meshes
from ..spec import CAPTURE_HEIGHT, Box, BoxInfluence, LevelSpec, MirrorView, Probe

H, WALL = 6.0, 5.0


def build(b):
    parts = meshes.room_box((-H, -H, 0.0), (H, H, WALL))
    del parts["ceiling"]
    b.add_all(parts, floor_z=0.0)
    b.add("fountain", meshes.prop_box((-0.75, -0.75, 0.0), (0.75, 0.75, 0.8)))

    court = Box.from_bounds((-H, -H, 0.0), (H, H, WALL))
    h = WALL / 2
    level = LevelSpec()
    level.probes += [
        # West and east halves reaching past the walls, so the whole court is covered and the
        # two only fade into each other, across the middle (inner ranges 1 m apart).
        Probe("court_sw", (-3.0, -3.0, CAPTURE_HEIGHT), BoxInfluence((-3.0, 0.0, h), (4.0, H + 1.0, h), (2.5, H + 1.0, h)), court, 0.0),
        Probe("court_ne", (3.0, 2.5, CAPTURE_HEIGHT), BoxInfluence((3.0, 0.0, h), (4.0, H + 1.0, h), (2.5, H + 1.0, h)), court, 0.0),
    ]
    level.views += [
        MirrorView("sw_fountain", "court_sw", -4.5, -4.0, yaw_deg=45.0, pitch_deg=-30.0),
        MirrorView("ne_corner", "court_ne", 4.0, 4.0, yaw_deg=225.0, pitch_deg=-25.0),
    ]
    return level
