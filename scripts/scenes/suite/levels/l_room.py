"""An L-shaped room: two 10 x 4 m arms meeting in a 4 x 4 m corner, 3 m high.

A box proxy can only be the whole L, so it reaches over the missing quadrant: each probe's
artist box is the L's bounds, the classic case where a box proxy misplaces reflections.
"""

from .. import meshes
from ..spec import CAPTURE_HEIGHT, Box, BoxInfluence, LevelSpec, MirrorView, Probe

HEIGHT = 3.0
L_SHAPE = [(0.0, 0.0), (10.0, 0.0), (10.0, 4.0), (4.0, 4.0), (4.0, 10.0), (0.0, 10.0)]
WALL_NAMES = ["wall_south", "wall_east_x_arm", "wall_north_x_arm", "wall_east_y_arm", "wall_north", "wall_west"]


def build(b):
    b.add("floor", [meshes.horizontal(L_SHAPE, 0.0, up=True)], floor_z=0.0)
    b.add("ceiling", [meshes.horizontal(L_SHAPE, HEIGHT, up=False)])
    for name, face in zip(WALL_NAMES, meshes.walls(L_SHAPE, 0.0, HEIGHT)):
        b.add(name, [face])

    room = Box.from_bounds((0.0, 0.0, 0.0), (10.0, 10.0, HEIGHT))
    h = HEIGHT / 2
    level = LevelSpec()
    level.probes += [
        # The corner reaches 1.5 m into each arm and fades out there; each arm ends at the
        # corner and fades out over its last 1.45 m (1.45 m between inner ranges, so the
        # weights cross over gently); every side without a band lies in a wall.
        Probe("corner", (2.0, 2.0, CAPTURE_HEIGHT), BoxInfluence((2.0, 2.0, h), (3.5, 3.5, h), (2.0, 2.0, h)), room, 0.0),
        Probe("arm_x", (8.5, 2.0, CAPTURE_HEIGHT), BoxInfluence((7.25, 2.0, h), (3.25, 2.0, h), (1.8, 2.0, h)), room, 0.0),
        Probe("arm_y", (2.0, 8.5, CAPTURE_HEIGHT), BoxInfluence((2.0, 7.25, h), (2.0, 3.25, h), (2.0, 1.8, h)), room, 0.0),
    ]
    level.views += [
        MirrorView("corner_diagonal", "corner", 1.0, 1.2, yaw_deg=45.0, pitch_deg=-35.0),
        MirrorView("arm_x_end", "arm_x", 6.5, 2.5, yaw_deg=0.0, pitch_deg=-35.0),
        MirrorView("arm_y_back", "arm_y", 1.5, 8.0, yaw_deg=-90.0, pitch_deg=-30.0),
    ]
    return level
