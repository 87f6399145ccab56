"""Face lists for rooms and props, and their conversion to Blender mesh objects.

Faces are lists of (x, y, z) world points. Every builder orients its faces so the normal
points where the surface is seen from (into the room for walls, out of a pillar for its
sides): single-sided geometry is what levels really contain, and the proxy builder must see
consistent winding. Objects keep an identity transform so the glTF nodes carry no transform
and Object and world coordinates agree.
"""

import math

import bmesh
import bpy


def newell_normal(face):
    nx = ny = nz = 0.0
    for i, (x0, y0, z0) in enumerate(face):
        x1, y1, z1 = face[(i + 1) % len(face)]
        nx += (y0 - y1) * (z0 + z1)
        ny += (z0 - z1) * (x0 + x1)
        nz += (x0 - x1) * (y0 + y1)
    return (nx, ny, nz)


def facing(face, normal_hint):
    """The face wound so its normal agrees with normal_hint."""
    n = newell_normal(face)
    if sum(a * b for a, b in zip(n, normal_hint)) < 0.0:
        return list(reversed(face))
    return list(face)


def polygon_area2(poly):
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]))


def ccw(poly):
    return list(poly) if polygon_area2(poly) > 0.0 else list(reversed(poly))


def horizontal(poly, z, up):
    """A floor (up=True, seen from above) or ceiling (seen from below) over a 2D polygon."""
    return facing([(x, y, z) for x, y in poly], (0.0, 0.0, 1.0 if up else -1.0))


def rect(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def walls(poly, z0, z1, inward=True):
    """One vertical quad per edge of a 2D polygon, as separate faces (edge i -> face i).

    inward=True faces into the polygon (room walls), False away from it (pillar sides).
    """
    poly = ccw(poly)
    faces = []
    for (ax, ay), (bx, by) in zip(poly, poly[1:] + poly[:1]):
        # Left of a counter-clockwise edge is the polygon's inside.
        hint = (-(by - ay), bx - ax, 0.0)
        if not inward:
            hint = tuple(-c for c in hint)
        faces.append(facing([(ax, ay, z0), (bx, by, z0), (bx, by, z1), (ax, ay, z1)], hint))
    return faces


def room_box(lo, hi):
    """The six inward faces of a box room, keyed by the axis their normal points away from."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    w = walls(rect(x0, y0, x1, y1), z0, z1)
    # ccw(rect) keeps the order y0-edge, x1-edge, y1-edge, x0-edge.
    return {
        "floor": [horizontal(rect(x0, y0, x1, y1), z0, up=True)],
        "ceiling": [horizontal(rect(x0, y0, x1, y1), z1, up=False)],
        "wall_ny": [w[0]],
        "wall_px": [w[1]],
        "wall_py": [w[2]],
        "wall_nx": [w[3]],
    }


def prop_box(lo, hi, bottom=False):
    """A solid block seen from outside; without a bottom when it stands on the floor."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    faces = walls(rect(x0, y0, x1, y1), z0, z1, inward=False)
    faces.append(horizontal(rect(x0, y0, x1, y1), z1, up=True))
    if bottom:
        faces.append(horizontal(rect(x0, y0, x1, y1), z0, up=False))
    return faces


def circle(cx, cy, r, segments, start=0, count=None):
    count = segments if count is None else count
    return [
        (cx + r * math.cos(2.0 * math.pi * i / segments), cy + r * math.sin(2.0 * math.pi * i / segments))
        for i in range(start, start + count)
    ]


def create_object(name, faces):
    """A mesh object from faces, welding equal points so each object is one connected sheet."""
    bm = bmesh.new()
    verts = {}
    for face in faces:
        loop = []
        for p in face:
            key = tuple(round(c, 9) for c in p)
            if key not in verts:
                verts[key] = bm.verts.new(key)
            loop.append(verts[key])
        bm.faces.new(loop)
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj
