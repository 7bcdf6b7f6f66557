#!/usr/bin/env python3
"""Writes the bad-input corpus: one folder per case under cases/, and manifest.tsv.

Each case is the files a hostile or careless user hands sweeptrace, the command line, the exit
code expected and a pattern its one-line message must match (it names the file and the place).
run_corpus.py runs them. Regenerate with `/usr/bin/python3 tests/bad_input/generate.py` (Debian's
Python, whose python3-openvdb writes the VDB cases' files; the output is committed; rerunning it
writes the same bytes).
"""
import gzip
import json
import os
import shutil
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.join(HERE, "cases")
if __name__ == "__main__":
    shutil.rmtree(CASES, ignore_errors=True)  # cases are written as they are declared below

BASE = {
    "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
    "film": {"width": 8, "height": 8, "spp": 1},
    "materials": {"m": {"type": "diffuse"}},
    "objects": [{"type": "sphere", "radius": 1, "material": "m"}],
}

cases = []  # (name, exit, pattern, args, setup)


def scene(**changes):
    s = json.loads(json.dumps(BASE))
    for path, value in changes.items():
        keys = path.split("__")
        node = s
        for k in keys[:-1]:
            node = node[int(k)] if isinstance(node, list) else node[k]
        last = keys[-1]
        if isinstance(node, list):
            node[int(last)] = value
        elif value is DELETE:
            del node[last]
        else:
            node[last] = value
    return json.dumps(s)


DELETE = object()


def mesh_scene(obj_name="mesh.obj", **extra):
    s = json.loads(json.dumps(BASE))
    s["objects"] = [dict({"type": "mesh", "file": obj_name, "material": "m"}, **extra)]
    return json.dumps(s)


def case(name, exit_code, pattern, args, files, setup=""):
    d = os.path.join(CASES, name)
    os.makedirs(d)
    for fname, content in files.items():
        p = os.path.join(d, fname)
        os.makedirs(os.path.dirname(p), exist_ok=True)
        with open(p, "wb") as f:
            f.write(content.encode() if isinstance(content, str) else content)
    cases.append((name, exit_code, pattern, args, setup))


def render_case(name, pattern, text, args="", fname="scene.json", extra=None, setup=""):
    files = {fname: text}
    files.update(extra or {})
    case(name, 2, pattern, f"render {fname} -o out.png --quiet {args}".strip(), files, setup)


def obj_case(name, pattern, obj, fname="mesh.obj"):
    render_case(name, pattern, mesh_scene(fname), extra={fname: obj})


E = r"^sweeptrace: error: "

# --- scene files: JSON syntax -------------------------------------------------------------------
render_case("json-not-json", E + r"scene\.json:1:1: invalid JSON", "hello")
render_case("json-empty", E + r"scene\.json:1:1: invalid JSON", "")
render_case("json-truncated", E + r"scene\.json:1:\d+: invalid JSON", '{"camera":')
render_case("json-trailing-comma", E + r"scene\.json:1:\d+: invalid JSON", scene()[:-1] + ",}")
render_case("json-duplicate-key", E + r"scene\.json: film\.width: duplicate key",
            scene().replace('"width": 8', '"width": 8, "width": 9'))
render_case("json-top-level-array", E + r"scene\.json: \(top level\): must be an object", "[1, 2]")
render_case("json-nul-byte", E + r"scene\.json:1:\d+: invalid JSON", scene().replace("diffuse", "dif\0fuse"))
render_case("json-bad-utf8", E + r"scene\.json:1:\d+: invalid JSON", scene().encode().replace(b"diffuse", b"dif\xff"))
render_case("json-number-overflow", E + r"scene\.json:1:\d+: number 1e999 is out of range",
            scene().replace('"radius": 1', '"radius": 1e999'))
render_case("json-nested-40", E + r"scene\.json:1:\d+: nested deeper than 32",
            scene().replace("[0, 0, 5]", "[" * 40 + "]" * 40))
render_case("json-nested-100000", E + r"scene\.json:1:\d+: nested deeper than 32",
            scene().replace("[0, 0, 5]", "[" * 100000 + "]" * 100000))
render_case("json-nested-objects", E + r"scene\.json:1:\d+: nested deeper than 32",
            scene().replace('"materials": {', '"materials": {"deep": ' + '{"a": ' * 50 + "1" + "}" * 50 + ", "))
render_case("json-long-key", E + r"scene\.json: camera\.x+\.\.\.x+: unknown key", scene(**{"camera__" + "x" * 5000: 1}))
render_case("json-long-value", E + r"scene\.json: materials\.m\.type: unknown material type",
            scene().replace('"diffuse"', '"' + "d" * 5000 + '"'))
render_case("json-newline-in-key", E + r"scene\.json: film\[\"w\\nidth\"\]: unknown key",
            scene().replace('"spp": 1', '"spp": 1, "w\\nidth": 3'))
# Found while reviewing the excerpts: a key cut inside a UTF-8 character made nlohmann's dump
# throw, an internal error (exit 3) on f0d10f8's successor before the cut was made UTF-8 aware.
render_case("json-utf8-key-in-excerpt", E + r"scene\.json: camera\.position: must be an array of 3 numbers .*got \[\{\"é+",
            scene(camera__position=[{"é" * 40: 1}]).replace("\\u00e9", "é"))
render_case("json-long-array-value", E + r"scene\.json: camera\.position: must be an array of 3 numbers",
            scene().replace("[0, 0, 5]", "[" + ", ".join(["1"] * 20000) + "]"))
# --- scene files: structure and ranges ---------------------------------------------------------
render_case("scene-unknown-top-key", E + r"scene\.json: lighting: unknown key", scene(lighting=[]))
render_case("scene-missing-camera", E + r"scene\.json: camera: missing", scene(camera=DELETE))
render_case("scene-missing-film", E + r"scene\.json: film: missing", scene(film=DELETE))
render_case("film-width-0", E + r"scene\.json: film\.width: must be in \[1, 16384\], got 0", scene(film__width=0))
render_case("film-width-16385", E + r"scene\.json: film\.width: must be in \[1, 16384\]", scene(film__width=16385))
render_case("film-width-float", E + r"scene\.json: film\.width: must be an integer", scene(film__width=1.5))
render_case("film-width-string", E + r"scene\.json: film\.width: must be an integer", scene(film__width="8"))
render_case("film-height-negative", E + r"scene\.json: film\.height: must be in", scene(film__height=-1))
render_case("film-height-huge", E + r"scene\.json: film\.height: must be an integer", scene(film__height=2**70))
render_case("film-spp-0", E + r"scene\.json: film\.spp: must be in \[1, 1048576\]", scene(film__spp=0))
render_case("film-spp-huge", E + r"scene\.json: film\.spp: must be in \[1, 1048576\]", scene(film__spp=2**21))
render_case("film-depth-0", E + r"scene\.json: film\.max_depth: must be in \[1, 1024\]", scene(film__max_depth=0))
render_case("film-depth-huge", E + r"scene\.json: film\.max_depth: must be in \[1, 1024\]", scene(film__max_depth=5000))
render_case("film-memory", E + r"scene\.json: the render needs an estimated .* \(film 16384x16384",
            scene(film__width=16384, film__height=16384), "--max-memory 1G")
render_case("seed-negative", E + r"scene\.json: seed: must be >= 0", scene(seed=-1))
render_case("seed-float", E + r"scene\.json: seed: must be an integer", scene(seed=1.5))
render_case("camera-look-at-position", E + r"scene\.json: camera\.look_at: must differ",
            scene(camera__look_at=[0, 0, 5]))
render_case("camera-fov-180", E + r"scene\.json: camera\.fov: must be a vertical field of view", scene(camera__fov=180))
render_case("camera-fov-0", E + r"scene\.json: camera\.fov:", scene(camera__fov=0))
render_case("camera-handedness-unknown", E + r"scene\.json: camera\.handedness: must be \"right\"", scene(camera__handedness="mirrored"))
render_case("mesh-inline-index-out-of-range", E + r"scene\.json: objects\[0\]\.indices\[2\]: must be in \[0, 2\], got 7",
            scene(objects=[{"type": "mesh", "material": "m", "vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 7]}]))
render_case("camera-up-parallel", E + r"scene\.json: camera\.up: must not be parallel", scene(camera__up=[0, 0, 1]))
render_case("camera-position-short", E + r"scene\.json: camera\.position: must be an array of 3", scene(camera__position=[1, 2]))
render_case("camera-position-string", E + r"scene\.json: camera\.position\[0\]: must be a number",
            scene(camera__position=["a", 0, 0]))
render_case("camera-aperture-negative", E + r"scene\.json: camera\.aperture: must be >= 0", scene(camera__aperture=-1))
render_case("camera-float-overflow", E + r"scene\.json: camera\.position\[2\]: is too large for single precision",
            scene(camera__position=[0, 0, 1e39]))
render_case("materials-not-object", E + r"scene\.json: materials: must be an object", scene(materials=[]))
render_case("material-unknown-type", E + r"scene\.json: materials\.m\.type: unknown material type",
            scene(materials={"m": {"type": "plastic"}}))
render_case("material-albedo-over-1", E + r"scene\.json: materials\.m\.albedo\[1\]: must be in \[0, 1\]",
            scene(materials={"m": {"type": "diffuse", "albedo": [0.5, 1.5, 0.5]}}))
render_case("material-emissive-black", E + r"scene\.json: materials\.m\.emission: an emissive material must emit",
            scene(materials={"m": {"type": "emissive", "emission": [0, 0, 0]}}))
render_case("material-rough-dielectric-no-roughness", E + r"scene\.json: materials\.m\.roughness: missing",
            scene(materials={"m": {"type": "rough_dielectric", "ior": 1.5}}))
render_case("material-rough-dielectric-roughness-2", E + r"scene\.json: materials\.m\.roughness: must be in \[0, 1\]",
            scene(materials={"m": {"type": "rough_dielectric", "roughness": 2}}))
render_case("material-coated-ior-below-1", E + r"scene\.json: materials\.m\.ior: must be",
            scene(materials={"m": {"type": "coated_diffuse", "ior": 0.8}}))
render_case("material-coated-roughness-negative", E + r"scene\.json: materials\.m\.roughness: must be in \[0, 1\]",
            scene(materials={"m": {"type": "coated_diffuse", "roughness": -0.2}}))
render_case("material-empty-name", E + r"scene\.json: materials\[\"\"\]: a material name must not be empty",
            scene(materials={"": {"type": "diffuse"}, "m": {"type": "diffuse"}}))
render_case("objects-not-array", E + r"scene\.json: objects: must be an array", scene(objects={}))
render_case("object-unknown-type", E + r"scene\.json: objects\[0\]\.type: unknown shape type", scene(objects__0__type="torus"))
render_case("object-missing-material", E + r"scene\.json: objects\[0\]\.material: missing",
            json.dumps(dict(BASE, objects=[{"type": "sphere", "radius": 1}])))
render_case("object-unknown-material", E + r"scene\.json: objects\[0\]\.material: unknown material", scene(objects__0__material="x"))
render_case("sphere-radius-negative", E + r"scene\.json: objects\[0\]\.radius: must be > 0", scene(objects__0__radius=-1))
render_case("sphere-radius-zero", E + r"scene\.json: objects\[0\]\.radius: must be > 0", scene(objects__0__radius=0))
render_case("box-min-over-max", E + r"scene\.json: objects\[0\]\.max\[0\]: must be > min\[0\]",
            scene(objects=[{"type": "box", "min": [1, 0, 0], "max": [0, 1, 1], "material": "m"}]))
render_case("quad-parallel-edges", E + r"scene\.json: objects\[0\]: edge_u and edge_v must not be parallel",
            scene(objects=[{"type": "quad", "corner": [0, 0, 0], "edge_u": [1, 0, 0], "edge_v": [2, 0, 0], "material": "m"}]))
render_case("triangle-collinear", E + r"scene\.json: objects\[0\]: a, b and c are collinear",
            scene(objects=[{"type": "triangle", "a": [0, 0, 0], "b": [1, 1, 1], "c": [2, 2, 2], "material": "m"}]))
render_case("transform-scale-zero", E + r"scene\.json: objects\[0\]\.transform\[0\]\.scale: must be > 0",
            scene(objects__0__transform=[{"scale": 0}]))
render_case("transform-axis-zero", E + r"scene\.json: objects\[0\]\.transform\[0\]\.rotate\.axis: must not be the zero vector",
            scene(objects__0__transform=[{"rotate": {"axis": [0, 0, 0], "degrees": 5}}]))
render_case("transform-two-keys", E + r"scene\.json: objects\[0\]\.transform\[0\]: each step has exactly one",
            scene(objects__0__transform=[{"scale": 2, "translate": [0, 0, 0]}]))
# --- scene coordinates the BVH and the intersectors cannot hold --------------------------------
HUGE = scene(objects=[{"type": "sphere", "center": [3e38, 0, 0], "radius": 1e38, "material": "m"}])
render_case("extent-sphere-overflow-bvh", E + r"scene\.json: objects\[0\]: the shape's box must lie within", HUGE, "--accel bvh")
render_case("extent-sphere-overflow-embree", E + r"scene\.json: objects\[0\]: the shape's box must lie within", HUGE, "--accel embree")
render_case("extent-center-1e19", E + r"scene\.json: objects\[0\]: the shape's box must lie within \+-1e\+18",
            scene(objects=[{"type": "sphere", "center": [1e19, 0, 0], "radius": 1, "material": "m"}]))
render_case("extent-transform-scale", E + r"scene\.json: objects\[0\]: with its transform, its box must lie within",
            scene(objects=[{"type": "sphere", "radius": 1e10, "material": "m", "transform": [{"scale": 1e20}]}]))
render_case("extent-transform-translate", E + r"scene\.json: objects\[1\]: with its transform",
            scene(objects=[BASE["objects"][0], {"type": "box", "size": [1, 1, 1], "material": "m",
                                                "transform": [{"translate": [0, -3e38, 0]}]}]))
render_case("extent-camera", E + r"scene\.json: camera\.position: coordinates must lie within", scene(camera__position=[0, 0, 1e30]))
render_case("extent-mesh-vertices", E + r"scene\.json: objects\[0\]: the mesh's vertices must lie within",
            mesh_scene(), extra={"mesh.obj": "v 0 0 0\nv 3e38 0 0\nv 0 1 0\nf 1 2 3\n"})
# --- scene files: the file itself ---------------------------------------------------------------
case("scene-missing", 2, E + r"nothere\.json: cannot read scene: no such file", "render nothere.json -o out.png --quiet", {})
case("scene-directory", 2, E + r"adir: cannot read scene: it is a directory", "render adir -o out.png --quiet", {"adir/keep": ""})
case("scene-fifo", 2, E + r"pipe\.json: cannot read scene: is a FIFO, not a regular file", "render pipe.json -o out.png --quiet", {},
     "fifo pipe.json")
case("scene-over-size-limit", 2, E + r"big\.json: cannot read scene: it is 17 MiB, over the limit of 16 MiB",
     "render big.json -o out.png --quiet", {}, "sparse big.json 17825792")
render_case("mesh-file-missing", E + r"scene\.json: objects\[0\]\.file: mesh file \"nothere\.obj\" not found", mesh_scene("nothere.obj"))
render_case("mesh-file-empty-name", E + r"scene\.json: objects\[0\]\.file: must name an OBJ or PLY file", mesh_scene(""))
render_case("mesh-file-directory", E + r"scene\.json: objects\[0\]\.file: mesh file \"sub\" is a directory", mesh_scene("sub"),
            extra={"sub/keep": ""})
case("mesh-over-size-limit", 2, E + r"scene\.json: objects\[0\]\.file: .*big\.obj: cannot read mesh: it is 513 MiB, over the limit of 512 MiB",
     "render scene.json -o out.png --quiet", {"scene.json": mesh_scene("big.obj")}, "sparse big.obj 537919488")

# --- OBJ meshes ----------------------------------------------------------------------------------
M = r"scene\.json: objects\[0\]\.file: .*mesh\.obj: "


def polygon(n, eol):
    return "".join(f"v {i} {i % 7} 0{eol}" for i in range(n)) + "f " + " ".join(str(i + 1) for i in range(n)) + eol


obj_case("obj-256-corners-cr", E + M + r"line 257: a face needs 3 to 255 vertices, this one has 256", polygon(256, "\r"))
obj_case("obj-256-corners-lf", E + M + r"line 257: a face needs 3 to 255 vertices, this one has 256", polygon(256, "\n"))
obj_case("obj-257-corners-crlf", E + M + r"line 258: a face needs 3 to 255 vertices, this one has 257", polygon(257, "\r\n"))
obj_case("obj-300-corners-cr", E + M + r"line 301: a face needs 3 to 255", polygon(300, "\r"))
obj_case("obj-511-corners-cr", E + M + r"line 512: a face needs 3 to 255", polygon(511, "\r"))
obj_case("obj-2-corners", E + M + r"line 4: a face needs 3 to 255 vertices, this one has 2", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n")
obj_case("obj-2-corners-cr", E + M + r"line 4: a face needs 3 to 255 vertices, this one has 2", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2\r")
obj_case("obj-index-out-of-range", E + M + r"line 4: vertex index out of range", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
obj_case("obj-index-out-of-range-cr", E + M + r"line 4: vertex index out of range", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 9\r")
obj_case("obj-index-out-of-range-mixed", E + M + r"line 6: vertex index out of range",
         "v 0 0 0\r\nv 1 0 0\rv 0 1 0\n\r\nf 1 2 3\rf 1 2 4\n")
obj_case("obj-index-negative-past-start", E + M + r"line 4: vertex index out of range", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -5\n")
obj_case("obj-index-zero", E + M + r"invalid OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n")
obj_case("obj-normal-out-of-range", E + M + r"line 5: normal index out of range",
         "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//7\n")
obj_case("obj-vertex-nan", E + M + r"line 3: vertex x 'nan' is not a decimal number", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n")
obj_case("obj-vertex-inf", E + M + r"line 3: vertex y 'inf' is not a decimal number", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n")
obj_case("obj-vertex-minus-inf-cr", E + M + r"line 2: vertex z '-inf' is not a decimal number", "v 0 0 0\rv 1 0 -inf\rv 0 1 0\rf 1 2 3\r")
obj_case("obj-vertex-float-overflow", E + M + r"line 3: vertex y 1e39 is not finite in single precision",
         "v 0 0 0\nv 1 0 0\nv 0 1e39 0\nf 1 2 3\n")
obj_case("obj-vertex-missing-z", E + M + r"line 2: vertex has no z coordinate", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n")
obj_case("obj-vertex-hex", E + M + r"line 1: vertex x '0x10' is not a decimal number", "v 0x10 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
obj_case("obj-vertex-trailing-junk", E + M + r"line 2: vertex z '3abc' is not a decimal number", "v 0 0 0\nv 1 0 3abc\nv 0 1 0\nf 1 2 3\n")
obj_case("obj-nul-byte", E + M + r"line 2: contains a NUL byte", "v 0 0 0\nv 1 0\x000\nv 0 1 0\nf 1 2 3\n")
obj_case("obj-no-faces", E + M + r"contains no faces", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")
obj_case("obj-empty", E + M + r"contains no faces", "")
obj_case("obj-binary-garbage", E + M + r"line \d+: ", bytes(range(1, 256)) * 4 + b"\nf 1 2\n")
obj_case("obj-face-words", E + M + r"invalid OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf a b c\n")

# --- PLY meshes and conductors (issue 26) -------------------------------------------------------
P = r"scene\.json: objects\[0\]\.file: .*mesh\.ply: "
PLY_HEAD = ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n")
PLY_TRI = "0 0 0\n1 0 0\n0 1 0\n"


def ply_case(name, pattern, ply):
    render_case(name, pattern, mesh_scene("mesh.ply"), extra={"mesh.ply": ply})


ply_case("ply-not-ply", E + P + r"header line 1: not a PLY file", "PLY\n" + PLY_HEAD[4:] + PLY_TRI + "3 0 1 2\n")
ply_case("ply-index-out-of-range", E + P + r"line 13: face 0 names vertex 3, the file has 3", PLY_HEAD + PLY_TRI + "3 0 1 3\n")
ply_case("ply-two-corners", E + P + r"line 13: face 0 has 2 corners", PLY_HEAD + PLY_TRI + "2 0 1\n")
ply_case("ply-vertex-nan", E + P + r"line 11: vertex 1's x is not finite", PLY_HEAD + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
ply_case("ply-truncated-ascii", E + P + r"line 13: the data ends early", PLY_HEAD + PLY_TRI + "3 0 1")
ply_case("ply-binary-truncated", E + P + r"byte \d+: the data ends early",
         PLY_HEAD.replace("ascii", "binary_little_endian").encode() + struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + b"\x03\x00\x00")
ply_case("ply-huge-count", E + P + r"header line 3: element \"vertex\" declares 4000000000 records",
         PLY_HEAD.replace("vertex 3", "vertex 4000000000").replace("ascii", "binary_big_endian"))
ply_case("ply-unknown-format", E + P + r"header line 2: unknown format", PLY_HEAD.replace("ascii", "utf8") + PLY_TRI)
ply_case("ply-no-faces", E + P + r"contains no faces", PLY_HEAD.replace("face 1", "face 0") + PLY_TRI)


def gz(data):
    """gzip bytes that do not depend on when they were written (mtime 0)."""
    return gzip.compress(data.encode() if isinstance(data, str) else data, mtime=0)


# .ply.gz (scene/gzip_file.hpp): inflated by name, its errors at the object's file.
GZ_P = r"scene\.json: objects\[0\]\.file: .*mesh\.ply\.gz: "
render_case("ply-gz-not-gzip", E + GZ_P + r"not a valid gzip file \(incorrect header check\)", mesh_scene("mesh.ply.gz"),
            extra={"mesh.ply.gz": PLY_HEAD + PLY_TRI + "3 0 1 2\n"})
render_case("ply-gz-truncated", E + GZ_P + r"truncated gzip data", mesh_scene("mesh.ply.gz"),
            extra={"mesh.ply.gz": gz(PLY_HEAD + PLY_TRI + "3 0 1 2\n")[:40]})
render_case("ply-gz-corrupt-ply", E + GZ_P + r"line 13: face 0 names vertex 3, the file has 3", mesh_scene("mesh.ply.gz"),
            extra={"mesh.ply.gz": gz(PLY_HEAD + PLY_TRI + "3 0 1 3\n")})
# 24 MiB of zeros in a 24 kB .gz, under an 8 MiB budget: the inflated buffer is charged before
# each time it grows, so the load stops at the growth that passes the budget (scene/gzip_file.hpp).
render_case("ply-gz-inflated-over-budget", E + GZ_P + r"the inflated mesh \(growing to [\d.]+ MB\) needs [\d.]+ MB, "
            r"which would bring the scene's data to [\d.]+ MB, over the load budget of 8\.4 MB \(--max-memory\)",
            mesh_scene("mesh.ply.gz"), args="--max-memory 8M", extra={"mesh.ply.gz": gz(bytes(24 << 20))})
render_case("ply-materials-from-obj", E + r"scene\.json: objects\[0\]\.materials: a PLY mesh has no materials",
            mesh_scene("mesh.ply", materials="from_obj").replace(', "material": "m"', ""),
            extra={"mesh.ply": PLY_HEAD + PLY_TRI + "3 0 1 2\n"})
C = r"scene\.json: materials\.m"
render_case("conductor-eta-negative", E + C + r"\.eta\[1\]: ", scene(materials__m={"type": "conductor", "eta": [0.2, -1, 1], "k": 3}))
render_case("conductor-eta-zero", E + C + r"\.eta: ", scene(materials__m={"type": "conductor", "eta": 0, "k": 3}))
render_case("conductor-k-negative", E + C + r"\.k: ", scene(materials__m={"type": "conductor", "eta": 1, "k": -0.5}))
render_case("conductor-unknown-metal", E + C + r"\.metal: unknown metal \"Gold\" \(known: Ag, Al, Au, Cu, CuZn, MgO, TiO2",
            scene(materials__m={"type": "conductor", "metal": "Gold"}))
render_case("conductor-metal-and-eta", E + C + r": give either \"metal\" or \"eta\" and \"k\", not both",
            scene(materials__m={"type": "conductor", "metal": "Au", "eta": 1, "k": 2}))
render_case("conductor-nothing", E + C + r": a conductor needs \"metal\"", scene(materials__m={"type": "conductor"}))
render_case("conductor-eta-without-k", E + C + r"\.k: missing", scene(materials__m={"type": "conductor", "eta": 1.5}))
render_case("conductor-roughness-2", E + C + r"\.roughness: ", scene(materials__m={"type": "conductor", "metal": "Cu", "roughness": 2}))

render_case("material-bump-checker", E + r"scene\.json: materials\.m\.bump_map\.checker: a bump map must be an image",
            scene(materials__m={"type": "diffuse", "bump_map": {"checker": {"a": [0, 0, 0], "b": [1, 1, 1]}}}))
render_case("material-bump-scale-alone", E + r"scene\.json: materials\.m\.bump_scale: bump_scale needs a bump_map",
            scene(materials__m={"type": "diffuse", "bump_scale": 2}))

# --- OBJ materials (mtllib / usemtl): a mesh object without "material" takes its OBJ's ----------
MTL_OBJ = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl a\nf 1/1 2/2 3/3\n"


def mtl_case(name, pattern, mtl=None, obj=MTL_OBJ):
    s = json.loads(mesh_scene())
    del s["objects"][0]["material"]
    files = {"mesh.obj": obj}
    if mtl is not None:
        files["m.mtl"] = mtl
    render_case(name, pattern, json.dumps(s), extra=files)


MF = r"scene\.json: objects\[0\]\.file: .*"
mtl_case("mtl-missing", E + MF + r"mesh\.obj: line 1: mtllib \"m\.mtl\" not found")
mtl_case("mtl-no-mtllib", E + MF + r"mesh\.obj: names no material library", obj="v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
mtl_case("mtl-usemtl-unknown", E + MF + r"mesh\.obj: line 8: usemtl \"a\": no such material", "newmtl b\nKd 1 1 1\n")
mtl_case("mtl-texture-missing", E + MF + r"m\.mtl: line 3: map_Kd: texture image \"wood\.png\" not found",
         "newmtl a\nKd 1 1 1\nmap_Kd -bm 1 wood.png\n")
mtl_case("mtl-normal-map-missing", E + MF + r"m\.mtl: line 2: normal map: texture image \"n\.png\" not found", "newmtl a\nnorm n.png\n")
mtl_case("mtl-bump-multiplier-missing", E + MF + r"m\.mtl: line 2: map_Bump -bm needs a number before the file",
         "newmtl a\nmap_Bump -bm h.png\n")
mtl_case("mtl-kd-not-number", E + MF + r"m\.mtl: line 2: Kd 'x' is not a decimal number", "newmtl a\nKd 1 x 1\n")
mtl_case("mtl-kd-over-1", E + MF + r"m\.mtl: line 2: Kd 2 is out of range", "newmtl a\nKd 2 1 1\n")
mtl_case("mtl-property-before-newmtl", E + MF + r"m\.mtl: line 1: Kd before any newmtl", "Kd 1 1 1\nnewmtl a\n")
mtl_case("mtl-duplicate-name", E + MF + r"m\.mtl: line 2: material \"a\" is already defined on line 1", "newmtl a\nnewmtl a\n")
mtl_case("mtl-nul-byte", E + MF + r"m\.mtl: line 2: contains a NUL byte", "newmtl a\nKd 1\x00 1 1\n")

# --- images (diff) -------------------------------------------------------------------------------


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def png(w, h, rows=None):
    ihdr = struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)
    raw = rows if rows is not None else b"".join(b"\0" + b"\x80" * (3 * w) for _ in range(h))
    return b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) + png_chunk(b"IDAT", zlib.compress(raw)) + png_chunk(b"IEND", b"")


def pfm(w, h, scale=-1.0, data=None):
    body = data if data is not None else struct.pack("<f", 0.5) * (3 * w * h)
    return f"PF\n{w} {h}\n{scale}\n".encode() + body


def exr_header(w, h, compression=0):
    def attr(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value
    channels = b"".join(c + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
    box = struct.pack("<iiii", 0, 0, w - 1, h - 1)
    return (b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + attr("channels", "chlist", channels) +
            attr("compression", "compression", bytes([compression])) + attr("dataWindow", "box2i", box) +
            attr("displayWindow", "box2i", box) + attr("lineOrder", "lineOrder", b"\0") +
            attr("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
            attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
            attr("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")


def tga(w, h, image_type=2, data=None):
    """A TGA header (no ID, no colour map, 24-bit, rows bottom-up) and its pixels, grey by default."""
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, image_type, 0, 0, 0, 0, 0, w, h, 24, 0)
    return header + (data if data is not None else b"\x80" * (3 * w * h))


GOOD = png(4, 4)
GOOD_PFM = pfm(4, 4)


def diff_case(name, pattern, bad, bad_name="bad.png", args="", setup=""):
    case(name, 2, pattern, f"diff {bad_name} good.png {args}".strip(), {bad_name: bad, "good.png": GOOD}, setup)


case("image-missing", 2, E + r"cannot read 'nothere\.png': no such file", "diff nothere.png good.png", {"good.png": GOOD})
diff_case("png-garbage", E + r"cannot read 'bad\.png': not a valid PNG \(.+\)", b"this is not a png at all")
diff_case("png-empty", E + r"cannot read 'bad\.png': not a valid PNG \(.+\)", b"")
diff_case("png-truncated", E + r"cannot read 'bad\.png': not a valid PNG \(.+\)", png(16, 16)[:60])
diff_case("png-huge-header", E + r"cannot read 'bad\.png': PNG size 10000x10000 is out of range", png(10000, 10000, b""))
diff_case("png-wide-header", E + r"cannot read 'bad\.png': PNG size 16777216x1 is out of range|cannot read 'bad\.png': not a valid PNG",
          png(1 << 24, 1, b""))
# Found by tests/fuzz/fuzz_png: stb reallocates to 2 GB for a chunk length the file cannot hold.
with open(os.path.join(HERE, "..", "fuzz", "corpus", "png", "regression-idat-length-2gb.png"), "rb") as f:
    diff_case("png-chunk-length-bomb", E + r"cannot read 'bad\.png': not a valid PNG \(chunk at byte \d+ claims \d+ bytes", f.read())
diff_case("png-no-iend", E + r"cannot read 'bad\.png': not a valid PNG \(no IEND chunk\)", GOOD[:-12])
diff_case("pfm-bad-magic", E + r"cannot read 'bad\.pfm': not a valid PFM file: magic number is 'P6'", b"P6\n4 4\n255\n", "bad.pfm")
diff_case("pfm-empty", E + r"cannot read 'bad\.pfm': not a valid PFM file: header ends before the magic number", b"", "bad.pfm")
diff_case("pfm-width-zero", E + r"cannot read 'bad\.pfm': PFM size 0x4 is out of range", pfm(0, 4), "bad.pfm")
diff_case("pfm-width-text", E + r"cannot read 'bad\.pfm': not a valid PFM file: the width 'abc' is not an integer",
          b"PF\nabc 4\n-1\n", "bad.pfm")
diff_case("pfm-huge-size", E + r"cannot read 'bad\.pfm': PFM size 70000x70000 is out of range", pfm(70000, 70000, data=b""), "bad.pfm")
diff_case("pfm-too-many-pixels", E + r"cannot read 'bad\.pfm': PFM size 65536x65536 is out of range", pfm(65536, 65536, data=b""), "bad.pfm")
diff_case("pfm-truncated-data", E + r"cannot read 'bad\.pfm': not a valid PFM file: pixel data is \d+ bytes", pfm(4, 4)[:-7], "bad.pfm")
diff_case("pfm-scale-zero", E + r"cannot read 'bad\.pfm': not a valid PFM file: scale must be a non-zero number", pfm(4, 4, 0.0), "bad.pfm")
diff_case("pfm-scale-nan", E + r"cannot read 'bad\.pfm': not a valid PFM file: (scale|the scale)", pfm(4, 4, "nan"), "bad.pfm")
diff_case("pfm-no-separator", E + r"cannot read 'bad\.pfm': not a valid PFM file: no whitespace byte", b"PF\n4 4\n-1", "bad.pfm")
diff_case("exr-garbage", E + r"cannot read 'bad\.exr': not a valid EXR file \(.+\)", b"not an exr file, just text", "bad.exr")
diff_case("exr-empty", E + r"cannot read 'bad\.exr': not a valid EXR file \(.+\)", b"", "bad.exr")
diff_case("exr-header-only", E + r"cannot read 'bad\.exr': not a valid EXR file \(.+\)", exr_header(4, 4), "bad.exr")
# ZIP compression (3): 16 lines per block, so the offset table of 16384 lines is 1024 entries.
diff_case("exr-huge-window", E + r"cannot read 'bad\.exr': EXR data window size 16384x16384 is out of range",
          exr_header(16384, 16384, 3) + b"\0" * 8 * 1024, "bad.exr")
diff_case("tga-truncated-pixels", E + r"cannot read 'bad\.tga': not a valid TGA file \(4x4 pixels need 48 bytes after byte 18, the file has 47\)",
          tga(4, 4)[:-1], "bad.tga")
# One run packet of 128 pixels in a 16-pixel image.
diff_case("tga-rle-overrun", E + r"cannot read 'bad\.tga': not a valid TGA file \(the RLE packet at byte 18 runs past the image",
          tga(4, 4, 10, b"\xff\x80\x80\x80"), "bad.tga")
diff_case("tga-huge-header", E + r"cannot read 'bad\.tga': TGA size 65535x65535 is out of range", tga(65535, 65535, data=b""), "bad.tga")
diff_case("image-unknown-extension", E + r"cannot read 'bad\.bmp': unknown image extension '\.bmp'", b"BM", "bad.bmp")
case("image-directory", 2, E + r"cannot read 'adir\.png': is a directory", "diff adir.png good.png", {"adir.png/keep": "", "good.png": GOOD})
case("image-fifo", 2, E + r"cannot read 'pipe\.pfm': is a FIFO, not a regular file", "diff pipe.pfm good.png", {"good.png": GOOD}, "fifo pipe.pfm")
case("image-over-size-limit", 2, E + r"cannot read 'big\.pfm': larger than the 1024 MiB", "diff big.pfm good.png", {"good.png": GOOD},
     "sparse big.pfm 1073741825")

# --- command lines -------------------------------------------------------------------------------
OK = {"scene.json": scene()}


def cli_case(name, pattern, args, files=None, setup=""):
    case(name, 2, pattern, args, dict(OK, **(files or {})), setup)


cli_case("cli-no-subcommand", E + r"A subcommand is required", "")
cli_case("cli-unknown-subcommand", E + r"A subcommand is required|not expected: paint", "paint scene.json")
cli_case("cli-unknown-option", E + r"The following argument was not expected: --bogus", "render scene.json -o out.png --bogus")
cli_case("cli-render-no-scene", E + r"scene is required", "render -o out.png")
cli_case("cli-spp-0", E + r"--spp: must be in \[1, 1048576\], got 0", "render scene.json -o out.png --spp 0")
cli_case("cli-spp-text", E + r"--spp: must be an integer in \[1, 1048576\], got 'abc'", "render scene.json -o out.png --spp abc")
cli_case("cli-spp-huge", E + r"--spp: must be in \[1, 1048576\], got 99999999", "render scene.json -o out.png --spp 99999999")
cli_case("cli-spp-beyond-int64", E + r"--spp: must be an integer in", "render scene.json -o out.png --spp 99999999999999999999999")
cli_case("cli-width-0", E + r"--width: must be in \[1, 16384\], got 0", "render scene.json -o out.png --width 0")
cli_case("cli-width-huge", E + r"--width: must be in \[1, 16384\], got 100000000", "render scene.json -o out.png --width 100000000")
cli_case("cli-width-derived-height", E + r"--width: keeping the film's aspect ratio \(8 to 64\) makes the other side 131072",
         "render scene.json -o out.png --width 16384", {"scene.json": scene(film__height=64)})
cli_case("cli-height-negative", E + r"--height: must be in \[1, 16384\], got -5", "render scene.json -o out.png --height -5")
cli_case("cli-height-float", E + r"--height: must be an integer", "render scene.json -o out.png --height 2.5")
cli_case("cli-depth-0", E + r"--max-depth: must be in \[1, 1024\], got 0", "render scene.json -o out.png --max-depth 0")
cli_case("cli-depth-huge", E + r"--max-depth: must be in \[1, 1024\], got 99999999", "render scene.json -o out.png --max-depth 99999999")
cli_case("cli-seed-negative", E + r"--seed: must be an integer in \[0, 18446744073709551615\], got '-1'", "render scene.json -o out.png --seed -1")
cli_case("cli-seed-exponent", E + r"--seed: must be an integer", "render scene.json -o out.png --seed 1e3")
cli_case("cli-seed-beyond-uint64", E + r"--seed: must be an integer", "render scene.json -o out.png --seed 99999999999999999999999")
cli_case("cli-threads-negative", E + r"--threads: must be an integer in \[0, 1024\]", "render scene.json -o out.png --threads -1")
cli_case("cli-threads-huge", E + r"--threads: must be an integer in \[0, 1024\]", "render scene.json -o out.png --threads 100000")
cli_case("cli-threads-text", E + r"--threads: must be an integer", "render scene.json -o out.png --threads 2x")
cli_case("cli-bench-threads-huge", E + r"bench: --threads must be in \[1, 1024\], got 100000", "bench scene.json --threads 100000")
cli_case("cli-bench-spp-huge", E + r"bench: --spp must be in \[1, 1048576\]", "bench scene.json --spp 2000000")
cli_case("cli-bench-repeat-0", E + r"bench: --repeat must be in \[1, 1000\], got 0", "bench scene.json --repeat 0")
cli_case("cli-accel-unknown", E + r"--accel: foo not in \{bvh,embree\}|--accel", "render scene.json -o out.png --accel foo")
cli_case("cli-max-memory-text", E + r"--max-memory: must be a size", "render scene.json -o out.png --max-memory lots")
cli_case("cli-max-memory-negative", E + r"--max-memory: must be a size", "render scene.json -o out.png --max-memory=-5G")
cli_case("cli-max-memory-refuses", E + r"scene\.json: the render needs an estimated .* more than the 1 kB that --max-memory allows",
         "render scene.json -o out.png --max-memory 1k")
cli_case("cli-memory-over-available", E + r"scene\.json: the render needs an estimated .*film 16384x16384.* more than",
         "render scene.json -o out.png --width 16384 --height 16384 --max-memory 2G")
cli_case("cli-output-extension", E + r"output 'out\.bmp': unknown image extension '\.bmp'", "render scene.json -o out.bmp")
cli_case("cli-output-no-dir", E + r"output 'nodir/out\.png': directory 'nodir' does not exist", "render scene.json -o nodir/out.png")
cli_case("cli-diff-one-arg", E + r"diff needs two images A B", "diff a.png", {"a.png": GOOD})
cli_case("cli-diff-negative-rmse", E + r"--max-rmse", "diff a.png a.png --max-rmse -1", {"a.png": GOOD})
cli_case("cli-diff-share-range", E + r"--max-share", "diff a.png a.png --max-share 2", {"a.png": GOOD})

# --- output paths that name an input -------------------------------------------------------------
O = E + r"output '"
case("out-is-scene-default-name", 2, O + r"scene\.png' is the scene 'scene\.png'", "render scene.png --quiet", {"scene.png": scene()})
case("out-is-scene", 2, O + r"scene\.pfm' is the scene 'scene\.pfm'", "render scene.pfm -o scene.pfm --quiet", {"scene.pfm": scene()})
case("out-is-scene-dotted", 2, O + r"\./sub/\.\./scene\.exr' is the scene 'scene\.exr'", "render scene.exr -o ./sub/../scene.exr --quiet",
     {"scene.exr": scene(), "sub/keep": ""})
case("out-is-scene-symlink", 2, O + r"link\.png' is the scene 'scene\.json'", "render scene.json -o link.png --quiet",
     {"scene.json": scene()}, "symlink link.png scene.json")
case("out-is-scene-hardlink", 2, O + r"hard\.png' is the scene 'scene\.json'", "render scene.json -o hard.png --quiet",
     {"scene.json": scene()}, "hardlink hard.png scene.json")
case("out-is-mesh", 2, O + r"mesh\.exr' is the scene's input '.*mesh\.exr'", "render scene.json -o mesh.exr --quiet",
     {"scene.json": mesh_scene("mesh.exr"), "mesh.exr": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"})
case("out-is-mesh-in-subdir", 2, O + r"m/tri\.png' is the scene's input '.*tri\.png'", "render scene.json -o m/tri.png --quiet",
     {"scene.json": mesh_scene("m/tri.png"), "m/tri.png": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"})
case("out-is-mesh-symlink", 2, O + r"link\.pfm' is the scene's input 'tri\.obj'", "render scene.json -o link.pfm --quiet",
     {"scene.json": mesh_scene("tri.obj"), "tri.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}, "symlink link.pfm tri.obj")
case("forensics-not-json", 2, E + r"--forensics 'f\.txt': the report is a \.json file",
     "render scene.json -o out.png --forensics f.txt --quiet", {"scene.json": scene()})
case("forensics-picture-is-output", 2, E + r"--forensics picture 'out-regions\.png' is the same file as output 'out-regions\.png'",
     "render scene.json -o out-regions.png --forensics out.json --quiet", {"scene.json": scene()})
case("forensics-is-scene", 2, E + r"--forensics 'scene\.json' is the scene 'scene\.json'",
     "render scene.json -o out.png --forensics scene.json --quiet", {"scene.json": scene()})
case("heatmap-is-a", 2, E + r"--heatmap 'a\.png' is the image A 'a\.png'", "diff a.png b.png --heatmap a.png", {"a.png": GOOD, "b.png": GOOD})
case("heatmap-is-b-dotted", 2, E + r"--heatmap '\./b\.png' is the image B 'b\.png'", "diff a.png b.png --heatmap ./b.png", {"a.png": GOOD, "b.png": GOOD})
case("heatmap-is-variance", 2, E + r"--heatmap 'v\.pfm' is the --variance-a image 'v\.pfm'",
     "diff a.pfm b.pfm --variance-a v.pfm --variance-b v.pfm --heatmap v.pfm",
     {"a.pfm": GOOD_PFM, "b.pfm": GOOD_PFM, "v.pfm": GOOD_PFM})
case("heatmap-is-symlink-to-a", 2, E + r"--heatmap 'h\.png' is the image A 'a\.png'", "diff a.png b.png --heatmap h.png",
     {"a.png": GOOD, "b.png": GOOD}, "symlink h.png a.png")


# --- pbrt-v4 scenes (the importer, scene/pbrt/pbrt_*): file:line, the fix, nothing written -------------
PBRT_OK = 'Film "rgb" "integer xresolution" 8 "integer yresolution" 8\nWorldBegin\n'


def pbrt_case(name, pattern, text, command="render", extra=None, args="", setup=""):
    files = {"scene.pbrt": text}
    files.update(extra or {})
    out = "out.json" if command == "convert" else "out.png"
    case(name, 2, pattern, f"{command} scene.pbrt -o {out} --quiet {args}".strip(), files, setup)


pbrt_case("pbrt-unknown-directive", E + r"scene\.pbrt:3: unknown directive \"Shpae\"", PBRT_OK + 'Shpae "sphere"\n')
pbrt_case("pbrt-unclosed-bracket", E + r"scene\.pbrt:3: the values of \"float radius\" are not closed: add '\]'",
          PBRT_OK + 'Shape "sphere" "float radius" [ 1\n')
pbrt_case("pbrt-unclosed-bracket-convert", E + r"scene\.pbrt:3: the values of \"float radius\" are not closed",
          PBRT_OK + 'Shape "sphere" "float radius" [ 1\n', command="convert")
pbrt_case("pbrt-unterminated-string", E + r"scene\.pbrt:3: unterminated string", PBRT_OK + 'Shape "sphere\n')
pbrt_case("pbrt-bad-type", E + r"scene\.pbrt:3: unknown parameter type \"flaot\"", PBRT_OK + 'Shape "sphere" "flaot radius" 1\n')
pbrt_case("pbrt-number-is-string", E + r"scene\.pbrt:3: \"float radius\" takes finite numbers", PBRT_OK + 'Shape "sphere" "float radius" "one"\n')
pbrt_case("pbrt-number-overflow", E + r"scene\.pbrt:3: \"float radius\" takes finite numbers", PBRT_OK + 'Shape "sphere" "float radius" 1e999\n')
pbrt_case("pbrt-point3-count", E + r"scene\.pbrt:3: \"point3 P\" takes a multiple of 3 numbers",
          PBRT_OK + 'Shape "trianglemesh" "point3 P" [0 0 0 1 0]\n')
pbrt_case("pbrt-index-out-of-range", E + r"scene\.pbrt:3: Shape \"trianglemesh\": index 7 out of range",
          PBRT_OK + 'Shape "trianglemesh" "point3 P" [0 0 0 1 0 0 0 1 0] "integer indices" [0 1 7]\n')
pbrt_case("pbrt-shape-before-world", E + r"scene\.pbrt:1: Shape must come after WorldBegin", 'Shape "sphere"\nWorldBegin\n')
pbrt_case("pbrt-attribute-end-unmatched", E + r"scene\.pbrt:3: AttributeEnd without a matching AttributeBegin", PBRT_OK + "AttributeEnd\n")
pbrt_case("pbrt-named-material-missing", E + r"scene\.pbrt:4: NamedMaterial \"steel\": no material of that name",
          PBRT_OK + 'NamedMaterial "steel"\nShape "sphere"\n')
pbrt_case("pbrt-texture-missing", E + r"scene\.pbrt:3: \"texture reflectance\": no spectrum texture named \"wood\"",
          PBRT_OK + 'Material "diffuse" "texture reflectance" "wood"\n')
pbrt_case("pbrt-include-missing", E + r"scene\.pbrt:3: Include: .*nothere\.pbrt: cannot read pbrt scene: no such file",
          PBRT_OK + 'Include "nothere.pbrt"\n')
pbrt_case("pbrt-include-cycle", E + r"loop\.pbrt:1: Include nested deeper than 16 files",
          PBRT_OK + 'Include "loop.pbrt"\n', extra={"loop.pbrt": 'Include "loop.pbrt"\n'})
pbrt_case("pbrt-plymesh-missing", E + r"scene\.pbrt:3: Shape \"plymesh\": \"gone\.ply\" not found",
          PBRT_OK + 'Shape "plymesh" "string filename" "gone.ply"\n')
# A mesh file the JSON loader refuses is said at the pbrt statement that named it, not at the JSON.
pbrt_case("pbrt-plymesh-corrupt", E + r"scene\.pbrt:3: Shape \"plymesh\": .*bad\.ply: header line 1: not a PLY file",
          PBRT_OK + 'Shape "plymesh" "string filename" "bad.ply"\n', extra={"bad.ply": "PLY\n" + PLY_HEAD[4:] + PLY_TRI + "3 0 1 2\n"})
pbrt_case("pbrt-plymesh-gz-truncated", E + r"scene\.pbrt:4: Shape \"plymesh\": .*mesh\.ply\.gz: truncated gzip data",
          PBRT_OK + 'Shape "sphere"\nShape "plymesh" "string filename" "mesh.ply.gz"\n',
          extra={"mesh.ply.gz": gz(PLY_HEAD + PLY_TRI + "3 0 1 2\n")[:-6]}, command="convert")
# 17 MiB of spaces in 17 KB: refused once the inflated text passes the 16 MiB a pbrt file may hold.
pbrt_case("pbrt-include-gz-bomb", E + r"scene\.pbrt:3: Include: .*bomb\.pbrt\.gz: decompressed size exceeds the 16 MiB limit",
          PBRT_OK + 'Include "bomb.pbrt.gz"\n', extra={"bomb.pbrt.gz": gz(b" " * (17 << 20))})
pbrt_case("pbrt-spectrum-file-missing",
          E + r"scene\.pbrt:3: material \"conductor\": \"spectrum eta\": \"spds/Au\.eta\.spd\" is not a named spectrum, "
          r"and no spectrum file of that name was found",
          PBRT_OK + 'Material "conductor" "spectrum eta" "spds/Au.eta.spd" "spectrum k" "spds/Au.k.spd"\nShape "sphere"\n')
pbrt_case("pbrt-spectrum-file-decreasing",
          E + r"scene\.pbrt:3: material \"conductor\": \"spectrum k\": spectrum file \"k\.spd\": line 4: wavelength 450 after 500",
          PBRT_OK + 'Material "conductor" "spectrum eta" "eta.spd" "spectrum k" "k.spd"\nShape "sphere"\n',
          extra={"eta.spd": "400 0.5\n800 0.5\n", "k.spd": "# k\n400 3\n500 3\n450 3\n"})
pbrt_case("pbrt-lookat-degenerate", E + r"scene\.pbrt:1: LookAt: the eye and the point looked at must differ",
          'LookAt 0 0 0  0 0 0  0 1 0\nWorldBegin\n')
pbrt_case("pbrt-fov-180", E + r"scene\.pbrt:1: Camera \"perspective\": \"fov\" must be strictly between 0 and 180",
          'Camera "perspective" "float fov" 180\nWorldBegin\n')
pbrt_case("pbrt-binary-file", E + r"scene\.pbrt:1: control byte 1", "Shape\x01\x02")
pbrt_case("pbrt-strict-unsupported", E + r"scene\.pbrt:3: Shape \"curve\" is not supported \(ignored\) \(--strict makes this an error\)",
          PBRT_OK + 'Shape "curve"\nShape "sphere"\n', args="--strict")
pbrt_case("pbrt-strict-unsupported-convert", E + r"scene\.pbrt:3: MakeNamedMedium \"fog\": medium type \"cloud\" is not supported",
          PBRT_OK + 'MakeNamedMedium "fog" "string type" "cloud"\n', command="convert", args="--strict")
case("pbrt-convert-not-pbrt", 2, E + r"convert reads pbrt-v4 scenes \(\.pbrt\), got 'scene\.json'", "convert scene.json -o out.json",
     {"scene.json": scene()})
case("pbrt-convert-out-not-json", 2, E + r"output 'out\.png': write the scene to a \.json file", "convert scene.pbrt -o out.png",
     {"scene.pbrt": PBRT_OK})
case("pbrt-convert-out-is-input", 2, E + r"output 'scene\.json' is the scene 'scene\.pbrt'", "convert scene.pbrt -o scene.json",
     {"scene.pbrt": PBRT_OK}, "symlink scene.json scene.pbrt")


# --- issue 32: the files a scene reads are protected, one memory budget, pbrt errors at pbrt lines --
# Every file the load read (read_files.hpp) is an input an output may not be: textures, maps,
# Includes, spectra, a pbrt Film's filename; by identity, so links count.
IN = r"' is the scene's input '"
TEX_SCENE = scene(materials__m={"type": "diffuse", "albedo": {"image": {"file": "tex.png"}}})
case("out-is-texture", 2, O + r"tex\.png" + IN + r"tex\.png'", "render scene.json -o tex.png --quiet",
     {"scene.json": TEX_SCENE, "tex.png": GOOD})
case("out-is-texture-hardlink", 2, O + r"h\.png" + IN + r"tex\.png'", "render scene.json -o h.png --quiet",
     {"scene.json": TEX_SCENE, "tex.png": GOOD}, "hardlink h.png tex.png")
case("out-is-texture-symlink", 2, O + r"s\.png" + IN + r"tex\.png'", "render scene.json -o s.png --quiet",
     {"scene.json": TEX_SCENE, "tex.png": GOOD}, "symlink s.png tex.png")
ENV_SCENE = scene(background={"environment": {"file": "env.pfm"}})
case("out-is-environment", 2, O + r"env\.pfm" + IN + r"env\.pfm'", "render scene.json -o env.pfm --quiet",
     {"scene.json": ENV_SCENE, "env.pfm": GOOD_PFM})
case("variance-is-environment", 2, E + r"--variance 'env\.pfm" + IN + r"env\.pfm'", "render scene.json -o out.png --variance env.pfm --quiet",
     {"scene.json": ENV_SCENE, "env.pfm": GOOD_PFM})
case("out-is-normal-map", 2, O + r"n\.png" + IN + r"n\.png'", "render scene.json -o n.png --quiet",
     {"scene.json": scene(materials__m={"type": "diffuse", "normal_map": {"image": {"file": "n.png"}}}), "n.png": GOOD})
case("pbrt-out-is-include", 2, O + r"inc\.png" + IN + r"inc\.png'", "render scene.pbrt -o inc.png --quiet",
     {"scene.pbrt": PBRT_OK + 'Include "inc.png"\n', "inc.png": 'Shape "sphere"\n'})
case("pbrt-convert-out-is-spectrum", 2, O + r"eta\.json" + IN + r"eta\.json'", "convert scene.pbrt -o eta.json --quiet",
     {"scene.pbrt": PBRT_OK + 'Material "conductor" "spectrum eta" "eta.json" "spectrum k" "k.spd"\nShape "sphere"\n',
      "eta.json": "400 1.5\n800 1.5\n", "k.spd": "400 3\n800 3\n"})
case("pbrt-film-filename-is-texture", 2, O + r"tex\.png" + IN + r"tex\.png'", "render scene.pbrt --quiet",
     {"scene.pbrt": 'Film "rgb" "integer xresolution" 8 "integer yresolution" 8 "string filename" "tex.png"\nWorldBegin\n'
                    'Texture "t" "spectrum" "imagemap" "string filename" "tex.png"\nMaterial "diffuse" "texture reflectance" "t"\n'
                    'Shape "sphere"\n', "tex.png": GOOD})

# Memory: one budget for the load (load_budget.hpp), run under a 4 GB address space as a user's
# `ulimit -v` would; each used to end in bad_alloc (exit 3) or take 4-16 GB.
AS = "address-space 4096"
# 2,000,000 faces of 255 uchar corners in a 2 MB .ply.gz (written by the runner): 488 MiB
# inflated, 2 GB of corners, 506 M triangles (6 GB): refused when the faces are charged, counted
# before a corner is read.
render_case("mem-ply-gz-fans", E + r"scene\.json: objects\[0\]\.file: .*fans\.ply\.gz: 2000000 faces as 506000000 triangles "
            r"\(510000000 corners\) needs 8\.13 GB, "
            r"which would bring the scene's data to .*, over the load budget of .* \(the memory available; --max-memory sets it\)",
            mesh_scene("fans.ply.gz"), setup="ply-gz-fans fans.ply.gz 2000000 ; " + AS)
# Six 2 MiB RLE TGAs of 8192 x 8192 (0.8 GB each decoded, each within the per-image limit): the
# sum is what the budget refuses, at the first image past it.
six = json.loads(scene())
six["materials"] = {f"m{i}": {"type": "diffuse", "albedo": {"image": {"file": f"t{i}.tga"}}} for i in range(6)}
six["objects"] = [{"type": "sphere", "radius": 0.1, "center": [i, 0, 0], "material": f"m{i}"} for i in range(6)]
render_case("mem-tga-sum", E + r"scene\.json: materials\.m\d\.albedo\.image\.file: .*t\d\.tga: TGA image 8192x8192 needs 805\.3 MB, "
            r"which would bring the scene's data to .*, over the load budget of .* \(the memory available; --max-memory sets it\)",
            json.dumps(six), setup=" ; ".join(f"rle-tga t{i}.tga 8192" for i in range(6)) + " ; " + AS)
render_case("mem-tga-max-memory", E + r"scene\.json: materials\.m1\.albedo\.image\.file: .*t1\.tga: TGA image 8192x8192 needs 805\.3 MB, "
            r"which would bring the scene's data to 1\.61 GB, over the load budget of 1\.07 GB \(--max-memory\)",
            json.dumps(six), args="--max-memory 1G", setup="rle-tga t0.tga 8192 ; rle-tga t1.tga 8192 ; " + AS)
# A 4 MB unused parameter on an AreaLightSource, then 4000 AttributeBegin levels (or 2000
# ObjectInstances): 16 GB (8 GB) when each level copied it; shared now, so the file is read to its end.
JUNK = '"float junk" [' + " 1" * 500000 + " ]"
AREA = 'AreaLightSource "diffuse" "rgb L" [1 1 1] ' + JUNK + "\n"
case("mem-pbrt-arealight-levels", 2, E + r"scene\.pbrt\.gz:4005: unknown directive \"Shpae\"", "render scene.pbrt.gz -o out.png --quiet",
     {"scene.pbrt.gz": gz(PBRT_OK + "AttributeBegin\n" + AREA + "AttributeBegin\n" * 4000 + "Shpae\n")}, AS)
case("mem-pbrt-object-instances", 2, E + r"scene\.pbrt\.gz:2007: unknown directive \"Shpae\"", "render scene.pbrt.gz -o out.png --quiet",
     {"scene.pbrt.gz": gz(PBRT_OK + 'ObjectBegin "o"\n' + AREA + 'Shape "sphere"\nObjectEnd\n' + 'ObjectInstance "o"\n' * 2000 + "Shpae\n")},
     AS)

# pbrt: the same depth limit for TransformBegin as for AttributeBegin; control characters escaped.
pbrt_case("pbrt-transform-depth", E + r"scene\.pbrt:4099: TransformBegin nested more than 4096 deep", PBRT_OK + "TransformBegin\n" * 4097)
pbrt_case("pbrt-escape-strict", E + r"scene\.pbrt:3: Shape \"cu\\x1b\[31mrve\\nsweeptrace: error: forged\"",
          PBRT_OK + 'Shape "cu\x1b[31mrve\\nsweeptrace: error: forged"\nShape "sphere"\n', args="--strict")

# The wrong kind of file is named as such, not "not found".
render_case("ply-is-directory", E + r"scene\.json: objects\[0\]\.file: mesh file \"d\.ply\" is a directory", mesh_scene("d.ply"),
            extra={"d.ply/keep": ""})
render_case("ply-is-fifo", E + r"scene\.json: objects\[0\]\.file: mesh file \"f\.ply\" is a FIFO", mesh_scene("f.ply"), setup="fifo f.ply")
render_case("ply-is-device", E + r"scene\.json: objects\[0\]\.file: mesh file \"z\.ply\" is a device", mesh_scene("z.ply"),
            setup="device z.ply /dev/zero")
render_case("texture-is-directory", E + r"scene\.json: materials\.m\.albedo\.image\.file: texture image \"tex\.png\" is a directory",
            TEX_SCENE, extra={"tex.png/keep": ""})
render_case("texture-is-fifo", E + r"scene\.json: materials\.m\.albedo\.image\.file: texture image \"tex\.png\" is a FIFO", TEX_SCENE,
            setup="fifo tex.png")
pbrt_case("pbrt-plymesh-is-device", E + r"scene\.pbrt:3: Shape \"plymesh\": \"z\.ply\" is a device",
          PBRT_OK + 'Shape "plymesh" "string filename" "z.ply"\n', setup="device z.ply /dev/zero")

# pbrt values the importer passes on are checked where they are read (file:line and the pbrt
# parameter); a check that can only fail after translation is said at the statement it came from.
F32 = r"takes numbers a 32-bit float holds"
pbrt_case("pbrt-light-scale-huge", E + r"scene\.pbrt:3: \"float scale\" " + F32, PBRT_OK + 'LightSource "point" "float scale" 1e300\n')
pbrt_case("pbrt-light-L-huge", E + r"scene\.pbrt:3: \"rgb L\" " + F32, PBRT_OK + 'AreaLightSource "diffuse" "rgb L" [1e300 1 1]\nShape "sphere"\n')
pbrt_case("pbrt-iso-huge", E + r"scene\.pbrt:1: \"float iso\" " + F32, 'Film "rgb" "float iso" 1e300\nWorldBegin\n')
pbrt_case("pbrt-maxcomponentvalue-huge", E + r"scene\.pbrt:1: \"float maxcomponentvalue\" " + F32,
          'Film "rgb" "float maxcomponentvalue" 1e300\nWorldBegin\n')
pbrt_case("pbrt-lensradius-huge", E + r"scene\.pbrt:1: \"float lensradius\" " + F32, 'Camera "perspective" "float lensradius" 1e300\nWorldBegin\n')
pbrt_case("pbrt-focaldistance-huge", E + r"scene\.pbrt:1: \"float focaldistance\" " + F32,
          'Camera "perspective" "float lensradius" 0.1 "float focaldistance" 1e300\nWorldBegin\n')
pbrt_case("pbrt-light-scale-overflow", E + r"scene\.pbrt:3: LightSource \"point\": \"I\" x \"scale\" is 1e\+6\d, too large for single precision",
          PBRT_OK + 'LightSource "point" "float scale" 1e30 "rgb I" [1e30 1e30 1e30]\n')
pbrt_case("pbrt-light-scale-overflow-convert", E + r"scene\.pbrt:3: LightSource \"point\": \"I\" x \"scale\" is 1e\+6\d, too large for single precision",
          PBRT_OK + 'LightSource "point" "float scale" 1e30 "rgb I" [1e30 1e30 1e30]\n', command="convert")
pbrt_case("pbrt-area-light-overflow", E + r"scene\.pbrt:3: AreaLightSource \"diffuse\": .*emission\[0\]: is too large for single precision, got 1\.0+1e\+60",
          PBRT_OK + 'AreaLightSource "diffuse" "rgb L" [1e30 1 1] "float scale" 1e30\nShape "sphere"\n')
pbrt_case("pbrt-iso-overflow", E + r"scene\.pbrt:3: LightSource \"point\": intensity\[0\]: is too large for single precision, got 1\.0+1e\+6\d",
          'Film "rgb" "integer xresolution" 8 "integer yresolution" 8 "float iso" 1e38\nWorldBegin\n'
          'LightSource "point" "rgb I" [1e30 1 1]\n')
pbrt_case("pbrt-focaldistance-far", E + r"scene\.pbrt:1: Camera \"perspective\": look_at: coordinates must lie within \+-1e\+18",
          'Camera "perspective" "float lensradius" 0.1 "float focaldistance" 1e30\nWorldBegin\nShape "sphere"\n')
pbrt_case("pbrt-light-singular-transform", E + r"scene\.pbrt:6: LightSource \"spot\": ",
          PBRT_OK + 'Shape "sphere"\nAttributeBegin\nScale 0 0 0\nLightSource "spot" "rgb I" [1 1 1]\nAttributeEnd\n')
pbrt_case("pbrt-tga-rle-overrun", E + r"scene\.pbrt:4: material .*t\.tga.*RLE packet at byte 18 runs past the image",
          PBRT_OK + 'Texture "t" "spectrum" "imagemap" "string filename" "t.tga"\nMaterial "diffuse" "texture reflectance" "t"\n'
          'Shape "sphere"\n', extra={"t.tga": tga(2, 2, 10, b"\x84\x80\x80\x80")})

# --- issue 40: no output overwrites another output or an input; devices and FIFOs left alone -----
# One rule for every command that writes (cli/output_guard.hpp): outputs compared with each other
# and with every file read, by the directory entry a write replaces and by device and inode; an
# existing output that is not a regular file (device, FIFO, folder) is refused, never replaced.
SAME = r" is the same file as "
NOT_REGULAR = r"; outputs are written as regular files and a non-regular one is never replaced"
case("out-variance-same", 2, E + r"--variance 'x\.exr'" + SAME + r"output 'x\.exr'",
     "render scene.json -o x.exr --variance x.exr --quiet", {"scene.json": scene(film__spp=2)})
case("out-variance-same-dotted", 2, E + r"--variance '\./x\.exr'" + SAME + r"output 'x\.exr'",
     "render scene.json -o x.exr --variance ./x.exr --quiet", {"scene.json": scene(film__spp=2)})
case("out-variance-symlink", 2, E + r"--variance 'v\.exr'" + SAME + r"output 'x\.exr'",
     "render scene.json -o x.exr --variance v.exr --quiet", {"scene.json": scene(film__spp=2), "x.exr": "an old image"},
     "symlink v.exr x.exr")
case("out-forensics-picture-dotted", 2, E + r"--forensics picture 'f-regions\.png'" + SAME + r"output '\./f-regions\.png'",
     "render scene.json -o ./f-regions.png --forensics f.json --quiet", {"scene.json": scene()})
case("merge-out-is-part", 2, E + r"output 'a\.exr' is the part 'a\.exr' \(the same file\)", "merge a.exr b.exr -o a.exr",
     {"a.exr": "a part", "b.exr": "a part"})
case("merge-out-is-part-dotted", 2, E + r"output 'sub/\.\./b\.exr' is the part 'b\.exr'", "merge a.exr b.exr -o sub/../b.exr",
     {"a.exr": "a part", "b.exr": "a part", "sub/keep": ""})
case("out-is-device", 2, E + r"output 'null\.png' is a device, not a regular file" + NOT_REGULAR,
     "render scene.json -o null.png --quiet", {"scene.json": scene()}, "device null.png /dev/null")
case("out-is-fifo", 2, E + r"output 'fifo\.png' is a FIFO, not a regular file" + NOT_REGULAR,
     "render scene.json -o fifo.png --quiet", {"scene.json": scene()}, "fifo fifo.png")
case("variance-is-device", 2, E + r"--variance 'full\.exr' is a device", "render scene.json -o out.exr --variance full.exr --quiet",
     {"scene.json": scene(film__spp=2)}, "device full.exr /dev/full")
case("forensics-is-device", 2, E + r"--forensics 'full\.json' is a device", "render scene.json -o out.png --forensics full.json --quiet",
     {"scene.json": scene()}, "device full.json /dev/full")
case("forensics-is-directory", 2, E + r"--forensics 'd\.json' is a directory", "render scene.json -o out.png --forensics d.json --quiet",
     {"scene.json": scene(), "d.json/keep": ""})
case("variance-is-directory", 2, E + r"--variance 'd\.exr' is a directory", "render scene.json -o out.exr --variance d.exr --quiet",
     {"scene.json": scene(film__spp=2), "d.exr/keep": ""})
case("merge-out-is-device", 2, E + r"output 'null\.exr' is a device", "merge a.exr -o null.exr", {"a.exr": "a part"},
     "device null.exr /dev/null")
case("merge-out-is-fifo", 2, E + r"output 'fifo\.exr' is a FIFO", "merge a.exr -o fifo.exr", {"a.exr": "a part"}, "fifo fifo.exr")
pbrt_case("convert-out-is-device", E + r"output 'out\.json' is a device", PBRT_OK, command="convert", setup="device out.json /dev/null")
case("heatmap-is-fifo", 2, E + r"--heatmap 'h\.png' is a FIFO", "diff a.png b.png --heatmap h.png", {"a.png": GOOD, "b.png": GOOD},
     "fifo h.png")
case("diff-json-is-device", 2, E + r"--json 'r\.json' is a device", "diff --golden g --actual a --json r.json",
     {"g/x.png": GOOD, "a/x.png": GOOD}, "device r.json /dev/full")
case("diff-html-page-is-golden", 2, E + r"--html panel 'g/x\.png\.golden\.png' is the --golden image 'g/x\.png\.golden\.png'",
     "diff --golden g --actual a --html g", {"g/x.png": GOOD, "g/x.png.golden.png": GOOD, "a/x.png": GOOD})

# reference-check: the same rule for its table and pictures, and its own inputs checked like render's.
REF_SCENE = PBRT_OK + 'LightSource "distant" "point3 from" [0 0 1] "point3 to" [0 0 0]\nShape "sphere"\n'
MARKED = "# <!-- reference-check: begin (generated, do not edit) -->\n# <!-- reference-check: end -->\n"
RC = E + r"reference-check: "


def refcheck_case(name, pattern, args, files=None, setup=""):
    """Folder F with one scene s (a sphere, and an 8 x 8 reference); `files` add or replace files."""
    f = {"F/s/scene-v4.pbrt": REF_SCENE, "F/s/TungstenRender.exr": GOOD_EXR}
    f.update(files or {})
    case(name, 2, pattern, ("reference-check F --spp 2 --downsample 1 " + args).strip(), f, setup)


def exr_rgb(w, h, value):
    """An uncompressed scanline EXR of FLOAT R, G, B, every pixel `value`."""
    def attr(name, kind, v):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(v)) + v
    channels = b"".join(c + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
    box = struct.pack("<iiii", 0, 0, w - 1, h - 1)
    head = (b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + attr("channels", "chlist", channels) +
            attr("compression", "compression", b"\0") + attr("dataWindow", "box2i", box) +
            attr("displayWindow", "box2i", box) + attr("lineOrder", "lineOrder", b"\0") +
            attr("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
            attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
            attr("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    line = struct.pack("<f", value) * (3 * w)
    first = len(head) + 8 * h
    offsets = b"".join(struct.pack("<Q", first + y * (8 + len(line))) for y in range(h))
    return head + offsets + b"".join(struct.pack("<ii", y, len(line)) + line for y in range(h))


GOOD_EXR = exr_rgb(8, 8, 0.5)
# The picture of scene "ref" is ref.png in --pictures: here the folder holding the reference ref.png.
refcheck_case("refcheck-pictures-over-reference", RC + r"picture 'F/ref/ref\.png' is the reference 'F/ref/ref\.png'",
              "--pictures F/ref --scene ref --reference ref.png", {"F/ref/scene-v4.pbrt": REF_SCENE, "F/ref/ref.png": GOOD})
refcheck_case("refcheck-table-is-scene", RC + r"--table 'F/s/scene\.md' is the scene 'F/s/scene\.md'",
              "--scene-file scene.md --table F/s/scene.md", {"F/s/scene.md": MARKED + REF_SCENE})
refcheck_case("refcheck-table-is-include", RC + r"--table 'F/s/inc\.md' is the scene's input '.*inc\.md'",
              "--table F/s/inc.md", {"F/s/scene-v4.pbrt": 'Include "inc.md"\n', "F/s/inc.md": MARKED + REF_SCENE})
refcheck_case("refcheck-table-is-directory", RC + r"--table 't\.md' is a directory", "--table t.md", {"t.md/keep": ""})
refcheck_case("refcheck-table-is-fifo", RC + r"--table 't\.md' is a FIFO", "--table t.md", setup="fifo t.md")
refcheck_case("refcheck-table-is-device", RC + r"--table 't\.md' is a device", "--table t.md", setup="device t.md /dev/full")
refcheck_case("refcheck-pictures-is-file", RC + r"--pictures 'p' is a regular file|--pictures 'p' .*: the pictures go into a folder",
              "--pictures p", {"p": "a file"})
refcheck_case("refcheck-reference-nan", RC + r"scene 's': reference 'F/s/TungstenRender\.exr': no pixel at the render's size is made of finite",
              "", {"F/s/TungstenRender.exr": exr_rgb(8, 8, float("nan"))})
refcheck_case("refcheck-reference-inf", RC + r"scene 's': reference 'F/s/TungstenRender\.exr': no pixel at the render's size is made of finite",
              "", {"F/s/TungstenRender.exr": exr_rgb(8, 8, float("inf"))})
refcheck_case("refcheck-reference-negative", RC + r"scene 's': reference 'F/s/TungstenRender\.exr': pixel \(0, 0\) is negative",
              "", {"F/s/TungstenRender.exr": exr_rgb(8, 8, -1.0)})
# A valid 8192 x 8192 reference (a PFM header grown by zeros) at --downsample 1: the memory estimate
# refuses the render before anything large is allocated (under a 4 GB address space).
BIG_PFM = b"PF\n8192 8192\n-1\n"
refcheck_case("mem-refcheck-reference-8192", RC + r"scene 's' needs an estimated .* \(8192x8192 from a 8192x8192 reference",
              "--reference big.pfm", {"F/s/big.pfm": BIG_PFM},
              setup=f"grow F/s/big.pfm {len(BIG_PFM) + 8192 * 8192 * 12} ; " + AS)
refcheck_case("refcheck-stand-in-missing", RC + r"--stand-in 'F/nothere\.png' not found", "--stand-in nothere.png")
refcheck_case("refcheck-scene-outside", RC + r"--scene '\.\./elsewhere': give the name of a subfolder", "--scene ../elsewhere",
              {"elsewhere/scene-v4.pbrt": REF_SCENE, "elsewhere/TungstenRender.exr": GOOD_EXR})
refcheck_case("refcheck-sppm-radius-huge", E + r"F/s/scene-v4\.pbrt:1: Integrator \"sppm\": \"float radius\" must be in \[",
              "", {"F/s/scene-v4.pbrt": 'Integrator "sppm" "float radius" [3e38]\n' + REF_SCENE})

# vcm's merging radius: checked where it is read, in a range its schedule keeps finite and non-zero.
VCM = r"scene\.json: film\.vcm_radius: must be in \[1\.1\d*e-16, 6\.3\d*e\+14\], got "
render_case("vcm-radius-huge", E + VCM + r"3e\+38", scene(film__integrator="vcm", film__vcm_radius=3e38))
render_case("vcm-radius-1e20", E + VCM + r"1e\+20", scene(film__integrator="vcm", film__vcm_radius=1e20))
render_case("vcm-radius-tiny", E + VCM, scene(film__integrator="vcm", film__vcm_radius=1e-45), args="--spp 257")
SPPM = r"scene\.pbrt:1: Integrator \"sppm\": \"float radius\" must be in \["
pbrt_case("pbrt-sppm-radius-huge", E + SPPM, 'Integrator "sppm" "float radius" [3e38]\n' + PBRT_OK)
pbrt_case("pbrt-sppm-radius-huge-convert", E + SPPM, 'Integrator "sppm" "float radius" [3e38]\n' + PBRT_OK, command="convert")
pbrt_case("pbrt-sppm-radius-tiny", E + SPPM + r".*got 1e-300", 'Integrator "sppm" "float radius" [1e-300]\n' + PBRT_OK)

# Farm parts: an empty --samples is a bad range; a part's header is checked (size, memory, kind of
# file) before its sums are read.
cli_case("part-samples-empty", E + r"--samples '': expected A:B", "render scene.json -o part.exr --samples ''")


def part_header(w, h, **changes):
    """The header of a farm part (image/partial_image.hpp) declaring w x h, and its ZIP offset table
    of zeros: the sums are not there. `changes` replace attributes: sweeptrace.KEY is given as KEY."""
    def attr(name, kind, v):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(v)) + v
    names = [b"B", b"G", b"R"] + [f"sum.{c}.{k}".encode() for c in "BGR" for k in range(4)]
    channels = b"".join(n + b"\0" + struct.pack("<iB3xii", 2 if len(n) == 1 else 0, 0, 1, 1) for n in sorted(names)) + b"\0"
    box = struct.pack("<iiii", 0, 0, w - 1, h - 1)
    strings = {"sweeptrace.part": "5", "sweeptrace.aovs": "off", "sweeptrace.fractionBits": "56", "sweeptrace.sceneHash": "0", "sweeptrace.seed": "1",
               "sweeptrace.maxDepth": "8", "sweeptrace.accel": "bvh", "sweeptrace.integrator": "path", "sweeptrace.sampler": "sobol",
               "sweeptrace.adaptive": "off", "sweeptrace.version": "0", "sweeptrace.spp": "4", "sweeptrace.samples": "0:4",
               "sweeptrace.checksum": "0"}
    strings.update({"sweeptrace." + k: v for k, v in changes.items()})
    head = (b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + attr("channels", "chlist", channels) +
            attr("compression", "compression", bytes([3])) + attr("dataWindow", "box2i", box) +
            attr("displayWindow", "box2i", box) + attr("lineOrder", "lineOrder", b"\0") +
            attr("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
            attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
            attr("screenWindowWidth", "float", struct.pack("<f", 1.0)) +
            b"".join(attr(k, "string", v.encode()) for k, v in strings.items()) + b"\0")
    return head + b"\0" * 8 * ((h + 15) // 16)


case("mem-merge-part-8192", 2, E + r"'big\.exr': merging parts of 8192x8192 needs an estimated .* more than the .* of memory available",
     "merge big.exr -o out.exr", {"big.exr": part_header(8192, 8192)}, AS)
case("merge-part-65536", 2, E + r"'big\.exr': data window is not 1\.\.16384 pixels a side", "merge big.exr -o out.exr",
     {"big.exr": part_header(65536, 65536)})
# Parts whose sample indices drew different numbers (render --sampler) are parts of different
# images: refused from their headers, naming both files and the field. A part of format 4 did
# not record its sampler: refused, saying to render it again.
case("merge-part-sampler", 2, E + r"'b\.exr' is not a part of the same render as 'a\.exr': sampler 'sobol' vs 'independent'$",
     "merge a.exr b.exr -o out.exr", {"a.exr": part_header(4, 2, samples="0:2"),
                                      "b.exr": part_header(4, 2, samples="2:4", sampler="independent")})
case("merge-part-format-4", 2, E + r"'old\.exr': part format 4, this program reads 5 \(render the part again with this program\)$",
     "merge old.exr -o out.exr", {"old.exr": part_header(4, 2, part="4")})
case("merge-part-directory", 2, E + r"cannot read 'd\.exr': is a directory", "merge d.exr -o out.exr", {"d.exr/keep": ""})
case("merge-part-fifo", 2, E + r"cannot read 'f\.exr': is a FIFO", "merge f.exr -o out.exr", {}, "fifo f.exr")
# The memory bdpt's light splats and --forensics take, charged before the render (issue 40): a
# depth-1024 bdpt may hold 1024 splats a sample for a wave of 64 tiles (671 MB), and forensics
# keeps 256 path types a region of a 1024 x 1024 image (4096 regions). Main's estimate left both
# out and rendered.
render_case("mem-bdpt-splats", E + r"scene\.json: the render needs an estimated .* \(film 128x128: .*, light splats at depth 1024: "
            r"671\.3 MB, scene: .*\), more than the .* that --max-memory allows",
            scene(film__width=128, film__height=128), args="--integrator bdpt --max-depth 1024 --max-memory 200M")
render_case("mem-forensics-regions", E + r"scene\.json: the render needs an estimated .* \(film 1024x1024: .*, --forensics: "
            r".* MB, scene: .*\), more than the .* that --max-memory allows",
            scene(film__width=1024, film__height=1024), args="--forensics f.json --max-memory 300M")


# --- participating media (issue 41, scene/load_media.hpp): placed errors, nothing written --------------
FOG = {"type": "homogeneous", "sigma_a": [0.1, 0.1, 0.1], "sigma_s": [1, 1, 1]}


def media_scene(media, **changes):
    s = json.loads(scene(**changes))
    s["media"] = media
    return json.dumps(s)


def grid(n, values, **extra):
    return dict({"type": "grid", "sigma_s": [1, 1, 1], "size": n, "density": values}, **extra)


render_case("media-sigma-negative", E + r"scene\.json: media\.fog\.sigma_s\[1\]: must be >= 0, got -1",
            media_scene({"fog": dict(FOG, sigma_s=[1, -1, 1])}))
render_case("media-scale-overflow", E + r"scene\.json: media\.fog\.sigma_a: times the medium's scale 1e\+30 is not a finite number",
            media_scene({"fog": dict(FOG, sigma_a=[1e30, 0, 0], scale=1e30)}))
render_case("media-g-one", E + r"scene\.json: media\.fog\.g: must be in \(-1, 1\)", media_scene({"fog": dict(FOG, g=1)}))
render_case("media-g-below", E + r"scene\.json: media\.fog\.g: must be in \(-1, 1\)", media_scene({"fog": dict(FOG, g=-1.5)}))
render_case("media-unknown-type", E + r"scene\.json: media\.fog\.type: unknown medium type \"cloud\" \(known: homogeneous, grid, vdb\)",
            media_scene({"fog": dict(FOG, type="cloud")}))
render_case("media-grid-wrong-size", E + r"scene\.json: media\.smoke\.density: must hold size\[0\] x size\[1\] x size\[2\] = 8 numbers, got 7",
            media_scene({"smoke": grid([2, 2, 2], [1] * 7)}))
render_case("media-grid-size-zero", E + r"scene\.json: media\.smoke\.size\[1\]: must be in \[1, 16777216\]",
            media_scene({"smoke": grid([2, 0, 2], [])}))
render_case("media-grid-density-negative", E + r"scene\.json: media\.smoke\.density\[3\]: must be >= 0, got -2",
            media_scene({"smoke": grid([2, 2, 1], [1, 1, 1, -2])}))
render_case("media-grid-box-empty", E + r"scene\.json: media\.smoke\.p1: must be above p0 on every axis",
            media_scene({"smoke": grid([1, 1, 1], [1], p0=[0, 0, 0], p1=[1, 0, 1])}))
render_case("media-grid-budget", E + r"scene\.json: medium \"smoke\"'s density grid needs 1\.2 MB, which would bring the scene's data to .* \(--max-memory\)",
            media_scene({"smoke": grid([100, 100, 30], [0] * 300000)}), args="--max-memory 1M")
render_case("media-object-unknown", E + r"scene\.json: objects\[0\]\.inside: unknown medium \"smoke\" \(defined in \"media\": fog\)",
            media_scene({"fog": FOG}, objects__0__inside="smoke"))
render_case("media-camera-unknown", E + r"scene\.json: camera\.medium: unknown medium \"fog\" \(defined in \"media\": none\)",
            media_scene({}, camera__medium="fog"))
render_case("media-interface-keys", E + r"scene\.json: materials\.m\.albedo: unknown key",
            media_scene({"fog": FOG}, materials__m={"type": "interface", "albedo": [1, 1, 1]}))
pbrt_case("pbrt-medium-unknown", E + r"scene\.pbrt:4: Shape: its MediumInterface names medium \"smoke\", which no MakeNamedMedium defines",
          PBRT_OK + 'MediumInterface "smoke" ""\nShape "sphere"\n')
pbrt_case("pbrt-medium-grid-size", E + r"scene\.pbrt:3: MakeNamedMedium \"smoke\": 3 \"density\" values, but nx x ny x nz = 2 x 2 x 1",
          PBRT_OK + 'MakeNamedMedium "smoke" "string type" "uniformgrid" "integer nx" 2 "integer ny" 2 "float density" [1 2 3]\n')
pbrt_case("pbrt-medium-lescale-size", E + r"scene\.pbrt:3: MakeNamedMedium \"glow\": 3 \"Lescale\" values, but the grid has 2 \(nx x ny x nz\)",
          PBRT_OK + 'MakeNamedMedium "glow" "string type" "uniformgrid" "integer nx" 2 "float density" [1 1] "rgb Le" [1 1 1] "float Lescale" [1 2 3]\n')
pbrt_case("pbrt-medium-g", E + r"scene\.pbrt:3: MakeNamedMedium \"fog\": \"g\" must be in \(-1, 1\)",
          PBRT_OK + 'MakeNamedMedium "fog" "string type" "homogeneous" "float g" 1\nMediumInterface "fog" ""\nShape "sphere"\n')


# VDB density grids (scene/vdb_grid.hpp): the .vdb files are written here by Debian's
# python3-openvdb (run this script with /usr/bin/python3), their random UUID replaced by a fixed
# one so that rerunning writes the same bytes.
def vdb_file(grids):
    import tempfile
    import pyopenvdb
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "g.vdb")
        pyopenvdb.write(path, grids=grids)
        data = bytearray(open(path, "rb").read())
    data[21:57] = b"00000000-0000-0000-0000-000000000000"  # the header's UUID, after magic, versions and a flag
    return bytes(data)


def float_grid(voxels, name="density", background=0.0):
    import pyopenvdb
    g = pyopenvdb.FloatGrid(background)
    g.name = name
    acc = g.getAccessor()
    for ijk, v in voxels.items():
        acc.setValueOn(ijk, v)
    return g


def vdb_scene(**medium):
    return media_scene({"smoke": dict({"type": "vdb", "sigma_s": [1, 1, 1], "file": "smoke.vdb"}, **medium)},
                       objects__0__inside="smoke", materials__m={"type": "interface"})


SMOKE = {(0, 0, 0): 1.0, (1, 0, 0): 0.5}
SMOKE_VDB = vdb_file([float_grid(SMOKE)])
render_case("media-vdb-missing", E + r"scene\.json: media\.smoke\.file: .*nothere\.vdb: not found",
            vdb_scene(file="nothere.vdb"))
render_case("media-vdb-empty-name", E + r"scene\.json: media\.smoke\.file: must name an OpenVDB \(\.vdb\) or NanoVDB \(\.nvdb\) file",
            vdb_scene(file=""))
render_case("media-vdb-not-vdb", E + r"scene\.json: media\.smoke\.file: .*smoke\.vdb: not an OpenVDB \(\.vdb\) or NanoVDB \(\.nvdb\) file",
            vdb_scene(), extra={"smoke.vdb": "# a smoke grid\n"})
render_case("media-vdb-truncated", E + r"scene\.json: media\.smoke\.file: .*smoke\.vdb: truncated: grid \"density\" ends at byte 10037, the file has 5000",
            vdb_scene(), extra={"smoke.vdb": SMOKE_VDB[:5000]})
render_case("media-vdb-truncated-header", E + r"scene\.json: media\.smoke\.file: .*smoke\.vdb: truncated or corrupt: the file \(40 bytes\) ends inside its header",
            vdb_scene(), extra={"smoke.vdb": SMOKE_VDB[:40]})
render_case("media-vdb-grid-name", E + r"scene\.json: media\.smoke\.file: .*smoke\.vdb: no grid named \"density\" \(the file holds: \"temperature\"\)",
            vdb_scene(), extra={"smoke.vdb": vdb_file([float_grid(SMOKE, name="temperature")])})


def vec3_grid(name):
    import pyopenvdb
    g = pyopenvdb.Vec3SGrid()
    g.name = name
    g.getAccessor().setValueOn((0, 0, 0), (1, 2, 3))
    return g


render_case("media-vdb-grid-type", E + r"scene\.json: media\.smoke\.file: .*smoke\.vdb: grid \"vel\" holds vec3s values; a density grid holds float",
            vdb_scene(grid="vel"), extra={"smoke.vdb": vdb_file([vec3_grid("vel")])})
render_case("media-vdb-huge-box", E + r"scene\.json: media\.smoke\.file: .*smoke\.vdb: medium \"smoke\"'s grid \"density\" \(its active box, "
            r"3001 x 3001 x 3001 voxels, dense\) needs 108\.11 GB, .* over the load budget of 1\.07 GB \(--max-memory\)",
            vdb_scene(), extra={"smoke.vdb": vdb_file([float_grid({(0, 0, 0): 1.0, (3000, 3000, 3000): 1.0})])},
            args="--max-memory 1G")
render_case("media-vdb-negative-density", E + r"scene\.json: media\.smoke\.file: .*smoke\.vdb: grid \"density\"'s voxel \(1, 0, 0\) is -2\.0+; a density must be >= 0",
            vdb_scene(), extra={"smoke.vdb": vdb_file([float_grid({(0, 0, 0): 1.0, (1, 0, 0): -2.0})])})
render_case("media-vdb-background", E + r"scene\.json: media\.smoke\.file: .*smoke\.vdb: grid \"density\"'s background value is 0\.5\d*, not 0",
            vdb_scene(), extra={"smoke.vdb": vdb_file([float_grid(SMOKE, background=0.5)])})
pbrt_case("pbrt-nanovdb-missing", E + r"scene\.pbrt:3: MakeNamedMedium \"smoke\": .*nothere\.nvdb: not found",
          PBRT_OK + 'MakeNamedMedium "smoke" "string type" "nanovdb" "string filename" "nothere.nvdb"\n'
          'MediumInterface "smoke" ""\nMaterial "interface"\nShape "sphere"\n')
pbrt_case("pbrt-nanovdb-no-filename", E + r"scene\.pbrt:3: MakeNamedMedium \"smoke\": a \"nanovdb\" medium needs \"string filename\"",
          PBRT_OK + 'MakeNamedMedium "smoke" "string type" "nanovdb"\nMediumInterface "smoke" ""\nShape "sphere"\n')
pbrt_case("pbrt-nanovdb-not-nvdb", E + r"scene\.pbrt:3: MakeNamedMedium \"smoke\": .*smoke\.nvdb: not an OpenVDB \(\.vdb\) or NanoVDB \(\.nvdb\) file",
          PBRT_OK + 'MakeNamedMedium "smoke" "string type" "nanovdb" "string filename" "smoke.nvdb"\n'
          'MediumInterface "smoke" ""\nMaterial "interface"\nShape "sphere"\n', extra={"smoke.nvdb": "NanoVDB?"})

# Media inside media with no way out (render/media/media_nesting.hpp): a boundary or the camera
# whose declared medium is not the one the surface it faces says.
FOG_BOX = {"type": "box", "min": [-2, -2, -2], "max": [2, 2, 2], "material": "i", "inside": "fog"}


def nesting_scene(**changes):
    s = json.loads(media_scene({"fog": FOG}, **changes))
    s["materials"]["i"] = {"type": "interface"}
    s["objects"].insert(0, FOG_BOX)
    return json.dumps(s)


# The ball (objects[1]) bounds fog inside and says vacuum outside, but the fog box is around it.
render_case("media-nesting-outside", E + r"scene\.json: media do not nest: objects\[1\] \(sphere\)'s \"outside\" is vacuum, but from its point "
            r"\([-\d., ]+\) along its outward normal the first surface, objects\[0\] \(box\), has \"fog\" on that side",
            nesting_scene(objects__0__radius=0.5, objects__0__inside="fog"))
# The camera, in the fog box, says vacuum (the diffuse ball beside it is no boundary: no verdict).
render_case("media-nesting-camera", E + r"scene\.json: media do not nest: the camera's \"medium\" is vacuum, but looking from \(0, 0, 1\.5\) along "
            r"\(1, 0, 0\) the first surface, objects\[0\] \(box\), has \"fog\" on that side",
            nesting_scene(camera__position=[0, 0, 1.5], camera__look_at=[0, 0, -1]))
# A glass ball filling most of the fog box says vacuum outside: seen from the box's inside first.
render_case("media-nesting-inside", E + r"scene\.json: media do not nest: objects\[0\] \(box\)'s \"inside\" is \"fog\", but from its point "
            r"\([-\d., ]+\) along its inward normal the first surface, glass ball, has vacuum on that side",
            nesting_scene(objects__0__radius=1.9, objects__0__inside="fog", objects__0__name="glass ball"))
# pbrt: a glass sphere (line 5) with vacuum outside, in a fog sphere (line 10).
pbrt_case("pbrt-medium-nesting", E + r"scene\.pbrt: media do not nest: Shape \"sphere\" \(scene\.pbrt:5\)'s \"outside\" is vacuum, but .* "
          r"the first surface, Shape \"sphere\" \(scene\.pbrt:10\), has \"fog\" on that side",
          PBRT_OK + 'MakeNamedMedium "fog" "string type" "homogeneous"\nMediumInterface "fog" ""\n'
          'Shape "sphere" "float radius" 1\nMaterial "interface"\nAttributeBegin\nMediumInterface "fog" ""\n'
          'Translate 0 0 -1\nShape "sphere" "float radius" 20\nAttributeEnd\n')


# --- sweeptrace denoise (issue 42): feature images without a channel NFOR reads, a NaN feature, a
# layer smaller than the image; the output naming the input. Written as uncompressed scanline EXRs.
def denoise_channel_names():
    names = []
    for n in ["R", "G", "B", "Albedo.R", "Albedo.G", "Albedo.B", "Ns.X", "Ns.Y", "Ns.Z", "P.Z"]:
        layer, _, rest = n.rpartition(".")
        names += [n, "Even." + n, "Odd." + n, f"{layer}Variance.{rest}" if layer else "Variance." + n]
    return names


def float_exr(w, h, channels, sampling=None):
    """An uncompressed scanline EXR of FLOAT channels {name: list of values (row-major, per
    sampled pixel)}; sampling {name: (xs, ys)} subsamples a channel."""
    sampling = sampling or {}
    names = sorted(channels)
    def attr(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value
    chlist = b"".join(n.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, *sampling.get(n, (1, 1))) for n in names) + b"\0"
    box = struct.pack("<iiii", 0, 0, w - 1, h - 1)
    header = (b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + attr("channels", "chlist", chlist) +
              attr("compression", "compression", b"\0") + attr("dataWindow", "box2i", box) +
              attr("displayWindow", "box2i", box) + attr("lineOrder", "lineOrder", b"\0") +
              attr("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
              attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
              attr("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    lines = []
    for y in range(h):
        data = b""
        for n in names:
            xs, ys = sampling.get(n, (1, 1))
            if y % ys == 0:
                sw = w // xs
                row = channels[n][(y // ys) * sw:(y // ys + 1) * sw]
                data += struct.pack(f"<{sw}f", *row)
        lines.append(struct.pack("<ii", y, len(data)) + data)
    at = len(header) + 8 * h
    table = b""
    for line in lines:
        table += struct.pack("<Q", at)
        at += len(line)
    return header + table + b"".join(lines)


def feature_exr(w=4, h=4, drop=(), nan=None, sampling=None):
    sampling = sampling or {}
    ch = {}
    for n in denoise_channel_names():
        if n in drop:
            continue
        xs, ys = sampling.get(n, (1, 1))
        ch[n] = [0.5] * ((w // xs) * (h // ys))
    if nan:
        name, x, y = nan
        ch[name][y * w + x] = float("nan")
    return float_exr(w, h, ch, sampling)


def denoise_case(name, pattern, image, args="-o out.exr"):
    case(name, 2, pattern, f"denoise in.exr {args}", {"in.exr": image})


denoise_case("denoise-no-features", E + r"'in\.exr' has no channel 'Even\.R': denoise needs colour, features",
             float_exr(4, 4, {c: [0.5] * 16 for c in "RGB"}))
denoise_case("denoise-no-odd-albedo", E + r"'in\.exr' has no channel 'Odd\.Albedo\.G'", feature_exr(drop=("Odd.Albedo.G",)))
denoise_case("denoise-nan-feature", E + r"'in\.exr': channel 'Ns\.X' is NaN at pixel \(1, 2\)", feature_exr(nan=("Ns.X", 1, 2)))
denoise_case("denoise-layer-smaller", E + r"cannot read 'in\.exr': channel 'Albedo\.R' is subsampled 2x2: its layer is smaller than the image's 4x4",
             feature_exr(sampling={"Albedo.R": (2, 2)}))
denoise_case("denoise-out-is-input", E + r"output '\./in\.exr' is the image to denoise 'in\.exr'", feature_exr(), "-o ./in.exr")
denoise_case("denoise-out-extension", E + r"output 'out\.txt': unknown image extension '\.txt'", feature_exr(), "-o out.txt")
case("denoise-not-exr", 2, E + r"cannot denoise 'in\.png': a feature image is an \.exr file", "denoise in.png -o out.exr", {"in.png": GOOD})


def main():
    with open(os.path.join(HERE, "manifest.tsv"), "w") as f:
        f.write("# name\texit\tpattern (Python re, searched in the one stderr line)\targuments\tsetup\n")
        for name, code, pattern, args, setup in cases:
            f.write(f"{name}\t{code}\t{pattern}\t{args}\t{setup}\n")
    print(f"{len(cases)} cases in {CASES}")


if __name__ == "__main__":
    main()
