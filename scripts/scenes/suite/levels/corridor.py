"""The seed's corridor: 18 x 3 x 3 m along X with three probes, one per third.

The long walls are split into thirds of different colours so a reflection taken from the
wrong probe (or without parallax correction) shows the wrong colour, not just a shifted
checker.
"""

from .. import meshes
from ..spec import CAPTURE_HEIGHT, Box, BoxInfluence, LevelSpec, MirrorView, Probe

LENGTH, WIDTH, HEIGHT = 18.0, 3.0, 3.0


def build(b):
    x0, x1, y0, y1 = -LENGTH / 2, LENGTH / 2, -WIDTH / 2, WIDTH / 2
    b.add("floor", [meshes.horizontal(meshes.rect(x0, y0, x1, y1), 0.0, up=True)], floor_z=0.0)
    b.add("ceiling", [meshes.horizontal(meshes.rect(x0, y0, x1, y1), HEIGHT, up=False)])
    ends = meshes.walls(meshes.rect(x0, y0, x1, y1), 0.0, HEIGHT)
    b.add("wall_end_px", [ends[1]])
    b.add("wall_end_nx", [ends[3]])
    for i, label in enumerate("abc"):
        xa, xb = x0 + i * LENGTH / 3, x0 + (i + 1) * LENGTH / 3
        side = meshes.walls(meshes.rect(xa, y0, xb, y1), 0.0, HEIGHT)
        b.add(f"wall_ny_{label}", [side[0]])
        b.add(f"wall_py_{label}", [side[2]])

    room = Box.from_bounds((x0, y0, 0.0), (x1, y1, HEIGHT))
    level = LevelSpec(artist_box_exact=True)  # a box room: its bounds are the exact proxy
    for label, x in zip("abc", (-6.0, 0.0, 6.0)):
        level.probes.append(
            Probe(
                name=f"corridor_{label}",
                capture=(x, 0.0, CAPTURE_HEIGHT),
                influence=BoxInfluence((x, 0.0, HEIGHT / 2), (4.0, 1.5, 1.5), (2.5, 1.5, 1.5)),
                proxy=room,
                floor_z=0.0,
            )
        )
    level.views += [
        MirrorView("a_look_px", "corridor_a", -7.5, 0.3, yaw_deg=0.0, pitch_deg=-35.0),
        MirrorView("b_look_nx", "corridor_b", 1.5, -0.4, yaw_deg=180.0, pitch_deg=-40.0),
        MirrorView("c_look_py", "corridor_c", 6.0, -1.0, yaw_deg=70.0, pitch_deg=-30.0),
    ]
    return level
