"""Writes a level of about TRIANGLES triangles and a scene with one probe in it, for measuring
what `build` costs on a level far denser than any game map (peak memory from
/usr/bin/time -v) and for checking that --max-triangles stops it.
    write_dense_room.py OUT_FOLDER TRIANGLES
The level is a 20 x 16 x 5 m room (binary PLY) whose six walls are regular grids, each split
into as many triangles as its share of the room's area; the probe captures at the room's
centre, 1.6 m up."""
import math
import os
import struct
import sys

out, wanted = sys.argv[1], int(sys.argv[2])
os.makedirs(out, exist_ok=True)
X, Y, Z = 20.0, 16.0, 5.0
# Each wall: origin and two edge vectors; triangles wind so that their normals face the room.
walls = [((0, 0, 0), (0, Y, 0), (X, 0, 0)), ((0, 0, Z), (X, 0, 0), (0, Y, 0)),
         ((0, 0, 0), (X, 0, 0), (0, 0, Z)), ((0, Y, 0), (0, 0, Z), (X, 0, 0)),
         ((0, 0, 0), (0, 0, Z), (0, Y, 0)), ((X, 0, 0), (0, Y, 0), (0, 0, Z))]
area = sum(math.dist((0, 0, 0), u) * math.dist((0, 0, 0), v) for _, u, v in walls)
vertices, faces = [], []
for origin, u, v in walls:
    lu, lv = math.dist((0, 0, 0), u), math.dist((0, 0, 0), v)
    cells = max(1.0, wanted * lu * lv / area / 2)  # two triangles a cell
    step = math.sqrt(lu * lv / cells)
    nu, nv = max(1, round(lu / step)), max(1, round(lv / step))
    base = len(vertices)
    for j in range(nv + 1):
        for i in range(nu + 1):
            a, b = i / nu, j / nv
            vertices.append(tuple(origin[k] + a * u[k] + b * v[k] for k in range(3)))
    for j in range(nv):
        for i in range(nu):
            p = base + j * (nu + 1) + i
            q, r, s = p + 1, p + nu + 2, p + nu + 1
            faces += [(p, r, q), (p, s, r)]
with open(os.path.join(out, "dense_room.ply"), "wb") as f:
    f.write(b"ply\nformat binary_little_endian 1.0\n")
    f.write(b"element vertex %d\nproperty float x\nproperty float y\nproperty float z\n" % len(vertices))
    f.write(b"element face %d\nproperty list uchar int vertex_indices\nend_header\n" % len(faces))
    f.write(b"".join(struct.pack("<fff", *p) for p in vertices))
    f.write(b"".join(struct.pack("<Biii", 3, *t) for t in faces))
with open(os.path.join(out, "dense_room.scene.json"), "w") as f:
    f.write('{"probeproxy_scene": 1, "up": "Z", "level": ["dense_room.ply"], "probes": [{"name": "centre",'
            ' "capture": [10, 8, 1.6], "influence": {"kind": "box", "center": [10, 8, 2.5],'
            ' "half_extents": [10, 8, 2.5]}, "proxy": "auto"}]}\n')
print(f"{len(faces)} triangles, {len(vertices)} vertices")
