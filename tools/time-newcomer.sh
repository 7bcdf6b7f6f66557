#!/usr/bin/env bash
# Times a newcomer's path on this machine: a fresh clone of this checkout's HEAD, then the
# README's first command in it, then the README's test command in the same clone (which reuses
# what the first one built). The commands are read from README.md itself, so what is timed is
# what the README says. ccache is disabled: a newcomer's cache is empty. Prints one line per
# step: wall seconds, then user + system CPU seconds of everything it ran.
# Usage: bash tools/time-newcomer.sh [--first-only]
# Needs ../shared beside the checkout for the mesh tests (linked beside the clone).
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
readme="$src/README.md"
# The first fenced block after each heading line: the README's two commands.
block_after() { awk -v key="$1" 'index($0, key) == 1 {f = 1} f && /^```$/ {n++; next} f && n == 1 {print; exit}' "$readme"; }
first=$(block_after "Your first picture")
tests=$(block_after "Run the whole test suite")
[ -n "$first" ] && [ -n "$tests" ] || { echo "time-newcomer: README.md: first or test command not found" >&2; exit 2; }
dir=$(mktemp -d /tmp/sweeptrace-newcomer.XXXXXX)
trap 'rm -rf "$dir"' EXIT
git clone -q "$src" "$dir/sweeptrace"
[ -d "$src/../shared" ] && ln -s "$(cd "$src/../shared" && pwd)" "$dir/shared"
cd "$dir/sweeptrace"
export CCACHE_DISABLE=1
run() {
  local name=$1 cmd=$2
  /usr/bin/time -f "%e %U %S" -o "$dir/time.txt" bash -c "$cmd" > "$dir/$name.log" 2>&1 || {
    echo "time-newcomer: $name failed, last lines:" >&2; tail -20 "$dir/$name.log" >&2; exit 1; }
  read -r wall user sys < "$dir/time.txt"
  printf '%s: %s s wall, %s s CPU  (%s)\n' "$name" "$wall" "$(awk -v u="$user" -v s="$sys" 'BEGIN {print u + s}')" "$(tail -1 "$dir/$name.log" | cut -c1-160)"
}
echo "time-newcomer: $(date -u +%Y-%m-%d\ %H:%M) UTC, $(nproc) cores, HEAD $(git rev-parse --short HEAD), load $(cut -d' ' -f1-3 /proc/loadavg)"
run "first command" "$first"
[ "${1:-}" = --first-only ] && exit 0
run "test command" "$tests"
