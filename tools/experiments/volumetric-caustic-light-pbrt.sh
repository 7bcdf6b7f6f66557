#!/bin/bash
# pbrt-v4 as a second opinion on volumetric-caustic's directly seen light (docs/media.md): the
# scene at 32x32 with pbrt's volpath at maxdepth 0 (emission seen directly, nothing scattered),
# with and without the gas, against our bdpt at --max-depth 1 (its light-tracing strategy finds
# the 5 mm x 4 mm quad that camera rays rarely hit). Prints each image's channel sums.
# Usage: tools/experiments/volumetric-caustic-light-pbrt.sh BUILD_DIR [PBRT_SPP=65536]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
st=$(cd "$1" && pwd)/sweeptrace; spp=${2:-65536}
scene=$root/../shared/bitterli/volumetric-caustic/scene-v4.pbrt
pbrt=$root/../shared/tools/pbrt-v4/pbrt
work=$(mktemp -d); cd "$work"
sed -e 's/"integer maxdepth" \[ 7 \]/"integer maxdepth" [ 0 ]/' -e 's/"integer \([xy]\)resolution" \[ 512 \]/"integer \1resolution" [ 32 ]/' "$scene" > gas.pbrt
# Without the gas: no medium, no interfaces' media (the front wall stays an interface).
sed -e '/MediumInterface/d' gas.pbrt | /usr/bin/python3 -c 'import re, sys; sys.stdout.write(re.sub(r"MakeNamedMedium \"gas\"\n(    \".*\n)*", "", sys.stdin.read()))' > nogas.pbrt
for f in nogas gas; do
  "$pbrt" --nthreads 2 --seed 1 --spp "$spp" --outfile "$work/$f-pbrt.exr" $f.pbrt > /dev/null
  "$st" render $f.pbrt --integrator bdpt --max-depth 1 --width 32 --height 32 --spp 1024 --sampler independent --quiet -o "$work/$f-ours.pfm"
  /usr/bin/python3 - "$root/tools" "$work" "$f" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from exr_channels import read_exr
from pfm import read_pfm
work, f = sys.argv[2], sys.argv[3]
ch, _ = read_exr(f"{work}/{f}-pbrt.exr")
ours = read_pfm(f"{work}/{f}-ours.pfm").sum(axis=(0, 1))
print(f"{f}: pbrt-v4 volpath maxdepth 0: " + " ".join("%.2f" % ch[c].sum() for c in "RGB")
      + "; ours bdpt depth 1: " + " ".join("%.2f" % v for v in ours))
PY
done
