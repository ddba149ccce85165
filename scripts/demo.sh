#!/usr/bin/env bash
# The README's first command: install, build, and render the demo scene into out/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"

bash "$root/scripts/build.sh"
mkdir -p "$root/out"
"$build/clrender" "$root/scenes/demo/demo.json" -o "$root/out/demo.png"
echo "demo: wrote $root/out/demo.png"
