"""The scene file of docs/cli_and_formats.md and the mirror-view files, written the same way every run.

Floats are rounded to 6 decimals (and -0.0 folded into 0.0) so trigonometry noise never
changes a byte; key order is fixed by construction, not sorted, to read like docs/cli_and_formats.md.
This module imports no bpy: the broken inputs use it too.
"""

import json

from . import spec


def clean(value):
    if isinstance(value, bool) or value is None or isinstance(value, (int, str)):
        return value
    if isinstance(value, float):
        r = round(value, 6)
        return 0.0 if r == 0.0 else r
    if isinstance(value, (list, tuple)):
        return [clean(v) for v in value]
    if isinstance(value, dict):
        return {k: clean(v) for k, v in value.items()}
    raise TypeError(f"cannot write {type(value).__name__} to JSON")


def _dump(value, indent):
    # json.dumps(indent=2) would put every vector component on its own line; vectors stay on
    # one line here, as in docs/cli_and_formats.md, and everything else is indented by 2.
    pad, inner = "  " * indent, "  " * (indent + 1)
    if isinstance(value, dict):
        if not value:
            return "{}"
        items = [f"{inner}{json.dumps(k)}: {_dump(v, indent + 1)}" for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(value, list):
        if all(not isinstance(v, (list, dict)) for v in value):
            return "[" + ", ".join(_dump(v, indent) for v in value) + "]"
        return "[\n" + ",\n".join(inner + _dump(v, indent + 1) for v in value) + "\n" + pad + "]"
    return json.dumps(value, ensure_ascii=False, allow_nan=False)


def dumps(data):
    return _dump(clean(data), 0) + "\n"


def write(path, data):
    path.write_text(dumps(data), encoding="utf-8")


def floats(v):
    return [float(c) for c in v]


def influence_json(influence):
    if isinstance(influence, spec.SphereInfluence):
        return {
            "kind": "sphere",
            "center": floats(influence.center),
            "radius": float(influence.radius),
            "inner_radius": float(influence.inner_radius),
        }
    return {
        "kind": "box",
        "center": floats(influence.center),
        "half_extents": floats(influence.half_extents),
        "rotation": [1.0, 0.0, 0.0, 0.0],
        "inner_half_extents": floats(influence.inner_half_extents),
    }


def probe_json(probe, cubemap, auto_proxy=False):
    """auto_proxy: the proxy is "auto" (probeproxy builds it) instead of the artist box."""
    box = {"kind": "box", "center": floats(probe.proxy.center), "half_extents": floats(probe.proxy.half_extents)}
    data = {
        "name": probe.name,
        "capture": floats(probe.capture),
        "influence": influence_json(probe.influence),
        "proxy": "auto" if auto_proxy else box,
    }
    if cubemap is not None:
        data["cubemap"] = cubemap
    data["reflection_planes"] = [{"point": [probe.capture[0], probe.capture[1], float(probe.floor_z)], "normal": [0.0, 0.0, 1.0]}]
    return data


def scene(meshes, probes, cubemaps=True, up="Z", auto_proxy=False):
    """meshes: file names (glTF meshes declare their own Y-up, the reader converts them);
    auto_proxy: every probe's proxy is "auto" instead of its artist box."""
    return {
        "probeproxy_scene": 1,
        "up": up,
        "meters_per_unit": 1.0,
        "level": [{"mesh": m} for m in meshes],
        "probes": [probe_json(p, spec.cubemap_pattern(p.name) if cubemaps else None, auto_proxy) for p in probes],
    }
