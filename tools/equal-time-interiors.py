#!/usr/bin/python3
"""Equal-time RMSE on the interiors (issue 34): an old build against a new one.

For each scene: a long reference render, then `render --time T --time-clock cpu` by each build,
and the RMSE of each against the reference (linear radiance, over every pixel and channel,
non-finite reference pixels masked). T is CPU seconds of all the render's threads (the
renderer's ProcessCpu budget clock), so the figures do not grow while other processes share
the machine. The reference is a render of --ref-factor x T CPU seconds (default 16) by the same
build as the render it judges (--shared-reference: the new build's, for both: half the cost).
The reference's own noise adds to every RMSE about 1/ref-factor of a render's variance.

The issue's settings are the defaults: 320x180, 60 CPU-s, 2 threads. Writes a markdown table
(--out, default docs/equal-time-interiors.md) with the command that made it.

Two settings of one build (e.g. uniform against adaptive sampling): the same binary as --old
and --new, with --old-args / --new-args added to each one's equal-time renders and --ref-args
to every reference (so the references stay uniform whatever the default). --fireflies adds the
issue's firefly check: classroom at --firefly-spp (1024) for each column, against a reference
of --firefly-ref-factor x that spp, and the count of 8x8 blocks whose mean is more than 5 sigma
(the two renders' stated variances, `render --variance`) from the reference's.

Build the old binary (main at 644dcf9) beside the new one, e.g.:
  git worktree add --detach ../wt-base 644dcf9
  cmake -S ../wt-base -B ../wt-base/build -DSWEEPTRACE_TESTS=OFF && cmake --build ../wt-base/build -j2 --target sweeptrace
Usage:
  /usr/bin/python3 tools/equal-time-interiors.py --old ../wt-base/build/sweeptrace --new build/sweeptrace
      [--time 60] [--ref-factor 16] [--threads 2] [--width 320 --height 180] [--scenes classroom,smallpt]
  /usr/bin/python3 tools/equal-time-interiors.py --old build/sweeptrace --new build/sweeptrace \
      --old-args="--adaptive off" --new-args="--adaptive on" --ref-args="--adaptive off" --shared-reference \
      --title "uniform against adaptive sampling" [--fireflies --firefly-size 80x45]
"""
import argparse
import os
import re
import shlex
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from equal_time import read_pfm  # noqa: E402  (the PFM reader of the guiding study)

SHARED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "bitterli")
REPO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
# (name, scene file, target ratio new / old from the issue)
SCENES = [
    ("classroom", os.path.join(SHARED, "classroom", "scene-v4.pbrt"), 0.5),
    ("kitchen", os.path.join(SHARED, "kitchen", "scene-v4.pbrt"), 0.5),
    ("staircase2", os.path.join(SHARED, "staircase2", "scene-v4.pbrt"), 0.5),
    ("coffee", os.path.join(SHARED, "coffee", "scene-v4.pbrt"), 0.5),
    ("smallpt", os.path.join(REPO, "scenes", "smallpt.json"), 0.7),
    ("cornell-box", os.path.join(REPO, "scenes", "cornell-box.json"), 0.7),
]


def render(binary, scene, args, seconds, seed, out, extra="", variance=None):
    """A --time render on the CPU clock (extra: more render arguments; variance: also write the
    variance of each pixel's mean there); returns its spp."""
    cmd = [binary, "render", scene, "--width", str(args.width), "--height", str(args.height), "--time", str(seconds),
           "--time-clock", "cpu", "--threads", str(args.threads), "--seed", str(seed), "-o", out] + shlex.split(extra)
    if variance:
        cmd += ["--variance", variance]
    return run_render(cmd)


def run_render(cmd):
    """Runs one render command; returns the spp of its summary line (adaptive: the mean)."""
    print("equal-time-interiors: " + " ".join(cmd), file=sys.stderr, flush=True)
    res = subprocess.run(cmd, stderr=subprocess.PIPE, text=True)
    if res.returncode != 0:
        raise SystemExit(f"equal-time-interiors: {' '.join(cmd)} failed:\n{res.stderr}")
    m = re.search(r"\d+x\d+, (\d+) spp", res.stderr)  # the summary line
    return int(m.group(1)) if m else -1


def block_outliers(image, var, ref, ref_var, block=8, sigmas=5.0):
    """8x8 blocks (any channel) whose mean is more than `sigmas` standard errors from the reference's."""
    h, w = (image.shape[0] // block) * block, (image.shape[1] // block) * block

    def sums(a):
        return a[:h, :w].reshape(h // block, block, w // block, block, -1).sum(axis=(1, 3))
    d = sums(image) - sums(ref)
    v = sums(var) + sums(ref_var)
    z = np.where(v > 0, np.abs(d) / np.sqrt(np.maximum(v, 1e-300)), 0.0)
    bad = np.any(z > sigmas, axis=-1)
    return int(bad.sum()), int(bad.size), float(z.max())


def fireflies(args, builds, extras):
    """The issue's firefly check on classroom; returns markdown lines."""
    scene = SCENES[0][1]
    if not os.path.exists(scene):
        return [f"Firefly check skipped: {scene} missing.\n"]
    w, h = (int(v) for v in args.firefly_size.split("x"))
    spp = args.firefly_spp
    ref_spp = int(args.firefly_ref_factor * spp)

    def fr(binary, seed, n, out, extra):
        cmd = [binary, "render", scene, "--width", str(w), "--height", str(h), "--spp", str(n), "--threads",
               str(args.threads), "--seed", str(seed), "--sampler", "independent", "-o", out + ".pfm",
               "--variance", out + "-var.pfm"] + shlex.split(extra)
        if not (os.path.exists(out + ".pfm") and os.path.exists(out + "-var.pfm")):
            run_render(cmd)
        return read_pfm(out + ".pfm"), read_pfm(out + "-var.pfm")

    if args.firefly_ref_factor > 0:
        ref = fr(args.new, 1001, ref_spp, os.path.join(args.work, f"classroom-fireflies-ref-{w}x{h}-{ref_spp}"), args.ref_args)
        ref_text = f"{ref_spp} spp (seed 1001, `{args.ref_args}`)"
    else:
        # The equal-time table's own classroom reference (same size), with its --variance.
        base = os.path.join(args.work, f"classroom-new-ref-{args.ref_factor * args.time:g}s")
        if (w, h) != (args.width, args.height) or not os.path.exists(base + "-var.pfm"):
            return [f"Firefly check skipped: --firefly-ref-factor 0 needs the table's classroom reference at "
                    f"{w}x{h} with its variance ({base}-var.pfm).\n"]
        ref = (read_pfm(base + ".pfm"), read_pfm(base + "-var.pfm"))
        ref_text = f"the table's classroom reference, {open(base + '.pfm.spp').read().strip()} spp (seed 1001, `{args.ref_args}`)"
    lines = [f"\n## Firefly check: classroom at {w}x{h}, {spp} spp, independent sampler\n\n",
             f"Reference: {ref_text}. A block fails when the difference of its mean "
             f"from the reference's, in any channel, is more than 5 standard errors (both renders' `--variance`).\n\n",
             "| column | render arguments | 8x8 blocks beyond 5 sigma | blocks | largest z |\n|---|---|---|---|---|\n"]
    for build, binary in builds:
        tag = re.sub(r"[^A-Za-z0-9]+", "_", extras[build]).strip("_")  # renders of other arguments are not reused
        img = fr(binary, 7, spp, os.path.join(args.work, f"classroom-fireflies-{build}-{tag}-{w}x{h}-{spp}"), extras[build])
        n, total, zmax = block_outliers(img[0], img[1], ref[0], ref[1])
        lines.append(f"| {build} | `{extras[build]}` | {n} | {total} | {zmax:.2f} |\n")
    return lines


def rmse(image, reference):
    ok = np.isfinite(reference) & np.isfinite(image)
    return float(np.sqrt(np.mean((image[ok] - reference[ok]) ** 2)))


def net_rmse(image, reference, ref_var):
    """The RMSE without the reference's own noise: E[(image - ref)^2] = the image's error^2 + the
    reference's variance (independent seeds), so the reference's stated variance of each pixel's
    mean (`render --variance`; under the Sobol sampler an overstatement, so this errs low) is
    subtracted, pixel by pixel summed. None without a variance file."""
    if ref_var is None:
        return None
    ok = np.isfinite(reference) & np.isfinite(image) & np.isfinite(ref_var)
    d = float(np.mean((image[ok] - reference[ok]) ** 2) - np.mean(ref_var[ok]))
    return float(np.sqrt(max(d, 0.0)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--old", required=True, help="sweeptrace binary of the baseline (main at 644dcf9)")
    ap.add_argument("--new", required=True, help="sweeptrace binary of the change")
    ap.add_argument("--time", type=float, default=60.0, help="CPU seconds per render (default 60)")
    ap.add_argument("--ref-factor", type=float, default=16.0, help="reference budget / --time (default 16)")
    ap.add_argument("--shared-reference", action="store_true", help="judge both builds by the new build's reference")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--width", type=int, default=320)
    ap.add_argument("--height", type=int, default=180)
    ap.add_argument("--scenes", default=",".join(s[0] for s in SCENES))
    ap.add_argument("--old-args", default="", help="more render arguments for the old column's equal-time renders")
    ap.add_argument("--new-args", default="", help="more render arguments for the new column's equal-time renders")
    ap.add_argument("--ref-args", default="", help="more render arguments for every reference render")
    ap.add_argument("--title", default="main at 644dcf9 against this branch", help="what old and new are, for the heading")
    ap.add_argument("--fireflies", action="store_true", help="add the firefly check on classroom (see above)")
    ap.add_argument("--firefly-spp", type=int, default=1024)
    ap.add_argument("--firefly-ref-factor", type=float, default=8.0,
                    help="the firefly reference's spp / --firefly-spp; 0: use the table's classroom reference "
                         "(same size; it needs --variance, which references rendered by this script have)")
    ap.add_argument("--firefly-size", default="320x180", help="WxH of the firefly check's renders")
    ap.add_argument("--work", default="equal-time-interiors", help="folder for the renders (kept; references reused)")
    ap.add_argument("--out", default=os.path.join(REPO, "docs", "equal-time-interiors.md"))
    args = ap.parse_args()
    wanted = args.scenes.split(",")
    unknown = [w for w in wanted if w not in [s[0] for s in SCENES]]
    if unknown:
        raise SystemExit(f"equal-time-interiors: --scenes: unknown scene(s) {', '.join(unknown)}")
    for b in (args.old, args.new):
        if not os.access(b, os.X_OK):
            raise SystemExit(f"equal-time-interiors: {b}: not an executable")
    os.makedirs(args.work, exist_ok=True)
    builds = [("old", args.old), ("new", args.new)]
    extras = {"old": args.old_args, "new": args.new_args}
    rows = []
    started = time.time()
    for name, scene, target in SCENES:
        if name not in wanted:
            continue
        if not os.path.exists(scene):
            print(f"equal-time-interiors: {scene} missing, {name} skipped", file=sys.stderr)
            continue
        ref_seconds = args.ref_factor * args.time
        refs = {}
        for build, binary in builds:
            if args.shared_reference and build == "old":
                continue
            path = os.path.join(args.work, f"{name}-{build}-ref-{ref_seconds:g}s.pfm")
            # A reference already in --work (same name: scene, build, budget) is reused with its spp.
            var_path = path[:-len(".pfm")] + "-var.pfm"
            if os.path.exists(path) and os.path.exists(path + ".spp"):
                spp = int(open(path + ".spp").read())
            else:
                spp = render(binary, scene, args, ref_seconds, 1001, path, args.ref_args, var_path)
                with open(path + ".spp", "w") as f:
                    f.write(str(spp))
            refs[build] = (read_pfm(path), spp, read_pfm(var_path) if os.path.exists(var_path) else None)
        if args.shared_reference:
            refs["old"] = refs["new"]
        result = {}
        for build, binary in builds:
            path = os.path.join(args.work, f"{name}-{build}-{args.time:g}s.pfm")
            spp = render(binary, scene, args, args.time, 7, path, extras[build])
            image = read_pfm(path)
            result[build] = (rmse(image, refs[build][0]), spp, refs[build][1], net_rmse(image, refs[build][0], refs[build][2]))
        ratio = result["new"][0] / result["old"][0] if result["old"][0] > 0 else float("nan")
        net_old, net_new = result["old"][3], result["new"][3]
        net_ratio = net_new / net_old if net_old and net_new is not None else None
        rows.append((name, target, result, ratio, net_ratio))
    with open(args.out, "w") as f:
        f.write(f"# Equal-time RMSE on the interiors: {args.title}\n\n")
        f.write("Generated by `/usr/bin/python3 tools/equal-time-interiors.py " + shlex.join(sys.argv[1:]) + "`")
        f.write(f" ({time.time() - started:.0f} s wall).\n\n")
        f.write(f"Each render: {args.width}x{args.height}, `--time {args.time:g} --time-clock cpu --threads {args.threads}`"
                f" (CPU seconds of all threads), seed 7. Reference: {args.ref_factor:g} x that budget, seed 1001, rendered by ")
        f.write("the new build for both columns" if args.shared_reference else "the same build as the column it judges")
        f.write(f" (`{args.ref_args}`).\n\n" if args.ref_args else ".\n\n")
        if args.old_args or args.new_args:
            f.write(f"Old column: `{args.old_args}`; new column: `{args.new_args}`.\n\n")
        f.write("The net column takes the reference's own noise out of both RMSEs (its `--variance`, summed over the "
                "pixels, subtracted from each squared error); the raw ratio is pulled toward 1 by it, about "
                "1/ref-factor of the old render's variance. The target is judged on the net ratio where there is one.\n\n")
        f.write("| scene | spp old | spp new | ref spp (old / new) | RMSE old | RMSE new | new / old | net new / old | issue's target |\n")
        f.write("|---|---|---|---|---|---|---|---|---|\n")
        for name, target, r, ratio, net_ratio in rows:
            judged = net_ratio if net_ratio is not None else ratio
            net = f"{net_ratio:.3f}" if net_ratio is not None else "n/a"
            f.write(f"| {name} | {r['old'][1]} | {r['new'][1]} | {r['old'][2]} / {r['new'][2]} | {r['old'][0]:.5g} | "
                    f"{r['new'][0]:.5g} | {ratio:.3f} | {net} | <= {target} {'met' if judged <= target else 'missed'} |\n")
        if args.fireflies:
            f.writelines(fireflies(args, builds, extras))
    print(open(args.out).read())


if __name__ == "__main__":
    main()
