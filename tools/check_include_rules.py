#!/usr/bin/env python3
"""The include rules of sweeptrace, checked: every #include in collision/ and raytracer/.

The rules (what the code is layered as; an include that breaks one is reported as file:line):

  collision    collision/ includes only collision/ and GLM (<glm/...>) besides the standard
               library: nothing of raytracer/, no other library.
  detail       collision/detail/ and collision/thesis/detail/ are the library's internals: only
               collision/ includes them.
  stage order  raytracer/'s stages, top to bottom:
                   cli -> accuracy -> render -> accel -> scene -> geometry -> collision
               A stage includes only itself and the stages below it (collision/ is below all).
               The leaves image/ (PNG/PFM/EXR, diff metrics), input_error.hpp (the
               "sweeptrace: error: ..." exception) and load_budget.hpp (the one memory
               budget of a scene load, charged by image readers and scene loaders) may be
               included by any stage and include only leaves and collision/.
               (The order is the one the code has: accuracy drives render and accel for the
               `sweeptrace accuracy` studies and cli drives it; accel builds over a Scene;
               scene's objects are geometry's Object and Transform.)
  side stages  raytracer/denoise/ (the NFOR denoiser) stands beside the chain: it includes only
               itself and the leaves, and only cli includes it (`sweeptrace denoise`,
               `render --denoise`): a denoiser works on images, never on the scene or the
               renderer.
  embree3      <embree3/...> only in raytracer/accel/embree_ray.hpp: the Embree API has one
               entry point; the other Embree files include that header.
  stb          <stb/...> only in the image I/O files, raytracer/image/*_io.cpp.
  openexr      <OpenEXR/...>, <Imath/...> only in raytracer/image/*_io.cpp.
  libjpeg      <jpeglib.h> only in raytracer/image/jpeg_io.cpp.
  zlib         <zlib.h> only in raytracer/scene/gzip_file.cpp.
  openvdb      <openvdb/...> and <nanovdb/...> (the rule "nanovdb") only in
               raytracer/scene/vdb_reader.cpp, the VDB reader module (sweeptrace-vdb.so, opened
               on the first vdb medium): the VDB readers' exceptions end there.
  cli11        <CLI/...> only in raytracer/cli/.
  nlohmann     <nlohmann/...> only in raytracer/scene/ (scene files), and in the two .cpp files
               that read or write the JSON formats of their own: accuracy/exchange.cpp (the
               exported ray families and scored results) and cli/diff_reports.cpp (diff --json).
               Never in a header: no other file sees the library.
  tinyobj      <tiny_obj_loader.h> only in raytracer/scene/.

Usage:
  check_include_rules.py [--root DIR]            exit 0 if no rule is broken, 1 otherwise
  check_include_rules.py --root DIR --expect F   self-check: exit 0 only if exactly the
                                                 violations listed in F ("path:line rule"
                                                 per line) are reported (the allowlist is
                                                 not applied)
"""
import argparse
import fnmatch
import os
import re
import sys

from self_check import compare_with_expected

STAGES = ["cli", "accuracy", "render", "accel", "scene", "geometry"]  # top to bottom
LEAVES = ["image", "input_error.hpp", "load_budget.hpp"]
SIDE_STAGES = {"denoise": ["cli"]}  # a side stage: the stages that may include it

# Known violations, each fixed by another change; an entry is (file, included header, why).
# An entry that no longer matches anything is itself reported, so the list cannot go stale.
ALLOWLIST = []

# Third-party headers: (rule, include prefix, glob patterns of the files allowed to include it).
LIBRARY_RULES = [
    ("embree3", "embree3/", ["raytracer/accel/embree_ray.hpp"]),
    ("stb", "stb/", ["raytracer/image/*_io.cpp"]),
    ("openexr", "OpenEXR/", ["raytracer/image/*_io.cpp"]),
    ("openexr", "Imath/", ["raytracer/image/*_io.cpp"]),
    ("libjpeg", "jpeglib.h", ["raytracer/image/jpeg_io.cpp"]),
    ("zlib", "zlib.h", ["raytracer/scene/gzip_file.cpp"]),
    ("openvdb", "openvdb/", ["raytracer/scene/vdb_reader.cpp"]),
    ("nanovdb", "nanovdb/", ["raytracer/scene/vdb_reader.cpp"]),
    ("cli11", "CLI/", ["raytracer/cli/*"]),
    ("nlohmann", "nlohmann/", ["raytracer/scene/*", "raytracer/accuracy/exchange.cpp", "raytracer/cli/diff_reports.cpp"]),
    ("tinyobj", "tiny_obj_loader.h", ["raytracer/scene/*"]),
]

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')


def stage_of(path):
    """The raytracer stage or leaf a repository path belongs to, or None."""
    parts = path.split("/")
    if parts[0] != "raytracer" or len(parts) < 2:
        return None
    return parts[1]


def resolve(path, kind, target, root):
    """A quoted include as a repository path: rooted ("raytracer/...") or beside the file."""
    if kind == '"' and not target.startswith(("raytracer/", "collision/")):
        beside = os.path.normpath(os.path.join(os.path.dirname(path), target))
        if os.path.exists(os.path.join(root, beside)):
            return beside
    return target


def check_stage(path, target):
    """The stage-order message for a raytracer file including a raytracer header, or None."""
    src, dst = stage_of(path), stage_of(target)
    if dst is None or src == dst:
        return None
    if dst in LEAVES:
        return None
    if src in LEAVES:
        return f"the leaf {src} includes the stage {dst}: leaves include only leaves and collision/"
    if src in SIDE_STAGES:
        return f"the side stage {src} includes {dst}: it includes only itself and the leaves"
    if dst in SIDE_STAGES:
        if src in SIDE_STAGES[dst]:
            return None
        return f"{src} includes the side stage {dst}: only {', '.join(SIDE_STAGES[dst])} may"
    if src not in STAGES or dst not in STAGES:
        return f"{src} -> {dst}: not a known stage (stages: {' -> '.join(STAGES)}; leaves: {', '.join(LEAVES)})"
    if STAGES.index(dst) < STAGES.index(src):
        return f"{src} includes {dst}, which is above it ({' -> '.join(STAGES)} -> collision)"
    return None


def check_include(path, kind, target):
    """Every rule the include `target` (as written or resolved) in `path` breaks: [(rule, message)]."""
    broken = []
    in_collision = path.startswith("collision/")
    if in_collision:
        if target.startswith("raytracer/"):
            broken.append(("collision", f"collision/ includes {target}: nothing of raytracer/"))
        elif kind == '"' and not target.startswith("collision/"):
            broken.append(("collision", f'collision/ includes "{target}": only collision/ headers'))
        elif kind == "<" and "/" in target and not target.startswith("glm/"):
            broken.append(("collision", f"collision/ includes <{target}>: GLM is its only library"))
    if "/detail/" in target and target.startswith("collision/") and not in_collision:
        broken.append(("detail", f"{target} is internal to collision/"))
    if path.startswith("raytracer/") and target.startswith("raytracer/"):
        msg = check_stage(path, target)
        if msg:
            broken.append(("stage order", msg))
    for rule, prefix, allowed in LIBRARY_RULES:
        if kind == "<" and target.startswith(prefix):
            if not any(fnmatch.fnmatch(path, pattern) for pattern in allowed):
                broken.append((rule, f"<{target}> only in {', '.join(allowed)}"))
    return broken


def source_files(root):
    for top in ("collision", "raytracer"):
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
            dirnames.sort()
            for name in sorted(filenames):
                if name.endswith((".cpp", ".hpp", ".h")):
                    yield os.path.relpath(os.path.join(dirpath, name), root).replace(os.sep, "/")


def violations(root):
    """[(path, line, rule, include, message)] for every broken rule under root."""
    found = []
    for path in source_files(root):
        with open(os.path.join(root, path), encoding="utf-8") as f:
            for number, text in enumerate(f, start=1):
                m = INCLUDE.match(text)
                if not m:
                    continue
                kind, written = m.group(1), m.group(2)
                target = resolve(path, kind, written, root)
                for rule, message in check_include(path, kind, target):
                    found.append((path, number, rule, target, message))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--root", default=os.path.dirname(here), help="the tree to check (default: this repo)")
    parser.add_argument("--expect", help="self-check: the file listing exactly the violations to find")
    args = parser.parse_args()
    found = violations(args.root)

    if args.expect:
        return compare_with_expected(args.expect, {f"{p}:{n} {rule}" for p, n, rule, _, _ in found}, "violation")

    used = set()
    failures = 0
    for path, number, rule, target, message in found:
        entry = next((a for a in ALLOWLIST if a[0] == path and a[1] == target and a[2] == rule), None)
        if entry:
            used.add(entry)
            print(f"{path}:{number}: allowed for now ({rule}): {message} [allowlist]")
            continue
        print(f"{path}:{number}: include rule '{rule}' broken: {message}")
        failures += 1
    for entry in ALLOWLIST:
        if entry not in used:
            print(f"{entry[0]}: allowlist entry for {entry[1]} ({entry[2]}) matches nothing: remove it "
                  "from tools/check_include_rules.py")
            failures += 1
    if failures:
        print(f"{failures} include rule violation(s); the rules are at the top of tools/check_include_rules.py")
        return 1
    print("include rules: all includes of collision/ and raytracer/ keep the order")
    return 0


if __name__ == "__main__":
    sys.exit(main())
