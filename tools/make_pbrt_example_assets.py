#!/usr/bin/python3
"""Writes the files scenes/pbrt/metals.pbrt uses, in the forms pbrt-v4's own scenes ship them
(standard library only):

  scenes/pbrt/geometry/vase.ply.gz       the project's vase (scenes/meshes/vase.obj, y up), as a
                                         gzip-compressed binary little-endian PLY: x y z nx ny nz u v
                                         per vertex, triangles as vertex_indices lists
  scenes/pbrt/textures/sky-equiarea.pfm  the project's sky (scenes/environments/showcase_sky.hdr)
                                         resampled to pbrt-v4's equal-area octahedral layout, 64 x 64
  scenes/pbrt/textures/vase-spiral.png   a glaze of three helical bands, 256 x 256 sRGB: a helix is
                                         chiral, so the scene's mirrored vase shows it is mirrored
  scenes/pbrt/spds/Au.eta.spd, Au.k.spd  gold's eta and k as pbrt-v4 spectrum files, from the Au table
                                         in tools/conductor_rgb.py (our copy of pbrt-v4's data)

Run from anywhere: python3 tools/make_pbrt_example_assets.py (rerunning writes the same bytes:
the gzip header's time is 0). Reads scenes/meshes/vase.obj and scenes/environments/showcase_sky.hdr,
which tools/make_showcase_assets.py makes; the PNG writer and the Au table are imported from it and
from tools/conductor_rgb.py, not copied.

The sky map. pbrt-v4's image infinite light looks a direction w up in its light space by
(u, v) = EqualAreaSphereToSquare(w) (Clarberg 2008), u along the columns from the left, v along
the rows from the top (the first row an image reader returns; PFM stores rows bottom to top, so
the top row is written last). metals.pbrt is a z-up world whose infinite light has no transform,
so light space is the world. Each texel is the mean of 4 x 4 sub-samples: w from
EqualAreaSquareToSphere (raytracer/render/sampling/equal_area_octahedral.cpp, reimplemented below), turned
into the sky's y-up frame by the rotation (x, y, z) -> (x, z, -y) (world +z is the sky's +Y, world
-y its +Z), and read from the equirectangular sky as our loader reads it (scenes/README.md,
"Environment": u = 1/2 + atan2(d.x, -d.z) / 2 pi, v = acos(d.y) / pi, nearest texel, RGBE decoded
as m 2^(e - 136)).

Checks, each fatal: the square <-> sphere round trip at every sub-sample (and its fixed points:
the centre is +z, the right edge's middle +x, the top edge's middle -y, a corner -z); the map's
mean radiance against the sky's solid-angle-weighted mean; the PFM and PLY read back from the
bytes written, the sun's texel the brightest, the PLY's vertices and triangles the OBJ's; the
spectrum files read back to the table.
"""
import gzip
import math
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "scenes")
OUT = os.path.join(SCENES, "pbrt")

sys.dont_write_bytecode = True  # importing our sibling tools must leave nothing in tools/
sys.path.insert(0, HERE)
import conductor_rgb  # noqa: E402  (the Au table: pbrt-v4's metal-Au-eta / metal-Au-k)
import make_showcase_assets  # noqa: E402  (the PNG writer, the sun's direction)

MAP_SIZE = 64
SUBSAMPLES = 4  # per texel side


def fail(message):
    sys.exit("make_pbrt_example_assets: " + message)


# --- the equal-area octahedral mapping (pbrt-v4's, as render/sampling/equal_area_octahedral.cpp) -------
def square_to_sphere(u, v):
    u, v = 2 * u - 1, 2 * v - 1
    a, b = abs(u), abs(v)
    signed_distance = 1 - (a + b)  # > 0 inside the diamond: the upper hemisphere
    r = 1 - abs(signed_distance)
    phi = (1.0 if r == 0 else (b - a) / r + 1) * math.pi / 4
    z = math.copysign(1 - r * r, signed_distance)
    sin_theta = r * math.sqrt(max(2 - r * r, 0.0))
    return (math.copysign(math.cos(phi), u) * sin_theta, math.copysign(math.sin(phi), v) * sin_theta, z)


def sphere_to_square(d):
    x, y, z = abs(d[0]), abs(d[1]), abs(d[2])
    length = math.sqrt(x * x + y * y + z * z)
    r = math.sqrt((x * x + y * y) / (length * (length + z)))
    phi = math.atan2(y, x) * 2 / math.pi
    v = phi * r
    u = r - v
    if d[2] < 0:
        u, v = 1 - v, 1 - u
    return 0.5 * (math.copysign(u, d[0]) + 1), 0.5 * (math.copysign(v, d[1]) + 1)


def check_equal_area(points):
    fixed = [((0.5, 0.5), (0, 0, 1)), ((1.0, 0.5), (1, 0, 0)), ((0.5, 0.0), (0, -1, 0)), ((0.0, 0.0), (0, 0, -1))]
    for (u, v), want in fixed:
        got = square_to_sphere(u, v)
        if max(abs(g - w) for g, w in zip(got, want)) > 1e-12:
            fail("square_to_sphere(%g, %g) = %s, not %s" % (u, v, got, want))
    for u, v in points:
        d = square_to_sphere(u, v)
        back = sphere_to_square(d)
        if abs(sum(c * c for c in d) - 1) > 1e-12 or max(abs(back[0] - u), abs(back[1] - v)) > 1e-12:
            fail("equal-area round trip: (%r, %r) -> %s -> %s" % (u, v, d, back))


# --- the sky -----------------------------------------------------------------------------------
def read_hdr(path):
    """A Radiance RGBE file in the standard orientation (-Y H +X W): rows of (r, g, b) floats,
    the top row first. Flat or new-style RLE scanlines."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"\n\n") + 2
    if b"FORMAT=32-bit_rle_rgbe" not in data[:end]:
        fail("%s: not a 32-bit_rle_rgbe file" % path)
    line_end = data.index(b"\n", end)
    words = data[end:line_end].split()
    if len(words) != 4 or words[0] != b"-Y" or words[2] != b"+X":
        fail("%s: resolution line %r is not '-Y H +X W'" % (path, data[end:line_end]))
    height, width = int(words[1]), int(words[3])
    pos = line_end + 1
    rows = []
    for _ in range(height):
        if data[pos:pos + 2] == b"\x02\x02" and 8 <= width < 32768:  # RLE: 4 channels in turn
            pos += 4
            channels = []
            for _ in range(4):
                chan = bytearray()
                while len(chan) < width:
                    count = data[pos]
                    if count > 128:
                        chan += bytes([data[pos + 1]]) * (count - 128)
                        pos += 2
                    else:
                        chan += data[pos + 1:pos + 1 + count]
                        pos += 1 + count
                channels.append(chan)
            texels = list(zip(*channels))
        else:
            texels = [tuple(data[pos + 4 * i:pos + 4 * i + 4]) for i in range(width)]
            pos += 4 * width
        rows.append([(0.0, 0.0, 0.0) if e == 0 else tuple(m * 2.0 ** (e - 136) for m in (r, g, b))
                     for r, g, b, e in texels])
    return rows


def sky_radiance(sky, d):
    """Our equirectangular lookup of a y-up direction (scenes/README.md, Environment)."""
    height, width = len(sky), len(sky[0])
    u = 0.5 + math.atan2(d[0], -d[2]) / (2 * math.pi)
    v = math.acos(max(-1.0, min(1.0, d[1]))) / math.pi
    return sky[min(height - 1, int(v * height))][min(width - 1, int(u * width))]


def world_to_sky(w):
    """metals.pbrt's z-up world to the sky's y-up frame: a rotation (world +z -> +Y, -y -> +Z)."""
    return (w[0], w[2], -w[1])


def equal_area_map(sky):
    """Rows of texels, the top row (pbrt-v4's v = 0) first; and every sub-sample's (u, v)."""
    n, s = MAP_SIZE, SUBSAMPLES
    rows, points = [], []
    for j in range(n):
        row = []
        for i in range(n):
            total = [0.0, 0.0, 0.0]
            for sj in range(s):
                for si in range(s):
                    u, v = (i + (si + 0.5) / s) / n, (j + (sj + 0.5) / s) / n
                    points.append((u, v))
                    c = sky_radiance(sky, world_to_sky(square_to_sphere(u, v)))
                    for k in range(3):
                        total[k] += c[k]
            row.append(tuple(t / (s * s) for t in total))
        rows.append(row)
    return rows, points


def check_sky_map(sky, rows):
    """Equal area: the map's plain mean is the sphere's mean radiance, which the equirect sky
    gives weighted by each row's solid angle (exact sin-band integrals)."""
    height = len(sky)
    want, got = 0.0, 0.0
    for j, row in enumerate(sky):
        band = (math.cos(math.pi * j / height) - math.cos(math.pi * (j + 1) / height)) / 2
        want += band * sum(sum(c) for c in row) / len(row)
    got = sum(sum(c) for row in rows for c in row) / (len(rows) * len(rows[0]))
    if abs(got - want) > 0.02 * want:
        fail("the equal-area map's mean radiance %.4f is not the sky's %.4f" % (got, want))


def write_pfm(path, rows):
    height, width = len(rows), len(rows[0])
    out = bytearray(b"PF\n%d %d\n-1.0\n" % (width, height))
    for row in reversed(rows):  # PFM: the bottom row first
        for c in row:
            out += struct.pack("<3f", *c)
    with open(path, "wb") as f:
        f.write(bytes(out))


def read_pfm(path):
    with open(path, "rb") as f:
        data = f.read()
    head = data.split(b"\n", 3)
    width, height = (int(x) for x in head[1].split())
    floats = struct.unpack("<%df" % (3 * width * height), head[3])
    rows = [[floats[3 * (y * width + x):3 * (y * width + x) + 3] for x in range(width)] for y in range(height)]
    return rows[::-1]  # the top row first, as image readers (ours, pbrt-v4's) return it


def check_pfm(path, rows):
    back = read_pfm(path)
    if len(back) != len(rows) or any(max(abs(a - b) for a, b in zip(p, q)) > 1e-6 * max(1.0, max(q))
                                     for rb, r in zip(back, rows) for p, q in zip(rb, r)):
        fail("%s does not read back as written" % path)
    # The sun, toward make_showcase_assets.SUN in the sky's frame, is where the map puts it.
    sun = make_showcase_assets.SUN
    world = (sun[0], -sun[2], sun[1])  # the inverse of world_to_sky
    u, v = sphere_to_square(world)
    n = len(back)
    lum = lambda c: 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
    brightest = max(((lum(c), x, y) for y, row in enumerate(back) for x, c in enumerate(row)))
    if abs(brightest[1] - int(u * n)) > 2 or abs(brightest[2] - int(v * n)) > 2:
        fail("the map's brightest texel (%d, %d) is not the sun's (%d, %d)" % (brightest[1], brightest[2], int(u * n), int(v * n)))


# --- the vase --------------------------------------------------------------------------------
def read_obj(path):
    """Vertices as (x y z nx ny nz u v), one per distinct (v, vt, vn) corner, and triangles."""
    pos, tex, nor, verts, faces, index = [], [], [], [], [], {}
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                pos.append(tuple(float(x) for x in w[1:4]))
            elif w[0] == "vt":
                tex.append(tuple(float(x) for x in w[1:3]))
            elif w[0] == "vn":
                nor.append(tuple(float(x) for x in w[1:4]))
            elif w[0] == "f":
                if len(w) != 4:
                    fail("%s: a face that is not a triangle: %s" % (path, line.strip()))
                face = []
                for corner in w[1:]:
                    if corner not in index:
                        p, t, n = (int(x) - 1 for x in corner.split("/"))
                        index[corner] = len(verts)
                        verts.append(pos[p] + nor[n] + tex[t])
                    face.append(index[corner])
                faces.append(tuple(face))
    return verts, faces


PLY_PROPERTIES = ("x", "y", "z", "nx", "ny", "nz", "u", "v")


def ply_bytes(verts, faces):
    header = ["ply", "format binary_little_endian 1.0",
              "comment vase.ply: made by tools/make_pbrt_example_assets.py from scenes/meshes/vase.obj (y up)",
              "element vertex %d" % len(verts)]
    header += ["property float %s" % p for p in PLY_PROPERTIES]
    header += ["element face %d" % len(faces), "property list uchar int vertex_indices", "end_header"]
    out = bytearray(("\n".join(header) + "\n").encode("ascii"))
    for v in verts:
        out += struct.pack("<8f", *v)
    for f in faces:
        out += struct.pack("<B3i", 3, *f)
    return bytes(out)


def check_ply(path, verts, faces):
    with open(path, "rb") as f:
        data = gzip.decompress(f.read())
    end = data.index(b"end_header\n") + len(b"end_header\n")
    lines = data[:end].decode("ascii").split("\n")
    if ("element vertex %d" % len(verts)) not in lines or ("element face %d" % len(faces)) not in lines:
        fail("%s: the header's counts are not the OBJ's" % path)
    if [l.split()[-1] for l in lines if l.startswith("property float")] != list(PLY_PROPERTIES):
        fail("%s: the vertex properties are not %s" % (path, " ".join(PLY_PROPERTIES)))
    vbytes = 32 * len(verts)
    if len(data) - end != vbytes + 13 * len(faces):
        fail("%s: %d data bytes, expected %d" % (path, len(data) - end, vbytes + 13 * len(faces)))
    for i, v in enumerate(verts):
        got = struct.unpack_from("<8f", data, end + 32 * i)
        if max(abs(a - b) for a, b in zip(got, v)) > 1e-6:
            fail("%s: vertex %d reads back as %s, not %s" % (path, i, got, v))
    for i, f in enumerate(faces):
        got = struct.unpack_from("<B3i", data, end + vbytes + 13 * i)
        if got != (3,) + f or not all(0 <= k < len(verts) for k in f):
            fail("%s: face %d reads back as %s" % (path, i, got))


# --- the spiral glaze --------------------------------------------------------------------------
def spiral_glaze(u, v):
    """Linear albedo at the vase's (u, v) (make_showcase_assets.py: u around, v from the outer
    bottom's centre, ~0.1 the foot, ~0.5 the lip): three teal bands climbing one way round, a
    rust ring under the lip and above the foot, cream between, the foot and inside unglazed."""
    cream, teal, rust, dark = (0.80, 0.74, 0.62), (0.08, 0.36, 0.40), (0.55, 0.20, 0.08), (0.10, 0.08, 0.07)
    if v < 0.10 or v > 0.53:
        return dark
    if 0.12 < v < 0.14 or 0.47 < v < 0.49:
        return rust
    if (3 * u + 9 * v) % 1.0 < 0.3:  # u up by 1/3 (a third of a turn): the band's v down by 1/9
        return teal
    return cream


# --- the spectrum files ------------------------------------------------------------------------
def spd_text(name, quantity, lam, values):
    lines = ["# %s of gold (Au): pbrt-v4's metal-Au-%s spectrum, (wavelength nm, value) pairs." % (quantity, quantity),
             "# Written by tools/make_pbrt_example_assets.py from the Au table in tools/conductor_rgb.py,",
             "# sweeptrace's own copy of pbrt-v4's data (its src/pbrt/util/spectrum.cpp)."]
    lines += ["%.6f %r" % (l, x) for l, x in zip(lam, values)]
    return "\n".join(lines) + "\n"


def read_spd(path):
    pairs = []
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].split()
            if line:
                pairs.append((float(line[0]), float(line[1])))
    return pairs


def write(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data)


def main():
    sky = read_hdr(os.path.join(SCENES, "environments", "showcase_sky.hdr"))
    rows, points = equal_area_map(sky)
    check_equal_area(points)
    check_sky_map(sky, rows)
    pfm = os.path.join(OUT, "textures", "sky-equiarea.pfm")
    os.makedirs(os.path.dirname(pfm), exist_ok=True)
    write_pfm(pfm, rows)
    check_pfm(pfm, rows)

    verts, faces = read_obj(os.path.join(SCENES, "meshes", "vase.obj"))
    ply = os.path.join(OUT, "geometry", "vase.ply.gz")
    write(ply, gzip.compress(ply_bytes(verts, faces), compresslevel=9, mtime=0))
    check_ply(ply, verts, faces)

    make_showcase_assets.write_png(os.path.join(OUT, "textures", "vase-spiral.png"), 256, 256, spiral_glaze)

    lam, eta, k = conductor_rgb.METALS["Au"]
    for quantity, values in (("eta", eta), ("k", k)):
        path = os.path.join(OUT, "spds", "Au.%s.spd" % quantity)
        write(path, spd_text("Au", quantity, lam, values).encode("ascii"))
        if read_spd(path) != [(float("%.6f" % l), x) for l, x in zip(lam, values)]:
            fail("%s does not read back as the table" % path)
    print("make_pbrt_example_assets: vase %d vertices, %d triangles; sky %dx%d equal-area; glaze 256x256; Au %d pairs"
          % (len(verts), len(faces), MAP_SIZE, MAP_SIZE, len(lam)))


if __name__ == "__main__":
    main()
