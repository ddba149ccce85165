#!/usr/bin/env bash
# The render farm on a real Slurm cluster (docs/farm.md): a two-node cluster on this machine
# (tests/farm/slurm_cluster.sh) renders through scripts/slurm-render.sh, and every result is
# compared byte for byte with the same command run in one process. Then one task's node dies
# in the middle of its frames, and a second run of the same command finishes the work without
# rendering any finished frame again; and Slurm requeues a running task, which then skips what
# its first run finished.
#
#   slurm_farm_test.sh CLRENDER SOURCE_DIR
#
# Exit 0: passed; 77: skipped (the daemons cannot run here; the reason is printed); else failed.
set -uo pipefail

clrender="$1"; source_dir="$2"
work="$(mktemp -d /tmp/clrender-farm-test.XXXXXX)"
cluster="$work/cluster"
failures=0

# Every daemon the test started is stopped, and the test fails if one is left.
cleanup() {
    local status=$?
    bash "$source_dir/tests/farm/slurm_cluster.sh" stop "$cluster"
    if pgrep -f -a "$cluster" >&2; then
        echo "FAILED: processes of the test cluster are still running (above)" >&2
        status=1
    fi
    rm -rf "$work"
    exit $status
}
trap cleanup EXIT

fail() { echo "FAILED: $*" >&2; failures=$((failures + 1)); }
check() { local what="$1"; shift; "$@" || fail "$what"; }
same_file() { cmp -s "$1" "$2" || { echo "  $1 differs from $2" >&2; return 1; }; }

bash "$source_dir/tests/farm/slurm_cluster.sh" start "$cluster"
status=$?
if [ $status -ne 0 ]; then
    echo "SKIPPED: the test cluster did not start (exit $status); see the reason above" >&2
    exit 77
fi
eval "$(bash "$source_dir/tests/farm/slurm_cluster.sh" env "$cluster")"
export CLRENDER="$clrender"

# The docs' commands run as written from a folder that looks like the repository: the scripts
# and the demo scenes, on the "shared filesystem" that both nodes see (this machine's).
repo="$work/repo"
mkdir -p "$repo/scenes"
cp -r "$source_dir/scripts" "$repo/scripts"
cp -r "$source_dir/scenes/demo" "$repo/scenes/demo"
cd "$repo" || exit 1
farm() { bash scripts/slurm-render.sh "$@"; }
one() { "$clrender" "$@" -q; }

# The nodes that ran the tasks of a farm folder's logs.
nodes_of() { sed -n 's/^clrender farm: task [0-9]* on \(node[0-9]*\),.*/\1/p' "$1"/logs/task_*.log | sort -u | tr '\n' ' '; }

# ---- 1. the documented commands: an animation with its video, a tiled still -----------------
commands="$(sed -n '/^## Quick start/,/^## /p' "$source_dir/docs/farm.md" | sed -n '/^```sh$/,/^```$/p' | grep -v '^```')"
[ -n "$commands" ] || fail "docs/farm.md has no sh block under '## Quick start'"
echo "$commands" >quick-start.sh
echo "--- docs/farm.md, Quick start:"; cat quick-start.sh
check "the Quick start commands succeed" bash -e quick-start.sh

one scenes/demo/showcase.json --size 320x180 --spp 4 -o one/frames/f_%04d.png --video one/showcase.mp4
one scenes/demo/demo.json --size 640x360 --spp 4 -o one/demo.png
check "the farm's video is the one-process video" same_file out/showcase.mp4 one/showcase.mp4
check "the farm's still is the one-process still" same_file out/demo.png one/demo.png
frames_checked=0
for frame in out/showcase.farm/frames/*.png; do
    same_file "$frame" "one/frames/f_${frame##*_}" || fail "frame $frame"
    frames_checked=$((frames_checked + 1))
done
[ "$frames_checked" -eq 96 ] || fail "96 frames expected in out/showcase.farm/frames, found $frames_checked"
task_logs=$(ls out/showcase.farm/logs/task_*.log | wc -l)
[ "$task_logs" -eq 8 ] || fail "8 task logs expected, found $task_logs"
for log in out/showcase.farm/logs/task_*.log out/demo.farm/logs/task_*.log; do
    grep -q '"percent":100.0' "$log" || fail "$log shows no finished task (--progress json)"
done
[ "$(nodes_of out/showcase.farm)" = "node1 node2 " ] || fail "the animation's tasks ran on: $(nodes_of out/showcase.farm)"
[ "$(nodes_of out/demo.farm)" = "node1 node2 " ] || fail "the still's tiles ran on: $(nodes_of out/demo.farm)"
ls -A out/showcase.farm/frames out/demo.farm/tiles | grep -q '^\.clrender-' && fail "temporary files were left"

# ---- 2. without --wait: the job ids, and the jobs run on ------------------------------------
jobs=$(farm --tasks 3 scenes/demo/showcase.json --frames 10-20 --size 160x90 -o nowait/f_%04d.png)
[[ "$jobs" =~ ^[0-9]+$ ]] || fail "without --wait, the job id is printed (got '$jobs')"
for _ in $(seq 1 120); do [ -z "$(squeue -h -j "$jobs" 2>/dev/null)" ] && break; sleep 0.5; done
one scenes/demo/showcase.json --frames 10-20 --size 160x90 -o one/nowait/f_%04d.png
for frame in one/nowait/*.png; do same_file "$frame" "nowait/${frame##*/}" || fail "frame $frame without --wait"; done

# ---- 3. a node dies mid-run; the same command again finishes without redoing frames --------
# Two tasks of 24 frames each, heavy enough that a task lasts several seconds.
kill_run=(--wait --tasks 2 scenes/demo/showcase.json --frames 0-47 --size 640x360 --spp 32 --video dies/flight.mp4)
started=$(date +%s)
farm "${kill_run[@]}" >first-run.out 2>first-run.err &
first_run=$!
victim_log=""
for _ in $(seq 1 600); do
    victim_log=$(grep -l '^clrender farm: task [0-9]* on node1,' dies/flight.farm/logs/task_*.log 2>/dev/null | head -1)
    [ -n "$victim_log" ] && [ "$(grep -c '"frames_done"' "$victim_log")" -ge 3 ] && break
    sleep 0.2
done
[ -n "$victim_log" ] || fail "no task started on node1"
bash "$source_dir/tests/farm/slurm_cluster.sh" kill-node "$cluster" node1
wait $first_run
first_status=$?
first_seconds=$(($(date +%s) - started))
echo "--- first run (node1 killed), exit $first_status after ${first_seconds} s:"; cat first-run.err
[ $first_status -eq 8 ] || fail "a run with a dead node exits 8 with --wait (got $first_status)"
grep -q 'NODE_FAIL on node1' first-run.err || fail "the failed task and its node are named"
grep -q 'task [01] (frames [0-9-]*): NODE_FAIL' first-run.err || fail "the failed frames are named"
grep -q 'flight.mp4 was not written' first-run.err || fail "the missing video is named"
[ -e dies/flight.mp4 ] && fail "no video may be written when a task failed"

# Frames finished before the node died keep their files: the rerun must not touch them.
(cd dies/flight.farm/frames && stat -c '%n %i %Y' ./*.png) >finished-before.txt
finished=$(wc -l <finished-before.txt)
[ "$finished" -ge 3 ] && [ "$finished" -lt 48 ] || fail "the first run left $finished of 48 frames (a partial run expected)"

bash "$source_dir/tests/farm/slurm_cluster.sh" restart-node "$cluster" node1
started=$(date +%s)
farm "${kill_run[@]}" >second-run.out 2>second-run.err
second_status=$?
second_seconds=$(($(date +%s) - started))
echo "--- second run, exit $second_status after ${second_seconds} s:"; cat second-run.err
[ $second_status -eq 0 ] || fail "the second run finishes the work (exit $second_status)"
(cd dies/flight.farm/frames && stat -c '%n %i %Y' $(cut -d' ' -f1 ../../../finished-before.txt)) >finished-after.txt
cmp -s finished-before.txt finished-after.txt || fail "frames finished by the first run were rendered again"
one scenes/demo/showcase.json --frames 0-47 --size 640x360 --spp 32 --video one/flight.mp4
check "the finished farm's video is the one-process video" same_file dies/flight.mp4 one/flight.mp4
ls -A dies/flight.farm/frames | grep -q '^\.clrender-' && fail "the dead node's temporary file was left after the rerun"
echo "farm figures: first run ${first_seconds} s (node1 killed), finishing run ${second_seconds} s, $finished frames kept"

# ---- 4. Slurm runs a task twice (requeued mid-chunk): the second run skips what the first did -
twice_run=(--wait --tasks 1 --sbatch "--requeue" scenes/demo/showcase.json --frames 0-47 --size 640x360 --spp 32
           --video twice/flight.mp4)
farm "${twice_run[@]}" >twice-run.out 2>twice-run.err &
twice=$!
for _ in $(seq 1 600); do
    [ "$(cat twice/flight.farm/logs/task_0.log 2>/dev/null | grep -c '"frames_done"')" -ge 3 ] && break
    sleep 0.2
done
array=$(cut -d, -f1 twice/flight.farm/jobs)
scontrol requeue "${array}_0" || fail "scontrol requeue ${array}_0"
# A requeued job waits two minutes before it may start again; once it is pending, let it start
# two seconds on. Not at once: the node revokes the first run's credential at the requeue, to the
# second, and a run launched within that second has a credential from it, which the node takes for
# a revoked one ("Killing non-startable batch JobId=...: Job credential revoked"), failing the task
# with no second run (about one run in three on a loaded machine).
for _ in $(seq 1 150); do
    [ "$(squeue -h -j "${array}_0" -o %T 2>/dev/null)" = PENDING ] &&
        scontrol update jobid="${array}_0" StartTime=now+2 2>/dev/null && break
    sleep 0.2
done
(cd twice/flight.farm/frames && stat -c '%n %i %Y' ./*.png) >requeued-before.txt
wait $twice || fail "a run whose task Slurm requeued succeeds (exit $?): $(cat twice-run.err)"
grep -q '^clrender farm: task 0 on node[12], job [0-9_]*, run 2,' twice/flight.farm/logs/task_0.log ||
    fail "the requeued task ran a second time (its log says run 2)"
(cd twice/flight.farm/frames && stat -c '%n %i %Y' $(cut -d' ' -f1 ../../../requeued-before.txt)) >requeued-after.txt
cmp -s requeued-before.txt requeued-after.txt || fail "the requeued task rendered frames of its first run again"
check "the requeued farm's video is the one-process video" same_file twice/flight.mp4 one/flight.mp4

[ $failures -eq 0 ] || { echo "$failures check(s) failed" >&2; exit 1; }
echo "passed"
