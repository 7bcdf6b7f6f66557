#!/usr/bin/env bash
# Regenerates every CSV, Markdown table and chart in docs/ from a Release build: the one command
# behind docs/RESULTS.md. About 10 minutes on 2 cores. Needs ../shared/meshes beside the checkout
# (or SWEEPTRACE_MESHES=dir) for the mesh comparison; without it that part is skipped.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
meshes=${SWEEPTRACE_MESHES:-../shared/meshes}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target sweeptrace
st="$build/sweeptrace"
mkdir -p docs

echo "== every intersector against the long double reference" >&2
"$st" accuracy --rays 20000 --seed 1 --csv docs/accuracy.csv --markdown docs/accuracy.md >/dev/null

echo "== the thesis's structures redone for rays" >&2
"$st" accuracy --structures --max-level 8 --budget 0.5 --rays 200000 --seed 1 \
  --csv docs/structures.csv --markdown docs/structures.md >/dev/null

if [ -d "$meshes" ]; then
  echo "== meshes: native BVH against Embree" >&2
  "$st" accuracy --meshes "$meshes" --rays 1000000 --inside-rays 100000 --seed 1 \
    --csv docs/mesh-comparison.csv --methods-csv docs/mesh-methods.csv --markdown docs/mesh-comparison.md >/dev/null
else
  echo "make-docs: $meshes not found, mesh comparison skipped" >&2
fi

echo "== analytic against tessellated, rendered" >&2
"$st" accuracy --tessellation --size 96 --spp 16 --reference-spp 256 --max-exponent 6 --seed 1 \
  --csv docs/tessellation.csv --markdown docs/tessellation.md >/dev/null

echo "== convergence" >&2
"$st" accuracy --convergence scenes/cornell-box.json scenes/smallpt.json --size 64 --spp 32 --reference-spp 512 \
  --csv docs/convergence.csv --markdown docs/convergence.md >/dev/null

/usr/bin/python3 tools/charts.py docs
