#!/usr/bin/python3
"""The mean of independent renders and the variance of that mean, per pixel, from their spread
(for a reference renderer that writes no variance of its own: pbrt-v4 run with several seeds);
or, with --compare, two images' channel means and their ratio.
Usage: mean_of_runs.py MEAN.pfm VARIANCE.pfm RUN RUN [RUN ...]
       mean_of_runs.py --compare A B
Inputs are colour .pfm or .exr files (pbrt-v4 writes .exr); outputs are .pfm.
"""
import sys

import numpy as np

from exr_channels import read_exr
from pfm import read_pfm, write_pfm


def read_image(path):
    if not path.endswith(".exr"):
        return read_pfm(path)
    channels, _ = read_exr(path)
    return np.stack([channels[c] for c in "RGB"], axis=-1).astype(np.float64)


def main(argv):
    if len(argv) == 3 and argv[0] == "--compare":
        a, b = read_image(argv[1]).mean(axis=(0, 1)), read_image(argv[2]).mean(axis=(0, 1))
        print("channel means R/G/B: %s against %s, ratio %s" % (
            " / ".join("%.5f" % v for v in a), " / ".join("%.5f" % v for v in b),
            " / ".join("%.4f" % v for v in a / b)))
        return
    if len(argv) < 4:
        raise SystemExit(__doc__)
    runs = np.stack([read_image(p) for p in argv[2:]])
    n = len(runs)
    write_pfm(argv[0], runs.mean(axis=0))
    # The unbiased sample variance of one run, over n: the variance of the runs' mean.
    write_pfm(argv[1], runs.var(axis=0, ddof=1) / n)
    print(f"mean of {n} runs written to {argv[0]}, the variance of that mean to {argv[1]}")


if __name__ == "__main__":
    main(sys.argv[1:])
