"""Removes the render timings Cycles stamps into every EXR header.

Cycles adds `cycles.<layer>.render_time`, `.synchronization_time` and `.total_time` to the
render result, and Blender writes such custom stamp fields whatever the `use_stamp_*`
settings say. They would make two runs of the suite differ, so they are cut out of the
header here; the pixel chunks are kept byte for byte and the offset table is shifted by the
bytes removed.
"""

import os
import struct

MAGIC = b"\x76\x2f\x31\x01"
_LINES_PER_CHUNK = {0: 1, 1: 1, 2: 1, 3: 16, 4: 32, 5: 16, 6: 32, 7: 32, 8: 256, 9: 256}


def _volatile(name):
    return name.endswith("_time") and name.startswith("cycles.")


def strip_timings(path):
    data = path.read_bytes()
    if data[:4] != MAGIC or data[5] & 0x1A:  # only single-part scan-line files
        raise ValueError(f"{path}: not a single-part scan-line OpenEXR file")
    pos, kept, removed = 8, [], 0
    compression = data_window = None
    while data[pos] != 0:
        start = pos
        pos = data.index(b"\0", pos) + 1
        name = data[start:pos - 1].decode("latin-1")
        pos = data.index(b"\0", pos) + 1
        (size,) = struct.unpack_from("<i", data, pos)
        pos += 4 + size
        if name == "compression":
            compression = data[pos - 1]
        elif name == "dataWindow":
            data_window = struct.unpack_from("<4i", data, pos - 16)
        if _volatile(name):
            removed += pos - start
        else:
            kept.append(data[start:pos])
    if not removed:
        return
    header_end = pos + 1
    height = data_window[3] - data_window[1] + 1
    lines = _LINES_PER_CHUNK[compression]
    chunks = (height + lines - 1) // lines
    offsets = struct.unpack_from(f"<{chunks}Q", data, header_end)
    table = struct.pack(f"<{chunks}Q", *(o - removed for o in offsets))
    body = data[header_end + 8 * chunks:]
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_bytes(data[:8] + b"".join(kept) + b"\0" + table + body)
    os.replace(tmp, path)
