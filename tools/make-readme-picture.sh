#!/usr/bin/env bash
# Renders the README's pictures from a Release build: the showcase (scenes/showcase.json) at a
# sample count where its glass and glossy tiles are clean, and the first command's render of
# scenes/default.json exactly as the README's first command makes it.
# Usage: bash tools/make-readme-picture.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
st="$build/sweeptrace"
[ -x "$st" ] || { echo "make-readme-picture: $st not found; build first (cmake --build $build --target sweeptrace)" >&2; exit 2; }
"$st" render scenes/showcase.json --width 960 --height 540 --spp 512 -o docs/showcase.png
"$st" render scenes/default.json -o docs/default.png
