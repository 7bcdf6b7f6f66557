#!/usr/bin/python3
"""NFOR's error on feature images already rendered, for comparing builds of the denoiser: each
--binary (LABEL=PATH) denoises WORK/NAME/features-SPP.exr, and the result's relMSE and mean HDR-FLIP
against REFS/NAME.exr are printed beside the raw render WORK/NAME/raw-RAW.exr's (the measures of
tools/denoise-chart.py, which renders the images this reads: its --work folder). Renders nothing;
prints, asserts nothing.

Usage: /usr/bin/python3 tools/denoise-quality.py --work DIR --refs /work/denoise-refs
           --binary before=/path/sweeptrace --binary after=build/sweeptrace
           [--scenes cornell-box,coffee,staircase2] [--spp 32] [--raw 256] [--threads 2]
"""
import argparse
import importlib.util
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("denoise_chart", os.path.join(HERE, "denoise-chart.py"))
chart = importlib.util.module_from_spec(spec)
spec.loader.exec_module(chart)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--work", required=True)
    p.add_argument("--refs", required=True)
    p.add_argument("--binary", action="append", required=True, help="LABEL=PATH, repeatable")
    p.add_argument("--scenes", default="cornell-box,coffee,staircase2")
    p.add_argument("--spp", type=int, default=32)
    p.add_argument("--raw", type=int, default=256)
    p.add_argument("--threads", type=int, default=2)
    args = p.parse_args()
    binaries = []
    for b in args.binary:
        label, sep, path = b.partition("=")
        if not sep:
            sys.exit(f"denoise-quality: --binary {b}: expected LABEL=PATH")
        binaries.append((label, path))
    flip_binary = binaries[-1][1]
    print(f"| scene | raw {args.raw} relMSE / FLIP | " + " | ".join(f"NFOR {args.spp} {label} relMSE / FLIP (CPU s)" for label, _ in binaries) + " |")
    print("|---|---|" + "---|" * len(binaries))
    for name in args.scenes.split(","):
        ref_path = os.path.join(args.refs, f"{name}.exr")
        ref = chart.colour(ref_path)
        raw = os.path.join(args.work, name, f"raw-{args.raw}.exr")
        cells = [f"{chart.relmse(chart.colour(raw), ref):.5f} / {chart.flip(flip_binary, raw, ref_path):.4f}"]
        for label, path in binaries:
            out = os.path.join(args.work, name, f"nfor-{args.spp}-{label}.pfm")
            cpu, _ = chart.run([path, "denoise", os.path.join(args.work, name, f"features-{args.spp}.exr"), "-o", out, "--threads",
                                str(args.threads), "--quiet"])
            cells.append(f"{chart.relmse(chart.colour(out), ref):.5f} / {chart.flip(flip_binary, out, ref_path):.4f} ({cpu:.1f})")
        print(f"| {name} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
