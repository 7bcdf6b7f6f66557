"""Renders a sweeptrace scene with Blender's Cycles, an independent path tracer, as a reference.

Run by tools/cycles-reference.sh inside Debian's Blender (`blender -b --python THIS -- ARGS`):
  --scene scenes/cornell-box.json --size 128 --spp 1024 --runs 8 --out reference_images/cycles/cornell-box

Translates what the Cornell box uses and nothing more: quads, boxes with rotate/translate
transforms, diffuse and one-sided emissive materials, a black background, a pinhole camera
with a vertical field of view. Anything else in the scene stops the script, since a silently
approximated translation would make the comparison meaningless.

Both renderers must estimate the same integral, so the settings that would make Cycles biased or
different are turned off or matched: no clamping, no light threshold, no glossy blur, no
denoising or adaptive sampling, a 1-pixel box filter (sweeptrace's default), and bounces
effectively unlimited (both renderers end paths by unbiased Russian roulette; the test renders
sweeptrace with the same depth, --max-depth, so neither truncates).

Writes OUT-mean.pfm (the mean of the runs) and OUT-variance.pfm (the variance of that mean per
pixel and channel, from the runs' spread: independent seeds), little-endian PFM, bottom row
first as PFM stores it.
"""
import argparse
import json
import math
import os
import struct
import sys
import tempfile

import bpy
import mathutils
import numpy as np

MAX_BOUNCES = 1024  # Cycles' largest; paths end by its Russian roulette long before
ARGS = None


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="cycles_reference.py")
    p.add_argument("--scene", required=True)
    p.add_argument("--size", type=int, default=128, help="width; height follows the scene's aspect")
    p.add_argument("--spp", type=int, default=1024)
    p.add_argument("--runs", type=int, default=8)
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--out", required=True)
    # For tools/cycles-direct-check.sh, which measures why the reference is made as it is:
    p.add_argument("--direct-only", action="store_true", help="no bounces: direct light only")
    p.add_argument("--light-sampling", choices=["bsdf", "mis"], default="bsdf",
                   help="bsdf: emitters found by BSDF sampling only (the reference); mis: Cycles' light sampling + MIS")
    p.add_argument("--split-light", type=int, default=1, help="cut each emissive quad into N x N quads")
    return p.parse_args(argv)


def fail(msg):
    print(f"cycles_reference.py: error: {msg}", file=sys.stderr)
    sys.exit(2)


# sweeptrace is Y-up, Blender Z-up; both right-handed: rotate +90 degrees about X.
TO_BLENDER = np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]], dtype=float)


def rotation(axis, degrees):
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    t = math.radians(degrees)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(t) * k + (1 - math.cos(t)) * (k @ k)


def transform_points(points, transforms, where):
    pts = np.asarray(points, dtype=float)
    for i, step in enumerate(transforms or []):
        keys = set(step)
        if keys == {"rotate"}:
            pts = pts @ rotation(step["rotate"]["axis"], step["rotate"]["degrees"]).T
        elif keys == {"translate"}:
            pts = pts + np.asarray(step["translate"], dtype=float)
        else:
            fail(f"{where}.transform[{i}]: only rotate and translate are translated, got {sorted(keys)}")
    return pts


def quad_faces(corner, u, v, n=1):
    """The quad as n x n quads, wound as the quad (front = u x v)."""
    c, u, v = (np.asarray(x, dtype=float) for x in (corner, u, v))
    verts = [c + u * i / n + v * j / n for j in range(n + 1) for i in range(n + 1)]
    faces = [[j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i]
             for j in range(n) for i in range(n)]
    return verts, faces


def box_faces(lo, hi):
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    verts = [[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
             [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]]
    # Outward normals (counter-clockwise seen from outside).
    faces = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [3, 7, 6, 2], [0, 4, 7, 3], [1, 2, 6, 5]]
    return verts, faces


def make_material(name, spec, where):
    mat = bpy.data.materials.new(name)
    mat["emissive"] = spec.get("type") == "emissive"
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    kind = spec.get("type")
    if kind == "diffuse" and set(spec) <= {"type", "albedo"}:
        bsdf = nodes.new("ShaderNodeBsdfDiffuse")  # roughness 0: Lambert
        bsdf.inputs["Color"].default_value = (*spec.get("albedo", [0.8] * 3), 1.0)
        bsdf.inputs["Roughness"].default_value = 0.0
        links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    elif kind == "emissive" and set(spec) <= {"type", "emission"}:
        # sweeptrace's emitters are one-sided and reflect nothing: emission on front faces,
        # black (absorbing, emitting nothing) on back faces.
        # Cycles 3.4's light sampling of mesh emitters is biased where the light is seen near
        # grazing: with it, direct light on the upper back wall comes out 0.7-4.5% below Lambert's
        # closed form for a polygon light (worse, -10% to -51%, if the quad is cut into smaller
        # triangles), while with the emitter found by BSDF sampling alone it agrees within noise
        # (reference_images/cycles/README.md). So the reference finds the light only by BSDF
        # sampling: unbiased, noisier, and the test counts its noise.
        mat.cycles.sample_as_light = ARGS.light_sampling == "mis"
        front = nodes.new("ShaderNodeEmission")
        front.inputs["Color"].default_value = (*spec["emission"], 1.0)
        front.inputs["Strength"].default_value = 1.0
        back = nodes.new("ShaderNodeEmission")
        back.inputs["Strength"].default_value = 0.0
        geom = nodes.new("ShaderNodeNewGeometry")
        mix = nodes.new("ShaderNodeMixShader")
        links.new(geom.outputs["Backfacing"], mix.inputs["Fac"])
        links.new(front.outputs["Emission"], mix.inputs[1])
        links.new(back.outputs["Emission"], mix.inputs[2])
        links.new(mix.outputs["Shader"], out.inputs["Surface"])
    else:
        fail(f"{where}: only diffuse (albedo) and emissive (emission) materials are translated")
    return mat


def add_object(i, obj, materials):
    where = f"objects[{i}]"
    kind = obj.get("type")
    if kind == "quad":
        n = ARGS.split_light if materials[obj["material"]].get("emissive") else 1
        verts, faces = quad_faces(obj["corner"], obj["edge_u"], obj["edge_v"], n)
    elif kind == "box":
        verts, faces = box_faces(obj["min"], obj["max"])
    else:
        fail(f"{where}: type {kind!r} is not translated (quad and box only)")
    extra = set(obj) - {"name", "type", "corner", "edge_u", "edge_v", "min", "max", "material", "transform"}
    if extra:
        fail(f"{where}: keys {sorted(extra)} are not translated")
    world = transform_points(verts, obj.get("transform"), where) @ TO_BLENDER.T
    mesh = bpy.data.meshes.new(f"mesh{i}")
    mesh.from_pydata([tuple(p) for p in world], [], faces)
    mesh.update()
    ob = bpy.data.objects.new(obj.get("name", f"object{i}"), mesh)
    ob.data.materials.append(materials[obj["material"]])
    bpy.context.scene.collection.objects.link(ob)


def add_camera(cam_spec, aspect):
    if set(cam_spec) - {"position", "look_at", "up", "fov"}:
        fail("camera: only position, look_at, up and fov are translated")
    pos = np.asarray(cam_spec["position"], dtype=float)
    fwd = np.asarray(cam_spec["look_at"], dtype=float) - pos
    fwd /= np.linalg.norm(fwd)
    right = np.cross(fwd, np.asarray(cam_spec.get("up", [0, 1, 0]), dtype=float))
    right /= np.linalg.norm(right)
    up = np.cross(right, fwd)
    # Blender's camera looks down its local -Z with local +Y up.
    basis = TO_BLENDER @ np.column_stack([right, up, -fwd])
    cam = bpy.data.cameras.new("camera")
    cam.sensor_fit = "VERTICAL"
    cam.angle_y = math.radians(cam_spec["fov"])
    cam.clip_start = 1e-3
    cam.clip_end = 1e7
    ob = bpy.data.objects.new("camera", cam)
    m = np.eye(4)
    m[:3, :3] = basis
    m[:3, 3] = TO_BLENDER @ pos
    ob.matrix_world = mathutils.Matrix([list(row) for row in m])  # rows; a bare list is read as columns
    bpy.context.scene.collection.objects.link(ob)
    bpy.context.scene.camera = ob


def set_up_render(scene_spec, size, spp, threads):
    scene = bpy.context.scene
    film = scene_spec.get("film", {})
    aspect = film.get("width", 1) / film.get("height", 1)
    scene.render.engine = "CYCLES"
    scene.render.resolution_x = size
    scene.render.resolution_y = max(1, round(size / aspect))
    scene.render.resolution_percentage = 100
    scene.render.threads_mode = "FIXED" if threads else "AUTO"
    if threads:
        scene.render.threads = threads
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.color_mode = "RGB"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    c = scene.cycles
    c.device = "CPU"
    c.samples = spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.blur_glossy = 0.0
    bounces = 0 if ARGS.direct_only else MAX_BOUNCES
    for attr in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
                 "volume_bounces", "transparent_max_bounces"):
        setattr(c, attr, bounces)
    bg = scene_spec.get("background", {"color": [0, 0, 0]})
    if bg != {"color": [0, 0, 0]}:
        fail("background: only a black background is translated")
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world
    return aspect


def render_run(seed, path):
    bpy.context.scene.cycles.seed = seed
    bpy.context.scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(path)
    w, h = img.size
    px = np.array(img.pixels[:], dtype=np.float64).reshape(h, w, img.channels)[:, :, :3]
    bpy.data.images.remove(img)
    return px  # bottom row first, as Blender and PFM both store images


def write_pfm(path, rgb):
    h, w, _ = rgb.shape
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(f"PF\n{w} {h}\n-1.0\n".encode("ascii"))
        f.write(struct.pack(f"<{w * h * 3}f", *rgb.astype(np.float32).ravel()))
    os.replace(tmp, path)


def main():
    global ARGS
    args = ARGS = parse_args()
    with open(args.scene) as f:
        spec = json.load(f)
    for key in set(spec) - {"description", "camera", "film", "background", "seed", "materials", "objects"}:
        fail(f"{key}: not translated")
    bpy.ops.wm.read_factory_settings(use_empty=True)
    aspect = set_up_render(spec, args.size, args.spp, args.threads)
    materials = {name: make_material(name, m, f"materials.{name}") for name, m in spec["materials"].items()}
    for i, obj in enumerate(spec["objects"]):
        add_object(i, obj, materials)
    add_camera(spec["camera"], aspect)
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(args.runs):
            runs.append(render_run(1 + k, os.path.join(tmp, f"run{k}.exr")))
    runs = np.stack(runs)
    mean = runs.mean(axis=0)
    var_of_mean = runs.var(axis=0, ddof=1) / len(runs)
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    write_pfm(args.out + "-mean.pfm", mean)
    write_pfm(args.out + "-variance.pfm", var_of_mean)
    print(f"cycles_reference.py: {len(runs)} runs x {args.spp} spp at {mean.shape[1]}x{mean.shape[0]}: "
          f"wrote {args.out}-mean.pfm and {args.out}-variance.pfm")


main()
