"""The test levels, in generation order. Each rendered level is a module here with
`build(builder) -> LevelSpec` (and optionally CHECKER_SIZE); `broken` is written by
suite/broken.py and renders nothing."""

LEVELS = (
    "corridor",
    "l_room",
    "u_corridors",
    "hall_pillars",
    "attic",
    "round_room",
    "courtyard",
    "tiny_closet",
    "hangar",
    "broken",
)
