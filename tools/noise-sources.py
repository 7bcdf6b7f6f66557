#!/usr/bin/python3
"""Equal-CPU-time study of the interiors' top noise sources (issue 34 items 4 and 5).

For each scene, one build, several ways to render it: the path tracer unguided (the default),
the path tracer with path guiding (--guiding on), and bidirectional path tracing
(--integrator bdpt). Each is rendered with `--time T --time-clock cpu` (CPU seconds of all the
render's threads) for each of --seeds, and its linear RMSE against one long reference render of
the same scene by the same build (the path tracer, unguided, --ref-factor x T CPU seconds, seed
1001) is printed with its spp. All three methods are unbiased, so any of them could be the
reference; the reference's own noise adds about 1/ref-factor of the default's variance to every
squared error alike, which pulls ratios toward 1 (the table also gives the RMSE with that noise
estimated and subtracted: the reference's per-pixel variance from --variance).

The scene list, the RMSE and the PFM reader are tools/equal-time-interiors.py's (imported, not
copied). Writes a markdown table (--out) with the command that made it.

Usage:
  /usr/bin/python3 tools/noise-sources.py --binary build/sweeptrace [--time 4] [--ref-factor 16]
      [--width 160 --height 90] [--threads 2] [--seeds 7,8,9] [--scenes classroom,kitchen]
      [--methods path,guided,bdpt] [--work DIR] [--out FILE]
"""
import argparse
import importlib.util
import os
import re
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location("equal_time_interiors", os.path.join(HERE, "equal-time-interiors.py"))
eti = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(eti)
from equal_time import display, outliers, z_test  # noqa: E402  (clamp to [0, 1], gamma 1/2.2; its folder is on sys.path now)

# method name -> the render options that select it
METHODS = {
    "path": ["--integrator", "path", "--guiding", "off"],
    "guided": ["--integrator", "path", "--guiding", "on"],
    "bdpt": ["--integrator", "bdpt"],
}


def render(binary, scene, args, method, seconds, seed, out, variance=None):
    """A --time render on the CPU clock by `method`; returns its spp. With --reuse, a render whose
    image and spp file (OUT.spp) are already in --work is not made again."""
    spp_file = out + ".spp"
    if args.reuse and os.path.exists(out) and os.path.exists(spp_file) and (not variance or os.path.exists(variance)):
        return int(open(spp_file).read())
    cmd = [binary, "render", scene, "--width", str(args.width), "--height", str(args.height), "--time", str(seconds),
           "--time-clock", "cpu", "--threads", str(args.threads), "--seed", str(seed), "-o", out] + METHODS[method]
    if variance:
        cmd += ["--variance", variance]
    print("noise-sources: " + " ".join(cmd), file=sys.stderr, flush=True)
    res = subprocess.run(cmd, stderr=subprocess.PIPE, text=True)
    if res.returncode != 0:
        raise SystemExit(f"noise-sources: {' '.join(cmd)} failed:\n{res.stderr}")
    m = re.search(r"\d+x\d+, (\d+) spp", res.stderr)  # the summary line
    spp = int(m.group(1)) if m else -1
    with open(spp_file, "w") as f:
        f.write(f"{spp}\n")
    return spp


def forensics_rows(report, top):
    """Per-sample variance of the image (luminance, mean over pixels) and of its `top` path types,
    in absolute units (variance share x total): shares alone cannot compare two renders."""
    import json
    d = json.load(open(report))
    samples = sum(r["samples"] for r in d["regions"])
    total = sum(r["variance"] * r["samples"] for r in d["regions"]) / samples
    types = sorted(d["path_types"], key=lambda t: -t["variance_share"])[:top]
    return total, [(t["path"], t["variance_share"] * total, t["mean_share"]) for t in types]


def forensics(args, scenes, wanted, methods):
    """--forensics-spp N: each scene by each path method at N spp (seed 1), with --forensics, and a
    table of the per-sample variance by path type: what a method changes in the top sources."""
    lines = [f"Forensics at equal spp ({args.width}x{args.height}, {args.forensics_spp} spp, seed 1, 1 thread): "
             "per-sample variance of the pixels' luminance, and by path type (share x total).", "",
             "| scene | method | per-sample variance | top path types: variance (mean share) |", "|---|---|---|---|"]
    for name in wanted:
        for method in methods:
            if method == "bdpt":
                continue  # forensics follow a camera path's vertices: refused under bdpt
            base = os.path.join(args.work, f"{name}-{args.width}x{args.height}-{method}-{args.forensics_spp}spp")
            if not (args.reuse and os.path.exists(base + ".json")):
                cmd = [args.binary, "render", scenes[name], "--width", str(args.width), "--height", str(args.height),
                       "--spp", str(args.forensics_spp), "--threads", "1", "--seed", "1", "--quiet", "-o", base + ".pfm",
                       "--forensics", base + ".json"] + METHODS[method]
                print("noise-sources: " + " ".join(cmd), file=sys.stderr, flush=True)
                subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
            total, types = forensics_rows(base + ".json", 4)
            lines.append(f"| {name} | {method} | {total:.4g} | " +
                         ", ".join(f"`{p}` {v:.3g} ({m:.1%})" for p, v, m in types) + " |")
    return "\n".join(lines) + "\n"


def bias_check(args, scenes, wanted):
    """--z-old BINARY --z-spp N: each scene by --binary and by BINARY (the path tracer, N spp,
    seeds 11 and 12, --variance), and equal_time.py's block z-test between the two: a change that
    moved the image's expectation fails it."""
    lines = [f"Block z-test, {args.binary} (seed 11) against {args.z_old} (seed 12), path tracer, "
             f"{args.width}x{args.height}, {args.z_spp} spp, 8x8 blocks:", ""]
    for name in wanted:
        parts = []
        for binary, seed, tag in ((args.binary, 11, "new"), (args.z_old, 12, "old")):
            base = os.path.join(args.work, f"{name}-{args.width}x{args.height}-z-{tag}-{args.z_spp}spp")
            if not (args.reuse and os.path.exists(base + ".pfm") and os.path.exists(base + "-var.pfm")):
                cmd = [binary, "render", scenes[name], "--width", str(args.width), "--height", str(args.height),
                       "--spp", str(args.z_spp), "--threads", str(args.threads), "--seed", str(seed), "--quiet",
                       "-o", base + ".pfm", "--variance", base + "-var.pfm"] + METHODS["path"]
                print("noise-sources: " + " ".join(cmd), file=sys.stderr, flush=True)
                subprocess.run(cmd, check=True)
            parts.append([(eti.read_pfm(base + ".pfm"), eti.read_pfm(base + "-var.pfm"), args.z_spp)])
        lines.append(f"- {name}: {z_test(parts[0], parts[1])}")
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", required=True, help="the sweeptrace binary")
    ap.add_argument("--time", type=float, default=4.0, help="CPU seconds per render (default 4; 0: no equal-time table)")
    ap.add_argument("--ref-factor", type=float, default=16.0, help="reference budget / --time (default 16)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--width", type=int, default=160)
    ap.add_argument("--height", type=int, default=90)
    ap.add_argument("--seeds", default="7,8,9")
    ap.add_argument("--scenes", default="classroom,kitchen,staircase2,coffee")
    ap.add_argument("--methods", default="path,guided,bdpt")
    ap.add_argument("--work", default="noise-sources", help="folder for the renders (kept; references reused)")
    ap.add_argument("--out", default="noise-sources.md")
    ap.add_argument("--forensics-spp", type=int, default=0,
                    help="also render each scene by each path method at this spp with --forensics (table below the other)")
    ap.add_argument("--z-old", help="a second binary: block z-test of its path render against --binary's")
    ap.add_argument("--z-spp", type=int, default=256, help="spp of the z-test's renders (default 256)")
    ap.add_argument("--reuse", action="store_true", help="keep renders already in --work (same name: same settings)")
    args = ap.parse_args()
    scenes = {s[0]: s[1] for s in eti.SCENES}
    wanted = args.scenes.split(",")
    methods = args.methods.split(",")
    seeds = [int(s) for s in args.seeds.split(",")]
    bad = [w for w in wanted if w not in scenes] + [m for m in methods if m not in METHODS]
    if bad:
        raise SystemExit(f"noise-sources: unknown scene(s) or method(s): {', '.join(bad)}")
    if not os.access(args.binary, os.X_OK):
        raise SystemExit(f"noise-sources: {args.binary}: not an executable")
    for name in [w for w in wanted if not os.path.exists(scenes[w])]:
        print(f"noise-sources: {scenes[name]} missing, {name} skipped", file=sys.stderr)
        wanted.remove(name)
    os.makedirs(args.work, exist_ok=True)
    started = time.time()
    rows = []
    for name in wanted if args.time > 0 else []:  # --time 0: only the z-test and forensics
        scene = scenes[name]
        ref_seconds = args.ref_factor * args.time
        size = f"{args.width}x{args.height}"
        ref_path = os.path.join(args.work, f"{name}-{size}-ref-{ref_seconds:g}s.pfm")
        var_path = os.path.join(args.work, f"{name}-{size}-ref-{ref_seconds:g}s-var.pfm")
        ref_spp = render(args.binary, scene, args, "path", ref_seconds, 1001, ref_path, var_path)
        ref = eti.read_pfm(ref_path)
        ref_var = float(np.mean(np.nan_to_num(eti.read_pfm(var_path), nan=0.0, posinf=0.0)))
        ref_display = display(ref)
        ref_outliers = outliers(ref)  # bright small features, not fireflies
        for method in methods:
            errs, spps, derrs, flies = [], [], [], []
            for seed in seeds:
                out = os.path.join(args.work, f"{name}-{size}-{method}-{args.time:g}s-{seed}.pfm")
                spp = render(args.binary, scene, args, method, args.time, seed, out)
                img = eti.read_pfm(out)
                errs.append(eti.rmse(img, ref))
                derrs.append(eti.rmse(display(img), ref_display))
                flies.append(int(np.count_nonzero(outliers(img) & ~ref_outliers)))
                spps.append(spp)
            mse = float(np.mean(np.square(errs)))
            net = float(np.sqrt(max(mse - ref_var, 0.0)))
            drms = float(np.sqrt(np.mean(np.square(derrs))))
            rows.append((name, method, spps, errs, float(np.sqrt(mse)), net, ref_spp, drms, flies))
            print(f"noise-sources: {name} {method} spp {spps} rmse {errs}", file=sys.stderr, flush=True)
    out = []
    if rows:
        out.append(f"Each render: {args.width}x{args.height}, `--time {args.time:g} --time-clock cpu --threads {args.threads}`, "
                   f"seeds {args.seeds}. Reference: the path tracer, unguided, {args.ref_factor:g} x that budget, seed 1001. "
                   "Net: the squared error minus the reference's mean per-pixel variance (its --variance file; "
                   "under Sobol an overstatement, so net errors are if anything too small). Display: clamped to [0, 1], "
                   "gamma 1/2.2. Fireflies: pixels over 4x the median of their 5x5 neighbourhood (and 0.5 above it) "
                   "that are not such pixels in the reference (equal_time.py's outliers).\n\n")
        base = {r[0]: r for r in rows if r[1] == "path"}  # the ratios' denominators
        out.append("Reference spp: " + ", ".join(f"{n} {r[6] if r[6] > 0 else 'not recorded'}" for n, r in base.items()) + ".\n\n")
        out.append("| scene | method | spp per seed | RMSE per seed | RMSE (rms of seeds) | net of reference noise | "
                   "/ path (rms) | / path (net) | display RMSE (rms) | / path (display) | fireflies per seed |\n"
                   "|---|---|---|---|---|---|---|---|---|---|---|\n")
        for name, method, spps, errs, rms, net, ref_spp, drms, flies in rows:
            b = base.get(name)
            ratio = f"{rms / b[4]:.3f}" if b else ""
            ratio_net = f"{net / b[5]:.3f}" if b and b[5] > 0 else ""
            out.append(f"| {name} | {method} | {', '.join(map(str, spps))} | {', '.join(f'{e:.4g}' for e in errs)} | "
                       f"{rms:.4g} | {net:.4g} | {ratio} | {ratio_net} | {drms:.4g} | {f'{drms / b[7]:.3f}' if b else ''} | "
                       f"{', '.join(map(str, flies))} |\n")
    if args.z_old:
        out.append("\n" + bias_check(args, scenes, wanted))
    if args.forensics_spp > 0:
        out.append("\n" + forensics(args, scenes, wanted, methods))
    with open(args.out, "w") as f:
        f.write("Generated by `/usr/bin/python3 tools/noise-sources.py " + " ".join(sys.argv[1:]) + "`")
        f.write(f" ({time.time() - started:.0f} s wall).\n\n" + "".join(out))
    print(open(args.out).read())


if __name__ == "__main__":
    main()
