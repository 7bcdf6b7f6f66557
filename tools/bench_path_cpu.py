#!/usr/bin/python3
"""The path tracer's CPU time per shipped scene, one build against another (issue 33: "the path
tracer itself no slower"): each scene rendered by `render --integrator path --threads 1` at a
fixed size and spp by both binaries, interleaved, --repeat times; the least CPU time (user +
system of the child, so other engineers' load on the shared machine counts little) per binary.
Prints a markdown table (scene, before s, after s, after / before).
Usage: /usr/bin/python3 tools/bench_path_cpu.py BEFORE_BINARY AFTER_BINARY [--spp 4] [--size 160x120] [--repeat 3]
"""
import argparse
import glob
import os
import resource
import subprocess
import sys
import tempfile


def cpu_seconds(cmd, check=True):
    """CPU seconds of the child; None when check is False and it refused its input (exit 2)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if r.returncode == 2 and not check:
        return None
    if r.returncode != 0:
        raise subprocess.CalledProcessError(r.returncode, cmd)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("--spp", type=int, default=4)
    ap.add_argument("--size", default="160x120")
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    w, h = a.size.split("x")
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = os.path.join(tempfile.mkdtemp(), "bench.pfm")
    print("| scene | before CPU s | after CPU s | after / before |\n|---|---|---|---|")
    for scene in sorted(glob.glob(os.path.join(root, "scenes", "*.json"))):
        best = {}
        for _ in range(a.repeat):
            for name, exe in (("before", a.before), ("after", a.after)):
                cmd = [exe, "render", scene, "--integrator", "path", "--threads", "1", "--spp", str(a.spp),
                       "--width", w, "--height", h, "--quiet", "-o", out]
                # A scene newer than the before build (a feature it lacks) is refused by it: said so.
                t = cpu_seconds(cmd, check=name == "after")
                if t is None:
                    break
                best[name] = min(best.get(name, t), t)
            if "before" not in best:
                break
        if "before" not in best:
            print("| %s | refused (exit 2) | | |" % os.path.basename(scene))
            continue
        print("| %s | %.3f | %.3f | %.3f |" % (os.path.basename(scene), best["before"], best["after"],
                                                best["after"] / best["before"]))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
