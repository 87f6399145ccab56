#!/usr/bin/env python3
"""Checks that a generated test-level suite is complete: check_suite.py DIR

Standard library only (runs with the system python3, no Blender). The level list is fixed
here, so a level that failed to generate is reported, not skipped; the files each level
must have are read from its own scene file and mirror-view files. Prints one line per
problem and exits 1 if there is any.
"""

import json
import sys
from pathlib import Path

RENDERED_LEVELS = ("corridor", "l_room", "u_corridors", "hall_pillars", "attic",
                   "round_room", "courtyard", "tiny_closet", "hangar")
# Box rooms: the artist box is the exact proxy, so the main scene file authors it. Every other
# level's main scene file asks for "auto" and `<level>.artist.scene.json` keeps the boxes.
EXACT_BOX_LEVELS = ("corridor", "tiny_closet", "hangar")
FACES = ("px", "nx", "py", "ny", "pz", "nz")
EXR_MAGIC = bytes((0x76, 0x2F, 0x31, 0x01))
MIN_MIRROR_VIEWS = 2
BROKEN_FILES = (
    "README.md", "valid_room.obj",
    "nan_vertex.obj", "nan_vertex.scene.json",
    "inf_vertex.ply", "inf_vertex.scene.json",
    "malformed.obj", "malformed.scene.json",
    "missing_mesh.scene.json",
    "empty_level.obj", "empty_level.scene.json",
    "bad_fields.scene.json",
    "syntax_error.scene.json",
    "unsupported_version.scene.json",
    "probe_outside.scene.json",
    "messy_but_valid.obj", "messy_but_valid.scene.json",
)


def _without_proxies(scene):
    probes = [{k: v for k, v in p.items() if k != "proxy"} for p in scene.get("probes", [])]
    return {**scene, "probes": probes}


class Checker:
    def __init__(self, root):
        self.root = root
        self.failures = []

    def fail(self, path, problem):
        self.failures.append(f"{path}: {problem}")

    def file(self, path, exr=False):
        if not path.is_file():
            self.fail(path, "missing")
            return False
        if path.stat().st_size == 0:
            self.fail(path, "empty")
            return False
        if exr:
            with open(path, "rb") as f:
                if f.read(4) != EXR_MAGIC:
                    self.fail(path, "not an OpenEXR file (magic bytes are not 76 2f 31 01)")
                    return False
        return True

    def json(self, path):
        if not self.file(path):
            return None
        try:
            return json.loads(path.read_text(encoding="utf-8"))
        except (ValueError, UnicodeDecodeError) as exc:
            self.fail(path, f"not valid JSON: {exc}")
            return None

    def rendered_level(self, name):
        level = self.root / name
        if not level.is_dir():
            self.fail(level, "level folder missing")
            return
        self.file(level / f"{name}.glb")
        scene = self.json(level / f"{name}.scene.json")
        if scene is not None:
            self.scene(level, scene)
            self.proxies(level / f"{name}.scene.json", scene, auto=name not in EXACT_BOX_LEVELS)
        artist_path = level / f"{name}.artist.scene.json"
        if name in EXACT_BOX_LEVELS:
            if artist_path.exists():
                self.fail(artist_path, "unexpected: the main scene file already authors the exact box")
        else:
            artist = self.json(artist_path)
            if artist is not None and scene is not None:
                self.proxies(artist_path, artist, auto=False)
                if _without_proxies(artist) != _without_proxies(scene):
                    self.fail(artist_path, "differs from the main scene file in more than the proxies")
        views = sorted((level / "mirror_views").glob("*.json"))
        if len(views) < MIN_MIRROR_VIEWS:
            self.fail(level / "mirror_views", f"{len(views)} mirror view(s), expected at least {MIN_MIRROR_VIEWS}")
        for path in views:
            view = self.json(path)
            if view is None:
                continue
            for key in ("name", "probe", "image", "width", "height", "position", "forward", "up", "fov_x_deg", "mirror_plane"):
                if key not in view:
                    self.fail(path, f"no field {key!r}")
            if "image" in view:
                self.file(path.parent / view["image"], exr=True)

    def scene(self, level, scene):
        path = level / f"{level.name}.scene.json"
        for entry in scene.get("level", []):
            mesh = entry["mesh"] if isinstance(entry, dict) else entry
            self.file(level / mesh)
        probes = scene.get("probes", [])
        if not probes:
            self.fail(path, "no probes")
        for probe in probes:
            name = probe.get("name", "?")
            pattern = probe.get("cubemap")
            if not pattern or "{face}" not in pattern:
                self.fail(path, f"probe {name}: no cubemap pattern with {{face}}")
                continue
            for face in FACES:
                self.file(level / pattern.replace("{face}", face), exr=True)
                self.file(level / "cubemaps" / f"{name}_position_{face}.exr", exr=True)

    def proxies(self, path, scene, auto):
        for probe in scene.get("probes", []):
            proxy = probe.get("proxy")
            if auto and proxy != "auto":
                self.fail(path, f"probe {probe.get('name', '?')}: proxy {proxy!r}, expected \"auto\"")
            if not auto and not (isinstance(proxy, dict) and proxy.get("kind") == "box"):
                self.fail(path, f"probe {probe.get('name', '?')}: proxy {proxy!r}, expected the artist box")

    def broken(self):
        for name in BROKEN_FILES:
            self.file(self.root / "broken" / name)


def main(argv):
    if len(argv) != 2:
        print("usage: check_suite.py SUITE_DIR", file=sys.stderr)
        return 2
    checker = Checker(Path(argv[1]))
    if not checker.root.is_dir():
        print(f"{checker.root}: suite folder missing")
        return 1
    for name in RENDERED_LEVELS:
        checker.rendered_level(name)
    checker.broken()
    for line in checker.failures:
        print(line)
    if checker.failures:
        print(f"check_suite: {len(checker.failures)} problem(s) in {checker.root}", file=sys.stderr)
        return 1
    print(f"check_suite: {checker.root} is complete ({len(RENDERED_LEVELS)} rendered levels + broken)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
