#!/usr/bin/env bash
# Compares the decoded RGB pixels of every PNG under two folders (same relative names):
#   scripts/compare_pixels.sh GOLDEN_IMG_DIR NEW_IMG_DIR   (PNG metadata changes file bytes, not pixels)
# Prints one line per differing or missing file, then "pixels identical: N files" or a count.
set -uo pipefail
a="$1"; b="$2"; n=0; bad=0
while IFS= read -r rel; do
  n=$((n+1))
  if [ ! -f "$b/$rel" ]; then echo "missing: $rel"; bad=$((bad+1)); continue; fi
  ha=$(ffmpeg -v error -i "$a/$rel" -f rawvideo -pix_fmt rgb24 - | sha256sum)
  hb=$(ffmpeg -v error -i "$b/$rel" -f rawvideo -pix_fmt rgb24 - | sha256sum)
  [ "$ha" = "$hb" ] || { echo "differs: $rel"; bad=$((bad+1)); }
done < <(cd "$a" && find . -name '*.png' | sort)
if [ "$bad" -eq 0 ]; then echo "pixels identical: $n files"; else echo "$bad of $n files differ"; exit 1; fi
