"""A 20 x 12 x 6 m hall with a 3 x 2 grid of 0.8 m square pillars.

The pillars occlude parts of the hall from each probe: the reflections they hide cannot be
right for any proxy, which is what the `occluded` count measures.
"""

from .. import meshes
from ..spec import CAPTURE_HEIGHT, Box, BoxInfluence, LevelSpec, MirrorView, Probe

LO, HI = (-10.0, -6.0, 0.0), (10.0, 6.0, 6.0)
PILLAR = 0.8


def build(b):
    b.add_all(meshes.room_box(LO, HI), floor_z=0.0)
    for i, (x, y) in enumerate((x, y) for y in (-3.0, 3.0) for x in (-5.0, 0.0, 5.0)):
        r = PILLAR / 2
        b.add(f"pillar_{i}", meshes.walls(meshes.rect(x - r, y - r, x + r, y + r), LO[2], HI[2], inward=False))

    hall = Box.from_bounds(LO, HI)
    level = LevelSpec()
    level.probes += [
        Probe("hall_west", (-5.0, 0.0, CAPTURE_HEIGHT), BoxInfluence((-5.0, 0.0, 3.0), (5.5, 6.0, 3.0), (4.0, 5.0, 2.5)), hall, 0.0),
        Probe("hall_east", (4.0, 1.0, CAPTURE_HEIGHT), BoxInfluence((5.0, 0.0, 3.0), (5.5, 6.0, 3.0), (4.0, 5.0, 2.5)), hall, 0.0),
    ]
    level.views += [
        MirrorView("west_pillars", "hall_west", -7.0, -1.0, yaw_deg=20.0, pitch_deg=-35.0),
        MirrorView("east_back", "hall_east", 6.0, 1.5, yaw_deg=200.0, pitch_deg=-40.0),
    ]
    return level
