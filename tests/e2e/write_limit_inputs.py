"""Writes the inputs that must stop at a size limit, each with a scene that uses it:
    write_limit_inputs.py OUT_FOLDER
  face_claims_2g_corners.{ply,off}  a face claiming 2^31 corners in a file of a few bytes
  off_claims_2g_vertices.off        an OFF header claiming 2^31 vertices
  dense_room.ply                    20,000 triangles (for --max-triangles 10000)
  big_file.ply                      a valid 2.3 MB mesh (for --max-file-mb 1)
  inflates_3mib.pk3                 maps/bomb.bsp: 3 MiB of zeros deflated to a few KiB
  claims_3gib.pk3                   maps/liar.bsp: a zip entry whose headers claim 3 GiB
  nested_1m.scene.json              a scene file nested a million arrays deep
tests/e2e/CMakeLists.txt runs `validate` over each and checks the one line it gets."""
import os
import struct
import subprocess
import sys
import zipfile

out = sys.argv[1]
os.makedirs(out, exist_ok=True)
here = os.path.dirname(os.path.abspath(__file__))


def scene(name, level, capture="[0.2, 0.2, 0.1]"):
    with open(os.path.join(out, name + ".scene.json"), "w") as f:
        f.write('{"probeproxy_scene": 1, "up": "Z", "level": [%s], "probes": [{"name": "p",'
                ' "capture": %s, "influence": {"kind": "sphere", "center": [0, 0, 0],'
                ' "radius": 10}, "proxy": "auto"}]}\n' % (level, capture))


def ply_header(vertices, faces, count_type="uchar"):
    return (b"ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n"
            b"property float y\nproperty float z\nelement face %d\nproperty list %s int "
            b"vertex_indices\nend_header\n" % (vertices, faces, count_type.encode()))


triangle = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
with open(os.path.join(out, "face_claims_2g_corners.ply"), "wb") as f:
    f.write(ply_header(3, 1, "uint") + triangle + struct.pack("<I3i", 2**31, 0, 1, 2))
scene("face_claims_2g_corners_ply", '"face_claims_2g_corners.ply"')
with open(os.path.join(out, "face_claims_2g_corners.off"), "w") as f:
    f.write("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2147483648 0 1 2\n")
scene("face_claims_2g_corners_off", '"face_claims_2g_corners.off"')
with open(os.path.join(out, "off_claims_2g_vertices.off"), "w") as f:
    f.write("OFF\n2147483648 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
scene("off_claims_2g_vertices", '"off_claims_2g_vertices.off"')

subprocess.run([sys.executable, os.path.join(here, "..", "..", "scripts", "limits", "write_dense_room.py"),
                out, "20000"], check=True, stdout=subprocess.DEVNULL)
# 2.3 MB of one valid mesh: 48,000 copies of a triangle.
copies = 48000
with open(os.path.join(out, "big_file.ply"), "wb") as f:
    f.write(ply_header(3 * copies, copies) + triangle * copies +
            b"".join(struct.pack("<B3i", 3, 3 * i, 3 * i + 1, 3 * i + 2) for i in range(copies)))
scene("big_file", '"big_file.ply"')

with zipfile.ZipFile(os.path.join(out, "inflates_3mib.pk3"), "w", zipfile.ZIP_DEFLATED) as z:
    z.writestr("maps/bomb.bsp", bytes(3 << 20))
scene("inflates_3mib", '{"mesh": "inflates_3mib.pk3", "map": "maps/bomb.bsp"}')
# A stored entry of 16 bytes whose local and central headers both claim 3 GiB.
liar = os.path.join(out, "claims_3gib.pk3")
with zipfile.ZipFile(liar, "w", zipfile.ZIP_STORED) as z:
    z.writestr("maps/liar.bsp", b"IBSP" + bytes(12))
data = bytearray(open(liar, "rb").read())
claimed = struct.pack("<I", 3 << 30)
local = data.find(b"PK\x03\x04")
data[local + 22:local + 26] = claimed  # uncompressed size
central = data.find(b"PK\x01\x02")
data[central + 24:central + 28] = claimed
open(liar, "wb").write(bytes(data))
scene("claims_3gib", '{"mesh": "claims_3gib.pk3", "map": "maps/liar.bsp"}')

depth = 1_000_000
with open(os.path.join(out, "nested_1m.scene.json"), "w") as f:
    f.write('{"probeproxy_scene": 1, "up": "Z", "level": ' + "[" * depth + "]" * depth +
            ', "probes": []}\n')
