"""Writes hostile level files too large or too binary to keep in tests/e2e/hostile/, each with a
scene that uses it:
    write_hostile_inputs.py OUT_FOLDER
  node_chain_8000.gltf        8,000 nodes, each the only child of the one before (stack depth)
  index_past_the_end.gltf     a quad whose index 9 names a vertex of 4
  position_scalar.gltf        a POSITION accessor of type SCALAR
  byte_offset_negative.gltf   an accessor at byteOffset -4
  glb_without_asset.glb       a GLB whose JSON has no "asset"
  glb_length_2g.glb           a GLB header claiming 2^32 - 1 bytes
  glb_buffer_with_uri.glb     a GLB whose buffer 0 names a uri instead of the BIN chunk
  ply_short_vertex_line.ply   an ASCII PLY whose vertex line holds two numbers of three
  crc_flipped.pk3             maps/room.bsp, stored, one byte flipped after its CRC was written
  spawn_1e20.bsp              a box room whose info_player_deathmatch stands at x = 1e20
  open_floor_200m.off         one quad 200 m square
tests/e2e/CMakeLists.txt runs the verbs over each and checks the one line they get."""
import base64
import json
import os
import struct
import sys
import zipfile

out = sys.argv[1]
os.makedirs(out, exist_ok=True)


def write(name, data):
    with open(os.path.join(out, name), "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)


def scene(name, level, capture=(0.5, 0.5, 1.0)):
    write(name + ".scene.json", json.dumps({
        "probeproxy_scene": 1, "up": "Z", "level": [level],
        "probes": [{"name": "p", "capture": list(capture),
                    "influence": {"kind": "sphere", "center": list(capture), "radius": 10},
                    "proxy": "auto"}]}) + "\n")


# A quad of two triangles on z = 0, 4 positions then 6 uint16 indices, as glTF JSON around
# its buffer; `gltf` edits the JSON before it is written.
quad_positions = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0)


def quad_gltf(indices=(0, 1, 2, 0, 2, 3)):
    data = quad_positions + struct.pack("<6H", *indices)
    return {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," +
                            base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    }


def gltf_file(name, gltf, capture=(0.5, 0.5, 1.0)):
    write(name + ".gltf", json.dumps(gltf))
    scene(name, name + ".gltf", capture)


chain = quad_gltf()
depth = 8000
chain["nodes"] = [{"children": [i + 1]} for i in range(depth - 1)] + [{"mesh": 0}]
gltf_file("node_chain_8000", chain)

gltf_file("index_past_the_end", quad_gltf((0, 1, 2, 0, 2, 9)))

scalar = quad_gltf()
scalar["accessors"][0].update({"type": "SCALAR", "count": 12})
del scalar["accessors"][0]["min"], scalar["accessors"][0]["max"]
gltf_file("position_scalar", scalar)

negative = quad_gltf()
negative["accessors"][0]["byteOffset"] = -4
gltf_file("byte_offset_negative", negative)


def glb(gltf, binary, length=None):
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
    total = 12 + len(body)
    return struct.pack("<4sII", b"glTF", 2, total if length is None else length) + body


def glb_of_quad(edit=None, length=None):
    gltf = quad_gltf()
    binary = base64.b64decode(gltf["buffers"][0]["uri"].split(",", 1)[1])
    del gltf["buffers"][0]["uri"]
    if edit:
        edit(gltf)
    return glb(gltf, binary, length)


write("glb_without_asset.glb", glb_of_quad(lambda g: g.pop("asset")))
scene("glb_without_asset", "glb_without_asset.glb")
write("glb_length_2g.glb", glb_of_quad(length=2**32 - 1))
scene("glb_length_2g", "glb_length_2g.glb")
write("glb_buffer_with_uri.glb",
      glb_of_quad(lambda g: g["buffers"][0].update({"uri": quad_gltf()["buffers"][0]["uri"]})))
scene("glb_buffer_with_uri", "glb_buffer_with_uri.glb")

write("ply_short_vertex_line.ply",
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")
scene("ply_short_vertex_line", "ply_short_vertex_line.ply")

write("open_floor_200m.off", "OFF\n4 1 0\n-100 -100 0\n100 -100 0\n100 100 0\n-100 100 0\n4 0 1 2 3\n")
scene("open_floor_200m", "open_floor_200m.off", (0, 0, 1.6))


def box_room_bsp(entities, size=(128.0, 128.0, 96.0)):
    """IBSP 46 with one shader and the six walls of a box room in game units, lumps in order."""
    X, Y, Z = size
    walls = [[(0, 0, 0), (X, 0, 0), (X, Y, 0), (0, Y, 0)], [(0, 0, Z), (0, Y, Z), (X, Y, Z), (X, 0, Z)],
             [(0, 0, 0), (0, Y, 0), (0, Y, Z), (0, 0, Z)], [(X, 0, 0), (X, 0, Z), (X, Y, Z), (X, Y, 0)],
             [(0, 0, 0), (0, 0, Z), (X, 0, Z), (X, 0, 0)], [(0, Y, 0), (X, Y, 0), (X, Y, Z), (0, Y, Z)]]
    verts, indexes, faces = b"", b"", b""
    for n, wall in enumerate(walls):
        for corner in reversed(wall):  # the game stores faces clockwise seen from the front
            verts += struct.pack("<3f", *corner) + bytes(32)
        indexes += struct.pack("<6i", 0, 2, 1, 0, 3, 2)
        faces += struct.pack("<7i", 0, -1, 1, 4 * n, 4, 6 * n, 6) + bytes(104 - 28)
    lumps = [entities.encode() + b"\0", b"textures/test/wall".ljust(64, b"\0") + struct.pack("<2I", 0, 1)]
    lumps += [b""] * 8 + [verts, indexes, b"", faces] + [b""] * 3
    header, body, at = b"IBSP" + struct.pack("<i", 46), b"", 8 + 8 * 17
    for lump in lumps:
        header += struct.pack("<ii", at + len(body), len(lump))
        body += lump
    return header + body


write("spawn_1e20.bsp", box_room_bsp(
    '{\n"classname" "worldspawn"\n}\n{\n"classname" "info_player_deathmatch"\n"origin" "1e20 0 24"\n}\n'))
scene("spawn_1e20", "spawn_1e20.bsp")

# A stored entry whose CRC no longer matches its bytes.
pk3 = os.path.join(out, "crc_flipped.pk3")
room = box_room_bsp('{\n"classname" "worldspawn"\n}\n')
with zipfile.ZipFile(pk3, "w", zipfile.ZIP_STORED) as z:
    z.writestr("maps/room.bsp", room)
data = bytearray(open(pk3, "rb").read())
data[data.find(b"IBSP") + 200] ^= 0xFF
write("crc_flipped.pk3", bytes(data))
write("crc_flipped.scene.json", json.dumps({
    "probeproxy_scene": 1, "up": "Z", "level": [{"mesh": "crc_flipped.pk3", "map": "maps/room.bsp"}],
    "probes": [{"name": "p", "capture": [2, 2, 1.5], "influence": {"kind": "sphere", "center": [2, 2, 1.5],
                                                                  "radius": 10}, "proxy": "auto"}]}) + "\n")
