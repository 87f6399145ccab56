# A job stopped from its progress callback (how the add-on's Esc cancels), with the module
# alone in Debian's Python:
#   python3 tests/blender/module_cancel_test.py --module-dir build/plugin/python \
#       --scene build/scenes/u_corridors/u_corridors.scene.json --work DIR
# Asserts: the callback's exception comes out of export_proxies and suggest_probes; no report
# follows it (the job stopped at its next report rather than running to the end); nothing is
# written; and the same calls without cancelling write their files.

import argparse
import os
import shutil
import sys

parser = argparse.ArgumentParser()
parser.add_argument("--module-dir", required=True)
parser.add_argument("--scene", required=True)
parser.add_argument("--work", required=True)
args = parser.parse_args()
sys.path.insert(0, os.path.abspath(args.module_dir))
import probeproxy_py as module  # noqa: E402

failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


class Cancelled(Exception):
    pass


def cancelling_after(first):
    calls = []

    def progress(done, total):
        calls.append((done, total))
        if len(calls) == first:
            raise Cancelled()
    return progress, calls


work = os.path.abspath(args.work)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
scene_path = os.path.abspath(args.scene)
scene = module.read_scene(scene_path)
probes = len(scene["probes"])
check(probes >= 4, "a scene of several probes (%d)" % probes)

for name, call, written in (
        ("export_proxies", lambda out, progress: module.export_proxies(
            scene, scene_path, out, None, {}, progress), "proxies.json"),
        ("suggest_probes", lambda out, progress: module.suggest_probes(
            scene, scene_path, out, None, {}, progress), "layout.scene.json")):
    out = os.path.join(work, name + "_cancelled")
    progress, calls = cancelling_after(1)
    try:
        call(out, progress)
        raised = False
    except Cancelled:
        raised = True
    check(raised, "%s: the callback's exception comes out" % name)
    check(len(calls) == 1, "%s: no report after the cancel (%d reports; a full run makes %s)"
          % (name, len(calls), calls[0][1] if calls else "?"))
    check(not os.path.exists(os.path.join(out, written)), "%s: nothing written" % name)
    whole = os.path.join(work, name + "_whole")
    progress, calls = cancelling_after(-1)
    call(whole, progress)
    check(os.path.exists(os.path.join(whole, written)) and len(calls) > 1,
          "%s: uncancelled, %d reports and %s written" % (name, len(calls), written))

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
