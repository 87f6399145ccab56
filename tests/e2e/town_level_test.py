"""The open-world test level (scripts/open_world/town_level.py) is what its docstring says: the
same size and seed write the same bytes, and a player reaches nearly all of it from the plaza
(streets, the plaza and every building's two rooms through their doorways): `survey` finds at
least 90% of the square walkable (walls and fountain take the rest).

    town_level_test.py PROBEPROXY GENERATOR WORK_FOLDER
"""
import json
import os
import subprocess
import sys

probeproxy, generator, work = sys.argv[1:4]
SIZE = 80.0
runs = []
for name in ("a", "b"):
    out = os.path.join(work, name)
    subprocess.run([sys.executable, generator, out, "--size", str(SIZE), "--seed", "3"],
                   check=True, capture_output=True)
    with open(os.path.join(out, "town.ply"), "rb") as f:
        runs.append(f.read())
if runs[0] != runs[1]:
    sys.exit("town_level: the same size and seed wrote different levels")
done = subprocess.run([probeproxy, "survey", os.path.join(work, "a", "town.scene.json"),
                       "--json"], check=True, capture_output=True, text=True)
walkable = json.loads(done.stdout)["walkable_m2"]
share = walkable / (SIZE * SIZE)
print("walkable %.0f m^2 of %.0f (%.1f%%)" % (walkable, SIZE * SIZE, 100 * share))
if not 0.9 <= share <= 1.0:
    sys.exit("town_level: %.1f%% of the square is walkable, expected 90-100%%" % (100 * share))
