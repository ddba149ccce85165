#!/usr/bin/env bash
# Renders a scene on a Slurm cluster (docs/farm.md). Run it on the cluster's login node, from a
# folder on the filesystem that the nodes share:
#
#   bash scripts/slurm-render.sh [--wait] [--tasks N] [--tiles K] [--sbatch "OPTIONS"]
#                                [--farm-dir DIR] SCENE [clrender options]
#
# An animation becomes one job array whose tasks render contiguous chunks of frames
# (clrender --frames ... --resume), and, when a video is wanted, one job that waits for all of
# them (afterok) and encodes it (clrender --assemble). A still becomes K row bands (clrender
# --crop ... --resume), one array task each, and one job that joins them (clrender --join).
# The results are byte for byte those of `clrender SCENE [clrender options]` in one process.
# Running the same command again renders only what is missing.
#
# Exit codes: 0 submitted (with --wait: every job succeeded); 1 usage; 2-6 clrender refused the
# command before anything was submitted (its own exit codes); 8 with --wait, a job failed (the
# frames or tiles are named); 9 Slurm refused or could not be reached; 130 interrupted while
# waiting (the jobs keep running).
set -uo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
me="slurm-render"

usage() { sed -n '2,19p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2; }
die() { echo "$me: error: $1" >&2; exit "${2:-1}"; }
say() { echo "$me: $*" >&2; }

# ---- the script's own options, then SCENE, then clrender's --------------------------------
wait_for_jobs=0; tasks=""; tiles=""; sbatch_options=""; farm_dir=""; farm_dir_given=0
while [ $# -gt 0 ]; do
    case "$1" in
        --wait) wait_for_jobs=1; shift ;;
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

# ---- clrender's options: the ones the farm decides itself are taken out --------------------
# Which options take a value is asked of clrender itself (its completion list names a value's
# type after the option), so that a value is never mistaken for an option.
declare -A takes_value=()
while read -r name type _; do
    [ -n "$type" ] && takes_value["$name"]=1
done < <("$clrender" --completion-words)

pass=(); output=""; video=""; frames=""; threads_chosen=0
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
        -o|--output) output="$value" ;;
        --video) video="$value" ;;
        --frames) frames="$value" ;;
        --resume|--progress|-q|--quiet) ;;  # every task resumes and logs --progress json
        --stats|--assemble|--join|--crop|--explain-pixel|--check|--frame-count|--list-devices|--version|-h|--help)
            die "$option cannot be used on the farm: it splits the work itself (docs/farm.md)" ;;
        *)
            case "$option" in -t|--threads|-d|--device|--reference) threads_chosen=1 ;; esac
            pass+=("$option"); [ $has_value -eq 1 ] && pass+=("$value") ;;
    esac
done

# ---- what the scene is: clrender checks it (and every option) before anything is queued ----
summary="$("$clrender" "$scene" "${pass[@]}" --check)" || exit $?
size=$(sed -n 's/^size: *\([0-9]*\) x \([0-9]*\),.*/\1 \2/p' <<<"$summary")
frame_count=$(sed -n 's/^frames: *\([0-9]*\).*/\1/p' <<<"$summary")
read -r width height <<<"$size"
[ -n "${height:-}" ] && [ -n "$frame_count" ] || die "cannot read the size and frames from clrender --check" 5
name="$(basename "$scene")"; name="${name%.*}"

# "5,7,10-20" as a list of frames, each checked against the animation.
expand_frames() {
    local part first last
    IFS=',' read -ra parts <<<"$1"
    for part in "${parts[@]}"; do
        if [[ "$part" =~ ^([0-9]+)-([0-9]+)$ ]]; then first=$((10#${BASH_REMATCH[1]})); last=$((10#${BASH_REMATCH[2]}))
        elif [[ "$part" =~ ^[0-9]+$ ]]; then first=$((10#$part)); last=$first
        else die "--frames $1: expected frames such as 7, 0-99 or 5,7,10-20"; fi
        [ "$first" -le "$last" ] && [ "$last" -lt "$frame_count" ] ||
            die "--frames $1: $part is not within the animation's frames 0-$((frame_count - 1))"
        seq "$first" "$last"
    done | sort -nu
}

# Frames as the shortest --frames list: "0-9,12".
frame_list() {
    awk 'NR==1{a=b=$1;next} $1==b+1{b=$1;next} {printf "%s%s,", a, (a==b?"":"-" b); a=b=$1}
         END{printf "%s%s\n", a, (a==b?"":"-" b)}'
}

# The formats clrender writes (docs/command-line.md, Outputs), checked here so that a typo
# fails now and not in every task.
case "${output,,}" in ""|*.png|*.ppm|*.exr) ;; *) die "-o $output: clrender writes .png, .ppm or .exr images" ;; esac
case "${video,,}" in ""|*.mp4|*.gif) ;; *) die "--video $video: clrender writes .mp4 or .gif videos" ;; esac

# ---- the outputs: those of the same command in one process (docs/command-line.md, Outputs) -
if [ "$frame_count" -gt 1 ]; then
    [ -z "$tiles" ] || die "--tiles splits a still; $scene is an animation of $frame_count frames, split by --tasks"
    # (a subshell: a wrong list exits it with the message, and this script with its status)
    selection=$(if [ -n "$frames" ]; then expand_frames "$frames"; else seq 0 $((frame_count - 1)); fi) || exit 1
    mapfile -t selected <<<"$selection"
    [ -z "$video" ] && [ -z "$output" ] && [ -z "$frames" ] && video="$name.mp4"
    if [ -n "$output" ] && ! [[ "$output" =~ %0?[0-9]*d|\# ]] && [ ${#selected[@]} -gt 1 ]; then
        die "-o $output: the farm writes ${#selected[@]} frames; give a frame pattern such as frames/${name}_%04d.png"
    fi
    final_output="${video:-${output:-${name}_NNNN.png}}"
else
    [ -z "$tasks" ] || die "--tasks splits an animation's frames; $scene is a still, split by --tiles"
    [ -z "$frames" ] || { expand_frames "$frames" >/dev/null || exit 1; }
    final_output="${output:-$name.png}"
    case "${final_output,,}" in
        *.exr) die "-o $final_output: tiles are joined as PNG; render an EXR still in one process" ;;
    esac
    k=${tiles:-8}
    [ "$k" -le "$height" ] || die "--tiles $k: the image has only $height rows"
fi

# ---- the farm folder: logs, tiles, the frames of a video, the jobs of the last submission --
if [ -z "$farm_dir" ]; then
    farm_dir="${final_output%.*}.farm"  # out/flight.mp4: out/flight.farm
    [ "$frame_count" -gt 1 ] && [ -z "$video" ] && farm_dir="$name.farm"  # frames only: no one output names it
fi
mkdir -p "$farm_dir/logs" || die "cannot make the farm folder $farm_dir" 4
farm_dir="$(cd "$farm_dir" && pwd)"

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
task_commands=(); task_names=(); final_command=""
common=("$clrender" "$scene" "${pass[@]}" --progress json)
# A task renders with the CPUs Slurm gave it, not with every core of a node that others share.
threads_line='t=${SLURM_CPUS_PER_TASK:-${SLURM_CPUS_ON_NODE:-}}; threads=(); [ -n "$t" ] && [ -z "${CLRENDER_DEVICE:-}" ] && threads=(-t "$t")'
[ $threads_chosen -eq 1 ] && threads_line='threads=()'

if [ "$frame_count" -gt 1 ]; then
    pattern="$output"
    if [ -z "$pattern" ] && [ -n "$video" ]; then
        digits=${#frame_count}; [ "$digits" -lt 4 ] && digits=4
        pattern="$farm_dir/frames/${name}_%0${digits}d.png"
    fi
    n=${tasks:-16}; [ "$n" -gt ${#selected[@]} ] && n=${#selected[@]}
    for ((i = 0; i < n; i++)); do
        from=$((i * ${#selected[@]} / n)); to=$(((i + 1) * ${#selected[@]} / n))
        list=$(printf '%s\n' "${selected[@]:from:to-from}" | frame_list)
        outputs=(); [ -n "$pattern" ] && outputs=(-o "$pattern")
        task_commands+=("$(quote "${common[@]}" --frames "$list" "${outputs[@]}" --resume)")
        task_names+=("frames $list")
    done
    if [ -n "$video" ]; then
        assemble_frames=(); [ -n "$frames" ] && assemble_frames=(--frames "$frames")
        final_command="$(quote "${common[@]}" "${assemble_frames[@]}" --assemble -o "$pattern" --video "$video")"
    fi
else
    one_frame=(); [ -n "$frames" ] && one_frame=(--frames "$frames")
    joins=()
    for ((i = 0; i < k; i++)); do
        y0=$((i * height / k)); y1=$(((i + 1) * height / k))
        tile="$farm_dir/tiles/${name}_tile_$((i + 1))_of_${k}.png"
        task_commands+=("$(quote "${common[@]}" "${one_frame[@]}" --crop "0,$width,$y0,$y1" -o "$tile" --resume)")
        task_names+=("tile $((i + 1)) of $k, rows $y0-$((y1 - 1))")
        joins+=(--join "$tile")
    done
    final_outputs=(); [ -n "$output" ] && final_outputs=(-o "$output")
    final_command="$(quote "${common[@]}" "${one_frame[@]}" "${joins[@]}" "${final_outputs[@]}")"
fi

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
