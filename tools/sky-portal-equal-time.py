#!/usr/bin/python3
"""Equal-time RMSE on scenes/sky-window.json (issue 39, finding 6): a room lit only by a uniform
sky through a window, rendered three ways at the same CPU time:

  unsampled   the old build (main before the sky was a light) on the scene without its portal:
              the sky found only by BSDF-sampled rays;
  sky         the new build, the same portal-less scene: at commit 663a987 next event
              estimation drew the sky uniformly over the sphere, MIS with BSDF sampling; it cost
              more than it gained, and since then a portal-less colour is no light, so this
              column is the first one's estimator again (docs/sky-and-portals.md);
  portal      the new build, the scene as committed: the sky drawn through the window's portal
              (render/lights/portal.hpp);
  guided      the old build, the portal-less scene with path guiding (`--guiding on`): BSDF
              sampling mixed with the learned guide, the sky still no light;
  guided sky  the new build, the same: where a guiding leaf learned where the sky is seen, next
              event estimation draws the sky from that (render/guiding/sky_guide.hpp).

Each is `render --time T --time-clock cpu` (CPU seconds of all the render's threads, so the
figures hold while other processes share the machine), for --seeds seeds; its RMSE (linear
radiance, every pixel and channel) against a reference of --ref-factor x T CPU seconds by the new
build through the portal, less the reference's own stated variance (net RMSE), averaged over the
seeds. The issue's targets: sky / unsampled <= 0.5 (now: guided sky / unsampled) and portal / sky
<= 0.5. Writes a markdown
table (--out) with the command that made it.

Build the old binary beside the new one, e.g. (main at 4d5f2e1, before this change):
  git worktree add --detach ../wt-base 4d5f2e1
  cmake -S ../wt-base -B ../wt-base/build -DSWEEPTRACE_TESTS=OFF && cmake --build ../wt-base/build -j2 --target sweeptrace
Usage:
  /usr/bin/python3 tools/sky-portal-equal-time.py --old ../wt-base/build/sweeptrace --new build/sweeptrace
      [--time 10] [--ref-factor 16] [--seeds 3] [--threads 2] [--width 160 --height 120] [--out FILE]
"""
import argparse
import importlib.util
import json
import os
import shlex
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from equal_time import read_pfm  # noqa: E402  (the PFM reader of the guiding study)

# run_render, rmse and net_rmse of the interiors' equal-time script (its file name has hyphens).
_spec = importlib.util.spec_from_file_location("equal_time_interiors", os.path.join(HERE, "equal-time-interiors.py"))
interiors = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(interiors)

SCENE = os.path.join(HERE, "..", "scenes", "sky-window.json")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--old", required=True, help="sweeptrace binary from before the sky was a light")
    ap.add_argument("--new", required=True, help="sweeptrace binary of the change")
    ap.add_argument("--time", type=float, default=10.0, help="CPU seconds per render (default 10)")
    ap.add_argument("--ref-factor", type=float, default=16.0, help="reference budget / --time (default 16)")
    ap.add_argument("--seeds", type=int, default=3, help="equal-time renders per column, their RMSEs averaged")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--width", type=int, default=160)
    ap.add_argument("--height", type=int, default=120)
    ap.add_argument("--work", default="/tmp/sky-portal-equal-time", help="renders go here")
    ap.add_argument("--out", default=os.path.join(HERE, "..", "docs", "sky-and-portals-equal-time.md"))
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)

    # The scene without its portal, for the old build (which does not know the key) and the middle column.
    with open(SCENE) as f:
        doc = json.load(f)
    del doc["background"]["portal"]
    plain = os.path.join(args.work, "sky-window-plain.json")
    with open(plain, "w") as f:
        json.dump(doc, f, indent=1)

    def render(binary, scene, seconds, seed, out, variance=None, extra=()):
        cmd = [binary, "render", scene, "--width", str(args.width), "--height", str(args.height), "--time",
               str(seconds), "--time-clock", "cpu", "--threads", str(args.threads), "--seed", str(seed), "-o", out]
        cmd += list(extra)
        if variance:
            cmd += ["--variance", variance]
        return interiors.run_render(cmd)

    ref_path = os.path.join(args.work, "reference.pfm")
    ref_var_path = os.path.join(args.work, "reference-var.pfm")
    ref_spp = render(args.new, SCENE, args.ref_factor * args.time, 1001, ref_path, ref_var_path)
    ref, ref_var = read_pfm(ref_path), read_pfm(ref_var_path)

    # (name, binary, scene, extra render arguments, the column its ratio is taken to)
    guided = ("--guiding", "on")
    columns = [("unsampled", args.old, plain, (), None), ("sky", args.new, plain, (), "unsampled"),
               ("portal", args.new, SCENE, (), "sky"), ("guided", args.old, plain, guided, "unsampled"),
               ("guided sky", args.new, plain, guided, "unsampled")]
    rows = {}
    # Seed by seed, the columns in turn, so that a change of the machine's load falls on all alike.
    for name, *_ in columns:
        rows[name] = ([], [])
    for k in range(args.seeds):
        for name, binary, scene, extra, _ in columns:
            out = os.path.join(args.work, f"{name.replace(' ', '-')}-{k}.pfm")
            errors, spps = rows[name]
            spps.append(render(binary, scene, args.time, 7 + k, out, extra=extra))
            errors.append(interiors.net_rmse(read_pfm(out), ref, ref_var))
    rows = {name: (float(np.mean(e)), float(np.std(e)), spps) for name, (e, spps) in rows.items()}

    command = "/usr/bin/python3 tools/sky-portal-equal-time.py " + " ".join(shlex.quote(a) for a in sys.argv[1:])
    lines = [
        "# Sky through a window: equal-time RMSE, unsampled vs sampled vs portal vs guided\n\n",
        f"`{command}`\n\n",
        f"scenes/sky-window.json at {args.width}x{args.height}, {args.time:g} CPU s per render "
        f"(`--time-clock cpu`, {args.threads} threads), {args.seeds} seeds per column; reference: the portal "
        f"column's estimator at {args.ref_factor * args.time:g} CPU s ({ref_spp} spp, seed 1001); RMSE net of "
        "the reference's stated variance, mean (and spread) over the seeds.\n\n",
        "| column | build | scene | spp per render | RMSE | ratio |\n|---|---|---|---|---|---|\n",
    ]
    for name, binary, scene, extra, base in columns:
        e, s, spps = rows[name]
        ratio = "" if base is None else f"{e / rows[base][0]:.3f} x {base}"
        what = ("with portal" if scene == SCENE else "portal removed") + (", " + " ".join(extra) if extra else "")
        lines.append(f"| {name} | `{binary}` | {what} | {', '.join(str(x) for x in spps)} | {e:.5f} (+-{s:.5f}) | {ratio} |\n")
    with open(args.out, "w") as f:
        f.writelines(lines)
    print("".join(lines))


if __name__ == "__main__":
    main()
