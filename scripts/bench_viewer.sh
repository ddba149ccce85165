#!/usr/bin/env bash
# clrender view's frames per second and input-to-image latency as the page sees them, in
# headless Chromium (bench/viewer_bench.py), at 1280x720 on the course's testScene_grads.json
# (from ../shared, or $CLRENDER_SHARED_DIR, skipped where it is absent) and the forest (generated into out/forest/ when
# missing). Figures: docs/benchmarks.md, Viewer. Options go to bench/viewer_bench.py, e.g.
#   scripts/bench_viewer.sh --seconds 10 --channel rgba --channel png
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"

cmake --build "$build" -j"$(nproc)" --target clrender clrender_make_forest > /dev/null
scenes=()
course="${CLRENDER_SHARED_DIR:-$root/../shared}/course-scenes/spring2023-a03/testScene_grads.json"
if [ -f "$course" ]; then
  scenes+=("$course")
else
  echo "bench_viewer: $course is absent, measuring the forest only" >&2
fi
[ -f "$root/out/forest/forest.json" ] || "$build/clrender_make_forest" "$root/out/forest" > /dev/null
scenes+=("$root/out/forest/forest.json")
exec /usr/bin/python3 "$root/bench/viewer_bench.py" "$build/clrender" "${scenes[@]}" "$@"
