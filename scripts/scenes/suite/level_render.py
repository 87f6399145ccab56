"""Turns one level module into its folder: GLB, cubemaps, position cubemaps, mirror views,
scene file.

One Blender scene per level; between renders only the camera, the material override or the
floor material changes, so Cycles' persistent data spares most of the per-render sync.
"""

import bpy

from . import cube, gltf, materials, mirror_views, render, scene_json, spec
from .builder import LevelBuilder

# Colour renders: a one-pixel-wide filter antialiases edges without smearing the checker.
COLOR_FILTER_WIDTH = 1.0


def _reset():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    return bpy.context.scene


def generate(name, module, out_dir, args):
    scene = _reset()
    builder = LevelBuilder(name, checker_size=getattr(module, "CHECKER_SIZE", 0.5))
    level = module.build(builder)
    level.check(name)

    files = 0
    glb = out_dir / f"{name}.glb"
    gltf.export_level(glb)  # before the camera exists: the file holds the level only
    files += 1

    render.configure(scene)
    materials.make_world(scene)
    cam = render.make_camera(scene)

    (out_dir / "cubemaps").mkdir()
    for probe in level.probes:
        cube.render_cube(scene, cam, probe.capture, out_dir / spec.cubemap_pattern(probe.name),
                         args.size, args.samples, COLOR_FILTER_WIDTH)
        files += 6
    with materials.position_override(scene):
        for probe in level.probes:
            cube.render_cube(scene, cam, probe.capture, out_dir / spec.position_pattern(probe.name),
                             args.size, 1, materials.POSITION_FILTER_WIDTH)
            files += 6

    views_dir = out_dir / "mirror_views"
    views_dir.mkdir()
    mirror = materials.perfect_mirror()
    width, height = args.view_size
    for view in level.views:
        probe = level.probe(view.probe)
        data = mirror_views.render_view(scene, cam, view, probe, builder.floors_at(probe.floor_z), mirror,
                                        views_dir, width, height, args.view_samples, COLOR_FILTER_WIDTH)
        scene_json.write(views_dir / f"{view.name}.json", data)
        files += 2
    with materials.position_override(scene):
        for view in level.views:
            mirror_views.render_position(scene, cam, view, level.probe(view.probe), views_dir, width, height)
            files += 1

    # The main scene file is the well-authored one; where a box is a poor proxy the artist
    # boxes stay beside it as the baseline (same probes, cubemaps and volumes, other proxies).
    scene_json.write(out_dir / f"{name}.scene.json",
                     scene_json.scene([glb.name], level.probes, auto_proxy=not level.artist_box_exact))
    files += 1
    if not level.artist_box_exact:
        scene_json.write(out_dir / spec.artist_scene_name(name), scene_json.scene([glb.name], level.probes))
        files += 1
    return files
