#!/usr/bin/env bash
# Builds clrender_bench (Release, into build-bench/ or $CLRENDER_BENCH_BUILD_DIR) and runs it:
# clrender and its Embree peer side by side on the generated scenes, printing the table of
# docs/benchmarks.md. Arguments go to the benchmark, e.g.
#   scripts/bench.sh --repeat 9 --json out/bench.json
#   scripts/bench.sh --scenes course,16+16 --size 960x540
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BENCH_BUILD_DIR:-$root/build-bench}"

bash "$root/scripts/install-deps.sh" >&2
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCLRENDER_BUILD_BENCH=ON >&2
cmake --build "$build" -j"$(nproc)" --target clrender_bench >&2
exec "$build/clrender_bench" "$@"
