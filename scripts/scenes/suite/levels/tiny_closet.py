"""A 1.0 x 0.8 x 2.2 m closet: every wall is within half a metre of the probe, where the
parallax of an uncorrected cubemap is largest and a proxy's few centimetres of error matter."""

from .. import meshes
from ..spec import Box, BoxInfluence, LevelSpec, MirrorView, Probe

LO, HI = (-0.5, -0.4, 0.0), (0.5, 0.4, 2.2)
CHECKER_SIZE = 0.2  # 0.5 m squares would leave two per wall


def build(b):
    b.add_all(meshes.room_box(LO, HI), floor_z=0.0)
    closet = Box.from_bounds(LO, HI)
    level = LevelSpec(artist_box_exact=True)  # a box room: its bounds are the exact proxy
    level.probes.append(
        Probe("closet", (0.1, -0.05, 1.5), BoxInfluence(closet.center, closet.half_extents, (0.4, 0.3, 1.0)), closet, 0.0)
    )
    level.views += [
        MirrorView("closet_back", "closet", 0.0, 0.3, yaw_deg=-90.0, pitch_deg=-45.0),
        MirrorView("closet_corner", "closet", -0.35, -0.25, yaw_deg=30.0, pitch_deg=-40.0),
    ]
    return level
