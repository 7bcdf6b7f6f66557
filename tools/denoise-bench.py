#!/usr/bin/python3
"""How long `sweeptrace denoise` takes on a 1920x1080 feature image (issue 42's speed bench: the
aim is 15 s on 2 cores). A bench, not a test: it prints, asserts nothing.

The input is rendered by the command itself: scenes/cornell-box.json at 1920x1080, 2 spp, with
its features (render --aovs), cached in --work. NFOR runs the same windows at every pixel, so its
cost is mostly the image's size; the picture moves it a little (weights that would be subnormal
are flushed, raytracer/denoise/subnormals.hpp: more of them, as in smooth 32-spp interiors, make
it faster). Then `denoise` --repeats times, alternating the
ISAs the binary offers (--isas: `default` is AVX-512 or AVX2 where the CPU has them, `avx2` and
`scalar` set SWEEPTRACE_SIMD to stop at AVX2 or force the baseline), each timed in wall seconds and in CPU seconds of the child (getrusage: user + system), so a busy
machine shows as wall > CPU / threads. With --baseline BINARY the same runs of another build
alternate with it (before/after ratios measured in one sitting).

Usage: /usr/bin/python3 tools/denoise-bench.py [--binary build/sweeptrace] [--baseline OTHER]
           [--threads 2] [--repeats 2] [--size 1920x1080] [--isas default,avx2,scalar]
           [--work /tmp/denoise-bench]
"""
import argparse
import os
import resource
import subprocess
import sys
import time

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def timed(cmd, env=None):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.time()
    res = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    wall = time.time() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if res.returncode != 0:
        sys.exit(f"denoise-bench: {' '.join(cmd)} exited {res.returncode}:\n{res.stderr}")
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--binary", default=os.path.join(REPO, "build", "sweeptrace"))
    p.add_argument("--baseline", help="another sweeptrace to alternate with (e.g. main's build)")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--repeats", type=int, default=2)
    p.add_argument("--size", default="1920x1080")
    p.add_argument("--isas", default="default,avx2,scalar", help="this build's runs: default, avx2, scalar (comma-separated)")
    p.add_argument("--work", default="/tmp/denoise-bench")
    args = p.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    os.makedirs(args.work, exist_ok=True)
    features = os.path.join(args.work, f"cornell-box-{width}x{height}.exr")
    if not os.path.exists(features):
        wall, cpu = timed([args.binary, "render", os.path.join(REPO, "scenes", "cornell-box.json"), "--width", str(width),
                           "--height", str(height), "--spp", "2", "--aovs", "--threads", str(args.threads), "--quiet",
                           "-o", features])
        print(f"input: {features} rendered ({cpu:.1f} CPU s, {wall:.1f} s wall)")
    runs = []
    for isa in args.isas.split(","):
        if isa not in ("default", "avx2", "scalar"):
            sys.exit(f"denoise-bench: --isas: unknown '{isa}' (default, avx2, scalar)")
        runs.append(("this build" if isa == "default" else f"this build, SWEEPTRACE_SIMD={isa}", args.binary,
                     None if isa == "default" else isa))
    if args.baseline:
        runs.append(("baseline build", args.baseline, None))
    print(f"denoise {width}x{height}, {args.threads} threads (wall s, CPU s):")
    results = {name: [] for name, _, _ in runs}
    for _ in range(args.repeats):
        for name, binary, simd in runs:
            env = dict(os.environ)
            env.pop("SWEEPTRACE_SIMD", None)
            if simd:
                env["SWEEPTRACE_SIMD"] = simd
            out = os.path.join(args.work, "denoised.pfm")
            wall, cpu = timed([binary, "denoise", features, "-o", out, "--threads", str(args.threads), "--quiet"], env)
            results[name].append((wall, cpu))
            print(f"  {name:36s} {wall:7.1f} {cpu:8.1f}", flush=True)
    print("best of each (the machine's other load only adds):")
    for name, values in results.items():
        wall = min(v[0] for v in values)
        cpu = min(v[1] for v in values)
        print(f"  {name:36s} {wall:7.1f} s wall, {cpu:7.1f} CPU s = {cpu / args.threads:.1f} s on {args.threads} idle cores")


if __name__ == "__main__":
    main()
