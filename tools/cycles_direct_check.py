"""Direct light on the Cornell box's back wall, rendered images against Lambert's closed form.

Usage (Debian's python3 with numpy): cycles_direct_check.py SCENE IMAGE.pfm VARIANCE.pfm [IMAGE VARIANCE ...]
Each IMAGE is a direct-light-only render of SCENE (sweeptrace --max-depth 2, or Cycles with no
bounces); VARIANCE the variance of its pixel means. For bands of height on the back wall above the
boxes, prints the image's mean relative difference from rho/pi * L * E, E the irradiance of the
quad light by Lambert's polygon formula, averaged over each pixel's area (8 x 8 midpoint rule),
and that difference in standard errors (z). tools/cycles-direct-check.sh runs it; the table it
prints is in reference_images/cycles/README.md. The test tests/raytracer/test_convergence_quad_light.cpp
makes the same comparison for sweeptrace, as a pass/fail test.
"""
import json
import math
import sys

import numpy as np

from pfm import read_pfm

BANDS = [(350, 400), (400, 450), (450, 500), (500, 530), (530, 550)]
SUB = 8




def polygon_irradiance(corners, p, n):
    s = 0.0
    for i in range(4):
        a = corners[i] - p
        b = corners[(i + 1) % 4] - p
        a /= np.linalg.norm(a)
        b /= np.linalg.norm(b)
        c = np.cross(a, b)
        s += math.acos(np.clip(a @ b, -1.0, 1.0)) * (c / np.linalg.norm(c)) @ n
    return abs(s) / 2.0


def truth_and_heights(scene, width, height):
    objs = {o["name"]: o for o in scene["objects"]}
    light, wall = objs["light"], objs["back wall"]
    c, u, v = (np.array(light[k], dtype=float) for k in ("corner", "edge_u", "edge_v"))
    corners = [c, c + u, c + u + v, c + v]
    L = np.array(scene["materials"][light["material"]]["emission"], dtype=float)
    rho = np.array(scene["materials"][wall["material"]]["albedo"], dtype=float)
    wall_z = wall["corner"][2]
    cam = scene["camera"]
    eye = np.array(cam["position"], dtype=float)
    fwd = np.array(cam["look_at"], dtype=float) - eye
    fwd /= np.linalg.norm(fwd)
    right = np.cross(fwd, np.array(cam.get("up", [0, 1, 0]), dtype=float))
    right /= np.linalg.norm(right)
    up = np.cross(right, fwd)
    half = math.tan(math.radians(cam["fov"]) / 2)
    truth = np.zeros((height, width, 3))
    band = np.full((height, width), -1)
    for y in range(height):
        for x in range(width):
            acc, ys = 0.0, []
            for j in range(SUB):
                for i in range(SUB):
                    fx, fy = x + (i + 0.5) / SUB, y + (j + 0.5) / SUB
                    d = fwd + (2 * fx / width - 1) * half * right + (1 - 2 * fy / height) * half * up
                    p = eye + (wall_z - eye[2]) / d[2] * d
                    ys.append(p[1])
                    if not (0 <= p[0] <= 555):
                        ys.append(-1)
                    acc += polygon_irradiance(corners, p, np.array([0.0, 0.0, -1.0]))
            for k, (lo, hi) in enumerate(BANDS):
                if min(ys) >= lo and max(ys) < hi:
                    band[y, x] = k
            if band[y, x] >= 0:
                truth[y, x] = rho / math.pi * L * acc / SUB**2
    return truth, band


def main():
    if len(sys.argv) < 4 or len(sys.argv) % 2:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        scene = json.load(f)
    images = [(read_pfm(a), read_pfm(b), a) for a, b in zip(sys.argv[2::2], sys.argv[3::2])]
    h, w, _ = images[0][0].shape
    truth, band = truth_and_heights(scene, w, h)
    print("| image | " + " | ".join(f"wall y {lo}-{hi}" for lo, hi in BANDS) + " |")
    print("|---|" + "---:|" * len(BANDS))
    for img, var, name in images:
        cells = []
        for k in range(len(BANDS)):
            m = band == k
            diff = (img[m] - truth[m]).mean()
            sigma = math.sqrt(var[m].sum() / 3) / m.sum()
            cells.append(f"{100 * diff / truth[m].mean():+.2f}% (z {diff / sigma:+.1f})")
        print(f"| {name} | " + " | ".join(cells) + " |")


main()
