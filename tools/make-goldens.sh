#!/usr/bin/env bash
# Regenerates reference_images/*.png from reference_images/goldens.txt (the one documented way;
# tests never write there). Usage: bash tools/make-goldens.sh [BUILD_DIR] [SCENE...]
# Renders with the native BVH; the image tests compare both accelerators against these.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shift || true
binary="$build/sweeptrace"
[ -x "$binary" ] || { echo "make-goldens: $binary not found; build first (cmake --build $build --target sweeptrace)" >&2; exit 2; }
wanted=" $* "
while read -r scene width height depth spp seed _test_spp _block; do
  case "$scene" in ''|'#'*) continue ;; esac
  if [ $# -gt 0 ] && [[ "$wanted" != *" $scene "* ]]; then continue; fi
  echo "make-goldens: $scene ${width}x${height}, $spp spp, max depth $depth, seed $seed" >&2
  "$binary" render "scenes/$scene.json" -o "reference_images/$scene.png" --width "$width" --height "$height" \
    --spp "$spp" --max-depth "$depth" --seed "$seed" --accel bvh --quiet
done < reference_images/goldens.txt
