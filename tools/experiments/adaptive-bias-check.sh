#!/usr/bin/env bash
# Issue 34's "no bias": each scene of the equal-time table rendered with --adaptive on (the
# independent sampler, so --variance is exact) and compared with the table's uniform reference by
# `sweeptrace diff`'s z-test on 8x8 block means (family-wise false-alarm rate 1%).
# Usage: bash tools/experiments/adaptive-bias-check.sh BINARY WORK SPP [SCENE...]
# WORK holds the references of tools/equal-time-interiors.py (NAME-new-ref-480s.pfm and -var.pfm).
set -euo pipefail
bin=$1 work=$2 spp=$3
shift 3
here=$(cd "$(dirname "$0")/../.." && pwd)
declare -A path=([classroom]=$here/../shared/bitterli/classroom/scene-v4.pbrt [kitchen]=$here/../shared/bitterli/kitchen/scene-v4.pbrt
  [staircase2]=$here/../shared/bitterli/staircase2/scene-v4.pbrt [coffee]=$here/../shared/bitterli/coffee/scene-v4.pbrt
  [smallpt]=$here/scenes/smallpt.json [cornell-box]=$here/scenes/cornell-box.json)
for s in "${@:-classroom kitchen staircase2 coffee smallpt cornell-box}"; do
  for name in $s; do
    out=$work/$name-adaptive-bias-$spp
    [ -f "$out.pfm" ] || "$bin" render "${path[$name]}" --width 320 --height 180 --spp "$spp" --threads 2 --seed 11 \
      --sampler independent --adaptive on -o "$out.pfm" --variance "$out-var.pfm" --quiet
    echo "== $name: --adaptive on, $spp spp, against the uniform reference"
    "$bin" diff "$out.pfm" "$work/$name-new-ref-480s.pfm" --linear --variance-a "$out-var.pfm" \
      --variance-b "$work/$name-new-ref-480s-var.pfm" 2>&1 | tail -4 || true
  done
done
