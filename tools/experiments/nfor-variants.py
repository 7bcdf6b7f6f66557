#!/usr/bin/env python3
"""NFOR's method variants scored against the chart's references (issue 42's Quality line): an
experiment's record, not a test; prints, asserts nothing. The variants are switches of a build with
tools/experiments/nfor-variants.patch applied (`git apply`; not part of the denoiser), read from
the environment variable NFOR_EXP (comma-separated; empty: the method as on main):
  novar     the renderer's sample variance everywhere, as Tungsten (no halves_variance, step 0)
  novarc    ... for the colour only (regression weights, error estimate, its smoothing)
  novarf    ... for the features' prefilter only
  p2s1      second pass: the guide's variance taken as the mean's (scale 1, not Tungsten's 2)
  p2smooth  second pass: the halves' spread (B - A)^2 / 4 as halves_variance scales the input's
            variance (its windowed sums), instead of per pixel (one degree of freedom)
  nop2      no second pass (the blended halves' mean)
  sellum    selection on the three channels' summed error (one choice per pixel)
  only0 / only1   the k = 0.5 / k = 1 candidate alone (selection map 0 / 1)
  noprefilter  the features' halves unfiltered (no paper 5.1)
  demod     the colour divided by the albedo's mean (features 0-2; 1 where it is 0) before NFOR and
            multiplied by it after, as albedo-demodulating denoisers do
and NFOR_K=k makes both candidates bandwidth k (one filter alone, any k).
With NFOR_DUMP=PREFIX the patched build also writes the error maps, candidates and selection map as
raw float planes (PREFIX-WHAT.raw), which --diagnose reads.

Each variant denoises WORK/SCENE/features-SPP.exr (the layout of tools/denoise-chart.py --work);
printed per scene: relMSE / mean HDR-FLIP (denoise CPU s). --oracle adds a per-pixel oracle choice
between only0's and only1's outputs (the one nearer the reference, summed over channels: a bound
on what any selection between the two candidates can give, the second pass applied to each);
--diagnose prints, per candidate, the mean of the noisy and of the smoothed error estimate against
the true MSE of the halves' mean, and how often the binary selection agrees with the true one;
--bandwidth-oracle K1,K2,.. adds each bandwidth alone (NFOR_K) and the per-pixel oracle over them
(which also picks each pixel's luckiest noise: a loose bound); --equal-flip adds, per variant, the raw spp whose FLIP equals its FLIP (log-log between the two
raw renders WORK/SCENE/raw-N.exr that bracket it).

Usage: /usr/bin/python3 tools/experiments/nfor-variants.py --binary PATCHED/sweeptrace
           --work /work/q-quality --refs /work/denoise-refs [--variants ';novar;novarf']
           [--scenes cornell-box,classroom,kitchen,staircase2,coffee] [--spp 32] [--oracle]
           [--diagnose] [--equal-flip] [--bandwidth-oracle 0.25,0.5,1,2,4] [--out /tmp/nfor-variants]
"""
import argparse
import glob
import importlib.util
import math
import os
import re
import resource
import subprocess

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("denoise_chart", os.path.join(HERE, "..", "denoise-chart.py"))
chart = importlib.util.module_from_spec(spec)
spec.loader.exec_module(chart)
from pfm import write_pfm  # noqa: E402  (tools/, on the path through denoise-chart's import)


def denoise(args, name, variant, dump=None, k=None):
    out = os.path.join(args.out, f"{name}-{args.spp}-{variant or 'main'}{'-k' + k if k else ''}.pfm")
    env = dict(os.environ, NFOR_EXP=variant)
    if k:
        env["NFOR_K"] = k
    if dump:
        env["NFOR_DUMP"] = dump
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([args.binary, "denoise", os.path.join(args.work, name, f"features-{args.spp}.exr"), "-o", out,
                    "--threads", "2", "--quiet"], env=env, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return out, after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def score(args, path, ref, ref_path):
    return chart.relmse(chart.colour(path), ref), chart.flip(args.binary, path, ref_path)


def equal_flip_spp(raw_flips, target):
    """The raw spp whose FLIP is `target`, log-log between the bracketing raw renders (None outside)."""
    for (s0, f0), (s1, f1) in zip(raw_flips, raw_flips[1:]):
        if f1 <= target <= f0:
            return s0 * (s1 / s0) ** (math.log(f0 / target) / math.log(f0 / f1))
    return None


def planes(prefix, what, channels, h, w):
    data = np.fromfile(f"{prefix}-{what}.raw", dtype=np.float32).reshape(channels, h, w)
    return data.transpose(1, 2, 0).astype(np.float64)


def diagnose(args, name, ref):
    h, w, _ = ref.shape
    prefix = os.path.join(args.out, f"{name}-{args.spp}-dump")
    denoise(args, name, "", dump=prefix)
    noisy, smooth = planes(prefix, "noisy_error", 6, h, w), planes(prefix, "error", 6, h, w)
    true = [(0.5 * (planes(prefix, f"ce{k}", 3, h, w) + planes(prefix, f"co{k}", 3, h, w)) - ref) ** 2 for k in (0, 1)]
    for k in (0, 1):
        print(f"  {name} k = {(0.5, 1.0)[k]}: estimated MSE noisy {noisy[..., 3 * k:3 * k + 3].mean():.3e}, smoothed "
              f"{smooth[..., 3 * k:3 * k + 3].mean():.3e}; true {true[k].mean():.3e}")
    chosen = smooth[..., 3:] < smooth[..., :3]
    better = true[1] < true[0]
    print(f"  {name}: k = 1 chosen (binary) at {chosen.mean():.2f} of pixel channels, better at {better.mean():.2f}; "
          f"the choice right at {(chosen == better).mean():.2f}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--binary", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--refs", required=True)
    p.add_argument("--variants", default="")
    p.add_argument("--scenes", default="cornell-box,classroom,kitchen,staircase2,coffee")
    p.add_argument("--spp", type=int, default=32)
    p.add_argument("--oracle", action="store_true")
    p.add_argument("--diagnose", action="store_true")
    p.add_argument("--equal-flip", action="store_true")
    p.add_argument("--bandwidth-oracle", default="")
    p.add_argument("--out", default="/tmp/nfor-variants")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    variants = args.variants.split(";")
    ks = [k for k in args.bandwidth_oracle.split(",") if k]
    print("| scene | " + " | ".join(v or "main" for v in variants) + (" | oracle of only0, only1" if args.oracle else "") +
          "".join(f" | k = {k} alone" for k in ks) + (" | oracle over them" if ks else "") + " |")
    for name in args.scenes.split(","):
        ref_path = os.path.join(args.refs, f"{name}.exr")
        ref = chart.colour(ref_path)
        raw_flips = []
        if args.equal_flip:
            raws = glob.glob(os.path.join(args.work, name, "raw-*.exr"))
            spps = sorted(int(re.search(r"raw-(\d+)\.exr$", r).group(1)) for r in raws)
            raw_flips = [(n, chart.flip(args.binary, os.path.join(args.work, name, f"raw-{n}.exr"), ref_path)) for n in spps]
        cells = []
        for v in variants:
            out, cpu = denoise(args, name, v)
            m, f = score(args, out, ref, ref_path)
            cell = f"{m:.5f} / {f:.4f} ({cpu:.1f})"
            if args.equal_flip:
                spp = equal_flip_spp(raw_flips, f)
                cell += f", FLIP of raw {spp:.0f} spp" if spp else ", FLIP outside the raw renders'"
            cells.append(cell)
        if args.oracle:
            a, b = (chart.colour(denoise(args, name, v)[0]) for v in ("only0", "only1"))
            pick = ((a - ref) ** 2).sum(-1, keepdims=True) < ((b - ref) ** 2).sum(-1, keepdims=True)
            out = os.path.join(args.out, f"{name}-{args.spp}-oracle.pfm")
            write_pfm(out, np.where(pick, a, b).astype(np.float32))
            cells.append("%.5f / %.4f" % score(args, out, ref, ref_path))
        if raw_flips:
            print(f"  {name} raw FLIP: " + ", ".join(f"{n} spp {f:.4f}" for n, f in raw_flips))
        if ks:
            outs = [denoise(args, name, "", k=k)[0] for k in ks]
            cells += ["%.5f / %.4f" % score(args, out, ref, ref_path) for out in outs]
            stack = np.stack([chart.colour(out) for out in outs])
            best = ((stack - ref) ** 2).sum(-1).argmin(0)
            out = os.path.join(args.out, f"{name}-{args.spp}-bandwidth-oracle.pfm")
            write_pfm(out, np.take_along_axis(stack, best[None, ..., None].repeat(3, -1), 0)[0].astype(np.float32))
            cells.append("%.5f / %.4f" % score(args, out, ref, ref_path))
        print(f"| {name} | " + " | ".join(cells) + " |", flush=True)
        if args.diagnose:
            diagnose(args, name, ref)


if __name__ == "__main__":
    main()
