#!/usr/bin/python3
"""Colour PFM files for the tools' scripts, the top row first (as sweeptrace's image readers and
pbrt-v4's return images; the file itself stores the bottom row first)."""
import numpy as np


def read_pfm(path):
    """(height, width, 3) float64, the top row first; exits with a message for other files."""
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            raise SystemExit(f"{path}: not a colour PFM")
        w, h = (int(v) for v in f.readline().split())
        scale = float(f.readline())
        data = np.fromfile(f, dtype="<f4" if scale < 0 else ">f4", count=w * h * 3)
    return data.reshape(h, w, 3)[::-1].astype(np.float64)


def write_pfm(path, img):
    """Writes (height, width, 3), the top row first, as a little-endian float PFM."""
    h, w, _ = img.shape
    with open(path, "wb") as f:
        f.write(f"PF\n{w} {h}\n-1.0\n".encode())
        np.ascontiguousarray(img[::-1]).astype("<f4").tofile(f)
