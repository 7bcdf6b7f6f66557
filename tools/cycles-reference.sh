#!/usr/bin/env bash
# Renders the Cycles reference of the Cornell box that tests/raytracer/test_image_cycles_reference.cpp
# compares against: reference_images/cycles/cornell-box-{mean,variance}.pfm. Blender's Cycles is an
# independent path tracer (Debian package `blender`, 3.4); tools/cycles_reference.py translates
# scenes/cornell-box.json for it and says which settings are matched and why. Tests never run
# this: Blender is not a build dependency, and the reference is data, regenerated only when the
# scene changes. About 6 minutes on 2 cores at the default 8 runs x 1024 spp.
# Usage: bash tools/cycles-reference.sh [RUNS] [SPP]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-8}
spp=${2:-1024}
command -v blender >/dev/null || { echo "cycles-reference: blender not found (apt-get install --no-install-recommends blender)" >&2; exit 2; }
blender --version | head -n 1
blender -b --python tools/cycles_reference.py -- --scene scenes/cornell-box.json --size 128 \
    --spp "$spp" --runs "$runs" --out reference_images/cycles/cornell-box 2>&1 | grep -v '^Fra:'
