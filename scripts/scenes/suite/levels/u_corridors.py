"""U-shaped corridors on two floors: ground z 0..3, a 0.5 m slab, upper z 3.5..6.5.

The two storeys share a footprint, so a probe must only see its own floor; the slab's
underside is the ground floor's ceiling and its top the upper floor, a second reflection
plane at z = 3.5.
"""

from .. import meshes
from ..spec import CAPTURE_HEIGHT, Box, BoxInfluence, LevelSpec, MirrorView, Probe

STOREY = 3.0
SLAB = 0.5
# Counter-clockwise: the south arm, the bend at x 9.5..12, the north arm, 2.5 m wide each.
U_SHAPE = [(0.0, 0.0), (12.0, 0.0), (12.0, 10.0), (0.0, 10.0), (0.0, 7.5), (9.5, 7.5), (9.5, 2.5), (0.0, 2.5)]
WALL_NAMES = ["wall_south", "wall_east", "wall_north", "wall_west_north_arm",
              "wall_inner_north", "wall_inner_east", "wall_inner_south", "wall_west_south_arm"]


def _storey(b, prefix, z0):
    z1 = z0 + STOREY
    b.add(prefix + "floor", [meshes.horizontal(U_SHAPE, z0, up=True)], floor_z=z0)
    b.add(prefix + "ceiling", [meshes.horizontal(U_SHAPE, z1, up=False)])
    for name, face in zip(WALL_NAMES, meshes.walls(U_SHAPE, z0, z1)):
        b.add(prefix + name, [face])
    return Box.from_bounds((0.0, 0.0, z0), (12.0, 10.0, z1))


def build(b):
    ground = _storey(b, "ground_", 0.0)
    upper_z = STOREY + SLAB
    upper = _storey(b, "upper_", upper_z)
    # The slab's rim closes it between the ground ceiling (its underside) and the upper floor.
    b.add("slab_edge", meshes.walls(U_SHAPE, STOREY, upper_z, inward=False))

    def probe(name, x, y, floor_z, room, center, half, inner):
        cz = floor_z + STOREY / 2
        return Probe(name, (x, y, floor_z + CAPTURE_HEIGHT),
                     BoxInfluence((*center, cz), (*half, STOREY / 2), (*inner, STOREY / 2)), room, floor_z)

    level = LevelSpec()
    # Each storey: a probe per arm and one in the bend, so every metre of floor is covered.
    # Each arm ends where the bend begins (x = 9.5) and fades out over its last 1.5 m; the bend
    # reaches 1.5 m into each arm and fades out there; every side without a band lies in a
    # wall. Inner ranges 1.75 m apart, so the weights cross over gently.
    for storey, floor_z, room in (("ground", 0.0, ground), ("upper", upper_z, upper)):
        level.probes += [
            probe(f"{storey}_south", 3.0, 1.25, floor_z, room, (4.75, 1.25), (4.75, 1.25), (3.25, 1.25)),
            probe(f"{storey}_bend", 10.75, 5.0, floor_z, room, (10.75, 5.0), (2.75, 5.0), (1.0, 5.0)),
            probe(f"{storey}_north", 3.0, 8.75, floor_z, room, (4.75, 8.75), (4.75, 1.25), (3.25, 1.25)),
        ]
    level.views += [
        MirrorView("ground_south_east", "ground_south", 1.5, 1.0, yaw_deg=0.0, pitch_deg=-35.0),
        MirrorView("ground_bend_north", "ground_bend", 11.0, 1.5, yaw_deg=90.0, pitch_deg=-30.0),
        MirrorView("upper_north_east", "upper_north", 2.0, 9.0, yaw_deg=0.0, pitch_deg=-35.0),
    ]
    return level
