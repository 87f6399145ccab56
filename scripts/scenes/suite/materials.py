"""Emissive checker materials, the mirror floor, the world-position override and the sky.

Every surface only emits: with no lamps a Cycles render has almost no noise and a cubemap
texel shows the surface's own colour, so comparing reconstructions against renders measures
the parallax correction and not light transport. The checker makes a wrongly placed
reflection visible even inside one wall.
"""

import colorsys
from contextlib import contextmanager

import bpy

# The sky of the open courtyard (and of any gap in a closed room): a colour no wall uses.
SKY_COLOR = (0.45, 0.65, 1.0)

# Moves the checker's cell borders off the round coordinates the walls sit on; otherwise a
# wall at x = -9 would flicker between two cells with the ray hit's rounding.
_CHECKER_OFFSET = (0.1234, 0.2345, 0.3456)
_DARK_TINT = 0.4


def palette_color(index):
    """Well separated colours: golden-ratio hue steps, alternating saturation and value."""
    hue = (0.03 + index * 0.618033988749895) % 1.0
    sat = (0.85, 0.6, 0.75)[index % 3]
    val = (0.9, 0.7)[index % 2]
    return colorsys.hsv_to_rgb(hue, sat, val)


def _new_material(name):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes = mat.node_tree.nodes
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    return mat, nodes, mat.node_tree.links, out


def checker_emission(name, color, square_size):
    mat, nodes, links, out = _new_material(name)
    geo = nodes.new("ShaderNodeNewGeometry")
    shift = nodes.new("ShaderNodeVectorMath")
    shift.operation = "ADD"
    shift.inputs[1].default_value = _CHECKER_OFFSET
    checker = nodes.new("ShaderNodeTexChecker")
    checker.inputs["Color1"].default_value = (*color, 1.0)
    checker.inputs["Color2"].default_value = (*(c * _DARK_TINT for c in color), 1.0)
    # Blender's checker cell is 1 / scale wide.
    checker.inputs["Scale"].default_value = 1.0 / square_size
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Strength"].default_value = 1.0
    links.new(geo.outputs["Position"], shift.inputs[0])
    links.new(shift.outputs["Vector"], checker.inputs["Vector"])
    links.new(checker.outputs["Color"], emission.inputs["Color"])
    links.new(emission.outputs["Emission"], out.inputs["Surface"])
    return mat


def perfect_mirror():
    mat, nodes, links, out = _new_material("mirror")
    glossy = nodes.new("ShaderNodeBsdfGlossy")
    glossy.distribution = "SHARP"
    glossy.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    glossy.inputs["Roughness"].default_value = 0.0
    links.new(glossy.outputs["BSDF"], out.inputs["Surface"])
    return mat


def world_position():
    """Emits the shading point's world position, so a texel stores where its ray hit."""
    mat, nodes, links, out = _new_material("world_position")
    geo = nodes.new("ShaderNodeNewGeometry")
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Strength"].default_value = 1.0
    links.new(geo.outputs["Position"], emission.inputs["Color"])
    links.new(emission.outputs["Emission"], out.inputs["Surface"])
    return mat


def make_world(scene):
    world = bpy.data.worlds.new("sky")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (*SKY_COLOR, 1.0)
    background.inputs["Strength"].default_value = 1.0
    scene.world = world
    return world


def set_sky_strength(scene, strength):
    scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = strength


def assign(obj, mat):
    obj.data.materials.clear()
    obj.data.materials.append(mat)


# The smallest pixel filter Cycles accepts: samples land within 0.005 px of the texel centre,
# so a position texel is the surface point the C++ ray caster finds for that centre.
POSITION_FILTER_WIDTH = 0.01


@contextmanager
def position_override(scene):
    """Every surface emits its world position and the sky is black, so sky texels read 0."""
    layer = scene.view_layers[0]
    layer.material_override = world_position()
    set_sky_strength(scene, 0.0)
    try:
        yield
    finally:
        layer.material_override = None
        set_sky_strength(scene, 1.0)
