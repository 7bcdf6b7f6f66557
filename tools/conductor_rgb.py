#!/usr/bin/env python3
"""Reduce the named metals' spectral optical constants (eta, k) to the RGB eta/k table in
raytracer/scene/named_metals.cpp, and print the reduction's error. docs/conductors.md states
the method; run: python3 tools/conductor_rgb.py

Data: the spectra pbrt-v4 names metal-<X>-eta / metal-<X>-k (its src/pbrt/util/spectrum.cpp; for
Ag, Al, Au, Cu on a 0.05 eV grid from 4.15 to 1.40 eV), the same numbers a pbrt scene that names
them means, so a converted scene reflects what its author saw. CuZn (brass) is pbrt-v4's CuZn_eta /
CuZn_k, 61 pairs every 10 nm from 290 to 890 nm; the copy of pbrt-v4's source this work could read
(2020) predates them, so the numbers were read from a verbatim copy of the later tables
(Paul-Hi/Rayce, rayce/core/spectrum.inl, which cites pbrt-v4) and checked against two other
independent copies: the refractiveindex.info brass data (Querry 1987) at 450, 500, ..., 700 nm and
pbrt-v4's values at 450, 530 and 630 nm as another port transcribed them.

Method, per RGB channel c of linear sRGB:
  1. The channel's spectral weight w_c(lambda) = (M_sRGB . xyz_bar(lambda))_c, illuminant E,
     xyz_bar the CIE 1931 2-degree matching functions (Wyman, Sloan & Shirley 2013's multi-lobe
     Gaussian fit), 380..780 nm every nm; each channel normalised so that a flat reflectance 1
     gives 1 (white stays white).
  2. The channel's target reflectance curve T_c(theta) = sum w_c R(theta, eta(l), k(l)) / sum w_c,
     R the exact unpolarised conductor Fresnel reflectance, the data linearly interpolated (held
     at the ends).
  3. (eta_c, k_c) fitted to T_c: at normal incidence exactly (k_c from eta_c and T_c(0) in closed
     form), eta_c chosen to minimise the cosine-weighted squared error over theta in [0, 90).
raytracer/scene/pbrt/pbrt_conductor_fit.cpp repeats reduce_metal step for step (same grid, bracket and
constants) for a pbrt scene's own sampled eta/k: change the two together.
Printed: the table, then per metal and channel the largest |R_rgb(theta) - T_c(theta)| over theta
and the error of the cosine-weighted albedo (what a furnace would see).
"""
import math

LAMBDA = [298.757050, 302.400421, 306.133759, 309.960449, 313.884003, 317.908142, 322.036835,
          326.274139, 330.624481, 335.092377, 339.682678, 344.400482, 349.251221, 354.240509,
          359.374420, 364.659332, 370.102020, 375.709625, 381.489777, 387.450562, 393.600555,
          399.948975, 406.505493, 413.280579, 420.285339, 427.531647, 435.032196, 442.800629,
          450.851562, 459.200653, 467.864838, 476.862213, 486.212463, 495.936707, 506.057861,
          516.600769, 527.592224, 539.061646, 551.040771, 563.564453, 576.670593, 590.400818,
          604.800842, 619.920898, 635.816284, 652.548279, 670.184753, 688.800964, 708.481018,
          729.318665, 751.419250, 774.901123, 799.897949, 826.561157, 855.063293, 885.601257]

METALS = {
    "Ag": (LAMBDA,
           [1.519, 1.496, 1.4325, 1.323, 1.142062, 0.932, 0.719062, 0.526, 0.388125, 0.294, 0.253313,
            0.238, 0.221438, 0.209, 0.194813, 0.186, 0.192063, 0.2, 0.198063, 0.192, 0.182, 0.173,
            0.172625, 0.173, 0.166688, 0.16, 0.1585, 0.157, 0.151063, 0.144, 0.137313, 0.132, 0.13025,
            0.13, 0.129938, 0.13, 0.130063, 0.129, 0.124375, 0.12, 0.119313, 0.121, 0.1255, 0.131,
            0.136125, 0.14, 0.140063, 0.14, 0.144313, 0.148, 0.145875, 0.143, 0.142563, 0.145,
            0.151938, 0.163],
           [1.08, 0.882, 0.761063, 0.647, 0.550875, 0.504, 0.554375, 0.663, 0.818563, 0.986, 1.120687,
            1.24, 1.34525, 1.44, 1.53375, 1.61, 1.641875, 1.67, 1.735, 1.81, 1.87875, 1.95, 2.029375,
            2.11, 2.18625, 2.26, 2.329375, 2.4, 2.47875, 2.56, 2.64, 2.72, 2.798125, 2.88, 2.97375,
            3.07, 3.159375, 3.25, 3.348125, 3.45, 3.55375, 3.66, 3.76625, 3.88, 4.010625, 4.15,
            4.293125, 4.44, 4.58625, 4.74, 4.908125, 5.09, 5.28875, 5.5, 5.720624, 5.95]),
    "Al": (LAMBDA,
           [0.273375, 0.28, 0.286813, 0.294, 0.301875, 0.31, 0.317875, 0.326, 0.33475, 0.344,
            0.353813, 0.364, 0.374375, 0.385, 0.39575, 0.407, 0.419125, 0.432, 0.445688, 0.46,
            0.474688, 0.49, 0.506188, 0.523, 0.540063, 0.558, 0.577313, 0.598, 0.620313, 0.644,
            0.668625, 0.695, 0.72375, 0.755, 0.789, 0.826, 0.867, 0.912, 0.963, 1.02, 1.08, 1.15,
            1.22, 1.3, 1.39, 1.49, 1.6, 1.74, 1.91, 2.14, 2.41, 2.63, 2.8, 2.74, 2.58, 2.24],
           [3.59375, 3.64, 3.689375, 3.74, 3.789375, 3.84, 3.894375, 3.95, 4.005, 4.06, 4.11375,
            4.17, 4.23375, 4.3, 4.365, 4.43, 4.49375, 4.56, 4.63375, 4.71, 4.784375, 4.86, 4.938125,
            5.02, 5.10875, 5.2, 5.29, 5.38, 5.48, 5.58, 5.69, 5.8, 5.915, 6.03, 6.15, 6.28, 6.42,
            6.55, 6.7, 6.85, 7.0, 7.15, 7.31, 7.48, 7.65, 7.82, 8.01, 8.21, 8.39, 8.57, 8.62, 8.6,
            8.45, 8.31, 8.21, 8.21]),
    "Au": (LAMBDA,
           [1.795, 1.812, 1.822625, 1.83, 1.837125, 1.84, 1.83425, 1.824, 1.812, 1.798, 1.782, 1.766,
            1.7525, 1.74, 1.727625, 1.716, 1.705875, 1.696, 1.68475, 1.674, 1.666, 1.658, 1.64725,
            1.636, 1.628, 1.616, 1.59625, 1.562, 1.502125, 1.426, 1.345875, 1.242, 1.08675, 0.916,
            0.7545, 0.608, 0.49175, 0.402, 0.3455, 0.306, 0.267625, 0.236, 0.212375, 0.194, 0.17775,
            0.166, 0.161, 0.16, 0.160875, 0.164, 0.1695, 0.176, 0.181375, 0.188, 0.198125, 0.21],
           [1.920375, 1.92, 1.918875, 1.916, 1.911375, 1.904, 1.891375, 1.878, 1.86825, 1.86,
            1.85175, 1.846, 1.84525, 1.848, 1.852375, 1.862, 1.883, 1.906, 1.9225, 1.936, 1.94775,
            1.956, 1.959375, 1.958, 1.951375, 1.94, 1.9245, 1.904, 1.875875, 1.846, 1.814625, 1.796,
            1.797375, 1.84, 1.9565, 2.12, 2.32625, 2.54, 2.730625, 2.88, 2.940625, 2.97, 3.015, 3.06,
            3.07, 3.15, 3.445812, 3.8, 4.087687, 4.357, 4.610188, 4.86, 5.125813, 5.39, 5.63125,
            5.88]),
    "Cu": (LAMBDA,
           [1.400313, 1.38, 1.358438, 1.34, 1.329063, 1.325, 1.3325, 1.34, 1.334375, 1.325, 1.317812,
            1.31, 1.300313, 1.29, 1.281563, 1.27, 1.249062, 1.225, 1.2, 1.18, 1.174375, 1.175, 1.1775,
            1.18, 1.178125, 1.175, 1.172812, 1.17, 1.165312, 1.16, 1.155312, 1.15, 1.142812, 1.135,
            1.131562, 1.12, 1.092437, 1.04, 0.950375, 0.826, 0.645875, 0.468, 0.35125, 0.272,
            0.230813, 0.214, 0.20925, 0.213, 0.21625, 0.223, 0.2365, 0.25, 0.254188, 0.26, 0.28, 0.3],
           [1.662125, 1.687, 1.703313, 1.72, 1.744563, 1.77, 1.791625, 1.81, 1.822125, 1.834,
            1.85175, 1.872, 1.89425, 1.916, 1.931688, 1.95, 1.972438, 2.015, 2.121562, 2.21, 2.177188,
            2.13, 2.160063, 2.21, 2.249938, 2.289, 2.326, 2.362, 2.397625, 2.433, 2.469187, 2.504,
            2.535875, 2.564, 2.589625, 2.605, 2.595562, 2.583, 2.5765, 2.599, 2.678062, 2.809,
            3.01075, 3.24, 3.458187, 3.67, 3.863125, 4.05, 4.239563, 4.43, 4.619563, 4.817, 5.034125,
            5.26, 5.485625, 5.717]),
    "CuZn": (list(range(290, 891, 10)),
             [1.358, 1.388, 1.419, 1.446, 1.473, 1.494, 1.504, 1.503, 1.497, 1.487, 1.471, 1.445, 1.405,
              1.350, 1.278, 1.191, 1.094, 0.994, 0.900, 0.816, 0.745, 0.686, 0.639, 0.602, 0.573,
              0.549, 0.527, 0.505, 0.484, 0.468, 0.460, 0.450, 0.452, 0.449, 0.445, 0.444, 0.444,
              0.445, 0.444, 0.444, 0.445, 0.446, 0.448, 0.450, 0.452, 0.455, 0.457, 0.458, 0.460,
              0.464, 0.469, 0.473, 0.478, 0.481, 0.483, 0.486, 0.490, 0.494, 0.500, 0.507, 0.515],
             [1.688, 1.731, 1.764, 1.789, 1.807, 1.815, 1.815, 1.815, 1.818, 1.818, 1.813, 1.805, 1.794,
              1.786, 1.784, 1.797, 1.829, 1.883, 1.957, 2.046, 2.145, 2.250, 2.358, 2.464, 2.568,
              2.668, 2.765, 2.860, 2.958, 3.059, 3.159, 3.253, 3.345, 3.434, 3.522, 3.609, 3.695,
              3.778, 3.860, 3.943, 4.025, 4.106, 4.186, 4.266, 4.346, 4.424, 4.501, 4.579, 4.657,
              4.737, 4.814, 4.890, 4.965, 5.039, 5.115, 5.192, 5.269, 5.346, 5.423, 5.500, 5.575]),
    "MgO": ([309.950012, 330.613007, 351.118988, 355.549011, 360.932007, 361.141998, 364.968994,
             382.065002, 386.712006, 393.337982, 404.634003, 430.935028, 435.781982, 457.829010,
             477.949036, 486.004974, 487.918030, 499.919006, 502.350006, 508.531982, 514.440002,
             546.166992, 589.258972, 632.874023, 643.718018, 656.325989, 667.635986, 690.695984,
             706.439026, 767.677979],
            [1.798, 1.785, 1.7768, 1.7755, 1.7732, 1.77318, 1.77186, 1.7668, 1.7655, 1.7638, 1.76104,
             1.7557, 1.75471, 1.7512, 1.7483, 1.74711, 1.7469, 1.7454, 1.7453, 1.74446, 1.7439,
             1.74077, 1.73737, 1.7346, 1.734, 1.73335, 1.73277, 1.73191, 1.73101, 1.72872],
            [0.0, 0.0, 0.0, 1e-6, 1e-6, 1e-6, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
             0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
    "TiO2": ([305.972015, 317.979004, 334.990997, 344.007019, 359.988007, 388.044006, 399.935028,
              412.031006, 419.985992, 439.957001, 460.037018, 479.985016, 499.919006, 520.049988,
              539.044006, 539.983032, 559.981995, 579.888000, 600.097046, 619.900024, 640.062012,
              659.819031, 680.088013, 700.056030, 719.976990, 740.179016, 760.147034, 779.747986,
              799.871033, 819.974060, 839.973083, 859.778015, 879.915039, 899.709961],
             [3.84, 5.38, 4.22, 4.36, 3.87, 3.49, 3.4, 3.24, 3.29, 3.2, 3.13, 3.08, 3.03, 3.0, 2.95,
              2.97, 2.94, 2.92, 2.9, 2.88, 2.87, 2.85, 2.84, 2.83, 2.82, 2.81, 2.81, 2.8, 2.79, 2.79,
              2.78, 2.78, 2.77, 2.77],
             [1.95, 2.18, 0.788, 0.0, 0.251, 0.0, 0.0, 0.022, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
              0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
              0.0]),
}


def lobe(x, mu, s1, s2):
    t = (x - mu) / (s1 if x < mu else s2)
    return math.exp(-0.5 * t * t)


def xyz_bar(l):  # Wyman, Sloan & Shirley 2013, multi-lobe fit of CIE 1931 2-degree
    x = 1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) - 0.065 * lobe(l, 501.1, 20.4, 26.2)
    y = 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1)
    z = 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8)
    return x, y, z


M = [[3.2404542, -1.5371385, -0.4985314], [-0.9692660, 1.8760108, 0.0415560], [0.0556434, -0.2040259, 1.0572252]]
WAVES = list(range(380, 781))
WEIGHTS = []
for c in range(3):
    w = [sum(M[c][j] * xyz_bar(l)[j] for j in range(3)) for l in WAVES]
    total = sum(w)
    WEIGHTS.append([v / total for v in w])


def interp(xs, ys, x):
    if x <= xs[0]:
        return ys[0]
    if x >= xs[-1]:
        return ys[-1]
    i = max(j for j in range(len(xs) - 1) if xs[j] <= x)
    t = (x - xs[i]) / (xs[i + 1] - xs[i])
    return ys[i] + t * (ys[i + 1] - ys[i])


def fresnel(cos_i, eta, k):  # textbook complex form, independent of the renderer's real closed form
    n = complex(eta, k)
    s2 = 1.0 - cos_i * cos_i
    cos_t_n = (n * n - s2) ** 0.5  # n cos(theta_t)
    rs = (cos_i - cos_t_n) / (cos_i + cos_t_n)
    rp = (n * n * cos_i - cos_t_n) / (n * n * cos_i + cos_t_n)
    return 0.5 * (abs(rs) ** 2 + abs(rp) ** 2)


THETAS = [math.radians(d + 0.5) for d in range(90)]  # midpoints; cosine weight cos sin


def reduce_metal(lam, eta, k):
    etas = [interp(lam, eta, l) for l in WAVES]
    ks = [interp(lam, k, l) for l in WAVES]
    out = []
    for c in range(3):
        w = WEIGHTS[c]
        target = [sum(wi * fresnel(math.cos(t), e, kk) for wi, e, kk in zip(w, etas, ks)) for t in THETAS]
        r0 = sum(wi * fresnel(1.0, e, kk) for wi, e, kk in zip(w, etas, ks))

        def k_for(e):
            k2 = (r0 * (e + 1) ** 2 - (e - 1) ** 2) / (1 - r0)
            return math.sqrt(k2) if k2 >= 0 else None

        def cost(e):
            kk = k_for(e)
            if kk is None:
                return float("inf")
            return sum(math.cos(t) * math.sin(t) * (fresnel(math.cos(t), e, kk) - tv) ** 2 for t, tv in zip(THETAS, target))

        grid = [0.01 * 1.01 ** i for i in range(700)]
        best = min(grid, key=cost)
        lo, hi = best / 1.01, best * 1.01
        for _ in range(60):  # golden section on the bracket
            a = hi - (hi - lo) * 0.618034
            b = lo + (hi - lo) * 0.618034
            if cost(a) < cost(b):
                hi = b
            else:
                lo = a
        e = 0.5 * (lo + hi)
        kk = k_for(e)
        if kk is None:  # a dielectric's channel: k = 0 and eta from R(0) alone
            s = math.sqrt(r0)
            e, kk = (1 + s) / (1 - s), 0.0
        fit = [fresnel(math.cos(t), e, kk) for t in THETAS]
        max_err, worst_theta = max((abs(f - tv), math.degrees(t)) for f, tv, t in zip(fit, target, THETAS))
        wsum = sum(2 * math.cos(t) * math.sin(t) * math.radians(1) for t in THETAS)
        alb_err = sum(2 * math.cos(t) * math.sin(t) * math.radians(1) * (f - tv) for t, f, tv in zip(THETAS, fit, target)) / wsum
        out.append((e, kk, r0, max_err, alb_err, worst_theta))
    return out


def main():
    print("// name: eta (r, g, b), k (r, g, b)    [normal-incidence RGB reflectance]")
    report = []
    for name, (lam, eta, k) in METALS.items():
        assert len(lam) == len(eta) == len(k), name
        r = reduce_metal(lam, eta, k)
        print('{"%s", {%.4f, %.4f, %.4f}, {%.4f, %.4f, %.4f}},  // R0 %.4f %.4f %.4f' %
              (name, r[0][0], r[1][0], r[2][0], r[0][1], r[1][1], r[2][1], r[0][2], r[1][2], r[2][2]))
        report.append((name, r))
    print("\nmetal  channel  max |R_rgb - R_spectral| over theta (at theta)   cosine-weighted albedo error")
    for name, r in report:
        for c, ch in enumerate("rgb"):
            print("%-5s  %s        %.5f (%4.1f deg)                             %+.5f" % (name, ch, r[c][3], r[c][5], r[c][4]))


if __name__ == "__main__":
    main()
