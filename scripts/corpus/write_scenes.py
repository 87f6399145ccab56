#!/usr/bin/python3
"""Writes one scene file per corpus map: a probe at every player spawn point.

    write_scenes.py PROBEPROXY PK3 OUT_FOLDER [--set tuning|validation] [MAP...]

The corpus is two sets of ten maps from the same data.pk3. The tuning set is what `layout`'s
choices were made on; the validation set was never used to tune anything, and a change to
`layout` is kept only if its figures there do not get worse. No other map of the pk3 is used.

For each MAP (default: the ten maps of the set, tuning by default) it asks `probeproxy level-info` for the
map's spawn points and the floor under each, and writes OUT_FOLDER/MAP/MAP.scene.json:
  - level: {"mesh": <the pk3, relative to the scene>, "map": "maps/MAP.bsp"}
  - one probe per spawn point, in entity order, named "spawn_NN_<classname>";
  - capture: eye height, 1.6 m above the floor under the spawn point (the first surface
    straight below its origin); if no floor is found within 64 m, the spawn origin + 0.85 m
    (a Quake 3 player's origin is 24 units, 0.75 m, above its feet);
  - influence: a sphere of 10 m around the capture point; proxy "auto".
It also writes OUT_FOLDER/corpus.json: per map, triangles, sky triangles, load time (ms) and
spawn points, as level-info measured them. Files are rewritten only when their bytes change.
"""
import json
import os
import subprocess
import sys

SETS = {
    "tuning": ["downer", "darkzone", "ruiner", "eggandbacon", "basement", "bloodprison",
               "stormkeep", "toxic", "skyway", "warfare"],
    "validation": ["aneurysm", "bleach", "desertfactory", "dieselpower", "evilspace", "final_rage",
                   "runningman", "silvercity", "soylent", "starship"],
}
EYE_HEIGHT_M = 1.6
ORIGIN_TO_EYE_M = 0.85
INFLUENCE_RADIUS_M = 10.0


def rounded(values):
    # Micrometres are far below anything a probe placement can mean; fixed digits keep the
    # files byte-identical run to run.
    return [round(v, 6) + 0.0 for v in values]


def capture_point(spawn):
    x, y, z = spawn["origin"]
    if spawn["floor_z"] is None:
        return rounded([x, y, z + ORIGIN_TO_EYE_M])
    return rounded([x, y, spawn["floor_z"] + EYE_HEIGHT_M])


def scene_for(info, pk3, scene_folder, map_name):
    probes = []
    for i, spawn in enumerate(info["spawn_points"]):
        capture = capture_point(spawn)
        probes.append({
            "name": "spawn_%02d_%s" % (i, spawn["classname"]),
            "capture": capture,
            "influence": {"kind": "sphere", "center": capture, "radius": INFLUENCE_RADIUS_M},
            "proxy": "auto",
        })
    return {
        "probeproxy_scene": 1,
        "up": "Z",
        "meters_per_unit": 1.0,
        "level": [{"mesh": os.path.relpath(pk3, scene_folder), "map": "maps/%s.bsp" % map_name}],
        "probes": probes,
    }


def write_if_changed(path, text):
    if os.path.exists(path):
        with open(path) as f:
            if f.read() == text:
                return
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def main():
    args = sys.argv[1:]
    chosen = "tuning"
    if "--set" in args:
        at = args.index("--set")
        if at + 1 >= len(args) or args[at + 1] not in SETS:
            sys.exit("write_scenes.py: --set takes tuning or validation")
        chosen = args[at + 1]
        del args[at:at + 2]
    if len(args) < 3:
        sys.exit(__doc__)
    probeproxy, pk3, out = args[0], os.path.abspath(args[1]), os.path.abspath(args[2])
    maps = args[3:] or SETS[chosen]
    figures = []
    for name in maps:
        result = subprocess.run([probeproxy, "level-info", pk3, "--map", "maps/%s.bsp" % name],
                                stdout=subprocess.PIPE, check=True, text=True)
        info = json.loads(result.stdout)
        folder = os.path.join(out, name)
        os.makedirs(folder, exist_ok=True)
        scene = scene_for(info, pk3, folder, name)
        write_if_changed(os.path.join(folder, name + ".scene.json"),
                         json.dumps(scene, indent=2) + "\n")
        figures.append({"map": name, "triangles": info["triangles"],
                        "sky_triangles": info["sky_triangles"],
                        "load_ms": round(info["load_ms"], 1),
                        "spawn_points": len(info["spawn_points"])})
        print("%-12s %7d triangles %5d sky %7.1f ms %3d spawn points" % (
            name, info["triangles"], info["sky_triangles"], info["load_ms"],
            len(info["spawn_points"])), file=sys.stderr)
    # Load times vary run to run: corpus.json is a report, not an input.
    with open(os.path.join(out, "corpus.json"), "w") as f:
        json.dump({"maps": figures}, f, indent=2)
        f.write("\n")


if __name__ == "__main__":
    main()
