#!/usr/bin/env bash
# The pictures of docs/media.md, rendered by the path tracer from the shipped medium scenes:
# docs/media-fog.png (scenes/fog.json), docs/media-fog-bdpt.png (the same by bdpt, which finds the
# caustic through the glass sphere) and docs/media-smoke.png (scenes/media/smoke.json, made by
# tools/make_smoke_grid.py). Usage: bash tools/media-pictures.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
st="${1:-build}/sweeptrace"
[ -x "$st" ] || { echo "media-pictures: $st not found; build first (cmake --build build --target sweeptrace)" >&2; exit 2; }
"$st" render scenes/fog.json --width 320 --height 240 --spp 512 --seed 1 --quiet -o docs/media-fog.png
"$st" render scenes/media/smoke.json --width 240 --height 240 --spp 512 --seed 1 --quiet -o docs/media-smoke.png
"$st" render scenes/fog.json --integrator bdpt --width 320 --height 240 --spp 256 --seed 1 --quiet -o docs/media-fog-bdpt.png
