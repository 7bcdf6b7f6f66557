#!/usr/bin/env bash
# Why the Cycles reference finds the Cornell box's light by BSDF sampling only: direct light on
# the back wall, from sweeptrace and from Cycles 3.4 with its light sampling (MIS) and without it
# (and with the light cut into 8 x 8 quads), each against Lambert's closed form. Prints the table
# of reference_images/cycles/README.md. About 8 minutes on 2 cores.
# Usage: bash tools/cycles-direct-check.sh [BUILD_DIR]   (needs blender; Debian's python3 with numpy)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
command -v blender >/dev/null || { echo "cycles-direct-check: blender not found (apt-get install --no-install-recommends blender)" >&2; exit 2; }
[ -x "$build/sweeptrace" ] || { echo "cycles-direct-check: $build/sweeptrace not found; build first" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scene=scenes/cornell-box.json
"$build/sweeptrace" render "$scene" --width 128 --height 128 --spp 4096 --max-depth 2 --sampler independent \
    --variance "$out/sweeptrace-variance.pfm" -o "$out/sweeptrace.pfm" >/dev/null 2>&1
cycles() {  # NAME ARGS...
    local name=$1; shift
    blender -b --python tools/cycles_reference.py -- --scene "$scene" --size 128 --spp 1024 --runs 2 \
        --direct-only --out "$out/$name" "$@" >/dev/null 2>&1
}
cycles cycles-mis --light-sampling mis
cycles cycles-mis-split8 --light-sampling mis --split-light 8
cycles cycles-bsdf --light-sampling bsdf
echo "direct light on the back wall against Lambert's polygon formula (128x128; sweeptrace 4096 spp, Cycles 2 x 1024 spp)"
/usr/bin/python3 tools/cycles_direct_check.py "$scene" \
    "$out/sweeptrace.pfm" "$out/sweeptrace-variance.pfm" \
    "$out/cycles-mis-mean.pfm" "$out/cycles-mis-variance.pfm" \
    "$out/cycles-mis-split8-mean.pfm" "$out/cycles-mis-split8-variance.pfm" \
    "$out/cycles-bsdf-mean.pfm" "$out/cycles-bsdf-variance.pfm" | sed "s|$out/||"
