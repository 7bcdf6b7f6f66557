#!/usr/bin/python3
"""What feature outputs cost (issue 42: "AOVs cost <= 10 % of render time"): each scene rendered by
one binary with and without `--aovs`, interleaved, --repeat times, to an .exr (so the cost of
writing the 46-channel feature EXR against the plain one is counted); the least CPU time (user +
system of the child: other engineers' load on a shared machine counts little) of each. With
--baseline OTHER_BINARY, that binary's renders with and without `--aovs` are timed in the same
rounds too (before and after a change, in one sitting). Prints a markdown table.

Identical runs on a shared virtual machine spread by +-15 %, so --perf N also profiles N rounds
of each binary's plain and `--aovs` renders (`perf record`, 2000 Hz, pooled) and estimates on / off
from the profiles: the samples of the whole run per sample of the path tracing itself (the
symbols in CORE, the same work with and without features), with `--aovs` over without (and the
same with the 12 symbols CORE held before, OLD_CORE). The
machine's load slows both alike, so the ratio holds better than the timings; the symbols whose
samples grew most are listed with their share of the `--aovs` profile.
Usage: /usr/bin/python3 tools/aov_cost.py BINARY [SCENE ...] [--baseline MAIN_BINARY] [--spp 16] [--size 320x180]
       [--repeat 3] [--threads 1] [--integrator path] [--perf 0]
Default scenes: scenes/cornell-box.json and ../shared/bitterli/classroom/scene-v4.pbrt.
"""
import argparse
import collections
import os
import subprocess
import sys
import tempfile

from bench_path_cpu import cpu_seconds  # tools/ is this script's folder, first on sys.path

# The path tracer's own work, rendered alike with and without features: the symbols of plain
# cornell-box and classroom profiles above 0.2 % (2026-12-06) but scene loading, the tile loop
# (PassRenderer::run_tiles, where render_tile and sample_pixel are inlined with the features'
# recording and pending writes) and accumulate_pass (whose colour sum the features take over:
# renderer.cpp). The radiance function has FeatureRecord::at_vertex inlined (a flag's test a
# vertex; features_at, which does the work, is out of line and not counted). The list before held
# 12 symbols: 68 % of a plain cornell-box profile (64 spp) and 34 % of classroom's (8 spp, loading
# included); this one 91 % and 86 %, so the ratio rests on more samples (docs/aovs.md, Cost).
CORE = ["PathIntegrator::radiance", "collision::intersect", "PixelSampler::get2d", "sample_bsdf", "traverse_nearest",
        "traverse_any", "LightSet::sample", "to_object_space", "spawn_ray_to", "offset_origin", "top_intersect", "top_any",
        "start_camera_sample", "PathIntegrator::shadow_ray", "CameraModel::generate", "sincosf", "surface_hit_to_world",
        "make_shading_context", "eval_bsdf", "object_intersect", "sample_home", "intersect_candidate", "affine_magnitude",
        "apply_affine", "IndirectClamp::limited", "nextafterf", "PixelFilter::sample", "emitted_radiance_at",
        "BvhAccel::intersect", "mesh_intersect", "mesh_occluded", "mesh_hit_to_world", "MeshInstanceShape::mesh_uv",
        "coat_albedo", "coated_terms", "eval_coated_diffuse", "sample_coated_diffuse", "ggx_reflection",
        "fresnel_conductor", "eval_texture", "image_texture", "EnvironmentLight::", "background_radiance",
        "equal_area_sphere_to_square"]
# The list this script had before 2026-12-06: its figure is printed beside (the "12-symbol" one).
OLD_CORE = CORE[:12]


def profile(files):
    """Samples per symbol of perf.data files, pooled; libraries and the kernel lumped by name."""
    count = collections.Counter()
    for f in files:
        out = subprocess.run(["perf", "report", "-i", f, "-n", "--no-children", "--sort", "dso,symbol", "-g", "none",
                              "--percent-limit", "0"], capture_output=True, text=True, check=True).stdout
        for line in out.splitlines():
            parts = line.split()
            if line.startswith("#") or len(parts) < 5 or not parts[0].endswith("%"):
                continue
            dso, symbol = parts[2], " ".join(parts[4:]).replace(" - -", "").replace("sweeptrace::", "")
            for lib in ("libz", "libOpenEXR", "[kernel", "ld-linux"):
                if dso.startswith(lib):
                    symbol = lib.strip("[") + " (all)"
            count[symbol] += int(parts[1])
    return count


def core(count, symbols=None):
    return sum(n for s, n in count.items() if any(c in s for c in (symbols or CORE)))


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("--baseline")
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--size", default="320x180")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--integrator", default="path")
    ap.add_argument("--perf", type=int, default=0)
    ap.add_argument("scenes", nargs="*", default=[os.path.join(root, "scenes", "cornell-box.json"),
                                                  os.path.join(root, "..", "shared", "bitterli", "classroom", "scene-v4.pbrt")])
    # Intermixed: with plain parse_args the positional `binary` takes the (empty) scene list with
    # it, and a scene named after --baseline is refused as unrecognized.
    a = ap.parse_intermixed_args()
    w, h = a.size.split("x")
    out = tempfile.mkdtemp()
    binaries = [("baseline", a.baseline)] if a.baseline else []
    binaries.append(("this", a.binary))
    runs = [(b, exe, aovs) for b, exe in binaries for aovs in (False, True)]
    print("%s, %s spp, %sx%s, %d thread(s), least CPU s of %d runs each, interleaved\n" %
          (a.integrator, a.spp, w, h, a.threads, a.repeat))
    print("| scene | binary | aovs off | aovs on | on / off |%s\n|---|---|---|---|---|%s" %
          (" profile on / off (top symbols' share of on) |" if a.perf else "", "---|" if a.perf else ""))

    def command(exe, aovs, scene, name):
        return [exe, "render", scene, "--integrator", a.integrator, "--threads", str(a.threads), "--spp", str(a.spp),
                "--width", w, "--height", h, "--quiet", "-o", os.path.join(out, name + ".exr")] + (["--aovs"] if aovs else [])

    for scene in a.scenes:
        best = {}
        for _ in range(a.repeat):
            for b, exe, aovs in runs:
                t = cpu_seconds(command(exe, aovs, scene, b))
                best[b, aovs] = min(best.get((b, aovs), t), t)
        profiles = collections.defaultdict(list)
        for i in range(a.perf):
            for b, exe, aovs in runs:
                data = os.path.join(out, "%s-%s-%d.data" % (b, aovs, i))
                subprocess.run(["perf", "record", "-q", "-F", "2000", "-o", data] + command(exe, aovs, scene, b),
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
                profiles[b, aovs].append(data)
        name = os.path.basename(os.path.dirname(scene) if scene.endswith(".pbrt") else scene)
        for b, exe in binaries:
            row = "| %s | %s | %.2f | %.2f | %.3f |" % (name, b, best[b, False], best[b, True], best[b, True] / best[b, False])
            if a.perf:
                off, on = profile(profiles[b, False]), profile(profiles[b, True])
                ratio, old = ((sum(on.values()) / core(on, c)) / (sum(off.values()) / core(off, c)) for c in (CORE, OLD_CORE))
                scale = core(on) / core(off)
                grown = sorted(((on[s] - off[s] * scale, s) for s in set(on) | set(off)), reverse=True)[:6]
                row += " %.3f (12-symbol core %.3f; %s) |" % (ratio, old, ", ".join("%s %.1f %%" % (s[:40], 100 * g / sum(on.values()))
                                                                                    for g, s in grown))
            print(row)
        sys.stdout.flush()


if __name__ == "__main__":
    main()
