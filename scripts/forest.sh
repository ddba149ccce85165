#!/usr/bin/env bash
# The forest flight in one command: installs what is missing, builds clrender and the forest
# generator, generates the forest scene into out/forest/ and renders the camera's flight
# through it to out/forest.mp4. Options go to the generator, e.g.
#   scripts/forest.sh --trees 5000 --seed 3 --size 1920x1080
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"

bash "$root/scripts/install-deps.sh" >&2
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" -j"$(nproc)" --target clrender clrender_make_forest
mkdir -p "$root/out"
"$build/clrender_make_forest" "$root/out/forest" "$@"
"$build/clrender" "$root/out/forest/forest.json" --video "$root/out/forest.mp4"
echo "forest: wrote $root/out/forest.mp4"
