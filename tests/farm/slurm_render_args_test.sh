#!/usr/bin/env bash
# scripts/slurm-render.sh without a cluster (docs/farm.md): sbatch, squeue, scontrol and
# scancel are stand-ins that record what they are asked and keep the batch scripts. The test
# checks what is refused before anything is queued (clrender's refusals, with its messages and
# exit codes, as `clrender --plan` reports them; a device no device here matches; a farm folder
# that is not the farm's), that the tasks split the work exactly (each
# frame once, each row once), that clrender's options reach every task unchanged, and, running
# the recorded batch scripts here one after another, that the result is byte for byte the
# one-process render.
#
#   slurm_render_args_test.sh CLRENDER SOURCE_DIR
set -uo pipefail

clrender="$1"; source_dir="$2"
work="$(mktemp -d /tmp/clrender-farm-args.XXXXXX)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAILED: $*" >&2; failures=$((failures + 1)); }

# ---- stand-ins for Slurm's commands ---------------------------------------------------------
fake="$work/bin"; mkdir -p "$fake"
cat >"$fake/sbatch" <<'EOF'
#!/usr/bin/env bash
# Records the options and the batch script (standard input); prints the next job id.
[ -n "${FAKE_SBATCH_FAILS:-}" ] && { echo "sbatch: error: Batch job submission failed: Invalid partition" >&2; exit 1; }
n=$(($(cat "$FAKE_SLURM/next" 2>/dev/null || echo 100) + 1)); echo "$n" >"$FAKE_SLURM/next"
printf '%s\n' "$@" >"$FAKE_SLURM/job_$n.options"
cat >"$FAKE_SLURM/job_$n.sh"
echo "$n"
EOF
cat >"$fake/squeue" <<'EOF'
#!/usr/bin/env bash
cat "$FAKE_SLURM/queue" 2>/dev/null; exit 0
EOF
cat >"$fake/scontrol" <<'EOF'
#!/usr/bin/env bash
exit 0
EOF
cat >"$fake/scancel" <<'EOF'
#!/usr/bin/env bash
echo "$@" >>"$FAKE_SLURM/cancelled"
EOF
chmod +x "$fake"/*
export PATH="$fake:$PATH" CLRENDER="$clrender"

# A run in a fresh folder with the demo scenes; FAKE_SLURM records what was submitted.
run_farm() {
    export FAKE_SLURM="$work/slurm"
    rm -rf "$FAKE_SLURM" "$work/run"; mkdir -p "$FAKE_SLURM" "$work/run"
    cp -r "$source_dir/scenes/demo" "$work/run/demo"
    (cd "$work/run" && bash "$source_dir/scripts/slurm-render.sh" "$@") >"$work/out.txt" 2>"$work/err.txt"
}
submitted() { ls "$FAKE_SLURM"/job_*.sh 2>/dev/null | wc -l; }

# Refused before anything is queued: exit code, a message naming the problem, no job.
expect_refusal() {
    local code="$1" fragment="$2"; shift 2
    run_farm "$@"; local status=$?
    [ $status -eq "$code" ] || fail "$*: exit $status, expected $code ($(cat "$work/err.txt"))"
    grep -qF -- "$fragment" "$work/err.txt" || fail "$*: the message lacks '$fragment': $(cat "$work/err.txt")"
    [ "$(submitted)" -eq 0 ] || fail "$*: a job was submitted"
    [ "$(grep -c . "$work/err.txt")" -ge 1 ] || fail "$*: no message"
}

expect_refusal 1 "--tasks must be a whole number" --tasks 0 demo/showcase.json
expect_refusal 1 "--tasks must be a whole number" --tasks abc demo/showcase.json
expect_refusal 1 "--tiles must be a whole number" --tiles -3 demo/demo.json
expect_refusal 1 "unknown option --task" --task 3 demo/showcase.json
expect_refusal 1 "no scene file given" --wait
expect_refusal 1 "--farm-dir: the value is empty" --farm-dir "" demo/demo.json
expect_refusal 1 "--stats cannot be used on the farm" demo/showcase.json --stats s.json
expect_refusal 1 "--crop cannot be used on the farm" demo/demo.json --crop 0,10,0,10
expect_refusal 1 "--assemble cannot be used on the farm" demo/showcase.json --assemble
expect_refusal 1 "--tiles splits a still" --tiles 4 demo/showcase.json
expect_refusal 1 "--tasks splits an animation" --tasks 4 demo/demo.json
expect_refusal 1 "the image has only 10 rows" --tiles 11 demo/demo.json --size 20x10
# What clrender refuses, the farm refuses before queueing, with clrender's message and exit
# code: the script takes the frames and names from `clrender --plan`, never from its own
# reading of the options.
expect_refusal 1 "give a frame pattern" demo/showcase.json -o one.png
expect_refusal 1 "frame 99 is out of range: the animation has 96 frames" demo/showcase.json --frames 90-99
expect_refusal 1 "frame 3 is out of range: the animation has 1 frame" demo/demo.json --frames 3
expect_refusal 1 "still.bmp" demo/demo.json -o still.bmp
expect_refusal 1 "flight.avi" demo/showcase.json --video flight.avi
# A still with --video: clrender refuses it, so the farm queues nothing and replaces nothing.
run_farm_keeping_image() {
    export FAKE_SLURM="$work/slurm"
    rm -rf "$FAKE_SLURM" "$work/run"; mkdir -p "$FAKE_SLURM" "$work/run"
    cp -r "$source_dir/scenes/demo" "$work/run/demo"
    echo "the user's image" >"$work/run/mine.png"
    (cd "$work/run" && bash "$source_dir/scripts/slurm-render.sh" "$@") >"$work/out.txt" 2>"$work/err.txt"
}
run_farm_keeping_image demo/demo.json -o mine.png --video v.mp4
[ $? -eq 1 ] && grep -q "is a still (one camera key)" "$work/err.txt" && [ "$(submitted)" -eq 0 ] ||
    fail "a still with --video is refused before queueing: $(cat "$work/err.txt")"
[ "$(cat "$work/run/mine.png")" = "the user's image" ] || fail "a refused still with --video changed the image"
[ ! -e "$work/run/mine.farm" ] || fail "a refused run made its farm folder"
# Names that a regular expression takes for frame patterns and clrender does not: a '#' in a
# folder, a three-digit width. Several frames into one name are refused, as clrender does.
expect_refusal 1 "the animation has 4 frames to write; give a frame pattern" demo/showcase.json --frames 0-3 -o 'a#b/f.png'
expect_refusal 1 "the animation has 4 frames to write; give a frame pattern" demo/showcase.json --frames 0-3 -o 'f_%100d.png'
# One frame into such a name is one task writing that one file.
run_farm --tasks 4 demo/showcase.json --frames 3 --size 32x18 -o 'a#b/f.png' || fail "one frame to a plain name: $(cat "$work/err.txt")"
[ "$(grep -c -- "-o 'a#b/f.png'" "$FAKE_SLURM/job_101.sh")" -eq 1 ] && grep -q -- '--array=0-0' "$FAKE_SLURM/job_101.options" ||
    fail "one frame to a plain name is one task writing it: $(cat "$FAKE_SLURM/job_101.sh")"
# Refused only by the final job in the past: --alpha with a video, EXR frames read back into a
# video (--assemble), an -o pattern that tiles cannot be joined into.
expect_refusal 1 "--alpha: the video v.mp4 would have no alpha channel" demo/showcase.json --alpha --video v.mp4
expect_refusal 1 "EXR frames cannot be read back into a video" demo/showcase.json -o 'f_%04d.exr' --video v.mp4
expect_refusal 1 "the farm's final job (clrender --assemble" demo/showcase.json -o 'f_%04d.exr' --video v.mp4
[ ! -e "$work/run/v.farm" ] || fail "a run that the final job would refuse made its farm folder"
expect_refusal 1 "is an EXR" demo/demo.json -o still.exr
# A device that no device here matches: clrender's message and exit code, unless the nodes are
# said to have devices this node lacks.
if "$clrender" --list-devices | grep -q '\[0\]'; then
    expect_refusal 3 "unknown OpenCL device 'nosuchdevicexyz'" demo/demo.json -d nosuchdevicexyz
    CLRENDER_DEVICE=nosuchdevicexyz expect_refusal 3 "unknown OpenCL device 'nosuchdevicexyz'" demo/demo.json
    run_farm --no-device-check demo/demo.json -d nosuchdevicexyz && [ "$(submitted)" -eq 2 ] ||
        fail "--no-device-check queues a device this node lacks: $(cat "$work/err.txt")"
fi

# ---- the farm folder: the only folder the farm writes its bookkeeping in --------------------
# A folder of the user's files is refused, whether named or the default name.
farm_dir_refused() {  # FOLDER_SETUP... -- farm arguments
    local setup=()
    while [ "$1" != -- ]; do setup+=("$1"); shift; done; shift
    export FAKE_SLURM="$work/slurm"
    rm -rf "$FAKE_SLURM" "$work/run"; mkdir -p "$FAKE_SLURM" "$work/run"
    cp -r "$source_dir/scenes/demo" "$work/run/demo"
    (cd "$work/run" && eval "${setup[*]}") || fail "setup ${setup[*]}"
    (cd "$work/run" && bash "$source_dir/scripts/slurm-render.sh" "$@") >"$work/out.txt" 2>"$work/err.txt"
}
farm_dir_refused 'mkdir mine && echo precious >mine/jobs' -- --farm-dir mine demo/demo.json
[ $? -eq 1 ] && grep -q "mine is a folder that the farm did not make" "$work/err.txt" && [ "$(submitted)" -eq 0 ] ||
    fail "an ordinary folder as --farm-dir is refused: $(cat "$work/err.txt")"
[ "$(cat "$work/run/mine/jobs")" = precious ] && [ "$(ls -A "$work/run/mine")" = jobs ] ||
    fail "a refused --farm-dir was written in: $(ls -A "$work/run/mine")"
farm_dir_refused 'mkdir demo.farm && echo precious >demo.farm/notes' -- demo/demo.json
[ $? -eq 1 ] && grep -q "demo.farm is a folder that the farm did not make" "$work/err.txt" ||
    fail "an ordinary folder under the default farm name is refused: $(cat "$work/err.txt")"
# A link to a user's folder is refused as the folder is; a marker that is a link is no marker.
farm_dir_refused 'mkdir mine && echo precious >mine/notes && ln -s mine link' -- --farm-dir link demo/demo.json
[ $? -eq 1 ] && [ "$(ls -A "$work/run/mine")" = notes ] || fail "a link to an ordinary folder is refused: $(cat "$work/err.txt")"
farm_dir_refused 'mkdir mine f && echo x >mine/notes && touch f/.clrender-farm && ln -s ../f/.clrender-farm mine/.clrender-farm' \
    -- --farm-dir mine demo/demo.json
[ $? -eq 1 ] && grep -q "is not a regular file" "$work/err.txt" || fail "a linked marker is refused: $(cat "$work/err.txt")"
farm_dir_refused 'ln -s nowhere gone' -- --farm-dir gone demo/demo.json
[ $? -eq 1 ] && grep -q "a symbolic link to nothing" "$work/err.txt" || fail "a dangling link is refused: $(cat "$work/err.txt")"
farm_dir_refused 'echo x >plain' -- --farm-dir plain demo/demo.json
[ $? -eq 1 ] && grep -q "not a folder" "$work/err.txt" || fail "a file as --farm-dir is refused: $(cat "$work/err.txt")"
# A marked folder whose entries lead elsewhere is refused: the farm writes only inside it.
farm_dir_refused 'mkdir -p f elsewhere && touch f/.clrender-farm && ln -s ../elsewhere f/logs' -- --farm-dir f demo/demo.json
[ $? -eq 1 ] && grep -q "has a symbolic link logs" "$work/err.txt" && [ -z "$(ls -A "$work/run/elsewhere")" ] ||
    fail "a farm folder with a linked entry is refused: $(cat "$work/err.txt")"
# A new folder, an empty one, and a link to a marked one are the farm's: marked, used.
farm_dir_refused 'true' -- --farm-dir new/f demo/demo.json --size 20x10
[ $? -eq 0 ] && [ -f "$work/run/new/f/.clrender-farm" ] && [ -s "$work/run/new/f/jobs" ] ||
    fail "a new farm folder is made and marked: $(cat "$work/err.txt")"
farm_dir_refused 'mkdir empty' -- --farm-dir empty demo/demo.json --size 20x10
[ $? -eq 0 ] && [ -f "$work/run/empty/.clrender-farm" ] || fail "an empty folder is marked and used: $(cat "$work/err.txt")"
farm_dir_refused 'mkdir f && touch f/.clrender-farm f/jobs && ln -s f link' -- --farm-dir link demo/demo.json --size 20x10
[ $? -eq 0 ] && [ -s "$work/run/f/jobs" ] && [ -L "$work/run/link" ] && grep -q -- "$work/run/f/tiles" "$FAKE_SLURM/job_101.sh" ||
    fail "a link to a farm folder is followed to it: $(cat "$work/err.txt")"
# clrender's own checks, with its exit codes: an option it does not know, a broken scene.
expect_refusal 1 "--spp" demo/demo.json --spp 0
expect_refusal 2 "missing.json" demo/missing.json
echo '{"spheres": [' >"$work/broken.json"
expect_refusal 2 "broken.json" "$work/broken.json"
CLRENDER="$work/nowhere/clrender" expect_refusal 1 "no clrender program at $work/nowhere/clrender" demo/demo.json
FAKE_SBATCH_FAILS=1 run_farm demo/demo.json
[ $? -eq 9 ] && grep -q "Invalid partition" "$work/err.txt" || fail "a refused sbatch exits 9 with its message"

# ---- the split: every selected frame once, in contiguous chunks -----------------------------
# The --frames lists of the array script's tasks, one line each.
task_frame_lists() { sed -n 's/.* --frames \([0-9,-]*\) .*/\1/p' "$FAKE_SLURM/job_101.sh"; }
expand() { tr ',' '\n' | while IFS=- read -r a b; do seq "$a" "${b:-$a}"; done; }

run_farm --tasks 7 demo/showcase.json --frames 5,7,10-20,90-95 --size 64x36 --video v.mp4 ||
    fail "a frame selection is submitted: $(cat "$work/err.txt")"
[ "$(task_frame_lists | wc -l)" -eq 7 ] || fail "7 tasks expected: $(task_frame_lists | tr '\n' ' ')"
[ "$(task_frame_lists | expand | tr '\n' ' ')" = "$(printf '%s\n' 5 7 $(seq 10 20) $(seq 90 95) | tr '\n' ' ')" ] ||
    fail "the chunks do not cover the selection once, in order: $(task_frame_lists | tr '\n' ' ')"
grep -q -- '--array=0-6' "$FAKE_SLURM/job_101.options" || fail "the job array has 7 tasks"
grep -q -- '--dependency=afterok:101' "$FAKE_SLURM/job_102.options" || fail "the video waits for the array (afterok)"
grep -q -- '--assemble' "$FAKE_SLURM/job_102.sh" || fail "the final job assembles the video"

run_farm --tasks 1000 demo/showcase.json --size 64x36 -o f/f_%04d.png
[ "$(task_frame_lists | wc -l)" -eq 96 ] || fail "at most one task per frame"
[ "$(submitted)" -eq 1 ] || fail "frames without a video need no final job"

# ---- the split of a still: every row once ----------------------------------------------------
run_farm --tiles 7 demo/demo.json --size 101x359 -o still.png || fail "a tiled still is submitted: $(cat "$work/err.txt")"
rows=$(sed -n 's/.* --crop 0,101,\([0-9]*\),\([0-9]*\) .*/\1 \2/p' "$FAKE_SLURM/job_101.sh")
[ "$(wc -l <<<"$rows")" -eq 7 ] || fail "7 tiles expected: $rows"
[ "$(while read -r a b; do seq "$a" $((b - 1)); done <<<"$rows" | tr '\n' ' ')" = "$(seq 0 358 | tr '\n' ' ')" ] ||
    fail "the tiles do not cover rows 0-358 once: $rows"
[ "$(grep -o -- '--join' "$FAKE_SLURM/job_102.sh" | wc -l)" -eq 7 ] || fail "the final job joins 7 tiles"

# ---- options reach every task unchanged; --sbatch reaches sbatch ------------------------------
run_farm --tasks 2 --sbatch "--partition=gpu --time=01:00:00" demo/showcase.json --size 64x36 --spp 2 \
    -D 'clrender.seed=7' --placeholders --video 'my video.mp4'
for job in 101 102; do
    grep -qx -- '--partition=gpu' "$FAKE_SLURM/job_$job.options" && grep -qx -- '--time=01:00:00' "$FAKE_SLURM/job_$job.options" ||
        fail "--sbatch options reach sbatch for job $job"
    grep -q -- '--size 64x36 --spp 2 -D clrender.seed=7 --placeholders' "$FAKE_SLURM/job_$job.sh" ||
        fail "clrender's options reach job $job unchanged"
done
grep -q -- "--video 'my video.mp4'" "$FAKE_SLURM/job_102.sh" || fail "a file name with a space is quoted"

# ---- an earlier run of the same output still queued -------------------------------------------
run_farm --tasks 2 demo/showcase.json --size 64x36 --video v.mp4
mkdir -p "$work/keep" && cp -r "$work/run/v.farm" "$work/keep/"
rerun_with_queue() {
    export FAKE_SLURM="$work/slurm"; rm -rf "$FAKE_SLURM"; mkdir -p "$FAKE_SLURM"
    echo "$1" >"$FAKE_SLURM/queue"
    (cd "$work/run" && rm -rf v.farm && cp -r "$work/keep/v.farm" . &&
        bash "$source_dir/scripts/slurm-render.sh" --tasks 2 demo/showcase.json --size 64x36 --video v.mp4) \
        >"$work/out.txt" 2>"$work/err.txt"
}
rerun_with_queue "101_1 RUNNING None"
[ $? -eq 1 ] && grep -q "still in the queue (job 101_1: RUNNING)" "$work/err.txt" && [ "$(submitted)" -eq 0 ] ||
    fail "a rerun while the earlier run is queued is refused: $(cat "$work/err.txt")"
rerun_with_queue "102 PENDING DependencyNeverSatisfied"
[ $? -eq 0 ] && grep -qx 102 "$FAKE_SLURM/cancelled" && [ "$(submitted)" -eq 2 ] ||
    fail "the earlier run's final job that can never start is cancelled, and the run submitted"

# ---- the recorded batch scripts, run here, give the one-process bytes -------------------------
run_tasks_here() {  # runs every array task, then the final job, as Slurm would
    local tasks; tasks=$(sed -n 's/^--array=0-//p' "$FAKE_SLURM/job_101.options")
    for i in $(seq 0 "$tasks"); do
        (cd "$work/run" && SLURM_ARRAY_TASK_ID=$i SLURMD_NODENAME=here SLURM_CPUS_ON_NODE=1 bash "$FAKE_SLURM/job_101.sh") \
            >>"$work/tasks.log" 2>&1 || fail "task $i failed: $(tail -3 "$work/tasks.log")"
    done
    [ -f "$FAKE_SLURM/job_102.sh" ] && { (cd "$work/run" && bash "$FAKE_SLURM/job_102.sh") >>"$work/tasks.log" 2>&1 ||
        fail "the final job failed: $(tail -3 "$work/tasks.log")"; }
}
run_farm --tiles 5 demo/demo.json --size 160x97 --spp 3 -o out/still.png && run_tasks_here
(cd "$work/run" && "$clrender" demo/demo.json --size 160x97 --spp 3 -o one.png -q)
cmp -s "$work/run/out/still.png" "$work/run/one.png" || fail "joined tiles differ from the one-process still"
grep -q '"percent":100.0' "$work/tasks.log" || fail "tasks log --progress json"

run_farm --tasks 3 demo/showcase.json --frames 0-9 --size 96x54 --video out/v.mp4 && run_tasks_here
(cd "$work/run" && "$clrender" demo/showcase.json --frames 0-9 --size 96x54 --video one.mp4 -q)
cmp -s "$work/run/out/v.mp4" "$work/run/one.mp4" || fail "the assembled video differs from the one-process video"
# Run twice (a requeued task): nothing renders again, the result is the same.
before=$(stat -c '%Y %i' "$work/run/out/v.farm/frames/"*.png | md5sum)
run_tasks_here
[ "$before" = "$(stat -c '%Y %i' "$work/run/out/v.farm/frames/"*.png | md5sum)" ] || fail "a task run twice rendered its frames again"
cmp -s "$work/run/out/v.mp4" "$work/run/one.mp4" || fail "a task run twice changed the video"

# A --frames selection without -o and --video: clrender's own default names, no final job.
run_farm --tasks 2 demo/showcase.json --frames 4-7 --size 32x18 && run_tasks_here
[ "$(submitted)" -eq 1 ] || fail "frames under the default names need no final job"
(cd "$work/run" && ls showcase_*.png 2>/dev/null | tr '\n' ' ') | grep -qx "showcase_0004.png showcase_0005.png showcase_0006.png showcase_0007.png " ||
    fail "the default frame names are clrender's: $(ls "$work/run")"

# A scene whose name holds a placeholder: the farm's own frame and tile names hold none, so the
# frames go where the final job reads them.
run_farm_named() {
    export FAKE_SLURM="$work/slurm"
    rm -rf "$FAKE_SLURM" "$work/run"; mkdir -p "$FAKE_SLURM" "$work/run"
    cp -r "$source_dir/scenes/demo" "$work/run/demo"
    cp "$work/run/demo/showcase.json" "$work/run/demo/fly%d#.json"
    cp "$work/run/demo/demo.json" "$work/run/demo/still%d#.json"
    (cd "$work/run" && bash "$source_dir/scripts/slurm-render.sh" "$@") >"$work/out.txt" 2>"$work/err.txt"
}
run_farm_named --tasks 2 'demo/fly%d#.json' --frames 0-3 --size 48x27 --video v.mp4 && run_tasks_here
(cd "$work/run" && "$clrender" 'demo/fly%d#.json' --frames 0-3 --size 48x27 --video one.mp4 -q)
cmp -s "$work/run/v.mp4" "$work/run/one.mp4" || fail "a scene named with a placeholder: the video differs: $(cat "$work/err.txt")"
run_farm_named --tiles 3 'demo/still%d#.json' --size 48x27 && run_tasks_here
(cd "$work/run" && "$clrender" 'demo/still%d#.json' --size 48x27 -o one.png -q)
cmp -s "$work/run/still%d#.png" "$work/run/one.png" || fail "a still named with a placeholder: the image differs: $(cat "$work/err.txt")"

# A scene whose name starts with '-', given after '--': clrender is given it as a path, not as
# an option, and the image is the one-process image.
run_farm_dash() {
    export FAKE_SLURM="$work/slurm"
    rm -rf "$FAKE_SLURM" "$work/run"; mkdir -p "$FAKE_SLURM" "$work/run"
    cp "$source_dir/scenes/demo/"* "$work/run/" && cp "$work/run/demo.json" "$work/run/-still.json"
    (cd "$work/run" && bash "$source_dir/scripts/slurm-render.sh" "$@") >"$work/out.txt" 2>"$work/err.txt"
}
run_farm_dash --tiles 3 -- -still.json --size 48x27 -o out.png && run_tasks_here ||
    fail "a scene named -still.json is submitted: $(cat "$work/err.txt")"
(cd "$work/run" && "$clrender" ./-still.json --size 48x27 -o one.png -q)
cmp -s "$work/run/out.png" "$work/run/one.png" || fail "a scene named -still.json: the image differs"

[ $failures -eq 0 ] || { echo "$failures check(s) failed" >&2; exit 1; }
echo "passed"
