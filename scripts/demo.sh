#!/usr/bin/env bash
# The README's first command: install, build, and render the demo into out/: a still image
# (demo.png) and the showcase video (showcase.mp4), a flight through a generated forest of
# camera-facing impostor trees (scripts/forest/, docs/forest.md). It installs and builds only
# what it runs (clrender and the forest generator): the tests, with GoogleTest, come with
# scripts/test.sh, the benchmarks, with Embree, with scripts/bench.sh.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"

bash "$root/scripts/build.sh" --demo clrender clrender_make_forest
render_start=$SECONDS
mkdir -p "$root/out"
"$build/clrender" "$root/scenes/demo/demo.json" -o "$root/out/demo.png"
echo "demo: first image after ${SECONDS} s: $root/out/demo.png"
"$build/clrender_make_forest" "$root/out/forest"
"$build/clrender" "$root/out/forest/forest.json" --video "$root/out/showcase.mp4"
echo "demo: rendering took $((SECONDS - render_start)) s, the whole demo ${SECONDS} s"
echo "demo: wrote $root/out/demo.png and $root/out/showcase.mp4"
