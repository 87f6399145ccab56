# What the add-on stores in the .blend file. A probe is an object (an empty) whose
# `probeproxy` settings say it is one: the capture point is the object's location, the
# influence volume's rotation is the object's, its centre is the location plus an offset.
# Lengths are Blender units (the scene's Unit Scale makes them metres); the influence follows
# the probe object's full world matrix (scene_io.py). Figures the build returns are kept
# as the report's JSON text, exactly as the library wrote them (a float property would round
# them to 32 bits).

import bpy
from bpy.props import (BoolProperty, CollectionProperty, EnumProperty, FloatProperty,
                       FloatVectorProperty, IntProperty, PointerProperty, StringProperty)

PROXY_MODES = [
    ("AUTO", "Auto", "Generate the proxy from the level"),
    ("BOX", "Authored box", "An axis-aligned box, or an oriented one with a rotation"),
    ("SPHERE", "Authored sphere", "A sphere around a centre"),
    ("MESH", "Authored mesh", "A convex mesh file"),
    ("CHEAP_K", "Cheap k", "No shape: the lookup is normalize(k (x - C) + r)"),
    ("INFINITE", "Infinite", "No parallax correction: plain cubemap lookup"),
]


class ProbeSettings(bpy.types.PropertyGroup):
    is_probe: BoolProperty(name="Reflection probe", default=False)
    # Position in the scene file's probe list (the runtime export keeps that order).
    order: IntProperty(default=0)
    influence_shape: EnumProperty(name="Influence", items=[
        ("BOX", "Box", "Box influence volume, rotated with the object"),
        ("SPHERE", "Sphere", "Sphere influence volume")], default="BOX")
    influence_offset: FloatVectorProperty(
        name="Centre offset", subtype="TRANSLATION", unit="LENGTH", size=3,
        description="Influence centre minus the capture point, in the probe's own frame (it "
                    "turns and scales with the object)")
    half_extents: FloatVectorProperty(
        name="Outer half-extents", subtype="XYZ", unit="LENGTH", size=3, default=(2, 2, 2),
        min=0.0, description="Outer range, half-extents along the object's axes, before the "
                             "object's scale")
    inner_half_extents: FloatVectorProperty(
        name="Inner half-extents", subtype="XYZ", unit="LENGTH", size=3, default=(2, 2, 2),
        min=0.0, description="Inner range: full weight inside, fading to zero at the outer one")
    radius: FloatProperty(name="Outer radius", unit="LENGTH", default=2.0, min=0.0)
    inner_radius: FloatProperty(name="Inner radius", unit="LENGTH", default=2.0, min=0.0)

    proxy_mode: EnumProperty(name="Proxy", items=PROXY_MODES, default="AUTO")
    proxy_center: FloatVectorProperty(name="Proxy centre", subtype="TRANSLATION",
                                      unit="LENGTH", size=3)
    proxy_half_extents: FloatVectorProperty(name="Proxy half-extents", subtype="XYZ",
                                            unit="LENGTH", size=3, default=(2, 2, 2), min=0.0)
    proxy_rotation: FloatVectorProperty(name="Proxy rotation", subtype="QUATERNION", size=4,
                                        default=(1, 0, 0, 0),
                                        description="w, x, y, z; identity: an axis-aligned box")
    proxy_radius: FloatProperty(name="Proxy radius", unit="LENGTH", default=2.0, min=0.0)
    proxy_k: FloatProperty(name="Proxy k", default=0.0, min=0.0, precision=6,
                           description="cheap_k's k, per Blender unit: the lookup is "
                                       "normalize(k (x - C) + r)")
    proxy_mesh: StringProperty(name="Proxy mesh", subtype="FILE_PATH",
                               description="Convex mesh file (.obj, .ply, .off, .glb)")

    # Scene file members the add-on carries through unchanged (cubemap, reflection planes).
    extra_json: StringProperty(default="{}")
    # The last Generate: this probe's `build --json` entry; the proxy object it made.
    result_json: StringProperty(default="")
    proxy_object: PointerProperty(type=bpy.types.Object)
    # scene_io.mesh_fingerprint of the proxy object as Generate made it: a different one means
    # the artist edited it (operators._take_edited_proxies).
    proxy_fingerprint: StringProperty(default="")

    # On level objects imported from a scene file: which of its level meshes they came from
    # and a fingerprint of their world-space geometry then (unchanged: build from the file).
    level_index: IntProperty(default=-1)
    level_fingerprint: StringProperty(default="")
    is_proxy: BoolProperty(default=False)


class Finding(bpy.types.PropertyGroup):
    probe: StringProperty()
    rule: StringProperty()
    severity: StringProperty()
    value: StringProperty()
    limit: StringProperty()
    message: StringProperty()
    hint: StringProperty()


class SceneSettings(bpy.types.PropertyGroup):
    scene_file: StringProperty(name="Scene file", subtype="FILE_PATH",
                               description="The scene.json this level was imported from")
    file_up: StringProperty(default="Z")
    meters_per_unit: FloatProperty(default=1.0)
    level_json: StringProperty(default="[]", description="The scene file's level list")
    measured_with_json: StringProperty(
        default="{}", description="What the scene's layout measured its floor with (seed points, "
        "grid, the player, tolerance): Validate and Suggest Probes measure the same floor")
    regenerate: BoolProperty(name="Regenerate authored",
                             description="Generate a proxy also where one is authored")
    tolerance_deg: FloatProperty(name="Tolerance (deg)", default=0.25, min=0.001)
    max_planes: IntProperty(name="Max planes", default=64, min=4, max=256)
    level_scope: EnumProperty(name="Level", items=[
        ("ALL", "Whole level", "Every mesh object that is not a probe or a proxy"),
        ("SELECTED", "Selected", "Only the selected level objects (the panel lists them)")],
        default="ALL", description="Which objects Generate, Validate and Export build from")
    level_used: StringProperty(default="")
    findings: CollectionProperty(type=Finding)
    validated: BoolProperty(default=False)
    show_volumes: BoolProperty(name="Show volumes", default=True)
    # Suggest Probes (`probeproxy layout`): its own tolerance, the level-wide one a player
    # sees (5 degrees, as `layout` and `survey`), not the proxies' 0.25.
    layout_tolerance_deg: FloatProperty(name="Layout tolerance (deg)", default=5.0, min=0.001)
    layout_max_probes: IntProperty(name="Max probes", default=0, min=0,
                                   description="At most this many probes (0: as many as the floor needs)")
    layout_map: StringProperty(default="", description="The last layout's error map (PNG)")
    layout_summary: StringProperty(default="")


classes = (ProbeSettings, Finding, SceneSettings)


def register():
    for c in classes:
        bpy.utils.register_class(c)
    bpy.types.Object.probeproxy = PointerProperty(type=ProbeSettings)
    bpy.types.Scene.probeproxy = PointerProperty(type=SceneSettings)


def unregister():
    del bpy.types.Scene.probeproxy
    del bpy.types.Object.probeproxy
    for c in reversed(classes):
        bpy.utils.unregister_class(c)
