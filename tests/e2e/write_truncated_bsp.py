"""Writes a Quake 3 BSP whose surfaces lump runs past the end of the file, and a scene that
uses it: `probeproxy build` must refuse it with one line naming the lump (exit 2).
    write_truncated_bsp.py OUT_FOLDER"""
import os
import struct
import sys

out = sys.argv[1]
os.makedirs(out, exist_ok=True)
header_bytes = 8 + 8 * 17
lumps = [(header_bytes, 0)] * 17
lumps[13] = (header_bytes, 104)  # one face record the file does not hold
with open(os.path.join(out, "truncated.bsp"), "wb") as f:
    f.write(b"IBSP" + struct.pack("<i", 46))
    for offset, length in lumps:
        f.write(struct.pack("<ii", offset, length))
    f.write(b"\0" * 50)
with open(os.path.join(out, "truncated.scene.json"), "w") as f:
    f.write('{"probeproxy_scene": 1, "up": "Z", "level": ["truncated.bsp"], "probes": [{"name": "p",'
            ' "capture": [0, 0, 1], "influence": {"kind": "sphere", "center": [0, 0, 1],'
            ' "radius": 10}, "proxy": "auto"}]}\n')
