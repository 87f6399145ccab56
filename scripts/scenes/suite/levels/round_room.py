"""A cylindrical room, radius 5 m, 4 m high, 48 wall segments, with an off-centre probe.

The wall is four objects (one per quadrant) so the cubemap shows which way is which; the
sphere influence volume exercises the scene file's sphere kind.
"""

import math

from .. import meshes
from ..spec import CAPTURE_HEIGHT, Box, LevelSpec, MirrorView, Probe, SphereInfluence

RADIUS, HEIGHT, SEGMENTS = 5.0, 4.0, 48


def build(b):
    ring = meshes.circle(0.0, 0.0, RADIUS, SEGMENTS)
    b.add("floor", [meshes.horizontal(ring, 0.0, up=True)], floor_z=0.0)
    b.add("ceiling", [meshes.horizontal(ring, HEIGHT, up=False)])
    wall = meshes.walls(ring, 0.0, HEIGHT)
    quarter = SEGMENTS // 4
    for q in range(4):
        b.add(f"wall_quadrant_{q}", wall[q * quarter:(q + 1) * quarter])

    room = Box.from_bounds((-RADIUS, -RADIUS, 0.0), (RADIUS, RADIUS, HEIGHT))
    # Centred at mid-height, the sphere must reach the floor's (and the ceiling's) rim: a
    # radius of R would leave a ring of floor near the wall in no volume.
    reach = math.hypot(RADIUS, HEIGHT / 2)
    level = LevelSpec()
    level.probes.append(
        Probe("round", (1.5, -1.0, CAPTURE_HEIGHT), SphereInfluence((0.0, 0.0, HEIGHT / 2), reach, RADIUS - 1.0), room, 0.0)
    )
    level.views += [
        MirrorView("toward_centre", "round", 2.5, -1.5, yaw_deg=150.0, pitch_deg=-35.0),
        MirrorView("toward_south_east", "round", -1.0, 2.0, yaw_deg=-60.0, pitch_deg=-30.0),
    ]
    return level
