"""An 8 x 6 m attic under a gabled roof: 1.5 m walls at the eaves, the ridge at 4 m along X.

A box proxy must either cut the roof's slopes or leave air above them; either way the
reflections of the sloped ceiling are off, which a convex proxy with the roof planes fixes.
"""

from .. import meshes
from ..spec import CAPTURE_HEIGHT, Box, BoxInfluence, LevelSpec, MirrorView, Probe

HX, HY = 4.0, 3.0
EAVE, RIDGE = 1.5, 4.0


def build(b):
    b.add("floor", [meshes.horizontal(meshes.rect(-HX, -HY, HX, HY), 0.0, up=True)], floor_z=0.0)
    b.add("wall_south", [meshes.facing([(-HX, -HY, 0.0), (HX, -HY, 0.0), (HX, -HY, EAVE), (-HX, -HY, EAVE)], (0, 1, 0))])
    b.add("wall_north", [meshes.facing([(-HX, HY, 0.0), (HX, HY, 0.0), (HX, HY, EAVE), (-HX, HY, EAVE)], (0, -1, 0))])
    for name, x, inward in (("gable_west", -HX, 1.0), ("gable_east", HX, -1.0)):
        gable = [(x, -HY, 0.0), (x, HY, 0.0), (x, HY, EAVE), (x, 0.0, RIDGE), (x, -HY, EAVE)]
        b.add(name, [meshes.facing(gable, (inward, 0, 0))])
    rise = RIDGE - EAVE
    b.add("roof_south", [meshes.facing([(-HX, -HY, EAVE), (HX, -HY, EAVE), (HX, 0.0, RIDGE), (-HX, 0.0, RIDGE)], (0, rise, -HY))])
    b.add("roof_north", [meshes.facing([(-HX, HY, EAVE), (HX, HY, EAVE), (HX, 0.0, RIDGE), (-HX, 0.0, RIDGE)], (0, -rise, -HY))])

    room = Box.from_bounds((-HX, -HY, 0.0), (HX, HY, RIDGE))
    h = RIDGE / 2
    level = LevelSpec()
    level.probes += [
        # Inner ranges 1.6 m apart: Lagarde's weights cross over gently (under 0.02 per cm).
        Probe("attic_west", (-2.0, 0.0, CAPTURE_HEIGHT), BoxInfluence((-2.0, 0.0, h), (3.0, HY, h), (1.2, HY, h)), room, 0.0),
        Probe("attic_east", (2.0, 0.5, CAPTURE_HEIGHT), BoxInfluence((2.0, 0.0, h), (3.0, HY, h), (1.2, HY, h)), room, 0.0),
    ]
    level.views += [
        MirrorView("west_slope", "attic_west", -3.0, -1.0, yaw_deg=30.0, pitch_deg=-35.0),
        MirrorView("east_gable", "attic_east", 3.0, 0.8, yaw_deg=210.0, pitch_deg=-40.0),
    ]
    return level
