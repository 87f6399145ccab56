"""Scenes that each break exactly one validation rule (`probeproxy validate`), written into
broken/ beside the bad inputs. All use broken/'s 4 x 3 x 3 m room (x -2..2, y -1.5..1.5,
z 0..3) and need no renders: validate reads no cubemap. `validate_clean` is the unbroken
base every variant changes in one place; the table in broken/README.md lists them.
No bpy here.
"""

from . import scene_json
from .spec import Box, BoxInfluence, Probe

ROOM = Box.from_bounds((-2.0, -1.5, 0.0), (2.0, 1.5, 3.0))
CAPTURE = (0.5, 0.25, 1.6)
INFLUENCE = BoxInfluence(ROOM.center, ROOM.half_extents, (1.5, 1.0, 1.5))


def _probe(name="probe", capture=CAPTURE, influence=INFLUENCE, proxy=ROOM):
    return Probe(name, capture, influence, proxy, 0.0)


def _box(lo, hi, inner):
    box = Box.from_bounds(lo, hi)
    return BoxInfluence(box.center, box.half_extents, inner)


def _proxy_obj(title, top):
    """A closed box over the room, faces wound outward; `top` is the list of top faces over
    the corners 5-8 (and vertex 9, the top's centre): a dent makes it concave, none leaves it
    open."""
    lines = [f"# {title}", "o proxy"]
    corners = [(-2, -1.5, 0), (2, -1.5, 0), (2, 1.5, 0), (-2, 1.5, 0),
               (-2, -1.5, 3), (2, -1.5, 3), (2, 1.5, 3), (-2, 1.5, 3), (0, 0, 2.5)]
    lines += [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in corners]
    faces = [(1, 4, 3, 2), (1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (4, 1, 5, 8)] + top
    lines += ["f " + " ".join(map(str, f)) for f in faces]
    return "\n".join(lines) + "\n"


DENTED_PROXY = _proxy_obj("dented_proxy.obj: the room's box with its top pushed in 0.5 m at the centre (concave)",
                          [(5, 6, 9), (6, 7, 9), (7, 8, 9), (8, 5, 9)])
OPEN_PROXY = _proxy_obj("open_proxy.obj: the room's box without its top (not closed)", [])

# Walls in this room: the same room with a wall across it at x = 0.5, so its east part is
# another space, entered by a door 0.8 m wide and 2 m high at its north end (the walkable
# floor is the floor a player reaches; faces both ways: a two-sided wall).
PARTITION_OBJ = """# partitioned_room.obj: the 4 x 3 x 3 m room split by a wall at x = 0.5 with a door at y 0.7..1.5
o room
v -2.0 -1.5 0.0
v 2.0 -1.5 0.0
v 2.0 1.5 0.0
v -2.0 1.5 0.0
v -2.0 -1.5 3.0
v 2.0 -1.5 3.0
v 2.0 1.5 3.0
v -2.0 1.5 3.0
v 0.5 -1.5 0.0
v 0.5 0.7 0.0
v 0.5 0.7 3.0
v 0.5 -1.5 3.0
v 0.5 0.7 2.0
v 0.5 1.5 2.0
v 0.5 1.5 3.0
f 1 2 3 4
f 5 8 7 6
f 1 5 6 2
f 2 6 7 3
f 3 7 8 4
f 4 8 5 1
o partition
f 9 10 11 12
f 9 12 11 10
f 13 14 15 11
f 13 11 15 14
"""

# rule id (or ids) expected -> (mesh, probes, extra files); the README table below says why.
VARIANTS = {
    "validate_clean": ("valid_room.obj", [_probe()]),
    "validate_not_convex": ("valid_room.obj", [_probe()]),
    "validate_not_closed": ("valid_room.obj", [_probe()]),
    "validate_capture_outside_proxy": ("valid_room.obj", [_probe(proxy=Box.from_bounds((-2.0, -1.5, 0.0), (0.0, 1.5, 3.0)))]),
    "validate_capture_outside_influence": ("valid_room.obj", [_probe(influence=_box((-2.0, -1.5, 0.0), (2.0, 1.5, 1.0), (1.5, 1.0, 0.5)))]),
    "validate_proxy_error": ("valid_room.obj", [_probe(proxy=Box.from_bounds((-3.0, -2.5, 0.0), (3.0, 2.5, 3.0)))]),
    "validate_floor_not_covered": ("valid_room.obj", [_probe(influence=_box((-2.0, -1.5, 0.0), (1.0, 1.5, 3.0), (1.0, 1.0, 1.5)))]),
    "validate_too_many_overlaps": ("valid_room.obj", [
        _probe(f"probe_{i}", (sx * 1.0, sy * 0.75, 1.6),
               BoxInfluence((sx * 1.0, sy * 0.75, 1.5), (2.0, 1.5, 1.5), (0.2, 0.2, 1.5)))
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (1, 1), (-1, 1), (0, 0)])]),
    "validate_inner_ranges_overlap": ("valid_room.obj", [
        _probe("west", (-1.0, 0.0, 1.6), _box((-2.0, -1.5, 0.0), (0.5, 1.5, 3.0), (1.0, 1.5, 1.5))),
        _probe("east", (1.0, 0.0, 1.6), _box((-0.5, -1.5, 0.0), (2.0, 1.5, 3.0), (1.0, 1.5, 1.5)))]),
    "validate_weight_jump": ("valid_room.obj", [
        _probe("west", (-1.0, 0.0, 1.6), _box((-2.0, -1.5, 0.0), (0.0, 1.5, 3.0), (1.0, 1.5, 1.5))),
        _probe("east", (1.0, 0.0, 1.6), _box((0.0, -1.5, 0.0), (2.0, 1.5, 3.0), (1.0, 1.5, 1.5)))]),
    "validate_influence_leak": ("partitioned_room.obj", [
        _probe(capture=(-0.75, 0.25, 1.6), proxy=Box.from_bounds((-2.0, -1.5, 0.0), (0.5, 1.5, 3.0)))]),
    "validate_reflected_camera": ("valid_room.obj", [_probe(proxy=Box.from_bounds((-2.0, -1.5, 0.3), (2.0, 1.5, 3.0)))]),
}

README = """
## Validation variants (`probeproxy validate`)

Each `validate_*.scene.json` is `validate_clean` (one probe in the room, capture (0.5, 0.25,
1.6), influence the room with inner range (1.5, 1.0, 1.5), proxy the room's box) with one
change; `validate --json` on it reports exactly the findings in the last column (exit 1), and on
`validate_clean` nothing (exit 0).

| scene file | the one change | finding |
|---|---|---|
| `validate_clean` | none | none |
| `validate_not_convex` | proxy is `dented_proxy.obj`: the box with its top pushed 0.5 m in at the centre | `proxy_concave_edge` |
| `validate_not_closed` | proxy is `open_proxy.obj`: the box without its top | `proxy_not_closed` |
| `validate_capture_outside_proxy` | proxy box only x -2..0 (the capture point is at x 0.5) | `capture_outside_proxy` |
| `validate_capture_outside_influence` | influence only z 0..1 (the capture point is at z 1.6) | `capture_outside_influence` |
| `validate_proxy_error` | proxy box 6 x 5 m instead of the room's 4 x 3 m | `proxy_error_over_tolerance` |
| `validate_floor_not_covered` | influence only x -2..1: the floor at x 1..2 has none | `floor_not_covered` |
| `validate_too_many_overlaps` | five probes, one per quarter and one in the middle, whose volumes all meet at the centre (the blend takes four) | `too_many_overlaps` |
| `validate_inner_ranges_overlap` | two probes whose inner ranges share x -0.25..0.25 | `inner_ranges_overlap` |
| `validate_weight_jump` | two probes whose volumes only touch at x = 0, no fade band there | `weight_jump` |
| `validate_influence_leak` | level `partitioned_room.obj` (a wall at x = 0.5, a door at its north end); the probe west of it, its influence the whole room | `influence_leak`, and `proxy_error_over_tolerance` as information (the far room's floor is not the room box's to serve, and no generated proxy serves it better) |
| `validate_reflected_camera` | proxy box starts 0.3 m above the floor (the reflection plane) | `reflected_camera_outside_proxy`, and what follows from it: `proxy_error_over_tolerance` (every floor reflection starts outside the proxy: a miss; the generated proxy serves the floor, so no `split_probe`) |
"""


def write_all(out):
    files = {"dented_proxy.obj": DENTED_PROXY, "open_proxy.obj": OPEN_PROXY,
             "partitioned_room.obj": PARTITION_OBJ}
    for name, (mesh, probes) in VARIANTS.items():
        data = scene_json.scene([mesh], probes, cubemaps=False)
        if name in ("validate_not_convex", "validate_not_closed"):
            proxy = "dented_proxy.obj" if name == "validate_not_convex" else "open_proxy.obj"
            data["probes"][0]["proxy"] = {"kind": "convex", "mesh": proxy}
        files[f"{name}.scene.json"] = scene_json.dumps(data)
    for name, text in files.items():
        (out / name).write_text(text, encoding="utf-8")
    return len(files)
