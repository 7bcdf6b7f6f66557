#!/usr/bin/python3
"""Writes scenes/meshes/torus_knot.obj: a closed tube around a (p, q) torus knot, with vertex normals.

The project ships only meshes it makes itself; this is the one its mesh scenes use. Standard
library only. Run from anywhere: python3 tools/make_torus_knot.py [output.obj]

The tube follows a rotation-minimising frame (double reflection, Wang et al. 2008), so the grid
does not twist around the curve; the frame's small mismatch after one full loop (the holonomy)
is spread evenly along the knot so the tube closes on itself exactly. Vertex normals are the
exact normals of the tube surface: the unit offset from the curve. The script checks that the
mesh is closed (every edge shared by exactly two triangles), that the tube does not cut itself,
and that every triangle winds counter-clockwise seen from outside.
"""
import math
import os
import sys

P, Q = 2, 3            # the trefoil
SEGMENTS = 320         # along the knot
SIDES = 28             # around the tube
TUBE_RADIUS = 0.5      # in knot units; the knot spans radius 1..3 around its axis


def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a): return mul(a, 1.0 / math.sqrt(dot(a, a)))


def curve(t):
    """Point on the knot, t in [0, 2 pi); Y is up so the knot lies flat on a floor."""
    r = 2.0 + math.cos(Q * t)
    return (r * math.cos(P * t), -math.sin(Q * t), r * math.sin(P * t))


def tangent(t):
    h = 1e-5
    return norm(sub(curve(t + h), curve(t - h)))


def rotate_about(v, axis, angle):
    """Rodrigues rotation of v about unit axis."""
    c, s = math.cos(angle), math.sin(angle)
    return add(add(mul(v, c), mul(cross(axis, v), s)), mul(axis, dot(axis, v) * (1.0 - c)))


def frames():
    ts = [2.0 * math.pi * i / SEGMENTS for i in range(SEGMENTS + 1)]
    points = [curve(t) for t in ts]
    tangents = [tangent(t) for t in ts]
    t0 = tangents[0]
    helper = (0.0, 1.0, 0.0) if abs(t0[1]) < 0.9 else (1.0, 0.0, 0.0)
    normals = [norm(cross(cross(t0, helper), t0))]
    for i in range(SEGMENTS):
        # Double reflection: reflect across the plane bisecting the two points, then across the
        # plane bisecting the reflected tangent and the next tangent.
        v1 = sub(points[i + 1], points[i])
        c1 = dot(v1, v1)
        r_l = sub(normals[i], mul(v1, 2.0 / c1 * dot(v1, normals[i])))
        t_l = sub(tangents[i], mul(v1, 2.0 / c1 * dot(v1, tangents[i])))
        v2 = sub(tangents[i + 1], t_l)
        c2 = dot(v2, v2)
        n = sub(r_l, mul(v2, 2.0 / c2 * dot(v2, r_l))) if c2 > 0.0 else r_l
        normals.append(norm(n))
    # Holonomy: the angle from the transported end frame back to the start frame, about the tangent.
    end, start = normals[SEGMENTS], normals[0]
    angle = math.atan2(dot(cross(end, start), tangents[0]), dot(end, start))
    out = []
    for i in range(SEGMENTS):
        n = rotate_about(normals[i], tangents[i], angle * i / SEGMENTS)
        out.append((points[i], tangents[i], n, cross(tangents[i], n)))
    return out


def build():
    vertices, normals, faces = [], [], []
    for (p, t, n, b) in frames():
        for j in range(SIDES):
            a = 2.0 * math.pi * j / SIDES
            d = add(mul(n, math.cos(a)), mul(b, math.sin(a)))
            vertices.append(add(p, mul(d, TUBE_RADIUS)))
            normals.append(d)
    idx = lambda i, j: (i % SEGMENTS) * SIDES + (j % SIDES)
    for i in range(SEGMENTS):
        for j in range(SIDES):
            a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
            faces.append((a, c, b))
            faces.append((a, d, c))
    return vertices, normals, faces


def check(vertices, normals, faces):
    edges = {}
    for f in faces:
        for k in range(3):
            e = (min(f[k], f[(k + 1) % 3]), max(f[k], f[(k + 1) % 3]))
            edges[e] = edges.get(e, 0) + 1
        # Counter-clockwise from outside: the face normal agrees with the vertex normals.
        fn = cross(sub(vertices[f[1]], vertices[f[0]]), sub(vertices[f[2]], vertices[f[0]]))
        if dot(fn, add(add(normals[f[0]], normals[f[1]]), normals[f[2]])) <= 0.0:
            sys.exit("make_torus_knot: a triangle winds clockwise")
    if any(count != 2 for count in edges.values()):
        sys.exit("make_torus_knot: mesh is not closed")
    # The tube must not cut itself: strands further apart along the knot than a tube diameter's
    # worth of arc must stay more than two tube radii apart.
    centres = [curve(2.0 * math.pi * i / SEGMENTS) for i in range(SEGMENTS)]
    step = math.sqrt(dot(sub(centres[1], centres[0]), sub(centres[1], centres[0])))
    skip = int(math.ceil(4.0 * TUBE_RADIUS / step)) + 1
    closest = min(math.sqrt(dot(sub(centres[i], centres[k]), sub(centres[i], centres[k])))
                  for i in range(SEGMENTS) for k in range(i + skip, SEGMENTS)
                  if (SEGMENTS - (k - i)) >= skip)
    if closest <= 2.0 * TUBE_RADIUS:
        sys.exit("make_torus_knot: the tube intersects itself (closest strands %.3f apart)" % closest)
    # Nor fold where the knot bends tighter than the tube is thick.
    h = 1e-4
    for i in range(SEGMENTS):
        t = 2.0 * math.pi * i / SEGMENTS
        a, b, c = curve(t - h), curve(t), curve(t + h)
        d1 = mul(sub(c, a), 0.5 / h)
        d2 = mul(add(sub(c, b), sub(a, b)), 1.0 / (h * h))
        curvature = math.sqrt(dot(cross(d1, d2), cross(d1, d2))) / dot(d1, d1) ** 1.5
        if curvature * TUBE_RADIUS >= 1.0:
            sys.exit("make_torus_knot: the tube folds where the knot bends sharply")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.normpath(os.path.join(here, "..", "scenes", "meshes", "torus_knot.obj"))
    vertices, normals, faces = build()
    check(vertices, normals, faces)
    lines = ["# (%d, %d) torus knot tube, %d triangles; made by tools/make_torus_knot.py" % (P, Q, len(faces))]
    lines += ["v %.6f %.6f %.6f" % v for v in vertices]
    lines += ["vn %.6f %.6f %.6f" % n for n in normals]
    lines += ["f %d//%d %d//%d %d//%d" % (a + 1, a + 1, b + 1, b + 1, c + 1, c + 1) for (a, b, c) in faces]
    tmp = out + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, out)
    print("wrote %s: %d vertices, %d triangles" % (out, len(vertices), len(faces)))


if __name__ == "__main__":
    main()
