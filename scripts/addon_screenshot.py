# docs/addon.md's screenshot of the add-on's panel after Import Scene, Generate Proxies and
# Validate Volumes on a suite level. Blender needs a display: run it under Xvfb, with event
# simulation (the built-in Transform panel is collapsed by a simulated click: Blender 3.4 has no
# Python call for it), then reduce the PNG to 256 colours:
#   blender -b --factory-startup --python-expr \
#     "import bpy; bpy.ops.wm.save_as_mainfile(filepath='/tmp/empty.blend')"
#   xvfb-run -a -s "-screen 0 1300x1700x24" blender --factory-startup --enable-event-simulate \
#     -p 0 0 1300 1660 /tmp/empty.blend \
#     --python scripts/addon_screenshot.py -- ADDON_DIR MODULE_DIR SCENE OUT.png
#   /usr/bin/python3 -c "import sys; from PIL import Image; \
#     Image.open(sys.argv[1]).quantize(256).save(sys.argv[1], optimize=True)" OUT.png
# (opening a file keeps the splash screen away).
import os
import sys

addon_dir, module_dir, scene_file, out = sys.argv[sys.argv.index("--") + 1:][:4]
sys.path.insert(0, os.path.abspath(addon_dir))
sys.path.insert(0, os.path.abspath(module_dir))

import addon_utils  # noqa: E402
import bpy  # noqa: E402


def view3d():
    for area in bpy.context.window.screen.areas:
        if area.type == "VIEW_3D":
            return area


# Wide enough for the findings' lines and the probe's vectors; a fifth argument `default`
# leaves Blender's default sidebar width, to check that every label is readable there.
SIDEBAR_PX = None if sys.argv[sys.argv.index("--") + 1:][4:5] == ["default"] else 520


def prepare():
    addon_utils.enable("probeproxy_addon", default_set=True, handle_error=None)
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    bpy.ops.probeproxy.import_scene(filepath=os.path.abspath(scene_file))
    level = [o for o in bpy.data.objects if o.type == "MESH"]
    for o in bpy.context.view_layer.objects:
        o.select_set(o in level)
    bpy.context.scene.probeproxy.regenerate = True
    bpy.ops.probeproxy.generate_proxies()
    for o in bpy.context.view_layer.objects:
        o.select_set(o in level)
    # Selects the probes the findings name and makes the first one active: the picture shows
    # its figures in the Probe panel and the findings below.
    bpy.ops.probeproxy.validate_volumes()
    area = view3d()
    space = area.spaces.active
    space.show_region_ui = True
    space.shading.type = "SOLID"
    space.shading.show_xray = True
    # Blender 3.4 cannot pick a sidebar tab from Python and shows the first ("Item", whose
    # Transform panel is built in); for the picture the add-on's panels move into it.
    from probeproxy_addon import panel
    for cls in reversed(panel.classes):
        bpy.utils.unregister_class(cls)
    for cls in panel.classes:
        cls.bl_category = "Item"
        bpy.utils.register_class(cls)
    bpy.context.scene.probeproxy.show_volumes = True
    steps = iter(mouse_steps())
    bpy.app.timers.register(lambda: next(steps, None), first_interval=1.0)


def region(area, kind):
    return next(r for r in area.regions if r.type == kind)


def widen_sidebar(area, width_px):
    """Sets the sidebar's width. Blender 3.4 has no Python call for it, and a simulated drag of
    its edge does not start the resize, so this writes the region's `sizex` (DNA ARegion,
    unscaled pixels) found after its winx, winy, visible, regiontype (4: UI), alignment and
    flag shorts; the region is laid out again when the sidebar is hidden and shown."""
    import ctypes
    ui = region(area, "UI")
    raw = ctypes.string_at(ui.as_pointer(), 512)
    shorts = [int.from_bytes(raw[i:i + 2], "little", signed=True) for i in range(0, 512, 2)]
    for i in range(len(shorts) - 6):
        if shorts[i:i + 4] == [ui.width, ui.height, 1, 4]:
            sizex = ctypes.c_short.from_address(ui.as_pointer() + 2 * (i + 6))
            sizex.value = int(width_px / bpy.context.preferences.system.ui_scale)
            return True
    print("addon_screenshot: sidebar width not found; left as it is")
    return False


def mouse_steps():
    """Sidebar width, then simulated mouse events, one batch per timer tick (each yield:
    seconds to the next)."""
    window = bpy.context.window_manager.windows[0]
    space = view3d().spaces.active
    if SIDEBAR_PX:
        widen_sidebar(view3d(), SIDEBAR_PX)
    space.show_region_ui = False
    yield 0.3
    space.show_region_ui = True
    yield 0.5
    # Collapse the built-in Transform panel (the first header, at the sidebar's top).
    ui = region(view3d(), "UI")
    x, y = ui.x + 60, ui.y + ui.height - 14
    window.event_simulate(type="MOUSEMOVE", value="NOTHING", x=x, y=y)
    yield 0.2
    window.event_simulate(type="LEFTMOUSE", value="PRESS", x=x, y=y)
    window.event_simulate(type="LEFTMOUSE", value="RELEASE", x=x, y=y)
    yield 0.5
    area = view3d()
    with bpy.context.temp_override(area=area, region=region(area, "WINDOW")):
        bpy.ops.view3d.view_all()
    # The sidebar covers the viewport's right part: back off and move the level left of it.
    from mathutils import Vector
    view = area.spaces.active.region_3d
    view.view_distance *= 1.2
    view.view_location += view.view_rotation @ Vector((0.12 * view.view_distance, 0.0, 0.0))
    yield 1.0
    shoot()
    yield None


def shoot():
    area = view3d()
    with bpy.context.temp_override(area=area):
        bpy.ops.screen.screenshot_area(filepath=os.path.abspath(out))
    # Under 300 KB for the repository: 8-bit RGB at full compression (then 256 colours).
    image = bpy.data.images.load(os.path.abspath(out))
    scene = bpy.context.scene
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.compression = 100
    image.save_render(os.path.abspath(out), scene=scene)
    bpy.ops.wm.quit_blender()


bpy.app.timers.register(prepare, first_interval=1.0)
