"""What a level declares: probes, their volumes and the reference mirror views.

These are plain data so a level module reads like a description of the level; everything
Blender-specific lives in the builder and the render modules.
"""

import math
from dataclasses import dataclass, field

# The scene file's coordinates are Z-up metres, the same frame Blender works in, so nothing
# here is ever converted.
EYE_HEIGHT = 1.7
CAPTURE_HEIGHT = 1.6


def cubemap_pattern(probe_name):
    """The scene file's `cubemap` value: {face} stands for px nx py ny pz nz."""
    return f"cubemaps/{probe_name}_{{face}}.exr"


def position_pattern(probe_name):
    """Same cameras, each texel holding the world position its centre ray hits."""
    return f"cubemaps/{probe_name}_position_{{face}}.exr"


def artist_scene_name(level):
    """The sibling scene file with the artist boxes, for levels where they are a poor proxy."""
    return f"{level}.artist.scene.json"


@dataclass(frozen=True)
class Box:
    """Axis-aligned box as the scene file stores it: centre and half-extents."""

    center: tuple
    half_extents: tuple

    @staticmethod
    def from_bounds(lo, hi):
        return Box(
            tuple((a + b) / 2.0 for a, b in zip(lo, hi)),
            tuple((b - a) / 2.0 for a, b in zip(lo, hi)),
        )

    def contains(self, p, margin=0.0):
        return all(abs(p[i] - self.center[i]) <= self.half_extents[i] - margin for i in range(3))


@dataclass(frozen=True)
class BoxInfluence:
    center: tuple
    half_extents: tuple
    inner_half_extents: tuple

    def contains(self, p):
        return Box(self.center, self.half_extents).contains(p)

    def inner_fits(self):
        return all(0.0 < i <= o for i, o in zip(self.inner_half_extents, self.half_extents))


@dataclass(frozen=True)
class SphereInfluence:
    center: tuple
    radius: float
    inner_radius: float

    def contains(self, p):
        return math.dist(p, self.center) <= self.radius

    def inner_fits(self):
        return 0.0 < self.inner_radius <= self.radius


@dataclass(frozen=True)
class Probe:
    name: str
    capture: tuple
    influence: object  # BoxInfluence | SphereInfluence
    proxy: Box  # the box an artist would place: the bounds of the room the probe is in
    floor_z: float  # height of the floor under the probe, its reflection plane


@dataclass(frozen=True)
class MirrorView:
    """A camera at eye height looking down at a mirror floor.

    Given as yaw/pitch because that is how one places such a view by hand; `forward` and
    `up` derive from them so they are orthonormal by construction.
    """

    name: str
    probe: str
    x: float
    y: float
    yaw_deg: float  # 0 looks along +X, 90 along +Y
    pitch_deg: float = -35.0  # below the horizon
    fov_x_deg: float = 70.0

    def position(self, floor_z):
        return (self.x, self.y, floor_z + EYE_HEIGHT)

    def forward(self):
        yaw, pitch = math.radians(self.yaw_deg), math.radians(self.pitch_deg)
        return (math.cos(pitch) * math.cos(yaw), math.cos(pitch) * math.sin(yaw), math.sin(pitch))

    def up(self):
        # World up made orthogonal to forward: the camera has no roll.
        yaw, pitch = math.radians(self.yaw_deg), math.radians(self.pitch_deg)
        return (-math.sin(pitch) * math.cos(yaw), -math.sin(pitch) * math.sin(yaw), math.cos(pitch))


@dataclass
class LevelSpec:
    probes: list = field(default_factory=list)
    views: list = field(default_factory=list)
    # True where each probe's artist box is exactly its room (a box-shaped room): the scene
    # file authors the box. Elsewhere the box is a poor proxy, so the scene file asks for
    # "auto" (probeproxy builds it, the workflow the tool recommends) and the boxes go to the
    # sibling `<level>.artist.scene.json`, the naive baseline the proxy table and validate
    # measure.
    artist_box_exact: bool = False

    def probe(self, name):
        for p in self.probes:
            if p.name == name:
                return p
        raise KeyError(f"no probe named {name!r}")

    def check(self, level):
        """Catch a mistyped level definition here rather than as a puzzling test failure."""
        names = [p.name for p in self.probes]
        if not names or len(set(names)) != len(names):
            raise ValueError(f"{level}: probe names must be non-empty and unique: {names}")
        for p in self.probes:
            if not p.influence.inner_fits():
                raise ValueError(f"{level}: probe {p.name}'s inner influence range exceeds the outer one")
            if not p.influence.contains(p.capture):
                raise ValueError(f"{level}: probe {p.name} captures outside its influence volume")
            if not p.proxy.contains(p.capture, margin=1e-6):
                raise ValueError(f"{level}: probe {p.name} captures outside its proxy box")
        views = [v.name for v in self.views]
        if len(views) < 2 or len(set(views)) != len(views):
            raise ValueError(f"{level}: needs at least two uniquely named mirror views: {views}")
        for v in self.views:
            p = self.probe(v.probe)
            if not p.influence.contains(v.position(p.floor_z)):
                raise ValueError(f"{level}: view {v.name} is outside probe {p.name}'s influence")
