#!/usr/bin/python3
"""Writes a town-like open level of a chosen size, for measuring what `layout` and `survey` cost
as the floor grows (1 ha, 4 ha, 25 ha...):

    town_level.py OUT_FOLDER --size 100 [--seed 1]

The level (binary PLY, Z up, metres) is a square of SIZE x SIZE m:
  - terrain: a height field on a 2 m grid, a few metres of gentle hills (slopes under 10 deg),
    eased over 4 m into the levelled plots;
  - streets every 40 m both ways, 8 m wide, following the terrain;
  - a plaza, the block nearest the centre left open and paved flat, a fountain in its middle;
  - in every other block, buildings on terrain levelled under their plots: walls 0.3 m thick
    and 3.5 m high, a roof, a doorway (1.2 x 2.2 m) onto the street, and an inner wall with a
    doorway of its own that splits the building into two rooms.
The same SIZE and SEED give the same bytes. Beside the level, OUT_FOLDER/town.scene.json holds
one probe at the plaza: the walkable floor is flood-filled from its capture point, and `layout`
places the rest.
"""
import argparse
import math
import os
import random
import struct

CELL_M = 2.0          # terrain grid
BLOCK_M = 40.0        # street pitch
STREET_M = 8.0        # street width
WALL_M = 0.3
STOREY_M = 3.5
DOOR_W_M, DOOR_H_M = 1.2, 2.2
HILL_M = 2.5          # terrain amplitude


class Mesh:
    def __init__(self):
        self.vertices, self.faces = [], []

    def quad(self, a, b, c, d):
        """Two triangles a b c, a c d (counter-clockwise seen from their front)."""
        base = len(self.vertices)
        self.vertices += [a, b, c, d]
        self.faces += [(base, base + 1, base + 2), (base, base + 2, base + 3)]

    def box(self, lo, hi):
        """A closed axis-aligned box, faces outward."""
        (x0, y0, z0), (x1, y1, z1) = lo, hi
        self.quad((x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0))  # bottom
        self.quad((x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1))  # top
        self.quad((x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1))  # -y
        self.quad((x1, y1, z0), (x0, y1, z0), (x0, y1, z1), (x1, y1, z1))  # +y
        self.quad((x0, y1, z0), (x0, y0, z0), (x0, y0, z1), (x0, y1, z1))  # -x
        self.quad((x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1))  # +x

    def write_ply(self, path):
        with open(path, "wb") as f:
            f.write(b"ply\nformat binary_little_endian 1.0\n")
            f.write(b"element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                    % len(self.vertices))
            f.write(b"element face %d\nproperty list uchar int vertex_indices\nend_header\n"
                    % len(self.faces))
            f.write(b"".join(struct.pack("<fff", *p) for p in self.vertices))
            f.write(b"".join(struct.pack("<Biii", 3, *t) for t in self.faces))


def hills(seed):
    """A smooth height function: a few long sine waves with seeded phases and directions."""
    rng = random.Random(seed)
    waves = [(rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi),
              rng.uniform(90.0, 220.0), HILL_M / 3.0) for _ in range(3)]

    def height(x, y):
        return sum(a * math.sin(2 * math.pi * (x * math.cos(d) + y * math.sin(d)) / w + p)
                   for p, d, w, a in waves)
    return height


def wall_with_door(mesh, a, b, base, door_at):
    """A wall of thickness WALL_M along the segment a -> b (axis-aligned, in plan) from `base`
    up a storey, with a doorway centred `door_at` metres from a (None: no door)."""
    horizontal = a[1] == b[1]
    length = abs((b[0] - a[0]) if horizontal else (b[1] - a[1]))
    lo_along = min(a[0], b[0]) if horizontal else min(a[1], b[1])
    across = a[1] if horizontal else a[0]
    pieces = [(0.0, length, 0.0)]
    if door_at is not None:
        d0, d1 = door_at - DOOR_W_M / 2, door_at + DOOR_W_M / 2
        pieces = [(0.0, d0, 0.0), (d1, length, 0.0), (d0, d1, DOOR_H_M)]  # the lintel
    for s0, s1, z0 in pieces:
        if s1 - s0 <= 1e-6:
            continue
        u0, u1 = lo_along + s0, lo_along + s1
        v0, v1 = across - WALL_M / 2, across + WALL_M / 2
        if horizontal:
            mesh.box((u0, v0, base + z0), (u1, v1, base + STOREY_M))
        else:
            mesh.box((v0, u0, base + z0), (v1, u1, base + STOREY_M))


def building(mesh, rng, x0, y0, x1, y1, base, door_side):
    """Walls, roof and an inner wall, doors onto `door_side` ('s' or 'n') and through the inner
    wall; the floor is the levelled terrain."""
    w, d = x1 - x0, y1 - y0
    door = rng.uniform(1.5, w - 1.5)
    wall_with_door(mesh, (x0, y0), (x1, y0), base, door if door_side == "s" else None)
    wall_with_door(mesh, (x0, y1), (x1, y1), base, door if door_side == "n" else None)
    wall_with_door(mesh, (x0, y0), (x0, y1), base, None)
    wall_with_door(mesh, (x1, y0), (x1, y1), base, None)
    split = x0 + rng.uniform(0.35, 0.65) * w  # the inner wall, across the building
    wall_with_door(mesh, (split, y0), (split, y1), base, rng.uniform(1.5, d - 1.5))
    mesh.box((x0 - WALL_M / 2, y0 - WALL_M / 2, base + STOREY_M),
             (x1 + WALL_M / 2, y1 + WALL_M / 2, base + STOREY_M + 0.3))


def town(size_m, seed):
    rng = random.Random(seed)
    height = hills(seed)
    blocks = max(1, int(size_m // BLOCK_M))
    pitch = size_m / blocks
    centre_block = (blocks // 2, blocks // 2)
    pads = []  # (x0, y0, x1, y1, z): terrain levelled to z inside, eased over 4 m around
    plots = []
    for bj in range(blocks):
        for bi in range(blocks):
            bx0, by0 = bi * pitch + STREET_M / 2, bj * pitch + STREET_M / 2
            bx1, by1 = (bi + 1) * pitch - STREET_M / 2, (bj + 1) * pitch - STREET_M / 2
            if (bi, bj) == centre_block:  # the plaza
                z = height((bx0 + bx1) / 2, (by0 + by1) / 2)
                pads.append((bx0, by0, bx1, by1, z))
                plots.append(("plaza", bx0, by0, bx1, by1, z))
                continue
            # Two rows of buildings, each facing its street; a gap between them.
            half = (by1 - by0) / 2
            for row, side in ((0, "s"), (1, "n")):
                x = bx0
                while x < bx1 - 6.0:
                    w = min(rng.uniform(8.0, 14.0), bx1 - x)
                    if w < 6.0:
                        break
                    y0 = by0 + 1.0 if row == 0 else by0 + half + 1.5
                    y1 = y0 + half - 2.5
                    z = height(x + w / 2, (y0 + y1) / 2)
                    pads.append((x, y0, x + w, y1, z))
                    plots.append((side, x, y0, x + w, y1, z))
                    x += w + rng.uniform(1.5, 4.0)

    # A pad reaches 4 m around it, less than a street: only the pads of the blocks around a point
    # can, taken in the order they were made (the easing is applied in that order).
    near = {}
    for index, (x0, y0, x1, y1, _) in enumerate(pads):
        block = (int((x0 + x1) / 2 // pitch), int((y0 + y1) / 2 // pitch))
        near.setdefault(block, []).append(index)

    def ground(x, y):
        z = height(x, y)
        bi, bj = int(x // pitch), int(y // pitch)
        around = sorted(i for di in (-1, 0, 1) for dj in (-1, 0, 1)
                        for i in near.get((bi + di, bj + dj), []))
        for x0, y0, x1, y1, zp in (pads[i] for i in around):
            dx = max(x0 - x, 0.0, x - x1)
            dy = max(y0 - y, 0.0, y - y1)
            dist = math.hypot(dx, dy)
            if dist < 4.0:
                t = dist / 4.0
                t = t * t * (3 - 2 * t)
                z = zp * (1 - t) + z * t
                if dist == 0.0:
                    break
        return z

    mesh = Mesh()
    n = int(round(size_m / CELL_M))
    grid = [[ground(i * CELL_M, j * CELL_M) for i in range(n + 1)] for j in range(n + 1)]
    for j in range(n):
        for i in range(n):
            x, y = i * CELL_M, j * CELL_M
            mesh.quad((x, y, grid[j][i]), (x + CELL_M, y, grid[j][i + 1]),
                      (x + CELL_M, y + CELL_M, grid[j + 1][i + 1]),
                      (x, y + CELL_M, grid[j + 1][i]))
    # A skirt around the edge: the level is walled in at 3 m, like a map's border.
    edge = [(0, 0), (size_m, 0), (size_m, size_m), (0, size_m), (0, 0)]
    for (ax, ay), (bx, by) in zip(edge, edge[1:]):
        lo = min(height(ax, ay), height(bx, by)) - HILL_M
        hi = lo + 2 * HILL_M + 3.0
        if ax == bx:
            mesh.box((ax - WALL_M / 2, min(ay, by), lo), (ax + WALL_M / 2, max(ay, by), hi))
        else:
            mesh.box((min(ax, bx), ay - WALL_M / 2, lo), (max(ax, bx), ay + WALL_M / 2, hi))
    plaza = None
    for kind, x0, y0, x1, y1, z in plots:
        if kind == "plaza":
            cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
            mesh.box((cx - 2.0, cy - 2.0, z), (cx + 2.0, cy + 2.0, z + 0.8))  # the fountain
            plaza = (cx + 6.0, cy, z)
        else:
            building(mesh, rng, x0, y0, x1, y1, z, kind)
    return mesh, plaza, len(plots) - 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out")
    parser.add_argument("--size", type=float, default=100.0, help="side of the square, m")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    if not args.size >= BLOCK_M:
        parser.error("--size must be at least %g m (one block)" % BLOCK_M)
    os.makedirs(args.out, exist_ok=True)
    mesh, plaza, buildings = town(args.size, args.seed)
    mesh.write_ply(os.path.join(args.out, "town.ply"))
    x, y, z = plaza
    with open(os.path.join(args.out, "town.scene.json"), "w") as f:
        f.write('{"probeproxy_scene": 1, "up": "Z", "meters_per_unit": 1.0, "level": ["town.ply"],'
                ' "probes": [{"name": "plaza", "capture": [%.3f, %.3f, %.3f], "influence":'
                ' {"kind": "box", "center": [%.3f, %.3f, %.3f], "half_extents": [8, 8, 4]},'
                ' "proxy": "auto"}]}\n' % (x, y, z + 1.6, x, y, z + 2.0))
    print("%s: %.0f x %.0f m, %d buildings, %d triangles" % (
        os.path.join(args.out, "town.ply"), args.size, args.size, buildings, len(mesh.faces)))


if __name__ == "__main__":
    main()
