#!/usr/bin/python3
"""The denoiser's error against the samples it saves (issue 42): raw and NFOR-denoised renders of
Bitterli's scenes against a long reference render of our own, by relMSE and mean HDR-FLIP, over
spp and CPU time. Writes the chart (docs/denoising-chart.png), the data (docs/denoising-data.tsv),
one picture per scene (docs/denoising/NAME.png: raw 32 spp | NFOR 32 spp | raw 256 spp |
reference) and the table of docs/denoising.md between its markers.

Per scene (the Bitterli folder's scene-v4.pbrt at a quarter of its size, at the depth of its
Tungsten reference as docs/reference-scenes.md gives it):
  reference  REFS/NAME.exr and REFS/NAME-variance.exr (render --variance): rendered with --ref-spp
             (default 4096) and seed 1 when missing; give --refs to reuse them.
  raw        a plain render at each --spp (seed 2, the default Sobol sampler, no features), CPU time
             of the render (getrusage of the child): the best the renderer does without a denoiser.
  denoised   render --aovs at each --denoise-spp (seed 2; its sampler, sobol-halves, gives the
             independent half buffers NFOR's error estimate needs), then sweeptrace denoise: the
             CPU time of both.
relMSE = mean over pixels and channels of (x - ref)^2 / (ref^2 + 0.01) (Rousselle et al.'s, as the
NFOR paper uses it). The reference's own noise adds mean(var_ref / (ref^2 + 0.01)) to every
relMSE ("floor" in the data); the raw spp of equal relMSE is found from the raw points by
relMSE - floor = a / spp (unbiased noise), a fitted on the raw renders of at least 64 spp.

Usage:
  /usr/bin/python3 tools/denoise-chart.py [--binary build/sweeptrace] [--bitterli ../shared/bitterli]
      [--refs /work/denoise-refs] [--ref-spp 4096] [--work /tmp/denoise-chart] [--threads 2]
      [--spp 4,8,16,32,64,128,256] [--denoise-spp 4,8,16,32,64] [--scenes cornell-box,classroom]
      [--compare 32:256]     the table's and pictures' NFOR spp and raw spp (the issue's 32 and 256)
      [--scale N]            sizes divided by N (a quick check of the script: --scale 8 --ref-spp 16
                             --spp 4,8 --denoise-spp 4 --compare 4:8 --docs /tmp/docs-copy)
"""
import argparse
import os
import re
import resource
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from equal_time import read_pfm  # noqa: E402
from exr_channels import read_exr  # noqa: E402

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
# name, width, height, max depth (the Tungsten reference's: docs/reference-scenes.md, "Depth")
SCENES = [
    ("cornell-box", 256, 256, 64),
    ("classroom", 320, 180, 16),
    ("kitchen", 320, 180, 16),
    ("staircase2", 256, 256, 64),
    ("coffee", 200, 250, 16),
]
RELMSE_EPSILON = 0.01


def run(cmd, allowed=(0,)):
    """Runs cmd; returns (its CPU seconds, user + system of the child, and its stderr)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    res = subprocess.run(cmd, stderr=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if res.returncode not in allowed:
        raise SystemExit(f"denoise-chart: {' '.join(cmd)} exited {res.returncode}:\n{res.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, res.stderr + res.stdout


def colour(path):
    if path.endswith(".pfm"):
        return read_pfm(path)
    ch, _ = read_exr(path)
    return np.stack([ch["R"], ch["G"], ch["B"]], axis=-1).astype(np.float64)


def relmse(x, ref):
    return float(np.mean((x - ref) ** 2 / (ref ** 2 + RELMSE_EPSILON)))


def flip(binary, image, ref):
    _, out = run([binary, "diff", image, ref, "--flip-mode", "hdr"], allowed=(0, 1, 4))
    m = re.search(r"HDR-FLIP mean\s+([0-9.eE+-]+)", out)
    if not m:
        raise SystemExit(f"denoise-chart: no HDR-FLIP mean in diff's output:\n{out}")
    return float(m.group(1))


def scene_args(args, name, w, h, depth):
    return [os.path.join(args.bitterli, name, "scene-v4.pbrt"), "--width", str(w), "--height", str(h),
            "--max-depth", str(depth), "--threads", str(args.threads), "--quiet"]


def reference(args, name, w, h, depth):
    ref = os.path.join(args.refs, f"{name}.exr")
    var = os.path.join(args.refs, f"{name}-variance.exr")
    if not (os.path.exists(ref) and os.path.exists(var)):
        os.makedirs(args.refs, exist_ok=True)
        print(f"{name}: reference, {args.ref_spp} spp", flush=True)
        run([args.binary, "render"] + scene_args(args, name, w, h, depth) +
            ["--spp", str(args.ref_spp), "--seed", "1", "-o", ref, "--variance", var])
    return ref, colour(ref), colour(var)


def measure_scene(args, name, w, h, depth):
    ref_path, ref, ref_var = reference(args, name, w, h, depth)
    floor = float(np.mean(ref_var / (ref ** 2 + RELMSE_EPSILON)))
    work = os.path.join(args.work, name)
    os.makedirs(work, exist_ok=True)
    rows = []
    for spp in sorted(set(args.spp) | set(args.denoise_spp)):
        if spp in args.spp:
            raw = os.path.join(work, f"raw-{spp}.exr")
            t0 = time.time()
            cpu, _ = run([args.binary, "render"] + scene_args(args, name, w, h, depth) + ["--spp", str(spp), "--seed", "2", "-o", raw])
            rows.append(dict(scene=name, kind="raw", spp=spp, cpu=cpu, denoise_cpu=0.0, relmse=relmse(colour(raw), ref),
                             flip=flip(args.binary, raw, ref_path), floor=floor))
            print(f"{name}: raw {spp} spp, {cpu:.1f} CPU s ({time.time() - t0:.0f} s wall), relMSE {rows[-1]['relmse']:.5f}", flush=True)
        if spp in args.denoise_spp:
            features = os.path.join(work, f"features-{spp}.exr")
            cpu, _ = run([args.binary, "render"] + scene_args(args, name, w, h, depth) +
                         ["--spp", str(spp), "--seed", "2", "--aovs", "-o", features])
            den = os.path.join(work, f"nfor-{spp}.pfm")
            dcpu, _ = run([args.binary, "denoise", features, "-o", den, "--threads", str(args.threads), "--quiet"])
            rows.append(dict(scene=name, kind="nfor", spp=spp, cpu=cpu + dcpu, denoise_cpu=dcpu,
                             relmse=relmse(colour(den), ref), flip=flip(args.binary, den, ref_path), floor=floor))
            print(f"{name}: NFOR {spp} spp, {cpu:.1f} + {dcpu:.1f} CPU s, relMSE {rows[-1]['relmse']:.5f}", flush=True)
    return rows, ref


def equal_relmse_spp(rows, target):
    """The raw spp whose relMSE would equal `target`, from relMSE - floor = a / spp."""
    raw = [r for r in rows if r["kind"] == "raw" and r["spp"] >= 64] or [r for r in rows if r["kind"] == "raw"][-1:]
    if not raw:
        return float("nan")
    floor = raw[0]["floor"]
    a = float(np.median([(r["relmse"] - floor) * r["spp"] for r in raw]))  # one point per spp: their median
    return a / (target - floor) if target > floor else float("inf")


def display(img):
    return np.clip(img, 0.0, 1.0) ** (1 / 2.2)


def picture(args, name, ref, docs):
    nspp, rspp = args.compare
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    work = os.path.join(args.work, name)
    panels = [(f"raw {nspp} spp", colour(os.path.join(work, f"raw-{nspp}.exr"))),
              (f"NFOR {nspp} spp", colour(os.path.join(work, f"nfor-{nspp}.pfm"))),
              (f"raw {rspp} spp", colour(os.path.join(work, f"raw-{rspp}.exr"))), (f"reference {args.ref_spp} spp", ref)]
    scale = 1.0 / max(np.percentile(ref.max(axis=-1), 99), 1e-6)
    h, w = ref.shape[:2]
    fig, axes = plt.subplots(1, 4, figsize=(4 * w / 80, h / 80 + 0.35), dpi=100)
    for ax, (title, img) in zip(axes, panels):
        ax.imshow(display(img * scale), interpolation="nearest")
        ax.set_title(title, fontsize=8)
        ax.axis("off")
    fig.tight_layout(pad=0.2)
    os.makedirs(os.path.join(docs, "denoising"), exist_ok=True)
    fig.savefig(os.path.join(docs, "denoising", f"{name}.png"))
    plt.close(fig)


def chart(rows, docs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(len(names), 2, figsize=(10, 2.6 * len(names)), squeeze=False)
    for i, name in enumerate(names):
        for j, (metric, label) in enumerate((("relmse", "relMSE"), ("flip", "mean HDR-FLIP"))):
            ax = axes[i][j]
            for kind, style in (("raw", "o-"), ("nfor", "s-")):
                pts = [r for r in rows if r["scene"] == name and r["kind"] == kind]
                ax.plot([r["cpu"] for r in pts], [r[metric] for r in pts], style, label="raw" if kind == "raw" else "NFOR")
                for r in pts:
                    ax.annotate(str(r["spp"]), (r["cpu"], r[metric]), fontsize=6, xytext=(2, 2), textcoords="offset points")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("CPU s (render + denoise); labels: spp")
            ax.set_ylabel(label)
            ax.set_title(f"{name}: {label}", fontsize=9)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(docs, "denoising-chart.png"), dpi=90)
    plt.close(fig)


def table(rows, command, compare):
    nspp, rspp = compare
    lines = [f"Generated {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} by:", "```", command, "```",
             f"| scene | raw {nspp} spp relMSE / FLIP | NFOR {nspp} spp relMSE / FLIP | raw {rspp} spp relMSE / FLIP "
             f"| NFOR {nspp} <= raw {rspp} (relMSE, FLIP) | raw spp of NFOR {nspp}'s relMSE | reference floor "
             f"| CPU s: render {nspp} --aovs + denoise / render {rspp} |",
             "|---|---|---|---|---|---|---|---|"]
    for name in dict.fromkeys(r["scene"] for r in rows):
        get = {(r["kind"], r["spp"]): r for r in rows if r["scene"] == name}
        r32, n32, r256 = get.get(("raw", nspp)), get.get(("nfor", nspp)), get.get(("raw", rspp))
        if not (r32 and n32 and r256):
            continue
        eq = equal_relmse_spp([r for r in rows if r["scene"] == name], n32["relmse"])
        ok = f"{'yes' if n32['relmse'] <= r256['relmse'] else '**no**'}, {'yes' if n32['flip'] <= r256['flip'] else '**no**'}"
        lines.append(f"| {name} | {r32['relmse']:.5f} / {r32['flip']:.4f} | {n32['relmse']:.5f} / {n32['flip']:.4f} | "
                     f"{r256['relmse']:.5f} / {r256['flip']:.4f} | {ok} | {eq:.0f} | {n32['floor']:.5f} | "
                     f"{n32['cpu'] - n32['denoise_cpu']:.1f} + {n32['denoise_cpu']:.1f} / {r256['cpu']:.1f} |")
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--binary", default=os.path.join(REPO, "build", "sweeptrace"))
    p.add_argument("--bitterli", default=os.path.join(REPO, "..", "shared", "bitterli"))
    p.add_argument("--refs", default="/work/denoise-refs")
    p.add_argument("--ref-spp", type=int, default=4096)
    p.add_argument("--work", default="/tmp/denoise-chart")
    p.add_argument("--docs", default=os.path.join(REPO, "docs"))
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--spp", default="4,8,16,32,64,128,256")
    p.add_argument("--denoise-spp", default="4,8,16,32,64")
    p.add_argument("--scenes", default=",".join(s[0] for s in SCENES))
    p.add_argument("--compare", default="32:256")
    p.add_argument("--scale", type=int, default=1)
    args = p.parse_args()
    args.compare = tuple(int(v) for v in args.compare.split(":"))
    args.spp = [int(s) for s in args.spp.split(",")]
    args.denoise_spp = [int(s) for s in args.denoise_spp.split(",")]
    wanted = args.scenes.split(",")
    rows = []
    for name, w, h, depth in SCENES:
        if name not in wanted:
            continue
        scene_rows, ref = measure_scene(args, name, w // args.scale, h // args.scale, depth)
        rows += scene_rows
        if args.compare[0] in args.denoise_spp and args.compare[1] in args.spp:
            picture(args, name, ref, args.docs)
    keys = ["scene", "kind", "spp", "cpu", "denoise_cpu", "relmse", "flip", "floor"]
    with open(os.path.join(args.docs, "denoising-data.tsv"), "w") as f:
        f.write("\t".join(keys) + "\n")
        for r in rows:
            f.write("\t".join(f"{r[k]:.6g}" if isinstance(r[k], float) else str(r[k]) for k in keys) + "\n")
    chart(rows, args.docs)
    command = "/usr/bin/python3 tools/denoise-chart.py " + " ".join(sys.argv[1:])
    md = os.path.join(args.docs, "denoising.md")
    text = open(md).read()
    begin, end = "<!-- denoise-chart: begin (generated, do not edit) -->", "<!-- denoise-chart: end -->"
    i, j = text.index(begin) + len(begin), text.index(end)
    open(md, "w").write(text[:i] + "\n" + table(rows, command, args.compare) + "\n" + text[j:])
    print(table(rows, command, args.compare))


if __name__ == "__main__":
    main()
