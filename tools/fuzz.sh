#!/usr/bin/env bash
# A long fuzz run from the committed corpus: bash tools/fuzz.sh [SECONDS=600] [HARNESS...]
# (harnesses: scene obj ply pbrt png pfm exr jpg hdr tga; default all, one after another). Uses the harnesses the main
# build made (build/tests/fuzz/project) or builds them with clang into build-fuzz; keeps what
# each finds in build-fuzz/work/NAME and writes any crash to build-fuzz/artifacts/. A crash that
# is a real bug becomes a regression file: copy it into tests/fuzz/corpus/NAME/ with the fix.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
harnesses=("${@:-scene obj ply pbrt png pfm exr jpg hdr tga}")
read -r -a harnesses <<< "${harnesses[*]}"
bin=build/tests/fuzz/project
if [ ! -x "$bin/fuzz_scene" ]; then
  bin=build-fuzz
  cmake -S tests/fuzz/project -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  cmake --build build-fuzz -j2 >/dev/null
fi
mkdir -p build-fuzz/artifacts
status=0
for h in "${harnesses[@]}"; do
  mkdir -p "build-fuzz/work/$h"
  dict=()
  [ -f "tests/fuzz/$h.dict" ] && dict=(-dict="tests/fuzz/$h.dict")
  echo "fuzz.sh: $h for $seconds s" >&2
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$bin/fuzz_$h" "${dict[@]}" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=10 \
    -max_len=16384 -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$h-" \
    "build-fuzz/work/$h" "tests/fuzz/corpus/$h" 2>"build-fuzz/$h.log" || status=1
  tail -n 12 "build-fuzz/$h.log" | grep -E "^(Done|stat::number_of_executed_units|stat::peak_rss_mb)|ERROR|SUMMARY" >&2 || true
done
exit $status
