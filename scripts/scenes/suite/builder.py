"""Collects a level's objects while a level module describes them.

Each object gets the next palette colour, so within a level no two objects share one and a
reflection showing the wrong wall is obvious. Floors are remembered with their height: a
mirror view turns exactly the floors of its reflection plane into mirrors.
"""

from . import materials, meshes


class LevelBuilder:
    def __init__(self, name, checker_size=0.5):
        self.name = name
        self.checker_size = checker_size
        self.objects = []
        self.floors = []  # (object, z)

    def add(self, name, faces, floor_z=None):
        if any(o.name == name for o in self.objects):
            raise ValueError(f"{self.name}: duplicate object name {name!r}")
        obj = meshes.create_object(name, faces)
        if obj.name != name:  # Blender renamed it: a clash with a datablock we did not make
            raise RuntimeError(f"{self.name}: object {name!r} was renamed to {obj.name!r}")
        color = materials.palette_color(len(self.objects))
        materials.assign(obj, materials.checker_emission(name, color, self.checker_size))
        self.objects.append(obj)
        if floor_z is not None:
            self.floors.append((obj, floor_z))
        return obj

    def add_all(self, parts, floor_z=None, prefix=""):
        """Adds the dict of named face lists room_box() returns, marking its floor."""
        for name, faces in parts.items():
            self.add(prefix + name, faces, floor_z=floor_z if name == "floor" else None)

    def floors_at(self, z):
        found = [obj for obj, fz in self.floors if abs(fz - z) < 1e-9]
        if not found:
            raise ValueError(f"{self.name}: no floor at z = {z}")
        return found
