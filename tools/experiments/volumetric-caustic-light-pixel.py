#!/usr/bin/python3
"""The directly seen light of ../shared/bitterli/volumetric-caustic in closed form (docs/media.md,
"volumetric-caustic by bdpt"): the 5 mm x 4 mm quad at y = 1.98 facing down, seen from the camera
at (0, 1, 7) (the file's transform, fov 19.5, square film) through the gas (sigma_t 1, entered at
the front wall z = 1). Prints the light's radiance summed over the pixels it covers at a film of
--size pixels (box filter: a pixel is the mean over its own footprint), with and without the
gas, and the pixel it lies in. Monte Carlo over the quad's area only (the integrand is smooth).
Usage: /usr/bin/python3 tools/experiments/volumetric-caustic-light-pixel.py [--size 128]"""
import argparse

import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument("--size", type=int, default=128)
a = ap.parse_args()
rng = np.random.default_rng(1)
n = 400000
p = np.stack([rng.uniform(-0.0075, -0.0025, n), np.full(n, 1.98), rng.uniform(-0.032, -0.028, n)], 1)
cam = np.array([0.0, 1.0, 7.0])
d = p - cam
dist = np.linalg.norm(d, axis=1)
w = d / dist[:, None]
cos_light = np.abs(w[:, 1])
gas = dist - (1.0 - cam[2]) / w[:, 2]  # the stretch from the front wall to the light
half = np.tan(np.radians(19.5 / 2.0))
# A pixel's solid angle in direction w: its area on the image plane at distance 1 times cos^3.
omega_pixel = (2.0 * half / a.size) ** 2 * (-w[:, 2]) ** 3
area = 0.005 * 0.004
L = np.array([541126.75, 381971.8, 127323.94])
with_gas = L * area * np.mean(np.exp(-gas) * cos_light / dist**2 / omega_pixel)
without = L * area * np.mean(cos_light / dist**2 / omega_pixel)
row = (1.0 - np.mean(w[:, 1] / -w[:, 2]) / half) / 2.0 * a.size
col = (1.0 + np.mean(w[:, 0] / -w[:, 2]) / half) / 2.0 * a.size
print(f"{a.size}x{a.size}: the light in pixel row {row:.2f}, column {col:.2f}; mean transmittance {np.mean(np.exp(-gas)):.4f}")
print("summed over pixels, with the gas:    %.1f %.1f %.1f" % tuple(with_gas))
print("summed over pixels, without the gas: %.1f %.1f %.1f" % tuple(without))
