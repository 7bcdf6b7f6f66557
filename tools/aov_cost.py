#!/usr/bin/python3
"""What feature outputs cost (issue 42: "AOVs cost <= 10 % of render time"): each scene rendered by
one binary with and without `--aovs`, interleaved, --repeat times, to an .exr (so the cost of
writing the 46-channel feature EXR against the plain one is counted); the least CPU time (user +
system of the child: other engineers' load on a shared machine counts little) of each. With
--baseline OTHER_BINARY, that binary's plain render is timed in the same rounds too (the cost of
the feature code when off). Prints a markdown table.
Usage: /usr/bin/python3 tools/aov_cost.py BINARY [SCENE ...] [--baseline MAIN_BINARY] [--spp 16] [--size 320x180]
       [--repeat 3] [--threads 1] [--integrator path]
Default scenes: scenes/cornell-box.json and ../shared/bitterli/classroom/scene-v4.pbrt.
"""
import argparse
import os
import sys
import tempfile

from bench_path_cpu import cpu_seconds  # tools/ is this script's folder, first on sys.path


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("--baseline")
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--size", default="320x180")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--integrator", default="path")
    ap.add_argument("scenes", nargs="*", default=[os.path.join(root, "scenes", "cornell-box.json"),
                                                  os.path.join(root, "..", "shared", "bitterli", "classroom", "scene-v4.pbrt")])
    a = ap.parse_args()
    w, h = a.size.split("x")
    out = tempfile.mkdtemp()
    runs = [("plain", a.binary, []), ("aovs", a.binary, ["--aovs"])]
    if a.baseline:
        runs.insert(0, ("baseline", a.baseline, []))
    print("%s, %s spp, %sx%s, %d thread(s), least CPU s of %d runs each, interleaved\n" %
          (a.integrator, a.spp, w, h, a.threads, a.repeat))
    print("| scene |%s aovs off | aovs on | on / off |%s\n|---|%s---|---|---|%s" %
          (" baseline |" if a.baseline else "", " off / baseline |" if a.baseline else "",
           "---|" if a.baseline else "", "---|" if a.baseline else ""))
    for scene in a.scenes:
        best = {}
        for _ in range(a.repeat):
            for name, exe, extra in runs:
                cmd = [exe, "render", scene, "--integrator", a.integrator, "--threads", str(a.threads), "--spp",
                       str(a.spp), "--width", w, "--height", h, "--quiet", "-o", os.path.join(out, name + ".exr")] + extra
                t = cpu_seconds(cmd)
                best[name] = min(best.get(name, t), t)
        row = "| %s |" % os.path.basename(os.path.dirname(scene) if scene.endswith(".pbrt") else scene)
        if a.baseline:
            row += " %.2f |" % best["baseline"]
        row += " %.2f | %.2f | %.3f |" % (best["plain"], best["aovs"], best["aovs"] / best["plain"])
        if a.baseline:
            row += " %.3f |" % (best["plain"] / best["baseline"])
        print(row)
        sys.stdout.flush()


if __name__ == "__main__":
    main()
