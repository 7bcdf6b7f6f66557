#!/usr/bin/python3
"""Writes scenes/media/smoke.json: a heterogeneous smoke plume (a `grid` medium, scenes/README.md "Media")
in a box of `interface` walls above a floor, lit by a quad lamp. The density is a sum of
Gaussian puffs along a rising, widening spiral, cut to 0 below 2% of its peak: sparse (most of
the box is empty), which is what a majorant grid is for (raytracer/render/media/majorant_grid.hpp).
Deterministic (no random numbers), so rerunning writes the same bytes.
Usage: /usr/bin/python3 tools/make_smoke_grid.py [--size 32] [-o scenes/media/smoke.json]
"""
import argparse
import json
import math


def density(n):
    puffs = []
    for k in range(24):
        s = k / 23.0
        a = 5.0 * s
        r = 0.12 + 0.18 * s
        puffs.append((0.5 + r * math.cos(a), 0.1 + 0.8 * s, 0.5 + r * math.sin(a), 0.035 + 0.04 * s, 1.0 - 0.6 * s))
    values = []
    for z in range(n):
        for y in range(n):
            for x in range(n):
                p = ((x + 0.5) / n, (y + 0.5) / n, (z + 0.5) / n)
                d = 0.0
                for (cx, cy, cz, w, h) in puffs:
                    q = ((p[0] - cx) ** 2 + (p[1] - cy) ** 2 + (p[2] - cz) ** 2) / (w * w)
                    d += h * math.exp(-0.5 * q)
                values.append(round(d, 3) if d >= 0.02 else 0)
    return values


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--size", type=int, default=32)
    ap.add_argument("-o", default="scenes/media/smoke.json")
    a = ap.parse_args()
    n = a.size
    scene = {
        "description": "A smoke plume: a heterogeneous grid medium, written by tools/make_smoke_grid.py",
        "camera": {"position": [0, 1.2, 4.2], "look_at": [0, 0.9, 0], "fov": 40},
        "film": {"width": 160, "height": 160, "spp": 64, "max_depth": 16},
        "background": {"color": [0.02, 0.02, 0.03]},
        "media": {"smoke": {"type": "grid", "sigma_a": [0.5, 0.5, 0.5], "sigma_s": [6, 6, 6], "g": 0.3,
                            "size": [n, n, n], "density": density(n),
                            "p0": [-1, 0, -1], "p1": [1, 2, 1]}},
        "materials": {
            "bounds": {"type": "interface"},
            "floor": {"type": "diffuse", "albedo": [0.6, 0.6, 0.6]},
            "lamp": {"type": "emissive", "emission": [12, 10, 8]},
        },
        "objects": [
            {"type": "box", "min": [-1, 0.001, -1], "max": [1, 2, 1], "material": "bounds", "inside": "smoke", "name": "smoke box"},
            {"type": "quad", "corner": [-4, 0, 4], "edge_u": [8, 0, 0], "edge_v": [0, 0, -8], "material": "floor", "name": "floor"},
            {"type": "quad", "corner": [1.5, 3, -0.5], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "material": "lamp", "name": "lamp"},
        ],
    }
    with open(a.o, "w") as f:
        json.dump(scene, f, separators=(",", ":"))
        f.write("\n")
    nonzero = sum(1 for v in scene["media"]["smoke"]["density"] if v)
    print(f"{a.o}: {n}^3 voxels, {nonzero} non-zero ({100.0 * nonzero / n ** 3:.1f}%)")


if __name__ == "__main__":
    main()
