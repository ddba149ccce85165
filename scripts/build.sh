#!/usr/bin/env bash
# Installs what is missing (Debian packages), then configures and builds into build/ (or
# $CLRENDER_BUILD_DIR), printing how long each step took.
#   build.sh                      everything: clrender, its tools, the tests and the benchmarks
#   build.sh TARGET...            only those targets (and what they need)
#   build.sh --demo TARGET...     the same with only the packages the demo needs
#                                 (install-deps.sh demo); a new build folder is then
#                                 configured without the tests and the benchmarks, whose
#                                 packages (GoogleTest, Embree) it does not install
#   build.sh --tests TARGET...    the same, with the tests and the benchmarks' scenes they check
#                                 switched on in the build folder whatever it had before
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"

packages=all
options=()
case "${1:-}" in
  --demo)
    packages=demo
    shift
    # Only a new folder: one configured before (by scripts/test.sh, say) keeps its test targets.
    [ -f "$build/CMakeCache.txt" ] || options=(-DCLRENDER_BUILD_TESTS=OFF -DCLRENDER_BUILD_BENCH=OFF)
    ;;
  --tests)
    shift
    options=(-DCLRENDER_BUILD_TESTS=ON -DCLRENDER_BUILD_BENCH=ON)
    ;;
esac
targets=()
for target in "$@"; do targets+=(--target "$target"); done

step_start=$SECONDS
bash "$root/scripts/install-deps.sh" "$packages"
packages_s=$((SECONDS - step_start))

step_start=$SECONDS
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "${options[@]}"
configure_s=$((SECONDS - step_start))

step_start=$SECONDS
cmake --build "$build" -j"$(nproc)" "${targets[@]}"
build_s=$((SECONDS - step_start))

echo "build.sh: packages ${packages_s} s, configure ${configure_s} s, build ${build_s} s (${*:-everything})"
