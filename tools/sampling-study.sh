#!/usr/bin/env bash
# The sampler and roulette study of issue #15 (docs/sampling.md): Sobol against independent
# samples and the adaptive against the classic roulette, RMSE at 16..1024 spp and at equal CPU
# time against today's estimator, and the roulette candidates' variance x time.
# Usage: bash tools/sampling-study.sh [BUILD_DIR]   (default: build; a Release build)
# One thread per render, CPU time. The Cornell box (whose targets are the tightest) at 128x128
# against an 8192-spp reference; the other scenes at 64 px wide (aspect kept) against 4096 spp,
# to fit a 2-core machine shared with other work. References (independent samples, classic
# roulette) are cached in BUILD_DIR/sampling-cache, keyed by the scene file's contents; delete
# it after a change to what the renderer converges to.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cmake --build "$build" -j2 --target sweeptrace
mkdir -p docs
cd "$build"
./sweeptrace accuracy --sampling ../scenes/cornell-box.json --size 128 --reference-spp 8192 --roulette-spp 256 \
  --cache sampling-cache --csv ../docs/sampling-cornell-box.csv --markdown ../docs/sampling-cornell-box.md
./sweeptrace accuracy --sampling ../scenes/default.json ../scenes/primitives.json ../scenes/smallpt.json \
  --size 64 --reference-spp 4096 --roulette-spp 0 \
  --cache sampling-cache --csv ../docs/sampling-scenes.csv --markdown ../docs/sampling-scenes.md
./sweeptrace accuracy --sampling ../scenes/default.json ../scenes/primitives.json ../scenes/smallpt.json \
  ../scenes/mesh.json --size 64 --roulette-spp 128 --roulette-only --markdown ../docs/sampling-roulette.md
