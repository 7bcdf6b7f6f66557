#!/usr/bin/env python3
"""Smoke case of `sweeptrace reference-check` (ctest label `reference`): cornell-box of
../shared/bitterli at 1/8 of the reference's size and 64 spp, a few seconds. Asserts what a broken
importer, renderer or comparison would fail: the image mean within 3 % of Tungsten's per channel,
at least 90 % of 8x8 blocks within |z| < 5, the table and the 3-panel picture written; and that
bad input (a folder, a downsample, a batch count, an --integrator setting) exits 2 writing nothing. Without ../shared it says so and exits with ctest's skip code
(77), as the tests reading the shared meshes do (with CI=true it fails instead)."""
import os
import re
import struct
import subprocess
import sys
import tempfile

binary, shared = sys.argv[1], sys.argv[2]
folder = os.path.join(shared, "bitterli")
if not os.path.isfile(os.path.join(folder, "cornell-box", "TungstenRender.exr")):
    need = f"this test needs {folder}/cornell-box (the shared/ folder beside the checkout)"
    if os.environ.get("CI") == "true":
        sys.exit("CI=true and " + need)
    print("SKIPPED: " + need)
    sys.exit(77)

with tempfile.TemporaryDirectory() as tmp:
    table = os.path.join(tmp, "table.md")
    # Bad input: one line, exit 2, nothing written.
    bad = subprocess.run([binary, "reference-check", os.path.join(tmp, "missing"), "--table", table],
                         capture_output=True, text=True)
    assert bad.returncode == 2, bad
    assert bad.stderr.count("\n") == 1 and "does not exist" in bad.stderr, bad.stderr
    bad = subprocess.run([binary, "reference-check", folder, "--scene", "cornell-box", "--downsample", "3",
                          "--table", table], capture_output=True, text=True)
    assert bad.returncode == 2 and "whole pixels" in bad.stderr, bad
    assert os.listdir(tmp) == [], os.listdir(tmp)
    bad = subprocess.run([binary, "reference-check", folder, "--scene", "cornell-box", "--downsample", "8",
                          "--spp", "30", "--batches", "16", "--table", table], capture_output=True, text=True)
    assert bad.returncode == 2 and "not a multiple of --batches 16" in bad.stderr, bad
    assert os.listdir(tmp) == [], os.listdir(tmp)
    for setting, says in (("cornell-box=photons", "give KIND or NAME=KIND with KIND path, bdpt or vcm"),
                          ("nosuch=bdpt", "no scene 'nosuch' is checked")):
        bad = subprocess.run([binary, "reference-check", folder, "--scene", "cornell-box", "--downsample", "8",
                              "--integrator", setting, "--table", table], capture_output=True, text=True)
        assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and says in bad.stderr, bad
        assert os.listdir(tmp) == [], os.listdir(tmp)

    run = subprocess.run([binary, "reference-check", folder, "--scene", "cornell-box", "--downsample", "8",
                          "--spp", "64", "--threads", "2", "--table", table,
                          # the depth the reference was rendered with (the file's "# gonsolo 65")
                          "--max-depth", "cornell-box=66"], capture_output=True, text=True)
    print(run.stdout, run.stderr)
    assert run.returncode in (0, 1), run
    m = re.search(r"mean ratio (\S+) (\S+) (\S+), blocks \|z\|<3 (\S+) % \|z\|<5 (\S+) %", run.stdout)
    assert m, run.stdout
    ratios = [float(v) for v in m.groups()[:3]]
    assert all(abs(r - 1.0) < 0.03 for r in ratios), ratios
    assert float(m.group(5)) >= 90.0, m.group(5)
    text = open(table).read()
    assert "<!-- reference-check: begin" in text and "| cornell-box | 128x128 | 64 |" in text, text
    png = open(os.path.join(tmp, "table", "cornell-box.png"), "rb").read(24)
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    assert struct.unpack(">II", png[16:24]) == (3 * 128, 128)
    # A second run replaces the generated block and keeps the page's own text.
    with open(table, "a") as f:
        f.write("hand-written\n")
    with open(table) as f:
        page = "intro\n" + f.read()
    with open(table, "w") as f:
        f.write(page)
    again = subprocess.run([binary, "reference-check", folder, "--scene", "cornell-box", "--downsample", "16",
                            "--spp", "4", "--threads", "2", "--table", table], capture_output=True, text=True)
    assert again.returncode in (0, 1), again
    text = open(table).read()
    assert text.startswith("intro\n") and text.endswith("hand-written\n") and text.count("begin (generated") == 1, text
    assert "| cornell-box | 64x64 | 4 |" in text, text
print("reference-check smoke: ok")
