#!/usr/bin/env bash
# Renders one image on a Slurm cluster: a job array whose tasks each render a range of the
# samples (`sweeptrace render --samples A:B`) into a shared folder, and a merge job that starts
# when every task has succeeded (--dependency=afterok) and sums the parts into the image, the
# same file bit for bit that one machine's `sweeptrace render --spp N` writes.
#
#   tools/slurm/farm.sh --spp N --tasks K [options] SCENE.json OUTPUT.png|.exr|.pfm [-- RENDER OPTIONS]
#     --dir DIR           shared folder for the job: parts/, logs/, farm.env (default: OUTPUT's
#                         folder / farm-<OUTPUT's name>)
#     --cpus C            cores per task (default 1); the render uses that many threads
#     --sweeptrace PATH   the binary, on a file system every node sees (default: build/sweeptrace
#                         of this checkout)
#     --sbatch "ARGS"     extra sbatch options for both jobs (partition, account, time limit)
#   RENDER OPTIONS go to every `sweeptrace render` (e.g. --width 1920 --height 1080 --seed 3).
#
# Task i of K renders samples [i*N/K, (i+1)*N/K). Running farm.sh again with the same arguments
# re-submits the job: tasks whose part already exists and verifies (same scene content, settings,
# program version and range) skip it, so only failed or preempted ranges are rendered again.
# Tasks are submitted with --requeue, so Slurm itself re-runs preempted ones. Progress:
# tools/slurm/status.sh DIR.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
die() { echo "farm: $*" >&2; exit 2; }

spp="" tasks="" dir="" cpus=1 sweeptrace="$here/../../build/sweeptrace" sbatch_extra=""
positional=()
while [ $# -gt 0 ]; do
    case "$1" in
        --spp) spp=$2; shift 2 ;;
        --tasks) tasks=$2; shift 2 ;;
        --dir) dir=$2; shift 2 ;;
        --cpus) cpus=$2; shift 2 ;;
        --sweeptrace) sweeptrace=$2; shift 2 ;;
        --sbatch) sbatch_extra=$2; shift 2 ;;
        --) shift; break ;;
        -*) die "unknown option '$1' (see the top of $0)" ;;
        *) positional+=("$1"); shift ;;
    esac
done
render_args=("$@")
[ ${#positional[@]} -eq 2 ] || die "usage: $0 --spp N --tasks K [options] SCENE.json OUTPUT.png [-- render options]"
[[ "$spp" =~ ^[1-9][0-9]*$ ]] || die "--spp must be a positive integer, got '$spp'"
[[ "$tasks" =~ ^[1-9][0-9]*$ ]] || die "--tasks must be a positive integer, got '$tasks'"
[[ "$cpus" =~ ^[1-9][0-9]*$ ]] || die "--cpus must be a positive integer, got '$cpus'"
[ "$tasks" -le "$spp" ] || die "--tasks $tasks is more than --spp $spp: every task needs a sample"
scene=$(realpath "${positional[0]}")
output=$(realpath -m "${positional[1]}")
[ -f "$scene" ] || die "scene '${positional[0]}' not found"
[ -x "$sweeptrace" ] || die "sweeptrace binary '$sweeptrace' not found (build it, or pass --sweeptrace)"
sweeptrace=$(realpath "$sweeptrace")
[ -n "$dir" ] || dir="$(dirname "$output")/farm-$(basename "${output%.*}")"
dir=$(realpath -m "$dir")
mkdir -p "$dir/parts" "$dir/logs"

# The job's settings, read by the task and merge scripts (and status.sh). A folder holds one job.
env_text=$(
    printf 'SCENE=%q\nOUTPUT=%q\nSPP=%q\nTASKS=%q\nSWEEPTRACE=%q\nRENDER_ARGS=(' \
        "$scene" "$output" "$spp" "$tasks" "$sweeptrace"
    [ ${#render_args[@]} -eq 0 ] || printf ' %q' "${render_args[@]}"
    printf ' )\n'
)
if [ -f "$dir/farm.env" ] && [ "$(cat "$dir/farm.env")" != "$env_text" ]; then
    die "$dir holds another farm job (its farm.env differs); use another --dir or remove it"
fi
printf '%s\n' "$env_text" > "$dir/farm.env"

# shellcheck disable=SC2086  # $sbatch_extra is a list of options on purpose
array=$(sbatch --parsable --array="0-$((tasks - 1))" --requeue --cpus-per-task="$cpus" \
    --job-name=sweeptrace-parts --output="$dir/logs/part-%a.log" $sbatch_extra \
    "$here/render-part.sbatch" "$dir")
array=${array%%;*}
# shellcheck disable=SC2086
merge=$(sbatch --parsable --dependency="afterok:$array" --kill-on-invalid-dep=yes \
    --job-name=sweeptrace-merge --output="$dir/logs/merge.log" $sbatch_extra \
    "$here/merge.sbatch" "$dir")
merge=${merge%%;*}
printf '%s %s\n' "$array" "$merge" > "$dir/jobs"
echo "farm: job array $array ($tasks tasks of $spp samples in all), merge job $merge -> $output"
echo "farm: progress: bash $here/status.sh $dir"
