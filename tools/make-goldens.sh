#!/usr/bin/env bash
# Regenerates reference_images/<scene>.png and <scene>-variance.exr from the settings in
# reference_images/goldens.txt: the one documented way (tests never write there).
# Usage: bash tools/make-goldens.sh [BUILD_DIR] [SCENE...]   (default: build, every scene)
# It runs the test binary's hidden generator ("[.make-goldens]"), so the goldens are rendered by
# exactly the code path the image tests render with (load_scene, the spec's film overrides,
# render() through the native BVH).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shift || true
binary="$build/tests/raytracer_tests"
[ -x "$binary" ] || { echo "make-goldens: $binary not found; build first (cmake --build $build --target raytracer_tests)" >&2; exit 2; }
SWEEPTRACE_GOLDEN_SCENES="$*" "$binary" "[.make-goldens]"
