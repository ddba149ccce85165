#!/usr/bin/env bash
# Renders an animation in several processes with GNU parallel, one job per frame, then
# assembles the frames into a video. Frames rendered separately are byte-identical to frames
# rendered in one run, so the video is the same as `clrender SCENE --video ...` would make.
#
#   scripts/render_parallel.sh SCENE OUT_DIR [JOBS]
#
# Writes OUT_DIR/frame_0000.png ... and OUT_DIR/video.mp4. $CLRENDER names the clrender
# binary (default: build/clrender beside this script). See docs/farm.md.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
clrender="${CLRENDER:-$root/build/clrender}"
scene="$1"
out="$2"
jobs="${3:-$(nproc)}"

mkdir -p "$out"
frames=$("$clrender" "$scene" --frame-count -q)
# -q quotes the command for the shell that parallel starts; --halt stops all jobs at the
# first failure, so a broken frame fails the whole render.
seq 0 $((frames - 1)) |
    parallel -q --jobs "$jobs" --halt now,fail=1 \
        "$clrender" "$scene" -q --frames {} -o "$out/frame_%04d.png"
"$clrender" "$scene" -q --assemble -o "$out/frame_%04d.png" --video "$out/video.mp4"
