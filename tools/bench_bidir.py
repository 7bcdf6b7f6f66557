#!/usr/bin/python3
"""The bidirectional methods' cost, one build against another (issue 39's speed targets), each
measurement run by both binaries alternately in one sitting, --repeat times, the least taken:
  - vcm on scenes/caustic.json at 320x180: iterations (spp) per CPU second, one thread, 32
    iterations (scene loading and the accelerator's build included);
  - vcm's equal-time RMSE on the same: a reference rendered once by the after build's bdpt (unbiased)
    in two halves of --ref-time CPU seconds each, seeds 1000 and 1001 (kept in --ref-cache, a
    folder), then each build's vcm at --rmse-time CPU seconds (render --time T --time-clock cpu),
    --rmse-seeds seeds each. Printed: the root of the mean squared error against the halves' mean,
    less the reference's own share (a quarter of the halves' mean squared difference: the
    reference's variance, which adds to every image's squared error alike), and the raw RMSE;
  - vcm's peak memory (maximum resident set of the process) at 1920x1080, depth 8, one iteration;
  - the path tracer's samples per CPU second on Bitterli's kitchen and classroom (textured), from
    ../shared/bitterli beside the checkout;
  - bdpt on scenes/cornell-box.json: samples per CPU second, one thread.
CPU time is user + system of the child, so other work on a shared machine counts little; memory
is GNU time's %M. Prints a markdown table (what, before, after, after / before).
Usage: /usr/bin/python3 tools/bench_bidir.py BEFORE_BINARY AFTER_BINARY [--repeat 2] [--skip-memory]
       [--skip-rmse] [--rmse-time 4] [--rmse-seeds 3] [--ref-time 120] [--ref-cache DIR]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

from equal_time import read_pfm  # tools/equal_time.py's PFM reader

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(os.path.dirname(ROOT), "shared")


def run(cmd):
    """CPU seconds and peak resident kilobytes of one run of cmd."""
    r = subprocess.run(["/usr/bin/time", "-f", "TIME %U %S %M"] + cmd, check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE, text=True)
    m = re.findall(r"TIME ([0-9.]+) ([0-9.]+) ([0-9]+)", r.stderr)[-1]
    return float(m[0]) + float(m[1]), int(m[2])


def best_of(binaries, args, repeat, key):
    best = {}
    for _ in range(repeat):
        for name, exe in binaries:
            v = key(run([exe] + args))
            best[name] = min(best.get(name, v), v)
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--skip-memory", action="store_true")
    ap.add_argument("--skip-rmse", action="store_true")
    ap.add_argument("--rmse-time", type=float, default=4.0)
    ap.add_argument("--rmse-seeds", type=int, default=3)
    ap.add_argument("--ref-time", type=float, default=120.0)
    ap.add_argument("--ref-cache", default=None)
    a = ap.parse_args()
    binaries = (("before", a.before), ("after", a.after))
    out = os.path.join(tempfile.mkdtemp(), "bench.pfm")
    common = ["--quiet", "-o", out]
    print("| measurement | before | after | after / before |\n|---|---|---|---|")

    def row(what, before, after):
        print("| %s | %.4g | %.4g | %.3f |" % (what, before, after, after / before))
        sys.stdout.flush()

    caustic = os.path.join(ROOT, "scenes", "caustic.json")
    spp = 32
    t = best_of(binaries, ["render", caustic, "--integrator", "vcm", "--threads", "1", "--spp", str(spp), "--width",
                           "320", "--height", "180"] + common, a.repeat, lambda r: r[0])
    row("vcm caustic.json 320x180: iterations per CPU s", spp / t["before"], spp / t["after"])

    if not a.skip_rmse:
        size = ["--width", "320", "--height", "180", "--quiet"]
        halves = []
        for half, seed in (("a", 1000), ("b", 1001)):
            path = os.path.join(a.ref_cache or os.path.dirname(out), "reference-%s.pfm" % half)
            if not os.path.exists(path):
                subprocess.run([a.after, "render", caustic, "--integrator", "bdpt", "--time", str(a.ref_time),
                                "--time-clock", "cpu", "--threads", "2", "--seed", str(seed), "-o", path] + size,
                               check=True)
            halves.append(read_pfm(path))
        ref = 0.5 * (halves[0] + halves[1])
        ref_var = float(np.mean((halves[0] - halves[1]) ** 2)) / 4.0
        sq = {"before": [], "after": []}
        for seed in range(1, a.rmse_seeds + 1):
            for name, exe in binaries:
                img = os.path.join(os.path.dirname(out), "%s-%d.pfm" % (name, seed))
                subprocess.run([exe, "render", caustic, "--integrator", "vcm", "--time", str(a.rmse_time),
                                "--time-clock", "cpu", "--threads", "1", "--seed", str(seed), "-o", img] + size,
                               check=True)
                sq[name].append(float(np.mean((read_pfm(img) - ref) ** 2)))
        rmse = {name: float(np.sqrt(max(0.0, np.mean(v) - ref_var))) for name, v in sq.items()}
        raw = {name: float(np.sqrt(np.mean(v))) for name, v in sq.items()}
        what = "vcm caustic.json 320x180: RMSE at %g CPU s (%d seeds; bdpt reference 2 x %g CPU s" % (
            a.rmse_time, a.rmse_seeds, a.ref_time)
        row(what + ", its variance taken out)", rmse["before"], rmse["after"])
        row(what + ", raw)", raw["before"], raw["after"])

    if not a.skip_memory:
        m = best_of(binaries, ["render", caustic, "--integrator", "vcm", "--spp", "1", "--max-depth", "8", "--width",
                               "1920", "--height", "1080"] + common, 1, lambda r: r[1])
        row("vcm caustic.json 1920x1080 depth 8: peak MB", m["before"] / 1024.0, m["after"] / 1024.0)

    for scene in ("kitchen", "classroom"):
        path = os.path.join(SHARED, "bitterli", scene, "scene-v4.pbrt")
        if not os.path.exists(path):
            print("| path %s: not found (%s) | | | |" % (scene, path))
            continue
        spp = 16  # loading the scene takes ~1.5 CPU s of the run
        t = best_of(binaries, ["render", path, "--integrator", "path", "--threads", "1", "--spp", str(spp), "--width",
                               "160", "--height", "90"] + common, a.repeat, lambda r: r[0])
        row("path %s 160x90: samples per CPU s (x 1e3)" % scene, 160 * 90 * spp / t["before"] / 1e3,
            160 * 90 * spp / t["after"] / 1e3)

    cornell = os.path.join(ROOT, "scenes", "cornell-box.json")
    spp = 8
    t = best_of(binaries, ["render", cornell, "--integrator", "bdpt", "--threads", "1", "--spp", str(spp), "--width",
                           "128", "--height", "128"] + common, a.repeat, lambda r: r[0])
    row("bdpt cornell-box.json 128x128: samples per CPU s (x 1e3)", 128 * 128 * spp / t["before"] / 1e3,
        128 * 128 * spp / t["after"] / 1e3)


if __name__ == "__main__":
    main()
