#!/usr/bin/python3
"""Writes the files scenes/showcase.json uses, all made by the project (standard library only):

  scenes/meshes/vase.obj               a glazed vase: a closed surface of revolution with vt and vn
  scenes/textures/vase_glaze.png       its albedo: glaze bands and a zigzag, 128 x 128 sRGB
  scenes/environments/showcase_sky.hdr a sky with a sun: 128 x 64 equirectangular Radiance RGBE

Run from anywhere: python3 tools/make_showcase_assets.py (rerunning writes the same bytes).

The vase is a profile curve (radius against height) turned about +Y: the outer wall, a round
lip and the inner wall as one smooth piece (vertex normals of the turned curve), the outer and
the inner bottom as flat discs with their own normals, so the bottom edge stays sharp. Every
triangle winds counter-clockwise seen from outside the clay; the script checks that the mesh is
closed (every edge shared by two triangles, the seam's duplicated vertices counted as one).
u runs once around (0 to 1, the seam's vertices duplicated), v along the profile from the centre
of the outer bottom (0) over the lip to the centre of the inner bottom (1).

The sky follows the loader's equirectangular convention (scenes/README.md, Environment): row 0
straight up (+Y), the centre column toward -Z, the right half toward +X. Radiance: a zenith blue
to a pale horizon, a little brighter toward the sun, a grey ground below the horizon, and a
sun disc of angular radius 8 degrees and radiance ~60 (its irradiance, about 3.6 at normal
incidence, is comparable to the sky's ~2.8 on a horizontal surface: soft-edged shadows, and
caustics through the glass that converge at the golden's sample counts).
"""
import math
import os
import struct
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "scenes")

# --- the vase ------------------------------------------------------------------------------
HEIGHT, THICK = 1.5, 0.05
SEGMENTS = 40      # around
WALL_STEPS = 20    # along each wall
LIP_STEPS = 5
DISC_STEPS = 4
CONTROL = [(0.0, 0.30), (0.25, 0.45), (0.55, 0.56), (0.85, 0.48), (1.1, 0.30), (1.3, 0.23), (1.5, 0.31)]


def outer_radius(y):
    """Catmull-Rom through CONTROL (height, radius), uniform in the control index."""
    ys = [c[0] for c in CONTROL]
    i = max(0, min(len(CONTROL) - 2, max(k for k in range(len(ys)) if ys[k] <= y)))
    t = (y - ys[i]) / (ys[i + 1] - ys[i])
    p = [CONTROL[max(0, min(len(CONTROL) - 1, j))][1] for j in (i - 1, i, i + 1, i + 2)]
    return 0.5 * (2 * p[1] + (-p[0] + p[2]) * t + (2 * p[0] - 5 * p[1] + 4 * p[2] - p[3]) * t * t
                  + (-p[0] + 3 * p[1] - 3 * p[2] + p[3]) * t ** 3)


def wall_piece():
    """Outer wall up, the lip, inner wall down: (r, y) points of one smooth curve."""
    pts = [(outer_radius(HEIGHT * k / WALL_STEPS), HEIGHT * k / WALL_STEPS) for k in range(WALL_STEPS + 1)]
    r_top = outer_radius(HEIGHT)
    cx = r_top - THICK / 2
    for k in range(1, LIP_STEPS):
        a = math.pi * k / LIP_STEPS
        pts.append((cx + THICK / 2 * math.cos(a), HEIGHT + THICK / 2 * math.sin(a)))
    inner = []
    for k in range(WALL_STEPS + 1):
        y = HEIGHT - (HEIGHT - THICK) * k / WALL_STEPS
        inner.append((outer_radius(y) - THICK, y))
    return pts + inner


def disc_piece(r_edge, y, outward):
    """A flat disc from the axis to r_edge (outward: -1 faces down, +1 faces up)."""
    pts = [(r_edge * k / DISC_STEPS, y) for k in range(DISC_STEPS + 1)]
    return pts if outward < 0 else list(reversed(pts))


def profile_normals(pts):
    """Per point, the mean of the adjacent segments' outward normals (dy, -dr)."""
    seg = []
    for (r0, y0), (r1, y1) in zip(pts, pts[1:]):
        n = (y1 - y0, -(r1 - r0))
        l = math.hypot(*n)
        seg.append((n[0] / l, n[1] / l))
    out = []
    for i in range(len(pts)):
        a = seg[max(0, i - 1)]
        b = seg[min(len(seg) - 1, i)]
        n = (a[0] + b[0], a[1] + b[1])
        l = math.hypot(*n)
        out.append((n[0] / l, n[1] / l))
    return out


def make_vase():
    bottom = disc_piece(outer_radius(0.0), 0.0, -1)
    wall = wall_piece()
    inner_bottom = disc_piece(outer_radius(THICK) - THICK, THICK, +1)
    pieces = [bottom, wall, inner_bottom]
    lengths = []
    for p in pieces:
        lengths.append([0.0])
        for (r0, y0), (r1, y1) in zip(p, p[1:]):
            lengths[-1].append(lengths[-1][-1] + math.hypot(r1 - r0, y1 - y0))
    total = sum(l[-1] for l in lengths)
    verts, uvs, normals, faces = [], [], [], []
    v_start = 0.0
    for p, lens in zip(pieces, lengths):
        ns = profile_normals(p)
        base = len(verts)
        for (r, y), (nr, ny), s in zip(p, ns, lens):
            for j in range(SEGMENTS + 1):
                phi = 2 * math.pi * j / SEGMENTS
                c, sn = math.cos(phi), math.sin(phi)
                verts.append((r * c, y, -r * sn))  # u grows counter-clockwise seen from above
                normals.append((nr * c, ny, -nr * sn))
                uvs.append((j / SEGMENTS, (v_start + s) / total))
        for i in range(len(p) - 1):
            for j in range(SEGMENTS):
                a = base + i * (SEGMENTS + 1) + j
                b, c2, d = a + 1, a + SEGMENTS + 1, a + SEGMENTS + 2
                if p[i][0] > 0:
                    faces.append((a, b, d))
                if p[i + 1][0] > 0:
                    faces.append((a, d, c2))
        v_start += lens[-1]
    return verts, uvs, normals, faces


def check_vase(verts, normals, faces):
    key = lambda i: tuple(round(x, 6) for x in verts[i])
    edges = {}
    for f in faces:
        for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            edges[(key(a), key(b))] = edges.get((key(a), key(b)), 0) + 1
    for (a, b), n in edges.items():
        if n != 1 or edges.get((b, a), 0) != 1:
            sys.exit("make_showcase_assets: the vase is not closed and consistently wound at %s-%s" % (a, b))
    for f in faces:
        p = [verts[i] for i in f]
        e1 = [p[1][k] - p[0][k] for k in range(3)]
        e2 = [p[2][k] - p[0][k] for k in range(3)]
        n = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
        m = [sum(normals[i][k] for i in f) for k in range(3)]
        if sum(n[k] * m[k] for k in range(3)) <= 0:
            sys.exit("make_showcase_assets: a triangle winds against its vertex normals")


def write_obj(path, verts, uvs, normals, faces):
    lines = ["# vase.obj: made by tools/make_showcase_assets.py (a closed surface of revolution)",
             "# %d vertices, %d triangles; vt (u around, v along the profile) and vn" % (len(verts), len(faces))]
    lines += ["v %.4f %.4f %.4f" % v for v in verts]
    lines += ["vt %.4f %.4f" % t for t in uvs]
    lines += ["vn %.3f %.3f %.3f" % n for n in normals]
    lines += ["f %d/%d/%d %d/%d/%d %d/%d/%d" % (a + 1, a + 1, a + 1, b + 1, b + 1, b + 1, c + 1, c + 1, c + 1)
              for a, b, c in faces]
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


# --- the glaze texture ---------------------------------------------------------------------
def glaze(u, v):
    """Linear albedo at (u, v): v = 0 is the outer bottom's centre, ~0.1 the foot, ~0.5 the lip."""
    cream, teal, rust, dark = (0.80, 0.74, 0.62), (0.08, 0.36, 0.40), (0.55, 0.20, 0.08), (0.10, 0.08, 0.07)
    zig = 0.012 * abs(((u * 12) % 1.0) * 2 - 1)  # a zigzag, 12 teeth around
    if v < 0.10 or v > 0.53:
        return dark                                 # unglazed foot, and the inside
    if 0.17 + zig < v < 0.21 + zig:
        return teal
    if 0.28 < v < 0.30 or 0.34 < v < 0.36:
        return rust
    if 0.41 - zig < v < 0.47 - zig:
        return teal
    return cream


def srgb_byte(x):
    x = max(0.0, min(1.0, x))
    s = 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
    return int(round(255 * s))


def write_png(path, width, height, pixel):
    raw = bytearray()
    for row in range(height):
        raw.append(0)
        v = 1.0 - (row + 0.5) / height  # the top row is v = 1
        for col in range(width):
            raw += bytes(srgb_byte(c) for c in pixel((col + 0.5) / width, v))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


# --- the sky -------------------------------------------------------------------------------
SUN = (-0.52, 0.57, 0.64)          # toward the sun: up and behind-left of the camera (+Z)
SUN_RADIUS = math.radians(8.0)
SUN_RADIANCE = (60.0, 57.0, 51.0)


def sky(d):
    l = math.sqrt(sum(x * x for x in SUN))
    s = [x / l for x in SUN]
    cos_sun = sum(d[k] * s[k] for k in range(3))
    if cos_sun > math.cos(SUN_RADIUS):
        return SUN_RADIANCE
    if d[1] < 0:
        return (0.35, 0.34, 0.32)  # the ground under the horizon, grey like the tiles
    t = d[1] ** 0.5
    zenith, horizon = (0.22, 0.38, 0.8), (0.9, 0.88, 0.82)
    glow = 0.6 * max(0.0, cos_sun) ** 8
    return tuple(horizon[k] * (1 - t) + zenith[k] * t + glow for k in range(3))


def rgbe(c):
    m = max(c)
    if m < 1e-32:
        return bytes(4)
    e = math.frexp(m)[1]
    scale = 256.0 / 2.0 ** e
    return bytes([int(c[0] * scale), int(c[1] * scale), int(c[2] * scale), e + 128])


def write_hdr(path, width, height):
    out = bytearray(b"#?RADIANCE\n# showcase_sky.hdr: made by tools/make_showcase_assets.py\n"
                    b"FORMAT=32-bit_rle_rgbe\n\n" + b"-Y %d +X %d\n" % (height, width))
    for row in range(height):
        theta = math.pi * (row + 0.5) / height          # from +Y
        for col in range(width):
            phi = 2 * math.pi * ((col + 0.5) / width - 0.5)  # 0 toward -Z, +pi/2 toward +X
            d = (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))
            out += rgbe(sky(d))
    with open(path, "wb") as f:
        f.write(bytes(out))


def main():
    verts, uvs, normals, faces = make_vase()
    check_vase(verts, normals, faces)
    write_obj(os.path.join(SCENES, "meshes", "vase.obj"), verts, uvs, normals, faces)
    write_png(os.path.join(SCENES, "textures", "vase_glaze.png"), 128, 128, glaze)
    write_hdr(os.path.join(SCENES, "environments", "showcase_sky.hdr"), 128, 64)
    print("make_showcase_assets: vase %d vertices, %d triangles; glaze 128x128; sky 128x64" % (len(verts), len(faces)))


if __name__ == "__main__":
    main()
