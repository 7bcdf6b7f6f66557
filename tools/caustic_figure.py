#!/usr/bin/python3
"""scenes/caustic.json by each integrator at equal CPU time, and how fast bdpt's and vcm's caustics converge.

1. Long bdpt and vcm renders (--ref-time CPU seconds each, seed 1) are the converged images.
2. `sweeptrace render --time T --time-clock cpu` with --integrator path, bdpt and vcm (seed 7).
3. The caustic region: the pixels whose centre ray (a pinhole, as the scene's camera) meets the
   floor under the water slab, 0.1 in from its edges (the camera is below the water, so nothing
   is in between). Its mean over pixels and channels per render, against the reference's, and
   what the picture shows: its median pixel and its mean clamped to [0, 1].
4. bdpt and vcm at each budget of --budgets (CPU seconds, seed 11 + i): the relative error of the
   caustic region's mean against its own long render's, the issue's "within 5% of its converged
   mean" check.
5. The same scene seen from above the water (the camera moved up, the caustic seen through the
   rippled surface: light, specular, specular, diffuse, specular, specular, camera), where no
   connection strategy reaches the floor: path, bdpt and vcm at --time each, and vcm at
   --ref-time; the region is the pixels whose centre ray meets the water's mean top level
   (y = 0.8) inside the same inset footprint, seen through the water.

Writes docs/integrators-caustic.md (the tables, and the command) and docs/integrators-caustic.png
(top: path | bdpt | vcm | vcm's long render; bottom: the same from above;
clamped to [0, 1] and raised to 1/2.2).
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
ABOVE_POSITION, ABOVE_LOOK_AT = [0, 1.6, -2.4], [0, 0, 0.3]  # above the water's top
WATER_TOP = 0.8  # tools/make_caustic_water.py's TOP: the ripples' mean level


def caustic_mask(scene_path, width, height, level=0.0):
    """Pixels whose centre ray meets the plane y = level inside the slab's inset footprint."""
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
        t = (level - eye[1]) / d[..., 1]
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
    # The view from above: the scene's own file with the camera moved (and the mesh by its path).
    with open(scene) as f:
        above_doc = json.load(f)
    above_doc["camera"]["position"], above_doc["camera"]["look_at"] = ABOVE_POSITION, ABOVE_LOOK_AT
    for o in above_doc["objects"]:
        if "file" in o:
            o["file"] = os.path.join(root, "scenes", o["file"])
    above = os.path.join(tmp, "caustic-above.json")
    with open(above, "w") as f:
        json.dump(above_doc, f)

    spp = {}

    def run(name, integrator, seconds, seed, scene_file=scene):
        out = os.path.join(tmp, name + ".pfm")
        spp[name] = render(exe, scene_file, a.width, a.height, out,
                           ["--integrator", integrator, "--time", str(seconds), "--time-clock", "cpu",
                            "--threads", str(a.threads), "--seed", str(seed)])
        return read_pfm(out)

    mask = caustic_mask(scene, a.width, a.height)
    ref = run("reference-bdpt", "bdpt", a.ref_time, 1)
    vref = run("reference-vcm", "vcm", a.ref_time, 1)
    imgs = {name: run(name, name, a.time, 7) for name in ("path", "bdpt", "vcm")}
    region = lambda img: float(img[mask].mean())
    # What the picture shows: the median pixel, and the mean clamped as a display clamps it. The
    # path tracer's plain mean is unbiased, made of a few fireflies carrying the light's radiance.
    median = lambda img: float(np.median(img[mask].mean(axis=-1)))
    shown = lambda img: float(np.clip(img[mask], 0, 1).mean())
    ref_mean, vref_mean = region(ref), region(vref)
    rows = [(name, a.time, spp[name], imgs[name]) for name in ("path", "bdpt", "vcm")]
    rows += [("bdpt long", a.ref_time, spp["reference-bdpt"], ref), ("vcm long", a.ref_time, spp["reference-vcm"], vref)]
    budgets = [float(b) for b in a.budgets.split(",") if b]
    conv = []
    for i, b in enumerate(budgets):
        bm = region(run("bdpt-%g" % b, "bdpt", b, 11 + i))
        vm = region(run("vcm-%g" % b, "vcm", b, 11 + i))
        conv.append((b, bm, spp["bdpt-%g" % b], vm, spp["vcm-%g" % b]))
    above_imgs = {name: run("above-" + name, name, a.time, 7, above) for name in ("path", "bdpt", "vcm")}
    above_ref = run("above-reference-vcm", "vcm", a.ref_time, 1, above)
    above_mask = caustic_mask(above, a.width, a.height, WATER_TOP)
    above_rows = [(n, a.time, spp["above-" + n], above_imgs[n]) for n in ("path", "bdpt", "vcm")]
    above_rows.append(("vcm long", a.ref_time, spp["above-reference-vcm"], above_ref))
    above_region = lambda img: float(img[above_mask].mean())
    above_median = lambda img: float(np.median(img[above_mask].mean(axis=-1)))
    above_shown = lambda img: float(np.clip(img[above_mask], 0, 1).mean())
    above_ref_mean = above_region(above_ref)

    cmd = "/usr/bin/python3 tools/caustic_figure.py --time %g --ref-time %g --budgets %s --threads %d" % (
        a.time, a.ref_time, a.budgets, a.threads)
    with open(os.path.join(root, "docs", "integrators-caustic.md"), "w") as f:
        f.write("# scenes/caustic.json: the caustic region by path, bdpt and vcm\n\n")
        f.write("Made by `%s` (%dx%d, %d thread(s), CPU seconds of the render's own clock; one seed "
                "each, a shared machine). The caustic region is %d pixels: the floor under the water "
                "slab. Reference: bdpt, %g CPU s, region mean %.4f; vcm's own long render, %g CPU s, "
                "region mean %.4f (%+.2f%% of bdpt's).\n\n" %
                (cmd, a.width, a.height, a.threads, int(mask.sum()), a.ref_time, ref_mean, a.ref_time, vref_mean,
                 100 * (vref_mean / ref_mean - 1)))
        f.write("| integrator | CPU s | spp | caustic-region mean | / bdpt reference | median pixel | displayed mean |\n"
                "|---|---|---|---|---|---|---|\n")
        for name, t, n, img in rows:
            m = region(img)
            f.write("| %s | %g | %s | %.4f | %.3f | %.4f | %.4f |\n" % (name, t, n, m, m / ref_mean, median(img), shown(img)))
        f.write("\nThe path tracer's mean is near the reference's (it is unbiased) but made of a few fireflies, "
                "each a pixel whose path hit the light through the water; its median pixel and its displayed "
                "(clamped to [0, 1]) mean show the picture: black under the water.\n")
        f.write("\nbdpt and vcm at smaller budgets (another seed each): relative error of the region's mean "
                "against the same integrator's long render\n\n")
        f.write("| CPU s | bdpt spp | bdpt mean | bdpt error | vcm spp | vcm mean | vcm error |\n|---|---|---|---|---|---|---|\n")
        for b, bm, bn, vm, vn in conv:
            f.write("| %g | %s | %.4f | %+.1f%% | %s | %.4f | %+.1f%% |\n" %
                    (b, bn, bm, 100 * (bm / ref_mean - 1), vn, vm, 100 * (vm / vref_mean - 1)))
        f.write("\nSeen from above the water (camera at %s looking at %s; the picture's bottom row): the "
                "region is the %d pixels whose centre ray meets the water's mean top level inside the same "
                "footprint, the floor seen through the water. Reference: vcm, %g CPU s.\n\n" %
                (ABOVE_POSITION, ABOVE_LOOK_AT, int(above_mask.sum()), a.ref_time))
        f.write("| integrator | CPU s | spp | region mean | / vcm long | median pixel | displayed mean |\n"
                "|---|---|---|---|---|---|---|\n")
        for name, t, n, img in above_rows:
            m = above_region(img)
            f.write("| %s | %g | %s | %.4f | %.3f | %.4f | %.4f |\n" %
                    (name, t, n, m, m / above_ref_mean, above_median(img), above_shown(img)))
        f.write("\n![top: path | bdpt | vcm | vcm long; bottom, the same from above](integrators-caustic.png)\n")
    for name, t, n, img in rows:
        m = region(img)
        print("%s: %g CPU s, %s spp, caustic-region mean %.4f (%.3f of bdpt's reference %.4f), median %.4f, "
              "displayed mean %.4f" % (name, t, n, m, m / ref_mean, ref_mean, median(img), shown(img)))
    for name, t, n, img in above_rows:
        m = above_region(img)
        print("from above, %s: %g CPU s, %s spp, region mean %.4f (%.3f of vcm long), median %.4f, displayed mean %.4f"
              % (name, t, n, m, m / above_ref_mean, above_median(img), above_shown(img)))
    for b, bm, bn, vm, vn in conv:
        print("%g CPU s: bdpt %s spp mean %.4f (%+.1f%%), vcm %s spp mean %.4f (%+.1f%% of vcm long)" %
              (b, bn, bm, 100 * (bm / ref_mean - 1), vn, vm, 100 * (vm / vref_mean - 1)))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 4, figsize=(12, 4.4))
    top = [(imgs["path"], "path, %g CPU s" % a.time), (imgs["bdpt"], "bdpt, %g CPU s" % a.time),
           (imgs["vcm"], "vcm, %g CPU s" % a.time), (vref, "vcm, %g CPU s" % a.ref_time)]
    bottom = [(above_imgs[n], "from above: %s, %g CPU s" % (n, a.time)) for n in ("path", "bdpt", "vcm")]
    bottom.append((above_ref, "from above: vcm, %g CPU s" % a.ref_time))
    for ax, (img, title) in zip(list(axes[0]) + list(axes[1]), top + bottom):
        ax.imshow(np.clip(img, 0, 1) ** (1 / 2.2))
        ax.set_title(title, fontsize=9)
    for ax in axes.flat:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(os.path.join(root, "docs", "integrators-caustic.png"), dpi=100)


if __name__ == "__main__":
    sys.exit(main())
