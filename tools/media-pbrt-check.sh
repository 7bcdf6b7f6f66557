#!/bin/bash
# pbrt-v4 as a second opinion on our media transport: scenes/pbrt/fog-grey.pbrt (scenes/fog.json
# in grey and white, so spectral and RGB rendering agree) rendered by pbrt-v4's volpath in RUNS
# independent runs (seeds 1..RUNS, their spread gives the variance of pbrt's mean) and by
# sweeptrace's path tracer through its pbrt importer with --variance, then compared by
# `sweeptrace diff` with both variances (the block z-test) and by channel means.
# Usage: tools/media-pbrt-check.sh BUILD_DIR [SPP_PER_PBRT_RUN=256] [RUNS=4] [OUR_SPP=1024] [SCENE=scenes/pbrt/fog-grey.pbrt]
# (scenes/pbrt/glow-grid.pbrt checks a uniformgrid's emission the same way)
# Needs ../shared/tools/pbrt-v4 (its README lists the runtime packages). Prints what it measured.
set -euo pipefail
build=${1:?usage: media-pbrt-check.sh BUILD_DIR [SPP_PER_RUN] [RUNS] [OUR_SPP] [SCENE]}
spp=${2:-256}; runs=${3:-4}; ours=${4:-1024}
root=$(cd "$(dirname "$0")/.." && pwd)
pbrt=$root/../shared/tools/pbrt-v4/pbrt
scene=$(realpath "${5:-$root/scenes/pbrt/fog-grey.pbrt}")
st=$(cd "$build" && pwd)/sweeptrace
[ -x "$pbrt" ] || { echo "media-pbrt-check: no pbrt-v4 at $pbrt (../shared/tools/pbrt-v4)"; exit 1; }
work=$(mktemp -d)
for seed in $(seq 1 "$runs"); do
  /usr/bin/time -f "pbrt-v4 seed $seed: %U+%S CPU s" "$pbrt" --nthreads 2 --seed "$seed" --spp "$spp" \
    --outfile "$work/pbrt-$seed.exr" "$scene" > /dev/null 2> "$work/pbrt-$seed.log" || { cat "$work/pbrt-$seed.log"; exit 1; }
  tail -1 "$work/pbrt-$seed.log"
done
/usr/bin/time -f "sweeptrace: %U+%S CPU s" "$st" render "$scene" --spp "$ours" --seed 1 --threads 2 --quiet \
  -o "$work/ours.pfm" --variance "$work/ours-var.pfm"
/usr/bin/python3 "$root/tools/mean_of_runs.py" "$work/pbrt-mean.pfm" "$work/pbrt-var.pfm" "$work"/pbrt-[0-9]*.exr
/usr/bin/python3 "$root/tools/mean_of_runs.py" --compare "$work/ours.pfm" "$work/pbrt-mean.pfm"
echo "sweeptrace diff (ours against pbrt-v4's mean, block z-test with both variances):"
"$st" diff "$work/ours.pfm" "$work/pbrt-mean.pfm" --linear --variance-a "$work/ours-var.pfm" --variance-b "$work/pbrt-var.pfm" || true
echo "images kept in $work"
