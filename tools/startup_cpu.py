#!/usr/bin/python3
"""What a sweeptrace process costs at start, one build against others: each command run by every
binary in turn (alternated, so the shared machine's load falls on all alike), --repeat times; the
median CPU time (user + system of the child, getrusage) per binary and command. The commands are
the short processes users run by the thousand: a bare start (`--version`, refused at once), a
`diff` of two small images (rendered first by the first binary), and a small render of
scenes/default.json (160x120, 32 spp). Written for the VDB reader module (raytracer/scene/
vdb_module.hpp): linking OpenVDB cost every process about 0.05 s of CPU at start.
Prints a markdown table. Timing only; asserts nothing.
Usage: /usr/bin/python3 tools/startup_cpu.py BINARY [BINARY...] [--repeat 15]
"""
import argparse
import os
import resource
import statistics
import subprocess
import tempfile


def cpu_seconds(cmd, cwd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binaries", nargs="+")
    ap.add_argument("--repeat", type=int, default=15)
    a = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    scene = os.path.join(root, "scenes", "default.json")
    work = tempfile.mkdtemp()
    binaries = [os.path.abspath(b) for b in a.binaries]
    for i in (0, 1):  # the two images diff compares: the same scene at two seeds
        subprocess.run([binaries[0], "render", scene, "--width", "64", "--height", "48", "--spp", "4", "--seed", str(i + 1),
                        "-o", f"img{i}.png"], cwd=work, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    commands = {
        "--version": ["--version"],
        "diff two 64x48 images": ["diff", "img0.png", "img1.png"],
        "render default.json 160x120 32 spp": ["render", scene, "--width", "160", "--height", "120", "--spp", "32",
                                               "-o", "out.png"],
    }
    times = {(b, c): [] for b in binaries for c in commands}
    for _ in range(a.repeat):
        for c, args in commands.items():
            for b in binaries:
                times[(b, c)].append(cpu_seconds([b] + args, work))
    names = a.binaries
    print(f"median CPU seconds of {a.repeat} runs each, alternated\n")
    print("| command | " + " | ".join(names) + " |")
    print("|---|" + "---|" * len(names))
    for c in commands:
        print(f"| {c} | " + " | ".join(f"{statistics.median(times[(b, c)]):.3f}" for b in binaries) + " |")


if __name__ == "__main__":
    main()
