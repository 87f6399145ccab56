# Blender's side of the render check (scripts/render_check.py runs it under xvfb-run with
# `blender -b`): EEVEE renders a level whose walls are coloured by their own world position,
# seen in a mirror floor through the Reflection Cubemaps the add-on makes from a proxies.json,
# and saves per camera what the check decodes (npz, float32, rows top down):
#   position, normal  where the camera ray lands on the level (emission, read exactly)
#   white             the mirror with every wall white: each pixel's probe weight
#   code_<axis>_<k>   the mirror with walls coloured (coarse, cos, sin) of one axis' position
#                     at one period (see `codes`): decoded to millimetres, as one R11G11B10F
#                     cubemap texel cannot hold a position better than ~1/64 of its value.
# Every bake and frame runs with one sample, no filter, no screen-space effects and a black
# world, so a mirror pixel is the blend of its probes' texels and nothing else.

import argparse
import json
import math
import os
import sys
import time

import bpy
import numpy as np
from mathutils import Vector

argv = sys.argv[sys.argv.index("--") + 1:]
parser = argparse.ArgumentParser()
for name in ("--module-dir", "--addon-dir", "--scene", "--proxies", "--cameras", "--out"):
    parser.add_argument(name, required=True)
parser.add_argument("--width", type=int, default=320)
parser.add_argument("--height", type=int, default=180)
parser.add_argument("--cubemap", default="512")
parser.add_argument("--no-geometry", action="store_true",
                    help="skip the position and normal frames (another set's serve: they do "
                    "not depend on the probes)")
args = parser.parse_args(argv)
sys.path[:0] = [os.path.abspath(args.module_dir), os.path.abspath(args.addon_dir),
                os.path.dirname(os.path.abspath(__file__))]
import position_code  # noqa: E402
import probeproxy_py  # noqa: E402
from probeproxy_addon import eevee_probes  # noqa: E402

MIRROR_NORMAL_Z = 0.7  # surfaces facing up at least this much are mirrors (as survey's floor)


def emission_material(name, colour_of):
    """A material emitting `colour_of(nodes, links, geometry)`'s colour socket, strength 1."""
    mat = bpy.data.materials.get(name) or bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    emission = nodes.new("ShaderNodeEmission")
    geometry = nodes.new("ShaderNodeNewGeometry")
    links.new(colour_of(nodes, links, geometry), emission.inputs["Color"])
    links.new(emission.outputs["Emission"], out.inputs["Surface"])
    return mat


def node(nodes, links, kind, operation, *inputs):
    """A shader node of `kind` (its `operation` when given) fed `inputs` in order: sockets
    linked, constants set; returns its first output."""
    made = nodes.new(kind)
    if operation is not None:
        made.operation = operation
    for i, value in enumerate(inputs):
        if hasattr(value, "is_linked"):  # a socket
            links.new(value, made.inputs[i])
        else:
            made.inputs[i].default_value = value
    return made.outputs[0]


def math_node(nodes, links, op, *inputs):
    return node(nodes, links, "ShaderNodeMath", op, *inputs)


def vector_math(nodes, links, op, *inputs):
    return node(nodes, links, "ShaderNodeVectorMath", op, *inputs)


def combine(nodes, links, r, g, b):
    return node(nodes, links, "ShaderNodeCombineXYZ", None, r, g, b)


def axis_of(nodes, links, vector, axis):
    node = nodes.new("ShaderNodeSeparateXYZ")
    links.new(vector, node.inputs[0])
    return node.outputs[axis]


def code_colour(axis, period, lo, size):
    def colour(nodes, links, geometry):
        p = axis_of(nodes, links, geometry.outputs["Position"], axis)
        coarse = math_node(nodes, links, "MULTIPLY_ADD", p, 1.0 / size[axis],
                           1.0 - lo[axis] / size[axis])
        phase = math_node(nodes, links, "MULTIPLY", p, 2.0 * math.pi / period)
        cos = math_node(nodes, links, "MULTIPLY_ADD",
                        math_node(nodes, links, "COSINE", phase), 0.5, 0.5)
        sin = math_node(nodes, links, "MULTIPLY_ADD",
                        math_node(nodes, links, "SINE", phase), 0.5, 0.5)
        return combine(nodes, links, coarse, cos, sin)
    return colour


def mirror_material():
    """Surfaces facing up: a perfect mirror; the rest black (the frame reads only mirrors)."""
    mat = bpy.data.materials.get("mirror") or bpy.data.materials.new("mirror")
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    glossy = nodes.new("ShaderNodeBsdfGlossy")
    glossy.distribution = "SHARP"
    glossy.inputs["Roughness"].default_value = 0.0
    glossy.inputs["Color"].default_value = (1, 1, 1, 1)
    black = nodes.new("ShaderNodeEmission")
    black.inputs["Color"].default_value = (0, 0, 0, 1)
    geometry = nodes.new("ShaderNodeNewGeometry")
    up = math_node(nodes, links, "GREATER_THAN",
                   axis_of(nodes, links, geometry.outputs["Normal"], 2), MIRROR_NORMAL_Z)
    mix = nodes.new("ShaderNodeMixShader")
    links.new(up, mix.inputs["Fac"])
    links.new(black.outputs[0], mix.inputs[1])
    links.new(glossy.outputs[0], mix.inputs[2])
    links.new(mix.outputs[0], out.inputs["Surface"])
    return mat


def set_up_render(scene):
    scene.render.engine = "BLENDER_EEVEE"
    scene.render.resolution_x, scene.render.resolution_y = args.width, args.height
    scene.render.resolution_percentage = 100
    scene.render.filter_size = 0.0
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.color_mode = "RGB"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    e = scene.eevee
    e.taa_render_samples = 1
    e.taa_samples = 1
    e.use_ssr = False
    e.use_gtao = False
    e.use_bloom = False
    e.use_motion_blur = False
    e.use_volumetric_lights = False
    e.gi_cubemap_resolution = args.cubemap
    e.gi_glossy_clamp = 0.0
    world = scene.world or bpy.data.worlds.new("black")
    scene.world = world
    world.use_nodes = False
    world.color = (0, 0, 0)


def frame(scene, camera, path):
    scene.camera = camera
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(path)
    pixels = np.empty(image.size[0] * image.size[1] * image.channels, dtype=np.float32)
    image.pixels.foreach_get(pixels)
    rgb = pixels.reshape(image.size[1], image.size[0], image.channels)[::-1, :, :3].copy()
    bpy.data.images.remove(image)
    os.remove(path)
    return rgb


def main():
    os.makedirs(args.out, exist_ok=True)
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    scene = bpy.context.scene
    set_up_render(scene)

    vertices, triangles = probeproxy_py.level_triangles(os.path.abspath(args.scene))
    mesh = bpy.data.meshes.new("level")
    mesh.from_pydata(vertices, [], triangles)
    mesh.update()
    level = bpy.data.objects.new("level", mesh)
    scene.collection.objects.link(level)
    lo, size = position_code.bounds(vertices)

    with open(args.proxies) as f:
        presets = eevee_probes.presets_in_export(json.load(f))
    reach = float(np.linalg.norm(size))
    eevee_probes.make_light_probes(scene, presets, 1.0, reach)

    with open(args.cameras) as f:
        cameras = json.load(f)["cameras"]
    camera_objects = []
    for c in cameras:
        data = bpy.data.cameras.new(c["name"])
        data.angle = math.radians(c.get("fov_deg", 70.0))
        data.clip_start, data.clip_end = 0.05, reach
        obj = bpy.data.objects.new(c["name"], data)
        obj.location = Vector(c["eye"])
        obj.rotation_mode = "QUATERNION"
        obj.rotation_quaternion = (Vector(c["target"]) - Vector(c["eye"])).to_track_quat("-Z", "Y")
        scene.collection.objects.link(obj)
        camera_objects.append(obj)

    frames = [dict() for _ in cameras]
    tmp = os.path.join(os.path.abspath(args.out), "frame.exr")
    timings = {}

    def shoot(key, material, bake):
        level.data.materials.clear()
        level.data.materials.append(material)
        start = time.time()
        if bake:
            bpy.ops.scene.light_cache_bake()
            level.data.materials.clear()
            level.data.materials.append(mirror_material())
        for k, cam in enumerate(camera_objects):
            frames[k][key] = frame(scene, cam, tmp)
        timings[key] = time.time() - start

    # Emission colours stay positive: positions from `lo`, normals as 0.5 + 0.5 n.
    if not args.no_geometry:
        shoot("position", emission_material("position", lambda n, l, g: vector_math(
            n, l, "SUBTRACT", g.outputs["Position"], tuple(lo))), False)
        shoot("normal", emission_material("normal", lambda n, l, g: vector_math(
            n, l, "MULTIPLY_ADD", g.outputs["Normal"], (0.5, 0.5, 0.5), (0.5, 0.5, 0.5))), False)
    shoot("white", emission_material("white", lambda n, l, g: combine(n, l, 1.0, 1.0, 1.0)), True)
    coded = position_code.codes(size)
    for axis, period in coded:
        key = "code_%d_%g" % (axis, period)
        shoot(key, emission_material(key, code_colour(axis, period, lo, size)), True)
    for k, c in enumerate(cameras):
        np.savez_compressed(os.path.join(args.out, c["name"] + ".npz"), **frames[k])
    with open(os.path.join(args.out, "frames.json"), "w") as f:
        json.dump({"renderer": "eevee", "lo": lo,
                   "size": size, "codes": coded, "cameras": cameras,
                   "width": args.width, "height": args.height, "cubemap": args.cubemap,
                   "probes": sorted(presets), "seconds": timings}, f, indent=1)


main()
