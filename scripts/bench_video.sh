#!/usr/bin/env bash
# The forest flight's MP4 against its two halves, side by side in one run (docs/benchmarks.md,
# Videos at the speed of the machine): `clrender --video` (and, given, an earlier clrender's),
# the frames alone to PPM files, and ffmpeg alone encoding those PPM files with clrender's x264
# settings, alternating for ROUNDS rounds (default 3). Every line gives the load average before
# the command, its wall time and its CPU time (user and system, children included): on a shared
# machine the wall times say little without them.
#   scripts/bench_video.sh [ROUNDS] [EARLIER_CLRENDER]
# The forest is generated into out/forest/ when missing; the frames and videos go to a
# temporary folder, removed at the end.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"
rounds="${1:-3}"
earlier="${2:-}"

cmake --build "$build" -j"$(nproc)" --target clrender clrender_make_forest > /dev/null
[ -f "$root/out/forest/forest.json" ] || "$build/clrender_make_forest" "$root/out/forest" > /dev/null
scene="$root/out/forest/forest.json"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# What clrender gives x264 (host/output/video_encoder.cpp), from frames ffmpeg converts itself.
encode_ppm=(ffmpeg -hide_banner -nostats -loglevel error -framerate 24 -i "$work/ppm/f_%04d.ppm"
  -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2,scale=out_color_matrix=bt709:out_range=tv,format=yuv420p'
  -colorspace bt709 -color_primaries bt709 -color_trc bt709 -color_range tv -c:v libx264 -pix_fmt yuv420p
  -crf 18 -preset veryfast -threads 4 -x264-params sync-lookahead=0 -movflags +faststart -fflags +bitexact -flags:v +bitexact -f mp4 -y "$work/f.mp4")

# measure NAME COMMAND...: one line of figures.
measure() {
  local name="$1" load
  shift
  load="$(cut -d' ' -f1 /proc/loadavg)"
  local TIMEFORMAT='%R %U %S'  # bash's own timing: wall, then user and system of the command's processes
  { time "$@" > /dev/null 2>&1; } 2> "$work/time"
  awk -v name="$name" -v load="$load" '{ printf "%-14s load %5s  wall %6.2f s  CPU %6.2f s\n", name, load, $1, $2 + $3 }' \
    "$work/time"
}

for round in $(seq 1 "$rounds"); do
  echo "round $round"
  if [ -n "$earlier" ]; then measure "mp4 earlier" "$earlier" "$scene" -q --video "$work/earlier.mp4"; fi
  measure "mp4" "$build/clrender" "$scene" -q --video "$work/v.mp4"
  rm -rf "$work/ppm" && mkdir "$work/ppm"
  measure "frames alone" "$build/clrender" "$scene" -q -o "$work/ppm/f_%04d.ppm"
  measure "ffmpeg alone" "${encode_ppm[@]}"
done
