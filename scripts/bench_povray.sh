#!/usr/bin/env bash
# clrender against POV-Ray on one scene, each as a whole process that writes its PNG
# (docs/benchmarks.md, Against POV-Ray). Installs what is missing (scripts/install-deps.sh,
# POV-Ray included), builds clrender and clrender_to_povray (Release, into build-bench/ or
# $CLRENDER_BENCH_BUILD_DIR), converts the scene, renders it once with each (untimed: clrender's
# caches and both programs' files are then warm), then times the two alternately and prints the
# median wall times, their ratio and how far the two pictures differ.
#
#   scripts/bench_povray.sh [SCENE] [--size WxH] [--repeat N] [--keep DIR]
#
# SCENE defaults to the course scene ../shared/course-scenes/spring2023-a03/testScene_grads.json
# (beside the repository); without it the script exits 77. --size defaults to 1920x1080,
# --repeat (timed runs of each) to 5; --keep DIR works in DIR and keeps the converted scene and
# both images there.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BENCH_BUILD_DIR:-$root/build-bench}"

scene=""
size="1920x1080"
repeat=5
keep=""
while [ $# -gt 0 ]; do
  case "$1" in
    --size) size="${2:?--size needs WIDTHxHEIGHT}"; shift 2 ;;
    --repeat) repeat="${2:?--repeat needs a number}"; shift 2 ;;
    --keep) keep="${2:?--keep needs a folder}"; shift 2 ;;
    -h|--help) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "bench_povray: unknown option '$1' (see --help)" >&2; exit 1 ;;
    *) [ -z "$scene" ] || { echo "bench_povray: one scene only, got '$scene' and '$1'" >&2; exit 1; }
       scene="$1"; shift ;;
  esac
done
[[ "$size" =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || { echo "bench_povray: --size wants WIDTHxHEIGHT, not '$size'" >&2; exit 1; }
[[ "$repeat" =~ ^[1-9][0-9]*$ ]] || { echo "bench_povray: --repeat wants a whole number from 1, not '$repeat'" >&2; exit 1; }

if [ -z "$scene" ]; then
  scene="$root/../shared/course-scenes/spring2023-a03/testScene_grads.json"
  if [ ! -f "$scene" ]; then
    echo "bench_povray: the course scenes are not here ($(realpath -m "$scene") is missing); give a scene path, e.g. scripts/bench_povray.sh scenes/demo/demo.json" >&2
    exit 77
  fi
fi
[ -f "$scene" ] || { echo "bench_povray: no scene file '$scene'" >&2; exit 2; }
scene="$(realpath "$scene")"

bash "$root/scripts/install-deps.sh" >&2
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCLRENDER_BUILD_BENCH=ON >&2
cmake --build "$build" -j"$(nproc)" --target clrender clrender_to_povray >&2

if [ -n "$keep" ]; then
  mkdir -p "$keep"
  work="$(realpath "$keep")"
else
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
fi
"$build/clrender_to_povray" "$scene" "$work/scene.pov" --size "$size"

threads="$(nproc)"
run_clrender() { "$build/clrender" -q "$scene" --size "$size" -o "$work/clrender.png"; }
# From the scene's folder, so that the .ini is named without any folder (POV-Ray's command line
# takes no spaces in a file name); -D: no display window; every core.
run_povray() { (cd "$work" && povray scene.ini +Opovray.png -D +WT"$threads" >povray.log 2>&1) || { cat "$work/povray.log" >&2; exit 3; }; }

# Wall seconds of one run of $1, the whole process.
seconds() {
  local start=$EPOCHREALTIME
  "$1"
  local end=$EPOCHREALTIME
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }'
}
median() { tr ' ' '\n' | grep . | sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

run_clrender  # untimed: fills clrender's program and image caches
run_povray    # untimed: the same files read once, for fairness
clrender_times=""
povray_times=""
for i in $(seq "$repeat"); do
  c=$(seconds run_clrender)
  p=$(seconds run_povray)
  echo "run $i: clrender ${c} s, POV-Ray ${p} s" >&2
  clrender_times="$clrender_times $c"
  povray_times="$povray_times $p"
done
c_med=$(echo "$clrender_times" | median)
p_med=$(echo "$povray_times" | median)

# How far the pictures differ: PSNR over RGB, and the share of pixels where some channel
# differs by more than 1 (ffmpeg's blend filter gives the per-channel difference).
psnr=$(ffmpeg -v info -nostats -i "$work/clrender.png" -i "$work/povray.png" -lavfi "[0:v]format=rgb24[a];[1:v]format=rgb24[b];[a][b]psnr" -f null - 2>&1 | sed -n 's/.*PSNR.* average:\([^ ]*\).*/\1/p' | tail -1)
differing=$(ffmpeg -v error -i "$work/clrender.png" -i "$work/povray.png" -lavfi "[0:v]format=rgb24[a];[1:v]format=rgb24[b];[a][b]blend=all_mode=difference,format=rgb24" -f rawvideo - |
  od -An -v -tu1 -w3 | awk '{ n++; if ($1 > 1 || $2 > 1 || $3 > 1) d++ } END { printf "%.4f", 100 * d / n }')

echo "scene: $scene ($size, $repeat runs each, alternating; $threads cores)"
echo "clrender median: $c_med s   (runs:$clrender_times)"
echo "POV-Ray  median: $p_med s   (runs:$povray_times)"
awk -v c="$c_med" -v p="$p_med" 'BEGIN { printf "clrender / POV-Ray: %.3f (POV-Ray takes %.1fx as long)\n", c / p, p / c }'
# POV-Ray's own account of its last run: the rest of its wall time is start-up, writing the PNG
# and shutdown.
pov_stage() { sed -n "s/.*$1 Time:.*(\([0-9.]*\) seconds).*/\1/p" "$work/povray.log" | head -1; }
echo "POV-Ray's last run by its log: parse $(pov_stage Parse) s, trace $(pov_stage Trace) s"
echo "pictures: PSNR ${psnr} dB, ${differing}% of pixels differ by more than 1 in some channel"
[ -z "$keep" ] || echo "kept in $work: scene.pov, scene.ini, clrender.png, povray.png"
