#!/usr/bin/python3
"""Where a denoised image's mean HDR-FLIP stands against the raw render's (issue 42's FLIP line):
the denoise chart's images (tools/denoise-chart.py --work DIR) scored on three regions of each
scene, so that "NFOR 32 spp is worse than raw 256 spp in FLIP" can be read as blur at edges, or as
residual noise on flat surfaces. A study, not a test: it prints, asserts nothing.

Regions, from the reference (REFS/NAME.exr) and the NFOR input's features (DIR/NAME/features-32.exr):
  flat                     the 80 % of pixels whose reference luminance changes least
                           (largest central difference over x and y, relative to luminance + 0.05);
  edge, features explain   the other 20 % where albedo, shading normal or relative depth also
                           change (any albedo/normal component by > 0.1, depth by > 2 %);
  edge, features do not    the rest: shadow edges, reflections, caustics, detail behind glass.
A region's FLIP is that of the reference with the region's pixels replaced by the image's, scaled
by 1 / the region's share of pixels: FLIP filters across pixels, so a region's border leaks into
its neighbours' score, and the three do not sum exactly to the whole image's.

Usage: /usr/bin/python3 tools/denoise-flip-regions.py --work /tmp/denoise-chart --refs /work/denoise-refs
           [--binary build/sweeptrace] [--scenes cornell-box,coffee] [--images nfor-32.pfm,raw-256.exr,...]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exr_channels import read_exr  # noqa: E402
from pfm import read_pfm, write_pfm  # noqa: E402

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def load(path):
    if path.endswith(".pfm"):
        return read_pfm(path)
    ch, _ = read_exr(path)
    return np.stack([ch[c] for c in "RGB"], axis=-1)


def change(img):
    """Largest absolute central difference over x and y (0 on the border)."""
    gx, gy = np.zeros_like(img), np.zeros_like(img)
    gx[:, 1:-1] = np.abs(img[:, 2:] - img[:, :-2])
    gy[1:-1] = np.abs(img[2:] - img[:-2])
    return np.maximum(gx, gy)


def hdr_flip(binary, image, ref):
    out = subprocess.run([binary, "diff", image, ref, "--flip-mode", "hdr"], capture_output=True, text=True).stdout
    m = re.search(r"HDR-FLIP mean\s+([0-9.e+-]+)", out)
    if not m:
        sys.exit(f"denoise-flip-regions: no HDR-FLIP mean in the output of diff {image} {ref}:\n{out}")
    return float(m.group(1))


def regions(ref, features):
    lum = ref.mean(axis=-1)
    light = change(lum) / (lum + 0.05)
    edge = light > np.quantile(light, 0.8)
    feat = np.zeros_like(lum)
    for c in ("Albedo.R", "Albedo.G", "Albedo.B", "Ns.X", "Ns.Y", "Ns.Z"):
        feat = np.maximum(feat, change(features[c]))
    depth = features["P.Z"]
    explained = (feat > 0.1) | (change(depth) / (np.abs(depth) + 1e-3) > 0.02)
    return [("flat", ~edge), ("edge, features explain", edge & explained), ("edge, features do not", edge & ~explained)]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=os.path.join(REPO, "build", "sweeptrace"))
    ap.add_argument("--work", required=True, help="tools/denoise-chart.py's --work directory")
    ap.add_argument("--refs", required=True, help="the chart's references (NAME.exr)")
    ap.add_argument("--scenes", default="cornell-box,kitchen,staircase2,coffee,classroom")
    ap.add_argument("--images", default="raw-32.exr,raw-128.exr,raw-256.exr,nfor-16.pfm,nfor-32.pfm,nfor-64.pfm")
    args = ap.parse_args()
    print("| scene | image | whole image | " + " | ".join(n for n, _ in regions(np.ones((3, 3, 3)), {
        c: np.zeros((3, 3)) for c in ("Albedo.R", "Albedo.G", "Albedo.B", "Ns.X", "Ns.Y", "Ns.Z", "P.Z")})) + " |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        ref_pfm, mixed = os.path.join(tmp, "ref.pfm"), os.path.join(tmp, "mixed.pfm")
        for name in args.scenes.split(","):
            ref_path = os.path.join(args.refs, f"{name}.exr")
            feat_path = os.path.join(args.work, name, "features-32.exr")
            if not (os.path.exists(ref_path) and os.path.exists(feat_path)):
                print(f"| {name} | (no reference or no chart images: skipped) | | | | |")
                continue
            ref = load(ref_path)
            write_pfm(ref_pfm, ref)
            masks = regions(ref, read_exr(feat_path)[0])
            shares = ", ".join(f"{n} {m.mean():.2f}" for n, m in masks)
            for image in args.images.split(","):
                img = load(os.path.join(args.work, name, image))
                write_pfm(mixed, img)
                cells = [f"{hdr_flip(args.binary, mixed, ref_pfm):.4f}"]
                for _, mask in masks:
                    x = ref.copy()
                    x[mask] = img[mask]
                    write_pfm(mixed, x)
                    cells.append(f"{hdr_flip(args.binary, mixed, ref_pfm) / mask.mean():.4f}")
                print(f"| {name} ({shares}) | {image} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
