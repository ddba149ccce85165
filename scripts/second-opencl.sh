#!/usr/bin/env bash
# The kernels on a second OpenCL implementation: Intel's CPU runtime (installed from PyPI by
# scripts/install-intel-opencl.sh into a user folder) beside PoCL (docs/opencl-devices.md).
#   1. The kernel stage tests and the whole-frame tests (kernels against the host reference
#      with the suite's tolerances, packet path against brute force byte for byte, course
#      scenes, feature variants) run with Intel's device selected (CLRENDER_DEVICE="Intel(R) OpenCL").
#   2. The generated scenes of scripts/oclgrind-scenes.sh and the demo scenes render on both
#      implementations; their images must be byte-identical (the kernels use no contraction
#      and no implementation-ordered built-ins on their geometry).
# Any failure fails the run.
#
#   scripts/second-opencl.sh            $CLRENDER_BUILD_DIR overrides build/
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"
start=$SECONDS

bash "$root/scripts/install-intel-opencl.sh" > /dev/null
source "${CLRENDER_INTEL_OPENCL_DIR:-$HOME/.cache/clrender-intel-opencl}/env.sh"
cmake --build "$build" -j2 --target clrender clrender_tests > /dev/null
# Each implementation compiles the kernels itself, once per run: no program store, and caches
# (clrender's and PoCL's) that start empty in this run's folder. A program is compiled from
# source the first time a test or render needs it and taken from the cache after that; Intel's
# runtime keeps no kernel cache of its own, and compiling every program anew in every test took
# most of this script's half hour.
export CLRENDER_PROGRAM_STORE=off
# The Intel runtime's platform: PoCL names its device after the processor ("pthread-...-Intel(R)
# Xeon(R) Processor"), so a selector "Intel" chose PoCL, and both parts compared PoCL with itself.
intel="Intel(R) OpenCL"

devices="$("$build/clrender" --list-devices)"
echo "$devices" | sed 's/^/second-opencl.sh: /'
grep -q 'Intel(R) OpenCL' <<< "$devices" || { echo "second-opencl.sh: Intel's runtime is not listed" >&2; exit 1; }
grep -q 'Portable Computing Language' <<< "$devices" || { echo "second-opencl.sh: PoCL is not listed" >&2; exit 1; }

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export CLRENDER_CACHE_DIR="$work/cache" POCL_CACHE_DIR="$work/pocl-cache"
failures=0

# Part 1: the tests on Intel's device.
# Intel's runtime compiles a program in 10 s to 2 minutes (the general program), PoCL in a few
# seconds: the tests below are those of the kernel stages and a whole-frame test of each kind of
# scene (the course's scenes, lights and planes, mirrors, meshes and their edges, double
# precision), chosen so that the programs they compile stay few. Part 2 renders every feature.
tests='Intersect*:Raygen*:Shade*:Seeds/*:Cameras/*:StructLayout*:AnalyticImage*:Course/*:DoublePrecision*'
tests+=':Lights.SpheresAndPlanesLitByPointLightsMatchTheReference:Mirrors*:EdgeBands.*:Meshes.LitMeshesAndTheirShadows*'
shards="$(nproc)"
pids=()
for ((shard = 0; shard < shards; shard++)); do
    CLRENDER_DEVICE="$intel" GTEST_TOTAL_SHARDS="$shards" GTEST_SHARD_INDEX="$shard" \
        "$build/clrender_tests" --gtest_filter="$tests" --gtest_brief=1 > "$work/tests.$shard.log" 2>&1 &
    pids+=($!)
done
for ((shard = 0; shard < shards; shard++)); do
    if ! wait "${pids[$shard]}"; then
        echo "second-opencl.sh: FAIL: tests on Intel's device (shard $shard of $shards)" >&2
        tail -n 60 "$work/tests.$shard.log" >&2
        failures=$((failures + 1))
    fi
done
cat "$work"/tests.*.log > "$work/tests.log"
grep -E '^\[ +PASSED|tests? ran' "$work/tests.log" | sed 's/^/second-opencl.sh: /' || true
echo "second-opencl.sh: tests on Intel's device in $((SECONDS - start)) s"

# Part 2: whole scenes on both implementations, byte for byte.
renders_start=$SECONDS
bash "$root/scripts/oclgrind-scenes.sh" "$work/scenes"
compare() { # name scene [options...]
    local name="$1" scene="$2"
    shift 2
    for device in PoCL Intel; do
        local selector="Portable"
        [ "$device" = Intel ] && selector="$intel"
        if ! "$build/clrender" "$scene" -q -d "$selector" -o "$work/$name.$device.%04d.png" "$@" > "$work/$name.$device.log" 2>&1; then
            echo "second-opencl.sh: FAIL: $name on $device: $(cat "$work/$name.$device.log")" >&2
            failures=$((failures + 1))
            return
        fi
    done
    for frame in "$work/$name".PoCL.*.png; do
        if ! cmp -s "$frame" "${frame/.PoCL./.Intel.}"; then
            echo "second-opencl.sh: FAIL: $name: $(basename "$frame") differs between PoCL and Intel" >&2
            failures=$((failures + 1))
        fi
    done
}
for scene in "$work/scenes"/*.json; do
    name="$(basename "$scene" .json)"
    compare "$name" "$scene" --size 160x100
    compare "${name}_double_spp3" "$scene" --size 97x61 --precision double --spp 3
done
compare demo "$root/scenes/demo/demo.json" --size 320x180
compare showcase "$root/scenes/demo/showcase.json" --size 320x180 --frames 0,40,95
echo "second-opencl.sh: whole scenes on both implementations in $((SECONDS - renders_start)) s"

if [ "$failures" -ne 0 ]; then
    echo "second-opencl.sh: $failures failures" >&2
    exit 1
fi
echo "second-opencl.sh: Intel's runtime agrees ($((SECONDS - start)) s)"
