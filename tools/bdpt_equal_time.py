#!/usr/bin/python3
"""Equal-CPU-time error of the path tracer and bidirectional path tracing (issue 33).

For each scene: a long bdpt render as the reference (--ref-time CPU seconds; a bdpt reference
because the path tracer misses what bdpt is for), then `sweeptrace render --time T --time-clock cpu`
with --integrator path and bdpt (seed 7, different from the reference's), and the linear RMSE of
each against the reference (over pixels and channels, unclamped). The reference's own noise adds
the same amount to both errors, so the ratio it prints is, if anything, closer to 1 than the
truth's. CPU time counts every thread of the render (the renderer's ProcessCpu clock), so the
figures do not grow while other processes share the machine.

Writes docs/integrators-equal-time.md and docs/integrators-equal-time.png (path | bdpt | reference
per scene, clamped to [0, 1] and raised to 1/2.2). Needs ../shared/bitterli (skips a scene that is missing).
Usage: /usr/bin/python3 tools/bdpt_equal_time.py [--build build] [--time 20] [--ref-time 240] [--size 128]
"""
import argparse
import os
import subprocess
import sys

import numpy as np

from equal_time import read_pfm  # tools/equal_time.py's reader (this folder is on sys.path)

SCENES = [("veach-bidir", "../shared/bitterli/veach-bidir/scene-v4.pbrt")]


def render(exe, scene, out, integrator, seconds, size, threads, seed):
    cmd = [exe, "render", scene, "-o", out, "--integrator", integrator, "--time", str(seconds), "--time-clock", "cpu",
           "--width", str(size), "--height", str(size), "--threads", str(threads), "--seed", str(seed), "--quiet"]
    subprocess.run(cmd, check=True)
    return read_pfm(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build")
    ap.add_argument("--time", type=float, default=20.0)
    ap.add_argument("--ref-time", type=float, default=240.0)
    ap.add_argument("--size", type=int, default=128)
    ap.add_argument("--threads", type=int, default=2)
    args = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    exe = os.path.join(root, args.build, "sweeptrace")
    work = os.path.join(root, args.build, "bdpt-equal-time")
    os.makedirs(work, exist_ok=True)
    rows = []
    pictures = []
    for name, rel in SCENES:
        scene = os.path.normpath(os.path.join(root, rel))
        if not os.path.exists(scene):
            print(f"bdpt_equal_time: skipping {name}: {scene} not found", file=sys.stderr)
            continue
        ref = render(exe, scene, os.path.join(work, f"{name}-ref.pfm"), "bdpt", args.ref_time, args.size, args.threads, 1)
        errors = {}
        for integrator in ("path", "bdpt"):
            img = render(exe, scene, os.path.join(work, f"{name}-{integrator}.pfm"), integrator, args.time, args.size,
                         args.threads, 7)
            errors[integrator] = float(np.sqrt(np.mean((img - ref) ** 2)))
        rows.append((name, errors["path"], errors["bdpt"], errors["bdpt"] / errors["path"]))
        pictures.append((name, [read_pfm(os.path.join(work, f"{name}-{i}.pfm")) for i in ("path", "bdpt")] + [ref]))
        print(f"{name}: RMSE path {errors['path']:.5f}, bdpt {errors['bdpt']:.5f}, ratio {rows[-1][3]:.3f}")
    if not rows:
        raise SystemExit("bdpt_equal_time: no scene found")
    out = os.path.join(root, "docs", "integrators-equal-time.md")
    with open(out, "w") as f:
        f.write("# Path tracing and bdpt at equal CPU time\n\n")
        f.write(f"`/usr/bin/python3 tools/bdpt_equal_time.py --time {args.time:g} --ref-time {args.ref_time:g} "
                f"--size {args.size}`: {args.size}x{args.size}, {args.threads} threads, each render "
                f"{args.time:g} CPU seconds, against a bdpt reference of {args.ref_time:g} CPU seconds "
                "(linear RMSE over pixels and channels; the reference's noise is in both).\n\n")
        f.write("| scene | RMSE path | RMSE bdpt | bdpt / path |\n|---|---|---|---|\n")
        for name, p, b, r in rows:
            f.write(f"| {name} | {p:.5f} | {b:.5f} | {r:.3f} |\n")
        f.write("\n![path, bdpt and the reference at equal CPU time](integrators-equal-time.png)\n")
    print(f"wrote {out}")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(len(pictures), 3, figsize=(9, 3.2 * len(pictures)), squeeze=False)
    for row, (name, images) in zip(axes, pictures):
        for ax, img, title in zip(row, images, (f"path, {args.time:g} CPU s", f"bdpt, {args.time:g} CPU s",
                                                f"reference, bdpt {args.ref_time:g} CPU s")):
            ax.imshow(np.clip(img, 0.0, 1.0) ** (1 / 2.2))
            ax.set_title(f"{name}: {title}", fontsize=9)
            ax.axis("off")
    fig.tight_layout()
    fig.savefig(os.path.join(root, "docs", "integrators-equal-time.png"), dpi=100)


if __name__ == "__main__":
    main()
