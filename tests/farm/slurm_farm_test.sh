#!/usr/bin/env bash
# The farm on a real Slurm: starts a single-node cluster on this machine (tools/slurm/
# local-cluster.sh: munged, slurmctld, slurmd, all in a temp dir), submits tools/slurm/farm.sh's
# job array for a small scene in 5 uneven tasks, waits (bounded), checks the merged image is
# the one-machine render byte for byte; then deletes one part and re-submits: only that range is
# rendered again, the others are verified and kept, and the image is the same again; then an
# adaptive render (--adaptive on) in 3 tasks, the same byte for byte as one machine's. The
# daemons are stopped on every exit path. The daemons not starting is a failure, with their logs.
#   slurm_farm_test.sh SOURCE_DIR SWEEPTRACE_BINARY
set -euo pipefail
src=$(realpath "$1")
bin=$(realpath "$2")
export PATH="$PATH:/usr/sbin"

if ! command -v sbatch >/dev/null || ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
    echo "slurm test: slurm-wlm or munge missing; installing them (tools/install-deps.sh)" >&2
    bash "$src/tools/install-deps.sh"
fi

SECONDS=0
say() { echo "slurm test [${SECONDS} s]: $*"; }
tmp=$(mktemp -d /tmp/sweeptrace-slurm-test.XXXXXX)
cleanup() {
    local rc=$?
    bash "$src/tools/slurm/local-cluster.sh" stop "$tmp/cluster" || true
    if [ $rc -ne 0 ]; then
        for f in "$tmp"/farm/logs/*.log; do
            [ -f "$f" ] && { echo "----- $f -----" >&2; tail -n 20 "$f" >&2; }
        done
        for f in "$tmp"/cluster/log/*.log; do
            [ -f "$f" ] && { echo "----- $f (last 30 lines) -----" >&2; tail -n 30 "$f" >&2; }
        done
    fi
    rm -rf "$tmp"
    exit $rc
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# If this script is killed outright (SIGKILL, e.g. by a ctest timeout) the trap cannot run: a
# detached watcher then stops the daemons within a second of its death.
setsid bash -c 'while kill -0 "$1" 2>/dev/null; do sleep 1; done; bash "$2" stop "$3"; rm -rf "$4"' \
    watcher $$ "$src/tools/slurm/local-cluster.sh" "$tmp/cluster" "$tmp" </dev/null >/dev/null 2>&1 &
bash "$src/tools/slurm/local-cluster.sh" start "$tmp/cluster"
export SLURM_CONF="$tmp/cluster/slurm.conf"
say "cluster up"

scene="$src/scenes/cornell-box.json"
size=(--width 40 --height 40)
spp=13  # 5 tasks: [0,2) [2,5) [5,7) [7,10) [10,13)

# Waits for the merge job of the farm in $1 (default $tmp/farm) to leave the queue, 90 s at most.
wait_for_merge() {
    local array merge state
    read -r array merge < "${1:-$tmp/farm}/jobs"
    for _ in $(seq 450); do
        state=$(scontrol -o show job "$merge" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p')
        case "$state" in
            COMPLETED) return 0 ;;
            FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY|PREEMPTED)
                echo "slurm test: merge job $merge ended $state" >&2; scontrol show job "$array" >&2; return 1 ;;
        esac
        sleep 0.2
    done
    echo "slurm test: merge job $merge not done after 90 s (state '${state:-unknown}')" >&2
    squeue >&2 || true
    return 1
}

bash "$src/tools/slurm/farm.sh" --spp $spp --tasks 5 --dir "$tmp/farm" --sweeptrace "$bin" \
    "$scene" "$tmp/farm/final.png" -- "${size[@]}"
wait_for_merge
status=$(bash "$src/tools/slurm/status.sh" "$tmp/farm")
echo "$status"
grep -q "ranges done: 5 of 5 (100%)" <<< "$status" || { echo "slurm test: status does not say 5 of 5" >&2; exit 1; }

"$bin" render "$scene" "${size[@]}" --spp $spp --quiet -o "$tmp/one.png"
cmp "$tmp/one.png" "$tmp/farm/final.png" || { echo "slurm test: farm image differs from the one-machine render" >&2; exit 1; }
say "farm image (5 tasks) = one-machine render, byte for byte"

# A lost part: re-submitting renders only its range; the other four are verified and kept.
rm "$tmp/farm/parts/part-000005-000007.exr" "$tmp/farm/final.png"
grep -q "ranges done: 4 of 5" <<< "$(bash "$src/tools/slurm/status.sh" "$tmp/farm")" ||
    { echo "slurm test: status does not show the lost part" >&2; exit 1; }
rm "$tmp"/farm/logs/part-*.log
bash "$src/tools/slurm/farm.sh" --spp $spp --tasks 5 --dir "$tmp/farm" --sweeptrace "$bin" \
    "$scene" "$tmp/farm/final.png" -- "${size[@]}"
wait_for_merge
kept=$(grep -l "already a verified part of this render, kept" "$tmp"/farm/logs/part-*.log | wc -l)
[ "$kept" -eq 4 ] || { echo "slurm test: $kept of the 4 finished parts were kept on the re-run, not 4" >&2; exit 1; }
grep -q "kept" "$tmp/farm/logs/part-2.log" && { echo "slurm test: the lost part was not rendered again" >&2; exit 1; }
cmp "$tmp/one.png" "$tmp/farm/final.png" || { echo "slurm test: re-run image differs" >&2; exit 1; }
say "re-run rendered only the lost range, image identical again"

# Adaptive sampling: each task renders the pilot again for the allocation, and the parts carry
# each pixel's count; 3 tasks, the first ending inside the pilot: [0,9) [9,18) [18,28).
bash "$src/tools/slurm/farm.sh" --spp 28 --tasks 3 --dir "$tmp/farm-adaptive" --sweeptrace "$bin" \
    "$scene" "$tmp/farm-adaptive/final.png" -- "${size[@]}" --adaptive on
wait_for_merge "$tmp/farm-adaptive"
"$bin" render "$scene" "${size[@]}" --spp 28 --adaptive on --quiet -o "$tmp/one-adaptive.png"
cmp "$tmp/one-adaptive.png" "$tmp/farm-adaptive/final.png" ||
    { echo "slurm test: adaptive farm image differs from the one-machine render" >&2; exit 1; }
say "adaptive farm image (3 tasks) = one-machine adaptive render, byte for byte"
