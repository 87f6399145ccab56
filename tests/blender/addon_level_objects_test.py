# Which Blender objects are the level, headless:
#   blender -b --factory-startup --python tests/blender/addon_level_objects_test.py -- \
#       --addon-dir plugin/blender --module-dir build/plugin/python
# Asserts, as a render would show the scene:
#   - a collection instance is level: its meshes' triangles where the instance puts them,
#     though the collection itself is excluded from the view layer; a mesh in it that is
#     disabled in renders is left out;
#   - a mesh disabled in renders, or in a collection disabled in renders, is no level object;
#   - Generate builds a probe's proxy with the instanced walls (a room made of one instanced
#     wall collection: the proxy ends at the instanced walls).

import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_harness import check, clear_objects, enable_addon, finish, inward_box, parse_args  # noqa: E402

args = parse_args("--addon-dir", "--module-dir")
native, scene_io = enable_addon(args.addon_dir, args.module_dir)
clear_objects()
scene = bpy.context.scene

# The room's walls in a collection of their own, excluded from the view layer (an asset an
# artist instances), with a helper box disabled in renders.
walls = bpy.data.collections.new("room_walls")
scene.collection.children.link(walls)
room = inward_box("room", (-3.0, -2.0, 0.0), (3.0, 2.0, 3.0))
helper = inward_box("blocking_volume", (-0.5, -0.5, 0.0), (0.5, 0.5, 1.0))
for obj in (room, helper):
    scene.collection.objects.unlink(obj)
    walls.objects.link(obj)
helper.hide_render = True
bpy.context.view_layer.layer_collection.children["room_walls"].exclude = True

instance = bpy.data.objects.new("room_instance", None)
instance.instance_type = "COLLECTION"
instance.instance_collection = walls
instance.location = (10.0, 0.0, 0.0)
scene.collection.objects.link(instance)

hidden = inward_box("hidden_in_renders", (20.0, 0.0, 0.0), (21.0, 1.0, 1.0))
hidden.hide_render = True
not_rendered = bpy.data.collections.new("not_rendered")
scene.collection.children.link(not_rendered)
ghost = inward_box("ghost", (30.0, 0.0, 0.0), (31.0, 1.0, 1.0))
scene.collection.objects.unlink(ghost)
not_rendered.objects.link(ghost)
not_rendered.hide_render = True

bpy.context.view_layer.update()  # the exclusion, as an operator run from the UI would see it
level = [o for o in scene.objects if scene_io.is_level_object(o)]
check([o.name for o in level] == ["room_instance"],
      "the level objects are the instance alone: %s" % [o.name for o in level])
parts, used = scene_io.level_parts(bpy.context, level)
check(len(parts) == 1 and parts[0]["name"] == "room_instance", "one part, the instance's")
xs = parts[0]["vertices"][0::3]
check(len(parts[0]["triangles"]) == 12 * 3,
      "the room's 12 triangles, not the helper's (%d indices)" % len(parts[0]["triangles"]))
check(min(xs) == 7.0 and max(xs) == 13.0, "placed by the instance: x %g..%g" % (min(xs), max(xs)))

# Generate on a probe in the instanced room: its proxy ends at the instanced walls.
scene.cursor.location = (10.5, 0.0, 1.5)
check(bpy.ops.probeproxy.add_probe() == {"FINISHED"}, "Add Probe in the instanced room")
probe = bpy.context.view_layer.objects.active
s = probe.probeproxy
s.half_extents = (3.0, 2.0, 1.5)
s.inner_half_extents = (2.5, 1.5, 1.0)
s.influence_offset = (-0.5, 0.0, 0.0)
check(bpy.ops.probeproxy.generate_proxies() == {"FINISHED"}, "Generate")
proxy = next((o for o in scene.objects if o.probeproxy.is_proxy), None)
check(proxy is not None, "a proxy object")
if proxy is not None:
    corners = [proxy.matrix_world @ v.co for v in proxy.data.vertices]
    lo = [min(c[i] for c in corners) for i in range(3)]
    hi = [max(c[i] for c in corners) for i in range(3)]
    check(all(abs(a - b) < 0.05 for a, b in zip(lo + hi, [7, -2, 0, 13, 2, 3])),
          "the proxy is the instanced room: %s .. %s" % (lo, hi))
finish()
