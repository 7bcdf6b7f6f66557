#!/usr/bin/env bash
# Progress of a farm job (farm.sh): how many of its sample ranges are done, which are missing,
# the Slurm state of its jobs and whether the image is written.
#   tools/slurm/status.sh DIR
# A part file is written atomically, so one that exists is complete; whether it verifies is
# checked by the task that would redo it (render --skip-existing) and by the merge.
set -euo pipefail
dir=${1:?usage: status.sh DIR}
# shellcheck source=/dev/null
source "$dir/farm.env"
done_count=0
missing=()
for ((i = 0; i < TASKS; i++)); do
    begin=$((i * SPP / TASKS)) end=$(((i + 1) * SPP / TASKS))
    if [ -f "$(printf '%s/parts/part-%06d-%06d.exr' "$dir" "$begin" "$end")" ]; then
        done_count=$((done_count + 1))
    else
        missing+=("$i:[$begin,$end)")
    fi
done
echo "ranges done: $done_count of $TASKS ($((100 * done_count / TASKS))%)"
[ ${#missing[@]} -eq 0 ] || echo "missing (task:[samples)): ${missing[*]}"
if [ -f "$dir/jobs" ] && command -v squeue >/dev/null; then
    read -r array merge < "$dir/jobs"
    echo "slurm jobs (array $array, merge $merge):"
    squeue -h -j "$array,$merge" -o '  %i %T %R' 2>/dev/null || echo "  none in the queue"
fi
if [ -f "$OUTPUT" ]; then echo "image: $OUTPUT"; else echo "image: not yet merged"; fi
