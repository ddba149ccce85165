#!/usr/bin/env bash
# The golden set: renders a fixed list of scenes with two clrender binaries and requires
# byte-identical outputs, for changes that must not move a pixel (a refactoring, a faster
# kernel). Usage:
#   scripts/golden-set.sh OLD_CLRENDER NEW_CLRENDER
# Environment (all optional):
#   GOLDEN_SHARED_DIR   the course material (default: ../shared from the repository); its
#                       course-scenes/ join the set when the folder exists
#   GOLDEN_FOREST_MAKER clrender_make_forest (default: the one beside NEW_CLRENDER); the set
#                       renders a small generated forest with impostors
#   GOLDEN_OLD_BENCH, GOLDEN_NEW_BENCH
#                       two clrender_bench binaries: the benchmark's generated scenes join the
#                       set (each bench writes clrender's image of every scene, --images)
#   GOLDEN_WORK_DIR     where the outputs go (default: a temporary folder, removed on success)
# Each case runs both binaries with the same arguments and compares the exit status, standard
# output (for --explain-pixel and --check) and every file written, with cmp. Prints a line per
# difference and a summary; exits 1 when anything differs or a case fails with both.
set -uo pipefail
if [ $# -ne 2 ]; then
    echo "usage: $0 OLD_CLRENDER NEW_CLRENDER" >&2
    exit 1
fi
old="$(realpath "$1")"
new="$(realpath "$2")"
for binary in "$old" "$new"; do
    [ -x "$binary" ] || { echo "golden-set: $binary is not an executable" >&2; exit 1; }
done
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
shared="${GOLDEN_SHARED_DIR:-$root/../shared}"
forest_maker="${GOLDEN_FOREST_MAKER:-$(dirname "$new")/clrender_make_forest}"
work="${GOLDEN_WORK_DIR:-$(mktemp -d "${TMPDIR:-/tmp}/golden-set.XXXXXX")}"
mkdir -p "$work"
export CLRENDER_CACHE_DIR="$work/cache"  # both binaries' programs, away from the user's cache

cases=0 files=0 differences=0 failures=0

# run_case NAME ARGS...: each binary runs `clrender ARGS` in its own folder $work/{old,new}/NAME,
# where relative outputs land; "@OUT@" in ARGS stands for that folder.
run_case() {
    local name="$1"
    shift
    cases=$((cases + 1))
    local side
    for side in old new; do
        local dir="$work/$side/$name" binary="$old"
        [ "$side" = new ] && binary="$new"
        rm -rf "$dir" && mkdir -p "$dir"
        local args=() arg
        for arg in "$@"; do args+=("${arg//@OUT@/$dir}"); done
        (cd "$dir" && "$binary" -q "${args[@]}" > "$dir/.stdout" 2> "$dir/.stderr"; echo $? > "$dir/.rc")
    done
    compare_folders "$name"
}

# compare_folders NAME: the two sides' files of case NAME, byte for byte.
compare_folders() {
    local name="$1" a="$work/old/$1" b="$work/new/$1"
    if [ "$(cat "$a/.rc")" != 0 ] || [ "$(cat "$b/.rc")" != 0 ]; then
        if [ "$(cat "$a/.rc")" != "$(cat "$b/.rc")" ]; then
            echo "DIFFERS $name: exit status $(cat "$a/.rc") (old) vs $(cat "$b/.rc") (new)"
            differences=$((differences + 1))
        else
            echo "FAILED  $name: both exit $(cat "$a/.rc"): $(head -c 300 "$b/.stderr")"
            failures=$((failures + 1))
        fi
    fi
    if ! diff <(cd "$a" && find . -type f ! -name .stderr | sort) <(cd "$b" && find . -type f ! -name .stderr | sort) > /dev/null; then
        echo "DIFFERS $name: the two sides wrote different files"
        differences=$((differences + 1))
    fi
    local rel
    while IFS= read -r rel; do
        files=$((files + 1))
        if ! cmp -s "$a/$rel" "$b/$rel"; then
            echo "DIFFERS $name: $rel"
            differences=$((differences + 1))
        fi
    done < <(cd "$a" && find . -type f ! -name .stderr ! -name .rc | sort)
}

# scene_cases NAME SCENE SIZE ARGS...: a still in float and in double at SIZE (- for the
# scene's own), smaller ones with samples and as EXR (the kernels' float output mode); an
# animation's frames too.
scene_cases() {
    local name="$1" scene="$2" size=()
    [ "$3" != - ] && size=(--size "$3")
    shift 3
    local frames still=()
    frames="$("$new" --frame-count "$scene" "$@" 2> /dev/null || echo 1)"
    [ "${frames:-1}" -gt 1 ] && still=(--frames $((frames / 3)))  # a still of an animation: one frame
    run_case "$name.float" "$scene" -o still.png "${size[@]}" "${still[@]}" "$@"
    run_case "$name.double" "$scene" -o still.png --precision double "${size[@]}" "${still[@]}" "$@"
    run_case "$name.spp4" "$scene" -o still.png --spp 4 --size 160x120 "${still[@]}" "$@"
    run_case "$name.exr-alpha" "$scene" -o still.exr --alpha --size 160x120 "${still[@]}" "$@"
    if [ "${frames:-1}" -gt 1 ]; then
        run_case "$name.frames" "$scene" -o 'frame_%04d.png' --frames 0-2,$((frames - 1)) --size 240x135 "$@"
        run_case "$name.frames-double" "$scene" -o 'frame_%04d.png' --frames 1,$((frames / 2)) --precision double \
            --size 240x135 "$@"
    fi
}

echo "golden-set: old $old"
echo "golden-set: new $new"
echo "golden-set: outputs in $work"

# The repository's scenes, and the same scenes under stress: lit billboards, no reflections
# left, far from the origin, tiny and huge.
demo="$root/scenes/demo/demo.json"
showcase="$root/scenes/demo/showcase.json"
scene_cases demo "$demo" -
scene_cases showcase "$showcase" 480x270
scene_cases demo-lit "$demo" - -D 'SunLocation=[30,40,20]' -D MaxDepth=2 -D 'spheres.3.IsMirror=1' -D 'billboards.1.IsMirror=1'
scene_cases showcase-depth0 "$showcase" 320x180 -D MaxDepth=0
scene_cases demo-far "$demo" - -D 'eye=[100000,1.5,100014]' -D 'lookat=[100000,1,100000]' \
    -D 'spheres.0.center=[99994.5,2.5,99984]' -D 'spheres.2.center=[100004.4,-0.9,100002]' \
    -D 'billboards.2.UpperLeft=[100002,6,99995]' -D 'billboards.2.LowerLeft=[100002,-3,99995]' \
    -D 'billboards.2.UpperRight=[100011,6,99995]'

# Generated stress scenes: hundreds of spheres and billboards under a sun with mirrors (the
# BVH for shadow and mirror rays, both kinds in its leaves; screen tiles with long lists).
stress="$work/scenes/stress.json"
mkdir -p "$work/scenes"
stress_scene() {  # stress_scene LIT: 1 with a sun
    awk -v lit="$1" 'BEGIN {
    srand(7);
    print "{ \"eye\": [0, 6, 30], \"lookat\": [0, 0, 0], \"up\": [0, 1, 0], \"fov_angle\": 55,";
    print "  \"width\": 320, \"height\": 240, \"DefaultColor\": [0.1, 0.1, 0.2],";
    if (lit) print "  \"SunLocation\": [20, 50, 30],";
    print "  \"MaxDepth\": 3, \"spheres\": [";
    for (i = 0; i < 400; ++i)
        printf "%s{\"center\": [%.3f, %.3f, %.3f], \"radius\": %.3f, \"ambient\": [%.2f, %.2f, %.2f], \"IsMirror\": %d}\n",
            (i ? "," : ""), rand() * 40 - 20, rand() * 10 - 2, rand() * -40 + 5, 0.2 + rand(), rand(), rand(), rand(), (i % 9 == 0);
    print "], \"billboards\": [";
    for (i = 0; i < 120; ++i) {
        x = rand() * 40 - 20; y = rand() * 8 - 2; z = rand() * -40 + 5; w = 0.5 + rand() * 2;
        printf "%s{\"UpperLeft\": [%.3f, %.3f, %.3f], \"LowerLeft\": [%.3f, %.3f, %.3f], \"UpperRight\": [%.3f, %.3f, %.3f], \"ambient\": [%.2f, %.2f, %.2f], \"IsMirror\": %d}\n",
            (i ? "," : ""), x, y + w, z, x, y, z + w * 0.3, x + w, y + w, z - w * 0.2, rand(), rand(), rand(), (i % 7 == 0);
    }
    print "] }";
}'
}
flat="$work/scenes/stress-flat.json"
stress_scene 1 > "$stress"
stress_scene 0 > "$flat"
scene_cases stress "$stress" -
scene_cases stress-flat "$flat" - -D MaxDepth=0
scene_cases stress-near "$stress" 200x150 -D 'eye=[0,0.5,3]'

# A generated forest with impostors (camera-facing billboards placed every frame).
if [ -x "$forest_maker" ]; then
    "$forest_maker" "$work/scenes/forest" --trees 300 --seed 5 --frames 4 --size 320x180 > /dev/null
    scene_cases forest "$work/scenes/forest/forest.json" -
else
    echo "golden-set: no forest generator at $forest_maker: forest skipped"
fi

# The course's scenes, when the course material is at hand.
if [ -d "$shared/course-scenes" ]; then
    n=0
    while IFS= read -r scene; do
        n=$((n + 1))
        scene_cases "course$n-$(basename "$scene" | tr -c 'A-Za-z0-9._\n-' _)" "$scene" 320x240 --placeholders
    done < <(find "$shared/course-scenes" -type f \( -name '*.js' -o -name '*.json' \) | sort)
else
    echo "golden-set: no course scenes under $shared: skipped"
fi

# What the explainer says of pixels on a lit sphere, a textured billboard and a mirror;
# --check's summary; the double-precision reference renderer's images.
run_case explain-sphere "$showcase" --explain-pixel 300,250 --frames 3
run_case explain-billboard "$demo" --explain-pixel 200,120
run_case explain-mirror "$showcase" --explain-pixel 480,290 --frames 10
run_case explain-stress "$stress" --explain-pixel 160,120
run_case explain-double "$showcase" --explain-pixel 470,300 --precision double
run_case check-showcase "$showcase" --check
run_case reference-demo "$demo" --reference -o ref.png --size 160x90
run_case reference-stress "$stress" --reference -o ref.png --size 120x90
run_case reference-showcase "$showcase" --reference -o 'ref_%04d.png' --frames 2,40 --size 120x68

# The benchmark's scenes, from each bench binary's own image of every scene.
if [ -n "${GOLDEN_OLD_BENCH:-}" ] && [ -n "${GOLDEN_NEW_BENCH:-}" ]; then
    cases=$((cases + 1))
    for side in old new; do
        bench="$GOLDEN_OLD_BENCH"
        [ "$side" = new ] && bench="$GOLDEN_NEW_BENCH"
        dir="$work/$side/bench"
        rm -rf "$dir" && mkdir -p "$dir/images"
        "$bench" --repeat 1 --size 480x270 --images "$dir/images" > "$dir/.stderr" 2>&1
        echo $? > "$dir/.rc"
    done
    compare_folders bench
fi

echo "golden-set: $cases cases, $files files compared, $differences differ, $failures failed on both sides"
if [ $differences -ne 0 ] || [ $failures -ne 0 ]; then exit 1; fi
[ -n "${GOLDEN_WORK_DIR:-}" ] || rm -rf "$work"
echo "golden-set: byte-identical"
