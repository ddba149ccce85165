#!/usr/bin/env bash
# Renders a scene on a Slurm cluster (docs/farm.md). Run it on the cluster's login node, from a
# folder on the filesystem that the nodes share:
#
#   bash scripts/slurm-render.sh [--wait] [--tasks N] [--tiles K] [--sbatch "OPTIONS"]
#                                [--farm-dir DIR] [--no-device-check] SCENE [clrender options]
#
# An animation becomes one job array whose tasks render contiguous chunks of frames
# (clrender --frames ... --resume), and, when a video is wanted, one job that waits for all of
# them (afterok) and encodes it (clrender --assemble). A still becomes K row bands (clrender
# --crop ... --resume), one array task each, and one job that joins them (clrender --join).
# The results are byte for byte those of `clrender SCENE [clrender options]` in one process.
# Running the same command again renders only what is missing. What is rendered and written is
# what `clrender SCENE [clrender options] --plan` plans; whatever clrender would refuse is
# refused before anything is queued. The farm writes its bookkeeping only in a farm folder,
# one that it made (marked by a .clrender-farm file) or an empty one.
#
# Exit codes: 0 submitted (with --wait: every job succeeded); 1 usage; 2-6 clrender refused the
# command before anything was submitted (its own exit codes); 8 with --wait, a job failed (the
# frames or tiles are named); 9 Slurm refused or could not be reached; 130 interrupted while
# waiting (the jobs keep running).
set -uo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
me="slurm-render"

usage() { sed -n '2,21p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2; }
die() { echo "$me: error: $1" >&2; exit "${2:-1}"; }
say() { echo "$me: $*" >&2; }

# ---- the script's own options, then SCENE, then clrender's --------------------------------
wait_for_jobs=0; tasks=""; tiles=""; sbatch_options=""; farm_dir=""; farm_dir_given=0; device_check=1
while [ $# -gt 0 ]; do
    case "$1" in
        --wait) wait_for_jobs=1; shift ;;
        --no-device-check) device_check=0; shift ;;
        --tasks|--tiles|--sbatch|--farm-dir)
            [ $# -ge 2 ] || die "$1 needs a value"
            case "$1" in
                --tasks) tasks="$2" ;; --tiles) tiles="$2" ;;
                --sbatch) sbatch_options="$2" ;; --farm-dir) farm_dir="$2"; farm_dir_given=1 ;;
            esac
            shift 2 ;;
        --tasks=*) tasks="${1#*=}"; shift ;;
        --tiles=*) tiles="${1#*=}"; shift ;;
        --sbatch=*) sbatch_options="${1#*=}"; shift ;;
        --farm-dir=*) farm_dir="${1#*=}"; farm_dir_given=1; shift ;;
        -h|--help) usage; exit 0 ;;
        --) shift; break ;;
        -*) die "unknown option $1 before the scene (clrender's options come after SCENE); see --help" ;;
        *) break ;;
    esac
done
[ $# -ge 1 ] || { usage; die "no scene file given"; }
scene="$1"; shift
# A scene named like an option (-s.json, given after --) reaches clrender as a path.
case "$scene" in -*) scene="./$scene" ;; esac
for number in tasks tiles; do
    value="${!number}"
    [ -z "$value" ] || [[ "$value" =~ ^[1-9][0-9]{0,5}$ ]] || die "--$number must be a whole number from 1, got '$value'"
done

[ $farm_dir_given -eq 0 ] || [ -n "$farm_dir" ] || die "--farm-dir: the value is empty"

clrender="${CLRENDER:-$root/build/clrender}"
[ -x "$clrender" ] && [ -f "$clrender" ] ||
    die "no clrender program at $clrender: build it (README) or set CLRENDER to one on the shared filesystem"
clrender="$(cd "$(dirname "$clrender")" && pwd)/$(basename "$clrender")"
for program in sbatch squeue scontrol scancel flock; do
    command -v "$program" >/dev/null || die "$program is not installed: run this on the cluster's login node" 9
done

# ---- the farm folder --------------------------------------------------------------------------
# The only folder the farm writes its bookkeeping in (and the only one it would ever delete
# in): one it made, marked by this file, or an empty folder, which it marks. A folder of the
# user's files is refused, and so is a marked folder whose entries lead elsewhere by links.
marker=".clrender-farm"
# The farm folder's physical path (links resolved, made or not), once it is known to be the
# farm's: missing, empty, or marked. Exit 1 with a message for any other; writes nothing.
farm_folder_path() {
    local named="$1" real entry
    if [ -L "$named" ] && [ ! -e "$named" ]; then
        die "--farm-dir $named: a symbolic link to nothing; name a folder" 1
    fi
    if [ -e "$named" ] && [ ! -d "$named" ]; then die "--farm-dir $named: not a folder" 1; fi
    real="$(realpath -m -- "$named")" || die "--farm-dir $named: cannot resolve the path" 1
    if [ -d "$real" ]; then
        if [ -L "$real/$marker" ] || { [ -e "$real/$marker" ] && [ ! -f "$real/$marker" ]; }; then
            die "--farm-dir $named: $real/$marker is not a regular file; this is not a farm folder" 1
        elif [ ! -f "$real/$marker" ] && [ -n "$(ls -A -- "$real")" ]; then
            die "$named is a folder that the farm did not make (no $marker file in it) and it is not empty: the farm keeps its logs, frames and tiles only in a folder of its own; give --farm-dir a new or empty folder" 1
        fi
        for entry in logs tiles frames jobs tasks .lock; do
            [ ! -L "$real/$entry" ] ||
                die "the farm folder $named has a symbolic link $entry: the farm writes only inside its own folder; remove the link" 1
        done
    fi
    printf '%s\n' "$real"
}
# Makes the farm folder at its physical path and marks it (it is new or empty, or marked).
make_farm_folder() {
    local real="$1"
    mkdir -p -- "$real/logs" || die "cannot make the farm folder $real" 4
    [ -f "$real/$marker" ] ||
        printf 'clrender farm folder, made by scripts/slurm-render.sh (docs/farm.md, The farm folder)\n' \
            >"$real/$marker" || die "cannot write in the farm folder $real" 4
}

# ---- clrender's options: the ones the farm decides itself are taken out --------------------
# Which options take a value is asked of clrender itself (its completion list names a value's
# type after the option), so that a value is never mistaken for an option.
declare -A takes_value=()
while read -r name type _; do
    [ -n "$type" ] && takes_value["$name"]=1
done < <("$clrender" --completion-words)

pass=(); given_outputs=(); threads_chosen=0
while [ $# -gt 0 ]; do
    option="$1"; value=""; has_value=0
    case "$option" in
        --*=*) value="${option#*=}"; option="${option%%=*}"; has_value=1 ;;
        -[a-zA-Z]?*) if [ -n "${takes_value[${option:0:2}]:-}" ]; then value="${option:2}"; option="${option:0:2}"; has_value=1; fi ;;
    esac
    if [ -n "${takes_value[$option]:-}" ] && [ $has_value -eq 0 ]; then
        [ $# -ge 2 ] || die "clrender option $option needs a value"
        value="$2"; has_value=1; shift
    fi
    shift
    case "$option" in
        -o|--output|--video|--frames) given_outputs+=("$option" "$value") ;;  # the farm sets them per job
        --resume|--progress|-q|--quiet) ;;  # every task resumes and logs --progress json
        --stats|--assemble|--join|--crop|--explain-pixel|--check|--plan|--frame-count|--list-devices|--version|-h|--help)
            die "$option cannot be used on the farm: it splits the work itself (docs/farm.md)" ;;
        *)
            case "$option" in -t|--threads|-d|--device|--reference) threads_chosen=1 ;; esac
            pass+=("$option"); [ $has_value -eq 1 ] && pass+=("$value") ;;
    esac
done

# ---- what the run is: clrender plans it (and checks everything a render checks without a
# device) before anything is queued; the farm takes the frames, names and sizes from the plan,
# never from its own reading of the options (docs/farm.md, What the farm asks clrender).
# The plan as shell assignments; lists one item a line.
read_plan() {
    python3 -c '
import json, shlex, sys
plan = json.load(sys.stdin)
def say(name, value):
    print(name + "=" + shlex.quote("" if value is None else str(value)))
say("still", 1 if plan["still"] else 0)
say("frame_count", plan["frame_count"])
say("planned_frames", "\n".join(str(f) for f in plan["frames"]))
say("frame_pattern", plan["frame_pattern"])
say("first_image", plan["images"][0]["path"] if plan["images"] else None)
say("video", plan["video"])
say("device", plan["device"])
split = plan["split"]
say("split_by", split["by"])
if split["by"] == "rows":
    say("x0", split["x0"]); say("x1", split["x1"]); say("y0", split["y0"]); say("y1", split["y1"])
'
}
# `clrender ... --plan` for a command; its refusal (message, exit code) is the script's.
plan_of() {
    local json status
    json="$("$clrender" "$@" --plan)"; status=$?
    [ $status -eq 0 ] || return $status
    read_plan <<<"$json" || die "cannot read clrender's --plan output" 5
}
plan="$(plan_of "$scene" "${pass[@]}" "${given_outputs[@]}")" || exit $?
eval "$plan"
mapfile -t selected <<<"$planned_frames"
name="$(basename "$scene")"; name="${name%.*}"

# ---- the device: a -d (or CLRENDER_DEVICE) that names no device here is refused now, with
# clrender's message, unless --no-device-check says the nodes have devices this node lacks.
if [ -n "$device" ] && [ $device_check -eq 1 ]; then
    answer="$("$clrender" --list-devices -d "$device" 2>&1 >/dev/null)"; status=$?
    if [ $status -ne 0 ]; then
        if grep -q "no OpenCL device found" <<<"$answer"; then
            say "note: this node has no OpenCL device, so -d '$device' is checked on the nodes only"
        else
            echo "$answer" >&2
            die "-d '$device' names no device on this node; if the compute nodes have it, add --no-device-check" "$status"
        fi
    fi
fi

# ---- the outputs: those of the same command in one process (docs/command-line.md, Outputs) -
if [ "$still" -eq 0 ]; then
    [ -z "$tiles" ] || die "--tiles splits a still; $scene is an animation of $frame_count frames, split by --tasks"
    final_output="${video:-${frame_pattern:-$first_image}}"
else
    [ -z "$tasks" ] || die "--tasks splits an animation's frames; $scene is a still, split by --tiles"
    final_output="$first_image"
    height=$((y1 - y0)); width=$((x1 - x0))
    k=${tiles:-8}
    [ "$k" -le "$height" ] || die "--tiles $k: the image has only $height rows"
fi

# ---- the farm folder: logs, tiles, the frames of a video, the jobs of the last submission --
if [ -z "$farm_dir" ]; then
    farm_dir="${final_output%.*}.farm"  # out/flight.mp4: out/flight.farm
    [ "$still" -eq 0 ] && [ -z "$video" ] && farm_dir="$name.farm"  # frames only: no one output names it
fi
farm_dir="$(farm_folder_path "$farm_dir")" || exit $?

# ---- the tasks and the final job ------------------------------------------------------------
# Words for the batch script, each as the shell reads it back: plain when it is made of safe
# characters (so that the scripts stay readable: --crop 0,640,0,90), else in single quotes.
quote() {
    local word
    for word in "$@"; do
        if [[ "$word" =~ ^[A-Za-z0-9_./,:=+%@-]+$ ]]; then printf '%s ' "$word"
        else printf "'%s' " "${word//\'/\'\\\'\'}"; fi
    done
}
# Frames as the shortest --frames list: "0-9,12".
frame_list() {
    awk 'NR==1{a=b=$1;next} $1==b+1{b=$1;next} {printf "%s%s,", a, (a==b?"":"-" b); a=b=$1}
         END{printf "%s%s\n", a, (a==b?"":"-" b)}'
}
task_commands=(); task_names=(); final_words=(); first_task_words=()
common=("$clrender" "$scene" "${pass[@]}")
# A task renders with the CPUs Slurm gave it, not with every core of a node that others share.
threads_line='t=${SLURM_CPUS_PER_TASK:-${SLURM_CPUS_ON_NODE:-}}; threads=(); [ -n "$t" ] && [ -z "${CLRENDER_DEVICE:-}" ] && threads=(-t "$t")'
[ $threads_chosen -eq 1 ] && threads_line='threads=()'
frames_given=(); for ((i = 0; i < ${#given_outputs[@]}; i += 2)); do
    [ "${given_outputs[i]}" = --frames ] && frames_given=(--frames "${given_outputs[i + 1]}")
done
output_given=(); for ((i = 0; i < ${#given_outputs[@]}; i += 2)); do
    case "${given_outputs[i]}" in -o|--output) output_given=(-o "${given_outputs[i + 1]}") ;; esac
done

if [ "$still" -eq 0 ]; then
    # The frames go where the same command in one process writes them: the -o pattern, the
    # default names of a --frames selection, or (a video only) the farm folder, under a name
    # that holds no placeholder but the frame number's.
    outputs=("${output_given[@]}")
    if [ -n "$video" ] && [ ${#output_given[@]} -eq 0 ]; then
        last=$((frame_count - 1)); digits=${#last}; [ "$digits" -lt 4 ] && digits=4
        outputs=(-o "$farm_dir/frames/frame_%0${digits}d.png")
    fi
    n=${tasks:-16}; [ "$n" -gt ${#selected[@]} ] && n=${#selected[@]}
    for ((i = 0; i < n; i++)); do
        from=$((i * ${#selected[@]} / n)); to=$(((i + 1) * ${#selected[@]} / n))
        list=$(printf '%s\n' "${selected[@]:from:to-from}" | frame_list)
        words=("${common[@]}" --progress json --frames "$list" "${outputs[@]}" --resume)
        [ $i -eq 0 ] && first_task_words=("${words[@]}")
        task_commands+=("$(quote "${words[@]}")")
        task_names+=("frames $list")
    done
    [ -n "$video" ] && final_words=("${common[@]}" "${frames_given[@]}" --assemble "${outputs[@]}" --video "$video")
else
    joins=()
    for ((i = 0; i < k; i++)); do
        band0=$((y0 + i * height / k)); band1=$((y0 + (i + 1) * height / k))
        tile="$farm_dir/tiles/tile_$((i + 1))_of_${k}.png"
        words=("${common[@]}" --progress json "${frames_given[@]}" --crop "$x0,$x1,$band0,$band1" -o "$tile" --resume)
        [ $i -eq 0 ] && first_task_words=("${words[@]}")
        task_commands+=("$(quote "${words[@]}")")
        task_names+=("tile $((i + 1)) of $k, rows $band0-$((band1 - 1))")
        joins+=(--join "$tile")
    done
    final_words=("${common[@]}" "${frames_given[@]}" "${joins[@]}" "${output_given[@]}")
fi
# The final job is clrender too: what it would refuse (EXR frames read back by --assemble, an
# -o that tiles cannot make) is refused now, not after every task has rendered.
# A task is clrender on part of the work: the first is planned too (the others differ from it
# only in their frames or rows).
task_errors="$(plan_of "${first_task_words[@]:1}" 2>&1 >/dev/null)" || {
    status=$?
    echo "$task_errors" >&2
    die "the farm's first task would refuse this command (above); render it in one process" $status
}
final_command=""
if [ ${#final_words[@]} -gt 0 ]; then
    # (its warnings are the user's command's, shown above: only a refusal is shown)
    final_errors="$(plan_of "${final_words[@]:1}" 2>&1 >/dev/null)" || {
        status=$?
        echo "$final_errors" >&2
        die "the farm's final job ($( [ "$still" -eq 0 ] && echo "clrender --assemble, which encodes the video from the frames" || echo "clrender --join, which joins the tiles")) would refuse this command (above); render it in one process" $status
    }
    final_command="$(quote "${final_words[@]}" --progress json)"
fi

make_farm_folder "$farm_dir"
exec 9>"$farm_dir/.lock" || die "cannot write in the farm folder $farm_dir" 4
flock -n 9 || die "another slurm-render.sh is submitting to $farm_dir right now"

# "JOB REASON" (or squeue's format $2) for each job of a comma list still pending or running.
# A job that Slurm has forgotten (MinJobAge after it ended) is no longer queued; any other
# squeue error fails.
still_queued() {
    local job answer
    for job in ${1//,/ }; do
        if ! answer=$(squeue -h -j "$job" -o "${2:-%i %r}" 2>&1); then
            grep -q 'Invalid job id' <<<"$answer" || { echo "$answer"; return 1; }
            answer=""
        fi
        [ -n "$answer" ] && echo "$answer"
    done
    return 0
}
# An earlier submission of this farm that is still queued or running would render the same
# files at the same time; its final job that can never start (a task failed) is cancelled.
if [ -s "$farm_dir/jobs" ]; then
    read -r old_jobs <"$farm_dir/jobs"
    earlier=$(still_queued "$old_jobs" '%i %T %r') || die "cannot ask Slurm about the earlier run: $earlier" 9
    while read -r job state reason; do
        [ -z "$job" ] && continue
        if [ "$reason" = DependencyNeverSatisfied ]; then
            scancel "$job" 2>/dev/null && say "cancelled job $job of the earlier run (a task it waited for failed)"
        else
            die "an earlier farm run of this output is still in the queue (job $job: $state): wait for it, or scancel ${old_jobs//,/ }"
        fi
    done <<<"$earlier"
fi

mkdir -p "$farm_dir/tiles" "$farm_dir/frames"
printf '%s\n' "${task_names[@]}" >"$farm_dir/tasks"

# One batch script for the array: task i runs command i. Slurm keeps a copy, so a requeued
# task runs what was submitted even if this folder changes.
array_script() {
    echo '#!/usr/bin/env bash'
    echo "# clrender farm task, written by scripts/slurm-render.sh (docs/farm.md)"
    echo 'echo "clrender farm: task $SLURM_ARRAY_TASK_ID on $SLURMD_NODENAME, job ${SLURM_ARRAY_JOB_ID}_$SLURM_ARRAY_TASK_ID, run $((${SLURM_RESTART_COUNT:-0} + 1)), $(date -u +%FT%TZ)" >&2'
    echo "$threads_line"
    echo 'case "$SLURM_ARRAY_TASK_ID" in'
    for i in "${!task_commands[@]}"; do
        echo "  $i) exec ${task_commands[$i]}\"\${threads[@]}\" ;;"
    done
    echo '  *) echo "no task $SLURM_ARRAY_TASK_ID" >&2; exit 1 ;;'
    echo 'esac'
}
final_script() {
    echo '#!/usr/bin/env bash'
    echo "# clrender farm final job, written by scripts/slurm-render.sh (docs/farm.md)"
    echo 'echo "clrender farm: final job $SLURM_JOB_ID on $SLURMD_NODENAME, $(date -u +%FT%TZ)" >&2'
    echo "exec $final_command"
}

# shellcheck disable=SC2086  # --sbatch holds several options, split as a shell would
submit() { sbatch --parsable --chdir="$PWD" --job-name="clrender-$name" $sbatch_options "$@"; }

# Slurm reads % in a log name as a placeholder (%a: the task); %% is a literal %.
logs="${farm_dir//%/%%}/logs"
count=${#task_commands[@]}
jobs=""
# Interrupted between the two submissions, the array would run with nobody to assemble it.
trap 'say "interrupted: cancelling the jobs queued so far${jobs:+ ($jobs)}"; [ -n "$jobs" ] && scancel ${jobs//,/ }; exit 130' INT TERM
array_job=$(array_script | submit --array="0-$((count - 1))" --output="$logs/task_%a.log" --open-mode=append) ||
    die "sbatch refused the job array (see its message above)" 9
array_job="${array_job%%;*}"
jobs="$array_job"; final_job=""
if [ -n "$final_command" ]; then
    final_job=$(final_script | submit --dependency="afterok:$array_job" --kill-on-invalid-dep=yes \
        --output="$logs/final.log" --open-mode=append) || {
        scancel "$array_job"; die "sbatch refused the final job (see its message above); cancelled job $array_job" 9; }
    final_job="${final_job%%;*}"
    jobs="$array_job,$final_job"
fi
echo "$jobs" >"$farm_dir/jobs"
trap - INT TERM
say "job array $array_job: $count task(s) ($(head -1 "$farm_dir/tasks")$([ "$count" -gt 1 ] && echo " ... $(tail -1 "$farm_dir/tasks")"))"
[ -n "$final_job" ] && say "job $final_job: writes $final_output once every task succeeded"
say "logs: $farm_dir/logs (tail -f $farm_dir/logs/*.log)"
echo "$jobs"
[ $wait_for_jobs -eq 1 ] || exit 0

# ---- --wait: until no job of the run is queued, then the outcome of each -------------------
trap 'say "interrupted: the jobs keep running (squeue -j $jobs; scancel ${jobs//,/ } stops them)"; exit 130' INT TERM
unreachable_since=""
while :; do
    # squeue may fail for a while (slurmctld restarting); five minutes without an answer end
    # the wait, not the jobs.
    if ! queued=$(still_queued "$jobs"); then
        [ -n "$unreachable_since" ] || unreachable_since=$SECONDS
        [ $((SECONDS - unreachable_since)) -lt 300 ] ||
            die "squeue has not answered for 5 minutes ($queued); the jobs $jobs may still run" 9
        sleep 5; continue
    fi
    unreachable_since=""
    [ -z "$queued" ] && break
    # A final job whose tasks failed can never start: cancel it (--kill-on-invalid-dep does the
    # same where the cluster allows it).
    if [ -n "$final_job" ] && grep -q "^$final_job DependencyNeverSatisfied" <<<"$queued"; then
        scancel "$final_job"
    fi
    sleep 1
done

# The state of every task of the array, and of the final job.
declare -A task_state=() task_node=() task_exit=()
while read -r line; do
    id=$(grep -o 'ArrayTaskId=[0-9]*' <<<"$line" | cut -d= -f2)
    [ -n "$id" ] || continue
    task_state[$id]=$(grep -o 'JobState=[A-Z_]*' <<<"$line" | cut -d= -f2)
    task_node[$id]=$(grep -o ' NodeList=[^ ]*' <<<"$line" | cut -d= -f2)
    task_exit[$id]=$(grep -o ' ExitCode=[0-9]*' <<<"$line" | cut -d= -f2)
done < <(scontrol -o show job "$array_job" 2>/dev/null)
final_state=""
[ -n "$final_job" ] && final_state=$(scontrol -o show job "$final_job" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2)

failed=0
for ((i = 0; i < count; i++)); do
    state="${task_state[$i]:-UNKNOWN}"
    [ "$state" = COMPLETED ] && continue
    failed=1
    detail="$state"; [ "$state" = FAILED ] && detail="FAILED with exit code ${task_exit[$i]:-?}"
    say "task $i ($(sed -n "$((i + 1))p" "$farm_dir/tasks")): $detail on ${task_node[$i]:-no node}; log: $farm_dir/logs/task_$i.log"
done
if [ -n "$final_job" ] && [ "$final_state" != COMPLETED ]; then
    if [ $failed -eq 1 ] && [ "${final_state:-CANCELLED}" = CANCELLED ]; then
        say "job $final_job did not run: $final_output was not written, since a task failed"
    else
        say "job $final_job (writes $final_output): ${final_state:-UNKNOWN}; log: $farm_dir/logs/final.log"
    fi
    failed=1
fi
if [ $failed -eq 1 ]; then
    say "run the same command again to render only what is missing"
    exit 8
fi
say "done: $final_output"
