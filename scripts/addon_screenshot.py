# The README's screenshot of the add-on's panel after Import Scene and Generate Proxies (and
# Validate Volumes, where this build has it). Blender needs a display: run it under Xvfb:
#   blender -b --factory-startup --python-expr \
#     "import bpy; bpy.ops.wm.save_as_mainfile(filepath='/tmp/empty.blend')"
#   xvfb-run -a -s "-screen 0 1200x800x24" blender --factory-startup /tmp/empty.blend \
#     --python scripts/addon_screenshot.py -- ADDON_DIR MODULE_DIR SCENE OUT.png
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
    if hasattr(bpy.ops.probeproxy, "validate_volumes"):
        try:
            bpy.ops.probeproxy.validate_volumes()
        except RuntimeError as e:  # no validation in this build: the panel shows Generate only
            print(e)
    probes = [o for o in bpy.data.objects if o.probeproxy.is_probe]
    bpy.context.view_layer.objects.active = probes[0]
    for o in bpy.context.view_layer.objects:
        o.select_set(o in probes)
    area = view3d()
    space = area.spaces.active
    space.show_region_ui = True
    space.shading.type = "SOLID"
    space.shading.show_xray = True
    region = next(r for r in area.regions if r.type == "WINDOW")
    with bpy.context.temp_override(area=area, region=region):
        bpy.ops.view3d.view_all()
    # Blender 3.4 cannot pick a sidebar tab from Python and shows the first ("Item", whose
    # Transform panel is built in); for the picture the add-on's panels move into it, on top.
    from probeproxy_addon import panel
    for cls in reversed(panel.classes):
        bpy.utils.unregister_class(cls)
    for cls in panel.classes:
        cls.bl_category = "Item"
        cls.bl_order = -1
        bpy.utils.register_class(cls)
    bpy.context.scene.probeproxy.show_volumes = True
    bpy.app.timers.register(shoot, first_interval=2.0)


def shoot():
    area = view3d()
    with bpy.context.temp_override(area=area):
        bpy.ops.screen.screenshot_area(filepath=os.path.abspath(out))
    # Under 300 KB for the repository: 8-bit RGB at full compression.
    image = bpy.data.images.load(os.path.abspath(out))
    scene = bpy.context.scene
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.compression = 100
    image.save_render(os.path.abspath(out), scene=scene)
    bpy.ops.wm.quit_blender()


bpy.app.timers.register(prepare, first_interval=1.0)
