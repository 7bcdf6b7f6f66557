#!/usr/bin/python3
"""Reads the named channels of a scanline OpenEXR file (uncompressed, ZIPS or ZIP; HALF or FLOAT):
enough for sweeptrace's own EXRs (render -o x.exr, render --aovs), for the scripts that chart
them without an OpenEXR module (Debian 12's python3 has none).

    from exr_channels import read_exr
    channels, (w, h) = read_exr("x.exr")   # {"R": array(h, w), "Albedo.R": ...}
"""
import struct
import zlib

import numpy as np


def _header(data):
    if data[:4] != b"\x76\x2f\x31\x01":
        raise ValueError("not an OpenEXR file")
    at, attrs = 8, {}
    while data[at] != 0:
        name_end = data.index(b"\0", at)
        kind_end = data.index(b"\0", name_end + 1)
        (size,) = struct.unpack_from("<i", data, kind_end + 1)
        attrs[data[at:name_end].decode()] = (data[name_end + 1:kind_end].decode(), data[kind_end + 5:kind_end + 5 + size])
        at = kind_end + 5 + size
    return attrs, at + 1


def _channels(value):
    out, at = [], 0
    while value[at] != 0:
        end = value.index(b"\0", at)
        pixel_type, _, xs, ys = struct.unpack_from("<iB3xii", value, end + 1)
        if xs != 1 or ys != 1:
            raise ValueError("subsampled channels are not read")
        out.append((value[at:end].decode(), pixel_type))
        at = end + 1 + 16
    return out


def _unzip(raw):
    """OpenEXR's ZIP: zlib, then a byte predictor, then the two interleaved halves."""
    d = np.frombuffer(zlib.decompress(raw), dtype=np.uint8).astype(np.int64)
    # t[0] = d[0], t[i] = t[i-1] + d[i] - 128 (mod 256)
    t = ((np.cumsum(d - 128) + 128) % 256).astype(np.uint8)
    half = (len(t) + 1) // 2
    out = np.empty(len(t), dtype=np.uint8)
    out[0::2], out[1::2] = t[:half], t[half:]
    return out.tobytes()


def read_exr(path):
    with open(path, "rb") as f:
        data = f.read()
    attrs, at = _header(data)
    x0, y0, x1, y1 = struct.unpack("<iiii", attrs["dataWindow"][1])
    w, h = x1 - x0 + 1, y1 - y0 + 1
    compression = attrs["compression"][1][0]
    lines = {0: 1, 2: 1, 3: 16}.get(compression)
    if lines is None:
        raise ValueError(f"{path}: compression {compression} is not read (only none, ZIPS, ZIP)")
    chans = _channels(attrs["channels"][1])
    blocks = (h + lines - 1) // lines
    offsets = struct.unpack_from(f"<{blocks}Q", data, at)
    sizes = [4 if t == 2 else 2 for _, t in chans]
    out = {name: np.zeros((h, w), dtype=np.float32) for name, _ in chans}
    for off in offsets:
        y, size = struct.unpack_from("<ii", data, off)
        raw = data[off + 8:off + 8 + size]
        n = min(lines, y1 + 1 - y)
        if size < n * w * sum(sizes):
            raw = _unzip(raw)
        at = 0
        for line in range(n):
            for (name, t), s in zip(chans, sizes):
                row = np.frombuffer(raw, dtype="<f4" if t == 2 else "<f2", count=w, offset=at)
                out[name][y - y0 + line] = row.astype(np.float32)
                at += w * s
    return out, (w, h)
