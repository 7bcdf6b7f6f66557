#!/usr/bin/env bash
# What a clean build costs, object by object: bash tools/time-build.sh [BUILD_DIR=build-time] [CMAKE_ARG...]
# Configures BUILD_DIR afresh as the README does (default generator, Release) with a launcher that
# times every compile (tools/cmake/time-command.sh; ccache is bypassed, so each object is really
# compiled), builds everything with -j2, and prints: the build's wall time and CPU time (user+sys
# of every process it ran: compiles, links, the fuzz project), the slowest objects, and the CPU per
# target. CPU seconds are the figure to compare on a shared machine; wall seconds are only
# meaningful when nothing else runs. The per-object log stays in BUILD_DIR/time-tu.log.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build-time}
shift || true
if [ -e "$dir" ] && [ ! -f "$dir/CMakeCache.txt" ] && [ -n "$(ls -A "$dir")" ]; then
  echo "time-build.sh: $dir exists and is not a build tree; not removing it" >&2
  exit 2
fi
rm -rf "$dir"
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
export SWEEPTRACE_TIME_LOG=$dir/time-tu.log
: > "$SWEEPTRACE_TIME_LOG"
launcher=$PWD/tools/cmake/time-command.sh
/usr/bin/time -o "$dir/time-configure.txt" -f "%e %U %S" \
  cmake -S . -B "$dir" -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" "$@" > "$dir/configure.log"
/usr/bin/time -o "$dir/time-build.txt" -f "%e %U %S" cmake --build "$dir" -j2 > "$dir/build.log" 2>&1 ||
  { tail -n 30 "$dir/build.log"; exit 1; }
python3 - "$dir" <<'PY'
import collections, os, re, sys
d = sys.argv[1]
cw, cu, cs = map(float, open(f"{d}/time-configure.txt").read().split()[-3:])
bw, bu, bs = map(float, open(f"{d}/time-build.txt").read().split()[-3:])
rows = []
for line in open(f"{d}/time-tu.log"):
    parts = line.split(None, 3)
    if len(parts) == 4 and re.match(r"^[0-9.]+$", parts[0]):
        rows.append((float(parts[0]) + float(parts[1]), float(parts[2]), parts[3].strip()))
def target(out):
    m = re.search(r"CMakeFiles/([^/]+)\.dir/", out)
    return m.group(1) if m else "?"
tu = sum(r[0] for r in rows)
print(f"configure: {cw:.0f} s wall, {cu + cs:.0f} s CPU")
print(f"build -j2: {bw:.0f} s wall, {bu + bs:.0f} s CPU (user {bu:.0f} + sys {bs:.0f});"
      f" {len(rows)} compiles {tu:.0f} s CPU, the rest (links, archives, cmake) {bu + bs - tu:.0f} s")
print(f"CPU / 2 = {(bu + bs) / 2:.0f} s: the wall time 2 idle cores would need at best")
print("\nslowest objects (CPU s, wall s):")
for c, w, out in sorted(rows, reverse=True)[:25]:
    print(f"  {c:6.1f} {w:6.1f}  {out.split('CMakeFiles/')[-1]}")
per = collections.defaultdict(lambda: [0, 0.0])
for c, w, out in rows:
    per[target(out)][0] += 1
    per[target(out)][1] += c
print("\nper target (objects, CPU s):")
for t, (n, c) in sorted(per.items(), key=lambda kv: -kv[1][1]):
    print(f"  {n:4d} {c:7.0f}  {t}")
PY
