#!/usr/bin/python3
"""scenes/caustic.json by each integrator at equal CPU time, and how fast bdpt's caustic converges.

1. A long bdpt render (--ref-time CPU seconds, seed 1) is the converged image.
2. `sweeptrace render --time T --time-clock cpu` with --integrator path and bdpt (seed 7).
3. The caustic region: the pixels whose centre ray (a pinhole, as the scene's camera) meets the
   floor under the water slab, 0.1 in from its edges (the camera is below the water, so nothing
   is in between). Its mean over pixels and channels per render, against the reference's, and
   what the picture shows: its median pixel and its mean clamped to [0, 1].
4. bdpt at each budget of --budgets (CPU seconds, seed 11 + i): the relative error of the caustic
   region's mean against the reference's, the issue's "within 5% of its converged mean" check.

Writes docs/integrators-caustic.md (the table, and the command) and docs/integrators-caustic.png
(path | bdpt | reference, clamped to [0, 1] and raised to 1/2.2).
Usage: /usr/bin/python3 tools/caustic_figure.py [--build build] [--time 10] [--ref-time 120]
       [--budgets 2,5,10,20] [--threads 1]
"""
import argparse
import json
import math
import os
import sys

import numpy as np

from equal_time import read_pfm, render  # tools/equal_time.py's PFM reader and render call

SLAB_HALF = 1.0 - 0.1  # tools/make_caustic_water.py's HALF, inset


def caustic_mask(scene_path, width, height):
    with open(scene_path) as f:
        cam = json.load(f)["camera"]
    eye, target, up = (np.array(cam[k], float) for k in ("position", "look_at", "up"))
    forward = target - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    true_up = np.cross(right, forward)
    half_h = math.tan(math.radians(cam["fov"]) / 2)
    half_w = half_h * width / height
    ys, xs = np.mgrid[0:height, 0:width]
    sx = ((xs + 0.5) / width * 2 - 1) * half_w
    sy = (1 - (ys + 0.5) / height * 2) * half_h
    d = forward[None, None, :] + sx[..., None] * right + sy[..., None] * true_up
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -eye[1] / d[..., 1]
    p = eye + t[..., None] * d
    return (d[..., 1] < 0) & (np.abs(p[..., 0]) < SLAB_HALF) & (np.abs(p[..., 2]) < SLAB_HALF)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build")
    ap.add_argument("--time", type=float, default=10.0)
    ap.add_argument("--ref-time", type=float, default=120.0)
    ap.add_argument("--budgets", default="2,5,10,20")
    ap.add_argument("--width", type=int, default=128)
    ap.add_argument("--height", type=int, default=80)
    ap.add_argument("--threads", type=int, default=1)
    a = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    exe = os.path.join(root, a.build, "sweeptrace")
    scene = os.path.join(root, "scenes", "caustic.json")
    tmp = os.path.join(root, a.build, "caustic-figure")
    os.makedirs(tmp, exist_ok=True)

    spp = {}

    def run(name, integrator, seconds, seed):
        out = os.path.join(tmp, name + ".pfm")
        spp[name] = render(exe, scene, a.width, a.height, out,
                           ["--integrator", integrator, "--time", str(seconds), "--time-clock", "cpu",
                            "--threads", str(a.threads), "--seed", str(seed)])
        return read_pfm(out)

    mask = caustic_mask(scene, a.width, a.height)
    ref = run("reference", "bdpt", a.ref_time, 1)
    path = run("path", "path", a.time, 7)
    bdpt = run("bdpt", "bdpt", a.time, 7)
    region = lambda img: float(img[mask].mean())
    # What the picture shows: the median pixel, and the mean clamped as a display clamps it. The
    # path tracer's plain mean is unbiased, made of a few fireflies carrying the light's radiance.
    median = lambda img: float(np.median(img[mask].mean(axis=-1)))
    shown = lambda img: float(np.clip(img[mask], 0, 1).mean())
    ref_mean = region(ref)
    rows = [(name, a.time, region(img), spp[name], median(img), shown(img))
            for name, img in (("path", path), ("bdpt", bdpt), ("reference", ref))]
    rows[-1] = ("bdpt reference",) + (a.ref_time,) + rows[-1][2:]
    budgets = [float(b) for b in a.budgets.split(",") if b]
    conv = [(b, region(run("bdpt-%g" % b, "bdpt", b, 11 + i))) for i, b in enumerate(budgets)]

    cmd = "/usr/bin/python3 tools/caustic_figure.py --time %g --ref-time %g --budgets %s --threads %d" % (
        a.time, a.ref_time, a.budgets, a.threads)
    with open(os.path.join(root, "docs", "integrators-caustic.md"), "w") as f:
        f.write("# scenes/caustic.json: the caustic region by path and bdpt\n\n")
        f.write("Made by `%s` (%dx%d, %d thread(s), CPU seconds of the render's own clock; one seed "
                "each, a shared machine). The caustic region is %d pixels: the floor under the water "
                "slab. Reference: bdpt, %g CPU s, region mean %.4f.\n\n" %
                (cmd, a.width, a.height, a.threads, int(mask.sum()), a.ref_time, ref_mean))
        f.write("| integrator | CPU s | spp | caustic-region mean | / reference | median pixel | displayed mean |\n"
                "|---|---|---|---|---|---|---|\n")
        for name, t, m, n, med, sh in rows:
            f.write("| %s | %g | %s | %.4f | %.3f | %.4f | %.4f |\n" % (name, t, n, m, m / ref_mean, med, sh))
        f.write("\nThe path tracer's mean is near the reference's (it is unbiased) but made of a few fireflies, "
                "each a pixel whose path hit the light through the water; its median pixel and its displayed "
                "(clamped to [0, 1]) mean show the picture: black under the water.\n")
        f.write("\nbdpt alone at smaller budgets (another seed each): relative error of the region's mean\n\n")
        f.write("| CPU s | caustic-region mean | error |\n|---|---|---|\n")
        for b, m in conv:
            f.write("| %g | %.4f | %+.1f%% |\n" % (b, m, 100 * (m / ref_mean - 1)))
        f.write("\n![path | bdpt | reference](integrators-caustic.png)\n")
    for name, t, m, n, med, sh in rows:
        print("%s: %g CPU s, %s spp, caustic-region mean %.4f (%.3f of the reference's %.4f), median %.4f, "
              "displayed mean %.4f" % (name, t, n, m, m / ref_mean, ref_mean, med, sh))
    for b, m in conv:
        print("bdpt %g CPU s: caustic-region mean %.4f, error %+.1f%%" % (b, m, 100 * (m / ref_mean - 1)))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(9, 2.2))
    for ax, img, title in zip(axes, (path, bdpt, ref), ("path, %g CPU s" % a.time, "bdpt, %g CPU s" % a.time,
                                                         "bdpt, %g CPU s" % a.ref_time)):
        ax.imshow(np.clip(img, 0, 1) ** (1 / 2.2))
        ax.set_title(title, fontsize=9)
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(os.path.join(root, "docs", "integrators-caustic.png"), dpi=100)


if __name__ == "__main__":
    sys.exit(main())
