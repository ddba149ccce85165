#!/usr/bin/env bash
# The README's first command: install, build, and render the demo scene into out/: a still
# image (demo.png) and the showcase animation as a video (showcase.mp4).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"

bash "$root/scripts/build.sh"
mkdir -p "$root/out"
"$build/clrender" "$root/scenes/demo/demo.json" -o "$root/out/demo.png"
"$build/clrender" "$root/scenes/demo/showcase.json" --video "$root/out/showcase.mp4"
echo "demo: wrote $root/out/demo.png and $root/out/showcase.mp4"
