#!/usr/bin/env bash
# The kernels on a GPU (docs/opencl-devices.md, A GPU), where `clrender --list-devices` lists
# one (NVIDIA's OpenCL platform, PoCL's CUDA driver, ...). Builds nothing: run it beside a
# build of clrender, clrender_tests and clrender_bench. The CPU stays the default device and the
# test suite passes without a GPU; this is the check for a machine that has one.
#   1. The kernel stage and whole-frame tests (second-opencl.sh's longer list) with the GPU selected
#      (CLRENDER_DEVICE=gpu), still against the double-precision host reference.
#   2. The feature scenes of scripts/oclgrind-scenes.sh and the demo scenes, rendered on the GPU
#      and compared with the host reference (clrender compare, 2/255); with a folder of PNGs
#      rendered by PoCL for the same commands (GPU_CHECK_CPU_IMAGES), how many are the same bytes.
#   3. The benchmark on the GPU (clrender_bench --device gpu), Embree on the CPU beside it, with
#      screen tiles of 16-ray packets and with one work-item a pixel (--per-pixel).
# Writes logs and bench.*.json into $GPU_CHECK_OUT (default: a new temporary folder). GPU_CHECK_DEVICE
# (a -d selector, default gpu), GPU_CHECK_REPEAT, GPU_CHECK_BENCH_SCENES and the GPU_CHECK_*_SECONDS
# limits change what it runs.
#
#   scripts/gpu-check.sh                $CLRENDER_BUILD_DIR overrides build/
#   scripts/gpu-check.sh --cpu-images DIR   render the scenes of part 2 with the default device into DIR
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"
out="${GPU_CHECK_OUT:-$(mktemp -d)}"
mkdir -p "$out"
export CLRENDER_CACHE_DIR=off CLRENDER_PROGRAM_STORE=off  # the GPU's driver compiles every kernel itself
device="${GPU_CHECK_DEVICE:-gpu}"  # another selector tries the script on any device
say() { echo "gpu-check.sh: $*"; }

# The scenes of part 2 and the options each is rendered with, one "name|scene|options" a line.
scene_list() {
    local scenes="$1"
    for scene in "$scenes"/*.json; do
        local name
        name="$(basename "$scene" .json)"
        echo "$name|$scene|--size 160x100 --frames 0"
        echo "${name}_double_spp3|$scene|--size 97x61 --precision double --spp 3 --frames 0"
    done
    echo "demo|$root/scenes/demo/demo.json|--size 320x180 --frames 0"
    echo "showcase|$root/scenes/demo/showcase.json|--size 320x180 --frames 40"
}

scenes="$out/scenes"
bash "$root/scripts/oclgrind-scenes.sh" "$scenes" > /dev/null

if [ "${1:-}" = "--cpu-images" ]; then
    mkdir -p "$2"
    scene_list "$scenes" | while IFS='|' read -r name scene options; do
        # shellcheck disable=SC2086 # options are words
        "$build/clrender" "$scene" -q $options -o "$2/$name.png" || say "FAIL: $name on the CPU"
    done
    exit 0
fi

start=$SECONDS
failures=0
say "logs, images and bench.*.json go into $out"
devices="$("$build/clrender" --list-devices 2>&1)"
echo "$devices" | sed 's/^/gpu-check.sh: /'
[ "$device" != gpu ] || grep -q '(GPU' <<< "$devices" || { say "no GPU device is listed" >&2; exit 1; }

# Part 1: the tests, one gtest shard per two CPUs (the driver's compiler runs on the CPU).
tests='PerPixel.*:ExactArithmetic.*:Intersect*:Raygen*:Shade*:Seeds/*:Cameras/*:StructLayout*:AnalyticImage*:Antialiasing*:BandedRender*'
tests+=':FeatureVariants*:ScreenTiles*:DoublePrecision*:Bvh.*:ImpostorFrames*:InstructorFrames*:Mirrors*'
tests+=':RecycledFrames*:Course/*:Scale*:Meshes.*:SharedEdges.*:EdgeBands.*:Lights.*:Planes.*:Clipping.*'
shards=$(( $(nproc) / 2 > 1 ? $(nproc) / 2 : 1 ))
pids=()
for ((shard = 0; shard < shards; shard++)); do
    CLRENDER_DEVICE="$device" GTEST_TOTAL_SHARDS="$shards" GTEST_SHARD_INDEX="$shard" \
        timeout "${GPU_CHECK_TEST_SECONDS:-240}" "$build/clrender_tests" --gtest_filter="$tests" \
        > "$out/tests.$shard.log" 2>&1 &
    pids+=($!)
done
for ((shard = 0; shard < shards; shard++)); do
    wait "${pids[$shard]}" || { say "FAIL: tests on the GPU (shard $shard of $shards)" >&2; failures=$((failures + 1)); }
done
cat "$out"/tests.*.log > "$out/tests.log"
grep -E '^\[  FAILED  \]|^\[  PASSED  \]|^\[  SKIPPED \]|tests? ran' "$out/tests.log" | sort | uniq -c | sed 's/^/gpu-check.sh: /'
say "tests on the GPU in $((SECONDS - start)) s"

# Part 2: whole scenes against the host reference, and the same bytes as the CPU's or not.
renders_start=$SECONDS
same=0
compared=0
while IFS='|' read -r name scene options; do
    # shellcheck disable=SC2086 # options are words
    if ! "$build/clrender" "$scene" -q --reference $options -o "$out/$name.reference.png" > "$out/$name.log" 2>&1 ||
        ! "$build/clrender" "$scene" -q -d "$device" $options -o "$out/$name.gpu.png" >> "$out/$name.log" 2>&1; then
        say "FAIL: $name: $(tail -n 3 "$out/$name.log")" >&2
        failures=$((failures + 1))
        continue
    fi
    # shellcheck disable=SC2086
    if ! "$build/clrender" compare "$scene" "$out/$name.reference.png" -d "$device" --tolerance 2 $options \
        > "$out/$name.compare" 2>&1; then
        say "FAIL: $name: $(head -n 4 "$out/$name.compare")" >&2
        failures=$((failures + 1))
    fi
    if [ -n "${GPU_CHECK_CPU_IMAGES:-}" ] && [ -f "$GPU_CHECK_CPU_IMAGES/$name.png" ]; then
        compared=$((compared + 1))
        if cmp -s "$out/$name.gpu.png" "$GPU_CHECK_CPU_IMAGES/$name.png"; then
            same=$((same + 1))
        else
            say "$name: the GPU's image is not the CPU's bytes"
        fi
    fi
done < <(scene_list "$scenes")
[ "$compared" -gt 0 ] && say "$same of $compared GPU images are the CPU's bytes"
say "whole scenes in $((SECONDS - renders_start)) s"

# Part 3: the benchmark, with screen tiles and 16-ray packets (the CPU's path) and with one
# work-item a pixel (--per-pixel).
for path in tiles per-pixel; do
    bench_start=$SECONDS
    flag=(--screen-tiles)
    [ "$path" = per-pixel ] && flag=(--per-pixel)
    timeout "${GPU_CHECK_BENCH_SECONDS:-300}" "$build/clrender_bench" --device "$device" "${flag[@]}" \
        --repeat "${GPU_CHECK_REPEAT:-5}" ${GPU_CHECK_BENCH_SCENES:+--scenes "$GPU_CHECK_BENCH_SCENES"} \
        --json "$out/bench.$path.json" 2>&1 | grep -v '^bench: ' | tee "$out/bench.$path.log" ||
        { say "FAIL: the benchmark ($path)" >&2; failures=$((failures + 1)); }
    say "benchmark ($path) in $((SECONDS - bench_start)) s"
done

if [ "$failures" -ne 0 ]; then
    say "$failures failures ($((SECONDS - start)) s)" >&2
    exit 1
fi
say "the GPU agrees with the reference ($((SECONDS - start)) s)"
