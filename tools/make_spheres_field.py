#!/usr/bin/python3
"""Writes scenes/spheres-field.json: the cover scene of Peter Shirley's "Ray Tracing in One
Weekend" (section 13): a field of small random spheres on a huge ground sphere, and three big
ones (glass, diffuse, metal). Analytic shapes only, so it measures the top level of the
acceleration structures (bench scenes/spheres-field.json).

Fixed seed: the same file every run. Standard library only.
Run from anywhere: python3 tools/make_spheres_field.py [output.json]

The layout follows the book: a 22 x 22 grid of cells (a, b in -11..10), one sphere of radius 0.2
per cell jittered by up to 0.9, skipped where it would touch the big metal sphere; materials
drawn diffuse (80%, albedo the product of two uniforms), metal (15%, albedo 0.5..1, roughness
0..0.5) or glass (5%, ior 1.5). The book's camera: from (13, 2, 3) toward the origin, vertical
field of view 20 degrees, aperture 0.1 focused at 10.
"""
import json
import math
import os
import random
import sys

SEED = 486


def main():
    rng = random.Random(SEED)
    r2 = lambda: round(rng.random(), 4)
    materials = {
        "ground": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]},
        "glass": {"type": "dielectric", "ior": 1.5},
        "brown": {"type": "diffuse", "albedo": [0.4, 0.2, 0.1]},
        "steel": {"type": "metal", "albedo": [0.7, 0.6, 0.5], "roughness": 0},
    }
    objects = [{"name": "ground", "type": "sphere", "center": [0, -1000, 0], "radius": 1000, "material": "ground"}]
    for a in range(-11, 11):
        for b in range(-11, 11):
            choose = rng.random()
            center = [round(a + 0.9 * rng.random(), 4), 0.2, round(b + 0.9 * rng.random(), 4)]
            if math.dist(center, [4, 0.2, 0]) <= 0.9:
                continue
            name = f"s{a + 11}_{b + 11}"
            if choose < 0.8:
                materials[name] = {"type": "diffuse", "albedo": [round(r2() * r2(), 4) for _ in range(3)]}
            elif choose < 0.95:
                materials[name] = {"type": "metal", "albedo": [round(0.5 + 0.5 * rng.random(), 4) for _ in range(3)],
                                   "roughness": round(0.5 * rng.random(), 4)}
            else:
                materials[name] = {"type": "dielectric", "ior": 1.5}
            objects.append({"name": name, "type": "sphere", "center": center, "radius": 0.2, "material": name})
    objects += [
        {"name": "glass ball", "type": "sphere", "center": [0, 1, 0], "radius": 1, "material": "glass"},
        {"name": "diffuse ball", "type": "sphere", "center": [-4, 1, 0], "radius": 1, "material": "brown"},
        {"name": "metal ball", "type": "sphere", "center": [4, 1, 0], "radius": 1, "material": "steel"},
    ]
    scene = {
        "description": f"The cover of \"Ray Tracing in One Weekend\": {len(objects)} spheres, made by "
                       f"tools/make_spheres_field.py (seed {SEED}). Analytic shapes only: the top level's benchmark.",
        "camera": {"position": [13, 2, 3], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 20,
                   "aperture": 0.1, "focus_distance": 10},
        "film": {"width": 480, "height": 270, "spp": 32, "max_depth": 8},
        "background": {"sky": {"horizon": [1, 1, 1], "zenith": [0.5, 0.7, 1.0]}},
        "seed": 1,
        "materials": materials,
        "objects": objects,
    }
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "scenes", "spheres-field.json")
    with open(out, "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")
    print(f"{out}: {len(objects)} spheres", file=sys.stderr)


if __name__ == "__main__":
    main()
