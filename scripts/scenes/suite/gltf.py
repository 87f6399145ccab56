"""The level as a GLB, as an artist's Blender would export it: +Y up, modifiers applied."""

import bpy

from .render import quiet_stdout


def export_level(path):
    # Geometry only: materials are Cycles node graphs the runtime would not understand, and
    # the cubemaps already carry the colours.
    with quiet_stdout():
        _export(path)
    if not path.is_file() or path.stat().st_size == 0:
        raise RuntimeError(f"the glTF exporter wrote nothing to {path}")


def _export(path):
    bpy.ops.export_scene.gltf(
        filepath=str(path),
        export_format="GLB",
        export_yup=True,
        export_apply=True,
        export_materials="NONE",
        export_cameras=False,
        export_lights=False,
        export_animations=False,
        export_extras=False,
        export_texcoords=False,
        export_normals=True,
        export_colors=False,
        use_selection=False,
        use_visible=False,
        use_renderable=False,
        use_active_collection=False,
        check_existing=False,
    )
