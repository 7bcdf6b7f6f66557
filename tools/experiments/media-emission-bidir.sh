#!/bin/bash
# bdpt and vcm against the path tracer on a glowing smoke (docs/media.md, "Media that emit"):
# scenes/media/smoke.json with emission [4, 1.5, 0.3] on its grid, scaled per voxel by the
# density itself (an Le grid, `emission_scale`), still lit by its quad lamp. Renders each with
# --variance and prints `sweeptrace diff`'s block z-test of bdpt and of vcm against the path
# tracer, and each render's CPU seconds.
# Usage: tools/experiments/media-emission-bidir.sh BUILD_DIR [SIZE=120] [PATH_SPP=1024] [SPP=256]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
st=$(cd "$1" && pwd)/sweeptrace; size=${2:-120}; path_spp=${3:-1024}; spp=${4:-256}
work=$(mktemp -d); cd "$work"
/usr/bin/python3 - "$root/scenes/media/smoke.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
m = s["media"]["smoke"]
m["emission"] = [4.0, 1.5, 0.3]
m["emission_scale"] = m["density"]
json.dump(s, open("glow.json", "w"))
PY
for k in path bdpt vcm; do
  n=$spp; [ $k = path ] && n=$path_spp
  /usr/bin/time -f "$k: %U+%S CPU s" "$st" render glow.json --integrator $k --width "$size" --height "$size" \
    --spp "$n" --seed 1 --threads 2 --quiet -o $k.exr --variance $k-var.exr
done
for k in bdpt vcm; do
  echo "$k against path:"
  "$st" diff $k.exr path.exr --linear --variance-a $k-var.exr --variance-b path-var.exr || true
done
