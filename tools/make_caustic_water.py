#!/usr/bin/python3
"""Writes scenes/meshes/caustic_water.obj: the rippled water slab of scenes/caustic.json.

A closed slab of water over x, z in [-1, 1]: a flat bottom at y = BOTTOM and a top at
y = TOP + h(x, z), h a sum of three crossing sine ripples, joined by four vertical sides. The
ripples are sized so that each crest is a weak lens focusing the light above onto the floor
below: a sine of amplitude a and wave number k has curvature a k^2 at its crest, a thin lens of
focal length 1 / ((ior - 1) a k^2), 0.9-1.2 for water here, about the height from the crests
to the floor. So the floor under the slab is lit only through two refractions (light, specular,
specular, diffuse):
what a camera path finds only by hitting the small light after leaving the floor through the
water, and what a light path finds every time.

Faces carry no vertex normals (flat facets: the caustic is a faceted one, which changes its
pattern, not how hard it is to find). Every triangle winds counter-clockwise seen from outside
(the dielectric's outside is the air), checked below together with closedness (every edge shared
by exactly two triangles). Standard library only:
    python3 tools/make_caustic_water.py [output.obj]
"""
import math
import os
import sys

N = 48               # grid cells per side, top and bottom alike (the sides then match)
HALF = 1.0           # the slab spans [-HALF, HALF] in x and z
BOTTOM, TOP = 0.6, 0.8
RIPPLES = [          # (amplitude, kx, kz, phase)
    (0.025, 2 * math.pi / 0.55, 2 * math.pi / 1.7, 0.3),
    (0.020, -2 * math.pi / 1.3, 2 * math.pi / 0.6, 1.1),
    (0.015, 2 * math.pi / 0.9, 2 * math.pi / 0.8, 2.0),
]


def height(x, z):
    return TOP + sum(a * math.sin(kx * x + kz * z + p) for a, kx, kz, p in RIPPLES)


def build():
    verts, tris = [], []
    def coord(i): return -HALF + 2 * HALF * i / N
    top = {}
    bottom = {}
    for i in range(N + 1):
        for j in range(N + 1):
            x, z = coord(i), coord(j)
            verts.append((x, height(x, z), z)); top[i, j] = len(verts)
            verts.append((x, BOTTOM, z)); bottom[i, j] = len(verts)
    for i in range(N):
        for j in range(N):
            a, b, c, d = top[i, j], top[i + 1, j], top[i + 1, j + 1], top[i, j + 1]
            tris += [(a, d, c), (a, c, b)]          # normal +y: (d - a) x (c - a) points up
            a, b, c, d = bottom[i, j], bottom[i + 1, j], bottom[i + 1, j + 1], bottom[i, j + 1]
            tris += [(a, b, c), (a, c, d)]          # normal -y
    # The four sides, each a strip of quads between the top's and the bottom's boundary.
    ring = [(i, 0) for i in range(N)] + [(N, j) for j in range(N)] + \
           [(N - i, N) for i in range(N)] + [(0, N - j) for j in range(N)]
    for k, p in enumerate(ring):
        q = ring[(k + 1) % len(ring)]
        tris += [(bottom[p], top[q], bottom[q]), (bottom[p], top[p], top[q])]
    return verts, tris


def check(verts, tris):
    edges = {}
    for t in tris:
        for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            edges[e] = edges.get(e, 0) + 1
    for (u, v), n in edges.items():
        assert n == 1 and edges.get((v, u)) == 1, "not closed or not consistently wound"
    # Consistent winding plus a positive signed volume means every face winds outward.
    vol = 0.0
    for a, b, c in tris:
        p, q, r = verts[a - 1], verts[b - 1], verts[c - 1]
        vol += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
                + p[2] * (q[0] * r[1] - q[1] * r[0])) / 6
    assert vol > 0, "faces wind inward"
    return vol


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "meshes", "caustic_water.obj")
    verts, tris = build()
    vol = check(verts, tris)
    with open(out, "w") as f:
        f.write("# Rippled water slab of scenes/caustic.json, made by tools/make_caustic_water.py\n")
        for v in verts:
            f.write("v %.6f %.6f %.6f\n" % v)
        for t in tris:
            f.write("f %d %d %d\n" % t)
    print("%s: %d vertices, %d triangles, closed, outward, volume %.4f" % (out, len(verts), len(tris), vol))


if __name__ == "__main__":
    main()
