#!/usr/bin/env bash
# The kernels under Oclgrind, the OpenCL simulator that checks every memory access, the
# OpenCL API calls and work-group data races (docs/opencl-devices.md). Two parts:
#   1. clrender renders small scenes under `oclgrind`: generated ones that switch on every
#      kernel feature (scripts/oclgrind-scenes.sh) in float, with several samples per pixel
#      and in double, at odd sizes; the project's demo scenes; the course scenes when
#      ../shared/course-scenes exists.
#   2. The kernel stage tests and a set of whole-frame tests (the non-tiled render kernel,
#      bands, antialiasing, double, impostors, mirrors, coverage masks, course scenes) run on Oclgrind's
#      OpenCL implementation through the ICD loader, still comparing with the reference.
# Any Oclgrind report (invalid access, data race, API error), any failed render or test
# fails the run. --uninitialized is left out: it crashes Oclgrind 21.10.
#
#   scripts/oclgrind.sh            $CLRENDER_BUILD_DIR overrides build/
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"
oclgrind_flags=(--check-api --data-races)

command -v oclgrind > /dev/null || { echo "oclgrind.sh: oclgrind is not installed (scripts/install-deps.sh)" >&2; exit 1; }
cmake --build "$build" -j2 --target clrender clrender_tests > /dev/null

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# Oclgrind must compile every program: a cached or stored binary would skip its compiler.
export CLRENDER_CACHE_DIR=off CLRENDER_PROGRAM_STORE=off
failures=0
renders=0
start=$SECONDS

fail() {
    echo "oclgrind.sh: FAIL: $1" >&2
    failures=$((failures + 1))
}

# Oclgrind's reports: "Invalid read of size 4 ...", "Read-write data race ...", API errors.
# Each kernel report names its kernel on a "Kernel:" line.
oclgrind_reports() {
    grep -E '^(Invalid|Read-write|Write-write|Uninitialized|Unaligned|Work-group divergence|Oclgrind)|Kernel: |data race' "$1" || true
}

# render NAME SCENE [CLRENDER OPTIONS...]: renders SCENE under Oclgrind. Passes when
# clrender exits 0 and prints nothing but its own warnings.
render() {
    local name="$1" scene="$2"
    shift 2
    local log="$work/$name.log"
    renders=$((renders + 1))
    local status=0
    oclgrind "${oclgrind_flags[@]}" "$build/clrender" "$scene" -q -o "$work/${name}_%04d.png" "$@" > "$log" 2>&1 || status=$?
    if [ "$status" -ne 0 ]; then
        fail "$name: clrender exited with $status under Oclgrind"
    elif grep -qv '^clrender: warning: ' "$log"; then
        fail "$name: Oclgrind reported"
    else
        return 0
    fi
    head -n 40 "$log" >&2
}

# Part 1: whole renders.
scenes="$work/scenes"
bash "$root/scripts/oclgrind-scenes.sh" "$scenes"
for scene in "$scenes"/*.json; do
    render "$(basename "$scene" .json)" "$scene"
done
for name in everything bvh impostors sun_and_shadows; do
    render "${name}_spp3" "$scenes/$name.json" --spp 3
done
for name in everything bvh impostors transparent_texels meshes; do
    render "${name}_double" "$scenes/$name.json" --precision double
done
# Partial screen tiles (fewer than 16 lanes in a row) and a single pixel.
render everything_37x21 "$scenes/everything.json" --size 37x21
render everything_1x1 "$scenes/everything.json" --size 1x1
render everything_17x40_double "$scenes/everything.json" --size 17x40 --precision double --spp 2

render demo "$root/scenes/demo/demo.json" --size 48x32
render showcase "$root/scenes/demo/showcase.json" --size 48x32 --frames 0,40,95

course="$root/../shared/course-scenes"
if [ -d "$course" ]; then
    while IFS= read -r scene; do
        name="course_$(basename "$(dirname "$scene")")_$(basename "$scene" | tr -c 'A-Za-z0-9_\n' '_')"
        # Scenes clrender rejects on any device (the older course format) are no kernel matter.
        if "$build/clrender" "$scene" -q --frame-count --size 48x32 --placeholders > /dev/null 2>&1; then
            render "$name" "$scene" --size 48x32 --frames 0 --placeholders
        fi
    done < <(find "$course" \( -name '*.json' -o -name '*.js' \) -not -path '*/reference-output/*' | sort)
else
    echo "oclgrind.sh: no $course: course scenes skipped"
fi
echo "oclgrind.sh: $renders renders in $((SECONDS - start)) s, $failures failed"

# Part 2: kernel tests on Oclgrind's ICD, selected by CLRENDER_DEVICE. The ICD loader reads
# the vendor list from OCL_ICD_VENDORS, so nothing under /etc changes.
tests_start=$SECONDS
echo /usr/lib/oclgrind/liboclgrind-rt-icd.so > "$work/oclgrind.icd"
tests='Intersect*:Raygen*:Shade*:Seeds/*:Cameras/*:StructLayout*:BandedRender*'
tests+=':Antialiasing.PartlyCovered*:Antialiasing.SameSeed*:ScreenTiles.FlatShading*:DoublePrecision*'
tests+=':ImpostorFrames*:Mirrors.MaxDepthZero*:FeatureVariants.SpheresOnly:FeatureVariants.BillboardsOnlyWithAlpha'
tests+=':FeatureVariants.SunAndMirrors:FeatureVariants.EmptyScene:CoverageMask.*'
tests+=':BvhPackets.FlatColours*:BvhPackets.AMovingCamera*'
tests+=':Course/*grads*:Course/*Undergrad*:Course/*v1_*:Course/*mickey*:Course/*SingleBB*:Course/*close*:Course/*scene1*'
# Left out: thousands of triangles through the brute-force kernel on one simulated thread; the
# mesh trees it checks are host code (SceneBvh tests), and the kernels run on the forest test.
tests+='-ImpostorFrames.LargeMeshesKeepTheirTreesWhileImpostorsTurn'
# Oclgrind simulates on one thread: the tests run as one gtest shard per CPU, side by side.
shards="$(nproc)"
pids=()
for ((shard = 0; shard < shards; shard++)); do
    OCL_ICD_VENDORS="$work" CLRENDER_DEVICE=Oclgrind OCLGRIND_CHECK_API=1 OCLGRIND_DATA_RACES=1 \
        GTEST_TOTAL_SHARDS="$shards" GTEST_SHARD_INDEX="$shard" \
        "$build/clrender_tests" --gtest_filter="$tests" --gtest_brief=1 > "$work/tests.$shard.log" 2>&1 &
    pids+=($!)
done
for ((shard = 0; shard < shards; shard++)); do
    if ! wait "${pids[$shard]}"; then
        fail "kernel tests on Oclgrind (shard $shard of $shards)"
        tail -n 60 "$work/tests.$shard.log" >&2
    fi
done
cat "$work"/tests.*.log > "$work/tests.log"
if [ -n "$(oclgrind_reports "$work/tests.log")" ]; then
    fail "kernel tests: Oclgrind reported"
    oclgrind_reports "$work/tests.log" | head -n 40 >&2
fi
grep -E '^\[ +PASSED|tests? ran' "$work/tests.log" | sed 's/^/oclgrind.sh: /' || true
echo "oclgrind.sh: kernel tests on Oclgrind in $((SECONDS - tests_start)) s"

if [ "$failures" -ne 0 ]; then
    echo "oclgrind.sh: $failures failures" >&2
    exit 1
fi
echo "oclgrind.sh: no reports ($((SECONDS - start)) s)"
