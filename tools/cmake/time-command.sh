#!/usr/bin/env bash
# Compiler launcher for tools/time-build.sh: runs the compile and appends one line to
# $SWEEPTRACE_TIME_LOG, "user_s sys_s wall_s output", so each object's CPU cost is known even on
# a machine other jobs share (CPU seconds barely move with load; wall seconds do).
out=?
prev=
for a in "$@"; do
  [ "$prev" = "-o" ] && out=$a
  prev=$a
done
exec /usr/bin/time -a -o "${SWEEPTRACE_TIME_LOG:?set by tools/time-build.sh}" -f "%U %S %e $out" "$@"
