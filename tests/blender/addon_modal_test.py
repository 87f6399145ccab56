# The long operators as an artist runs them, from a window (Xvfb), not a script:
#   blender -b --factory-startup --python-expr \
#     "import bpy; bpy.ops.wm.save_as_mainfile(filepath='/tmp/empty.blend')"
#   xvfb-run -a blender --factory-startup --enable-event-simulate /tmp/empty.blend \
#     --python tests/blender/addon_modal_test.py -- --addon-dir plugin/blender \
#     --module-dir build/plugin/python
# (opening a file keeps the splash screen, which takes Esc, away). Asserts:
#   - Generate Proxies invoked from the 3D view runs modal (RUNNING_MODAL: Blender stays live)
#     and, left alone, builds every probe's proxy;
#   - Esc pressed while it runs cancels it: no proxy is made, nothing changes;
#   - the same for Suggest Probes: left alone, it lays the hall out; cancelled, the probes it
#     would replace are still there after twice the time a whole run took.
# Exits 0 when every check passes (os._exit: Blender's own exit code is 0 whatever a timer does).

import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_harness import check, enable_addon, failures, inward_box, parse_args  # noqa: E402

args = parse_args("--addon-dir", "--module-dir")
TIMEOUT_S = 90.0


def view3d_override():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == "VIEW_3D")
    region = next(r for r in area.regions if r.type == "WINDOW")
    return window, dict(window=window, area=area, region=region)


def proxies():
    return [o for o in bpy.data.objects if o.probeproxy.is_proxy]


def probes():
    return [o for o in bpy.data.objects if o.probeproxy.is_probe]


def setup():
    """A 40 x 6 m hall of many probes, so a build lasts past the first report."""
    enable_addon(args.addon_dir, args.module_dir)
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    inward_box("hall", (0.0, 0.0, 0.0), (40.0, 6.0, 3.0))
    for i in range(16):
        bpy.context.scene.cursor.location = (1.25 + 2.5 * i, 3.0, 1.5)
        bpy.ops.probeproxy.add_probe()
        p = bpy.context.view_layer.objects.active.probeproxy
        p.half_extents = (1.5, 3.0, 1.5)
        p.inner_half_extents = (1.0, 2.5, 1.0)


def invoke(operator):
    window, override = view3d_override()
    with bpy.context.temp_override(**override):
        return window, operator("INVOKE_DEFAULT")


def wait(until, seconds=TIMEOUT_S):
    """Yields timer intervals until `until()` or the time is up; the caller checks."""
    import time
    start = time.monotonic()
    while not until() and time.monotonic() - start < seconds:
        yield 0.1


def steps():
    setup()
    count = len(probes())
    check(count == 16, "16 probes")
    # Generate, cancelled at once.
    window, started = invoke(bpy.ops.probeproxy.generate_proxies)
    check(started == {"RUNNING_MODAL"}, "Generate runs modal from a window: %s" % started)
    window.event_simulate(type="ESC", value="PRESS")
    window.event_simulate(type="ESC", value="RELEASE")
    yield 3.0  # the job stops at its next report; the modal handler sees it finish
    yield from wait(lambda: False, 2.0)
    check(not proxies(), "Esc: no proxy made (%d)" % len(proxies()))
    # Generate, left alone.
    window, started = invoke(bpy.ops.probeproxy.generate_proxies)
    check(started == {"RUNNING_MODAL"}, "Generate again: %s" % started)
    yield from wait(lambda: len(proxies()) == count)
    check(len(proxies()) == count, "left alone: every probe's proxy (%d)" % len(proxies()))
    # Suggest Probes, left alone, timed.
    import time
    start = time.monotonic()
    window, started = invoke(bpy.ops.probeproxy.suggest_probes)
    check(started == {"RUNNING_MODAL"}, "Suggest Probes runs modal: %s" % started)
    yield from wait(lambda: bool(bpy.context.scene.probeproxy.layout_summary))
    took = time.monotonic() - start
    check(bool(bpy.context.scene.probeproxy.layout_summary),
          "left alone: the layout (%s, %.1f s)" % (bpy.context.scene.probeproxy.layout_summary,
                                                   took))
    # Suggest Probes, cancelled: after twice as long as a whole run, the probes it would have
    # replaced are still there.
    for probe in probes():
        probe["before_cancel"] = True
    window, started = invoke(bpy.ops.probeproxy.suggest_probes)
    window.event_simulate(type="ESC", value="PRESS")
    window.event_simulate(type="ESC", value="RELEASE")
    yield from wait(lambda: False, 2.0 * took + 1.0)
    check(probes() and all(p.get("before_cancel") for p in probes()),
          "Esc: the probes it would replace stay")
    print("%d check(s) failed" % len(failures) if failures else "all checks passed", flush=True)
    os._exit(1 if failures else 0)


sequence = steps()
bpy.app.timers.register(lambda: next(sequence, None), first_interval=1.0)
