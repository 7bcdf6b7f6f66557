#!/usr/bin/python3
"""The raw-noise cost of the sobol-halves sampler (docs/aovs.md, "Independent halves"): relMSE,
less the reference's own noise, of `render --sampler sobol` and `--sampler sobol-halves` at equal
spp, each the mean of three seeds, against the denoising chart's 4096-spp references, with the
CPU time of a render (getrusage of the child). The two samplers' renders alternate, so a busy
machine slows both alike.

Usage:
  /usr/bin/python3 tools/sampler-halves-cost.py [--binary build/sweeptrace] [--refs /work/denoise-refs]
      [--bitterli ../shared/bitterli] [--spp 32,128] [--scenes cornell-box,coffee] [--work /tmp/sampler-halves-cost]
"""
import argparse
import os
import resource
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exr_channels import read_exr  # noqa: E402

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
# name: width, height, max depth (as tools/denoise-chart.py renders them)
SCENES = {"cornell-box": (256, 256, 64), "classroom": (320, 180, 16), "kitchen": (320, 180, 16),
          "staircase2": (256, 256, 64), "coffee": (200, 250, 16)}
SEEDS = (2, 3, 4)


def colour(path):
    ch, _ = read_exr(path)
    return np.stack([ch["R"], ch["G"], ch["B"]], axis=-1).astype(np.float64)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--binary", default=os.path.join(REPO, "build", "sweeptrace"))
    p.add_argument("--refs", default="/work/denoise-refs")
    p.add_argument("--bitterli", default=os.path.join(REPO, "..", "shared", "bitterli"))
    p.add_argument("--spp", default="32,128")
    p.add_argument("--scenes", default="cornell-box,coffee")
    p.add_argument("--work", default="/tmp/sampler-halves-cost")
    args = p.parse_args()
    os.makedirs(args.work, exist_ok=True)
    for name in args.scenes.split(","):
        w, h, depth = SCENES[name]
        ref = colour(os.path.join(args.refs, f"{name}.exr"))
        floor = float(np.mean(colour(os.path.join(args.refs, f"{name}-variance.exr")) / (ref ** 2 + 0.01)))
        for spp in (int(s) for s in args.spp.split(",")):
            err = {"sobol": [], "sobol-halves": []}
            cpu = {"sobol": 0.0, "sobol-halves": 0.0}
            for seed in SEEDS:
                for sampler in err:
                    out = os.path.join(args.work, f"{name}-{sampler}-{spp}-{seed}.exr")
                    before = resource.getrusage(resource.RUSAGE_CHILDREN)
                    subprocess.run([args.binary, "render", os.path.join(args.bitterli, name, "scene-v4.pbrt"), "--width", str(w),
                                    "--height", str(h), "--max-depth", str(depth), "--threads", "2", "--quiet", "--spp", str(spp),
                                    "--seed", str(seed), "--sampler", sampler, "-o", out], check=True, stderr=subprocess.DEVNULL)
                    after = resource.getrusage(resource.RUSAGE_CHILDREN)
                    cpu[sampler] += after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
                    err[sampler].append(float(np.mean((colour(out) - ref) ** 2 / (ref ** 2 + 0.01))) - floor)
            for sampler, e in err.items():
                print(f"{name} {spp} spp {sampler}: relMSE - floor {np.mean(e):.6f} "
                      f"(seeds {', '.join(f'{v:.6f}' for v in e)}), {cpu[sampler] / len(SEEDS):.1f} CPU s a render")
            print(f"{name} {spp} spp: sobol-halves / sobol {np.mean(err['sobol-halves']) / np.mean(err['sobol']):.3f}", flush=True)


if __name__ == "__main__":
    main()
