"""Deliberately broken (and one deliberately messy but valid) inputs, as plain text files.

Each carries exactly one kind of problem, with a scene file of its own that is otherwise
correct, so a test can expect one specific one-line error (exit code 2) per file, or, for
`probe_outside` a validation finding, and for `messy_but_valid` a clean load. README.md in
the output lists them. No bpy here: nothing is rendered.
"""

from . import scene_json, validation_variants
from .spec import Box, BoxInfluence, Probe

# A 4 x 3 x 3 m box room around the origin: small, valid, and easy to reason about.
LO, HI = (-2.0, -1.5, 0.0), (2.0, 1.5, 3.0)
ROOM = Box.from_bounds(LO, HI)
PROBE = Probe("probe", (0.5, 0.25, 1.6), BoxInfluence(ROOM.center, ROOM.half_extents, (1.5, 1.0, 1.5)), ROOM, 0.0)


def _fmt(v):
    return f"{v:.6f}" if isinstance(v, float) else str(v)


def _room_vertices():
    (x0, y0, z0), (x1, y1, z1) = LO, HI
    return [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
            (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]


# 1-based, every quad wound to face into the room.
ROOM_QUADS = [(1, 2, 3, 4), (5, 8, 7, 6), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 8, 4), (4, 8, 5, 1)]


def _room_obj(title, vertex_override=None):
    lines = [f"# {title}", "o room"]
    for i, v in enumerate(_room_vertices(), start=1):
        text = vertex_override.get(i) if vertex_override else None
        lines.append(text or "v " + " ".join(_fmt(c) for c in v))
    lines += ["f " + " ".join(map(str, q)) for q in ROOM_QUADS]
    return "\n".join(lines) + "\n"


def _room_ply(title, vertex_override):
    verts = _room_vertices()
    lines = ["ply", "format ascii 1.0", f"comment {title}", f"element vertex {len(verts)}",
             "property float x", "property float y", "property float z",
             f"element face {len(ROOM_QUADS)}", "property list uchar int vertex_indices", "end_header"]
    for i, v in enumerate(verts, start=1):
        lines.append(vertex_override.get(i) or " ".join(_fmt(c) for c in v))
    lines += [f"4 {' '.join(str(i - 1) for i in q)}" for q in ROOM_QUADS]
    return "\n".join(lines) + "\n"


MALFORMED_OBJ = """# malformed.obj: OBJ with lines no reader can make sense of
o room
v -2.0 -1.5 0.0
v 2.0 -1.5 0.0
v 2.0 1.5 0.0
v -2.0 1.5 zero
this line is not OBJ at all
v 1.0 2.0
f 1 4 3 2
f 1 2 99
f 3 4
"""

EMPTY_OBJ = """# empty_level.obj: vertices but not a single face: a level with no surfaces
o nothing
v -2.0 -1.5 0.0
v 2.0 -1.5 0.0
v 2.0 1.5 0.0
"""

# The room again, written the way real exports come out; every face (but the fin's back)
# faces into the room. Problems, by line group:
#  - the floor is two triangles split along its diagonal (1-3), and a two-sided "fin" stands
#    on that diagonal as two triangles of opposite winding: edge 1-3 has 4 faces (non-manifold);
#  - the -Y wall uses its own copies of the corner vertices (9-12 duplicate 1, 2, 6, 5):
#    unwelded seams along the floor and the ceiling;
#  - the +X wall has a window: four quads around a 1 x 1 m opening into nothing (open hole);
#  - a zero-area triangle (13-15 are one point), a collinear one (1, 16, 2 on the floor edge);
#  - the -X wall is a hexagon with a collinear midpoint on its top and bottom edges (n-gon),
#    the ceiling a quad; one face uses the v/vt/vn form, another v//vn;
#  - vertex 24 is used by no face; `o`, `g` and `s` lines as exporters write them.
MESSY_OBJ = """# messy_but_valid.obj: non-manifold, open, duplicated and degenerate, but a real level
# (see broken/README.md). A loader must accept it.
o messy_room
g walls
s off
v -2.0 -1.5 0.0
v 2.0 -1.5 0.0
v 2.0 1.5 0.0
v -2.0 1.5 0.0
v -2.0 -1.5 3.0
v 2.0 -1.5 3.0
v 2.0 1.5 3.0
v -2.0 1.5 3.0
v -2.0 -1.5 0.0
v 2.0 -1.5 0.0
v 2.0 -1.5 3.0
v -2.0 -1.5 3.0
v 0.5 0.5 0.0
v 0.5 0.5 0.0
v 0.5 0.5 0.0
v 0.0 -1.5 0.0
v 0.0 0.0 1.0
v 2.0 -0.5 1.0
v 2.0 0.5 1.0
v 2.0 0.5 2.0
v 2.0 -0.5 2.0
v -2.0 0.0 0.0
v -2.0 0.0 3.0
v 1.0 1.0 2.5
vt 0.0 0.0
vt 1.0 0.0
vt 1.0 1.0
vn 0.0 0.0 1.0
vn 0.0 0.0 -1.0
g floor
f 1/1/1 2/2/1 3/3/1
f 1//1 3//1 4//1
g fin
f 1 3 17
f 1 17 3
g degenerate
f 13 14 15
f 1 16 2
g walls
f 9 12 11 10
f 2 18 19 3
f 2 6 21 18
f 6 7 20 21
f 3 19 20 7
f 3 7 8 4
f 8 23 5 1 22 4
g ceiling
f 5 8 7 6
"""

README = """# Broken test inputs

Written by `scripts/scenes/generate_suite.py --levels broken`. Every input has its own scene
file; apart from the one problem listed, each is correct (a probe `probe` in a 4 x 3 x 3 m
room, x -2..2, y -1.5..1.5, z 0..3, with a box influence and box proxy, no cubemap).
`valid_room.obj` is that room, unbroken, shared by the scene files whose problem is in the
JSON itself.

| scene file | mesh | problem | expected |
|---|---|---|---|
| `nan_vertex.scene.json` | `nan_vertex.obj` | vertex 3 is `v nan 1.5 0.0` | exit 2, one line naming the file and the non-finite vertex |
| `inf_vertex.scene.json` | `inf_vertex.ply` (ASCII PLY) | vertex index 6 (0-based) has `x = inf` | exit 2, one line naming the file and the non-finite vertex |
| `malformed.scene.json` | `malformed.obj` | a vertex coordinate `zero`, a line that is not OBJ, a vertex with two coordinates, a face index 99 (the file has 6 `v` lines), a face with two vertices | exit 2, one line naming the file and the first problem |
| `missing_mesh.scene.json` | `does_not_exist.glb` | the mesh file does not exist | exit 2, one line naming the missing file |
| `empty_level.scene.json` | `empty_level.obj` | three vertices, no faces: the level has no surface | exit 2, one line saying the level has no faces |
| `bad_fields.scene.json` | `valid_room.obj` | `$.probes[0].influence.radius` is -2 (sphere influence), `$.probes[1]` has no `capture` | exit 2, one line naming the JSON path, e.g. `bad_fields.scene.json: $.probes[0].influence.radius: expected a positive number, got -2` |
| `syntax_error.scene.json` | - | the JSON text is cut off in the middle of a probe | exit 2, one line naming the file and the line/column |
| `unsupported_version.scene.json` | `valid_room.obj` | `"probeproxy_scene": 99` | exit 2, one line naming the field |
| `probe_outside.scene.json` | `valid_room.obj` | the file is well formed, but probe `probe` captures at (6, 0, 1.6): outside the room, its influence volume and its proxy | loads; `build` and `export` refuse it (exit 2, one line: outside its influence volume); `validate` will report it as a finding (exit 1) |
| `messy_but_valid.scene.json` | `messy_but_valid.obj` | non-manifold edge (4 faces on the floor diagonal 1-3), an open window hole in the +X wall, duplicate (unwelded) vertices along the -Y wall, a zero-area triangle (three copies of one point), a collinear triangle, a hexagon with collinear vertices, quads, `v/vt/vn` and `v//vn` faces, an unused vertex | loads and builds without error: real levels look like this |
"""


def _scene(mesh, probe=PROBE):
    return scene_json.scene([mesh], [probe], cubemaps=False)


def write_all(out):
    files = {
        "valid_room.obj": _room_obj("valid_room.obj: a closed 4 x 3 x 3 m box room, faces inward"),
        "nan_vertex.obj": _room_obj("nan_vertex.obj: vertex 3 has a NaN coordinate", {3: "v nan 1.5 0.0"}),
        "inf_vertex.ply": _room_ply("inf_vertex.ply: vertex 6 (0-based) has an infinite coordinate", {7: "inf 1.5 3.0"}),
        "malformed.obj": MALFORMED_OBJ,
        "empty_level.obj": EMPTY_OBJ,
        "messy_but_valid.obj": MESSY_OBJ,
        "README.md": README + validation_variants.README,
    }
    scenes = {
        "nan_vertex": _scene("nan_vertex.obj"),
        "inf_vertex": _scene("inf_vertex.ply"),
        "malformed": _scene("malformed.obj"),
        "missing_mesh": _scene("does_not_exist.glb"),
        "empty_level": _scene("empty_level.obj"),
        "messy_but_valid": _scene("messy_but_valid.obj", Probe("probe", (-1.0, 0.75, 1.6), PROBE.influence, ROOM, 0.0)),
        "probe_outside": _scene("valid_room.obj", Probe("probe", (6.0, 0.0, 1.6), PROBE.influence, ROOM, 0.0)),
    }
    bad = _scene("valid_room.obj")
    bad["probes"][0]["influence"] = {"kind": "sphere", "center": [0.0, 0.0, 1.5], "radius": -2, "inner_radius": 1.0}
    second = dict(bad["probes"][0], name="probe_without_capture", influence=_scene("valid_room.obj")["probes"][0]["influence"])
    del second["capture"]
    bad["probes"].append(second)
    scenes["bad_fields"] = bad
    version = _scene("valid_room.obj")
    version["probeproxy_scene"] = 99
    scenes["unsupported_version"] = version

    for name, data in scenes.items():
        files[f"{name}.scene.json"] = scene_json.dumps(data)
    text = scene_json.dumps(_scene("valid_room.obj"))
    files["syntax_error.scene.json"] = text[: text.index('"influence"') + 20]

    for name, text in files.items():
        (out / name).write_text(text, encoding="utf-8")
    return len(files) + validation_variants.write_all(out)
