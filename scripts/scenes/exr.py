"""Minimal OpenEXR scan-line reader (standard library only) for the suite's own checks.

Reads what the suite writes: single-part scan-line files, FLOAT or HALF channels, no
compression, ZIPS or ZIP. Enough to check the face convention without OpenImageIO.
"""

import array
import itertools
import struct
import sys
import zlib

MAGIC = b"\x76\x2f\x31\x01"
_LINES_PER_CHUNK = {0: 1, 2: 1, 3: 16}  # NONE, ZIPS, ZIP
_SIZES = {1: 2, 2: 4}  # HALF, FLOAT


class ExrError(ValueError):
    pass


def _cstr(data, pos):
    end = data.index(b"\0", pos)
    return data[pos:end].decode("latin-1"), end + 1


def _header(data):
    if data[:4] != MAGIC:
        raise ExrError("not an OpenEXR file (bad magic bytes)")
    if data[5] & 0x1A:  # tiled, deep or multi-part
        raise ExrError("only single-part scan-line files are supported")
    pos, attrs = 8, {}
    while data[pos] != 0:
        name, pos = _cstr(data, pos)
        kind, pos = _cstr(data, pos)
        (size,) = struct.unpack_from("<i", data, pos)
        attrs[name] = (kind, data[pos + 4:pos + 4 + size])
        pos += 4 + size
    return attrs, pos + 1


def _channels(raw):
    channels, pos = [], 0
    while raw[pos] != 0:
        name, pos = _cstr(raw, pos)
        pixel_type, _, xs, ys = struct.unpack_from("<iB3xii", raw, pos)
        if pixel_type not in _SIZES or xs != 1 or ys != 1:
            raise ExrError(f"channel {name}: unsupported type or subsampling")
        channels.append((name, pixel_type))
        pos += 16
    return channels


def _unzip(chunk, expected):
    raw = zlib.decompress(chunk)
    if len(raw) != expected:
        raise ExrError("bad ZIP chunk size")
    t = bytes(itertools.accumulate(raw, lambda a, b: (a + b - 128) & 255))
    half = (len(t) + 1) // 2
    out = bytearray(len(t))
    out[0::2] = t[:half]
    out[1::2] = t[half:]
    return bytes(out)


def read(path):
    """Returns (width, height, {channel: list of floats, row 0 = top of the image})."""
    with open(path, "rb") as f:
        data = f.read()
    attrs, pos = _header(data)
    channels = _channels(attrs["channels"][1])
    compression = attrs["compression"][1][0]
    if compression not in _LINES_PER_CHUNK:
        raise ExrError(f"unsupported compression {compression}")
    xmin, ymin, xmax, ymax = struct.unpack("<4i", attrs["dataWindow"][1])
    width, height = xmax - xmin + 1, ymax - ymin + 1
    lines = _LINES_PER_CHUNK[compression]
    chunks = (height + lines - 1) // lines
    offsets = struct.unpack_from(f"<{chunks}Q", data, pos)
    planes = {name: [0.0] * (width * height) for name, _ in channels}
    for offset in offsets:
        y, size = struct.unpack_from("<ii", data, offset)
        body = data[offset + 8:offset + 8 + size]
        rows = min(lines, ymax + 1 - y)
        expected = rows * width * sum(_SIZES[t] for _, t in channels)
        if compression != 0 and size < expected:
            body = _unzip(body, expected)
        if len(body) != expected:
            raise ExrError("truncated chunk")
        p = 0
        for r in range(rows):
            row = (y - ymin + r) * width
            for name, pixel_type in channels:
                n = width * _SIZES[pixel_type]
                if pixel_type == 2:
                    values = array.array("f")
                    values.frombytes(body[p:p + n])
                    if sys.byteorder == "big":
                        values.byteswap()
                    vals = values.tolist()
                else:
                    vals = list(struct.unpack(f"<{width}e", body[p:p + n]))
                planes[name][row:row + width] = vals
                p += n
    return width, height, planes
