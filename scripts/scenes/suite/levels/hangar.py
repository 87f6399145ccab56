"""An 80 x 50 x 20 m hangar with two shipping containers: far walls, so parallax is small
except on the containers, and coordinates large enough to show precision problems."""

from .. import meshes
from ..spec import Box, BoxInfluence, LevelSpec, MirrorView, Probe

LO, HI = (-40.0, -25.0, 0.0), (40.0, 25.0, 20.0)
CHECKER_SIZE = 2.0  # 0.5 m squares would alias to noise at this distance
CAPTURE_Z = 2.0


def build(b):
    b.add_all(meshes.room_box(LO, HI), floor_z=0.0)
    b.add("container_a", meshes.prop_box((-30.0, 8.0, 0.0), (-18.0, 10.5, 2.6)))
    b.add("container_b", meshes.prop_box((10.0, -15.0, 0.0), (12.5, -3.0, 2.6)))

    hangar = Box.from_bounds(LO, HI)
    level = LevelSpec(artist_box_exact=True)  # a box room (the containers stand inside it)
    level.probes += [
        Probe("hangar_west", (-20.0, 0.0, CAPTURE_Z), BoxInfluence((-20.0, 0.0, 10.0), (22.0, 25.0, 10.0), (18.0, 23.0, 9.0)), hangar, 0.0),
        Probe("hangar_east", (20.0, 0.0, CAPTURE_Z), BoxInfluence((20.0, 0.0, 10.0), (22.0, 25.0, 10.0), (18.0, 23.0, 9.0)), hangar, 0.0),
    ]
    level.views += [
        MirrorView("west_container", "hangar_west", -22.0, -3.0, yaw_deg=110.0, pitch_deg=-35.0),
        MirrorView("east_far_wall", "hangar_east", 22.0, 2.0, yaw_deg=180.0, pitch_deg=-30.0),
    ]
    return level
