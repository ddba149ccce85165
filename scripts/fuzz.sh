#!/usr/bin/env bash
# Builds the libFuzzer targets with clang into build-fuzz/ and runs each for a bounded time:
# the scene loader, the image loader once per decoder path (PNG, JPEG, PPM P3, PPM P6), and the
# viewer's request handling (clrender view) and the OBJ reader,
# each run with its own seed corpus and dictionary. Prints the executions per target and
# fails if any target found a crash, a hang, a leak or a sanitizer report.
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET]      (default 30; CI uses the default)
#
# $CLRENDER_FUZZ_BUILD_DIR overrides build-fuzz/. Each target keeps the inputs it found in
# build-fuzz/fuzz/corpus/TARGET, so later runs start from where earlier ones stopped; a
# finding is saved under build-fuzz/fuzz/findings/TARGET/ and its log is printed. See
# docs/robustness.md for long runs and for turning a finding into a regression test.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${1:-30}"
case "$seconds" in '' | *[!0-9]*) echo "usage: scripts/fuzz.sh [SECONDS_PER_TARGET]" >&2; exit 1 ;; esac

bash "$root/scripts/install-deps.sh"
# Only the fuzz targets: the renderer and the tests are not needed here, and the fuzz build's
# instrumentation would only slow them down.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    -DCLRENDER_BUILD_FUZZERS=ON -DCLRENDER_BUILD_TESTS=OFF -DCLRENDER_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target clrender_fuzz_scene_loader clrender_fuzz_image_loader clrender_fuzz_view_request clrender_fuzz_obj_reader \
    clrender_fuzz_seeds

work="$build/fuzz"
rm -rf "$work/seeds" "$work/logs"
"$build/fuzz/clrender_fuzz_seeds" "$root" "$work/seeds"
mkdir -p "$work/logs"

# target name, binary, seed folder, dictionary
targets=(
    "scene      clrender_fuzz_scene_loader scene  scene.dict"
    "png        clrender_fuzz_image_loader png    png.dict"
    "jpeg       clrender_fuzz_image_loader jpeg   jpeg.dict"
    "ppm_p3     clrender_fuzz_image_loader ppm_p3 ppm.dict"
    "ppm_p6     clrender_fuzz_image_loader ppm_p6 ppm.dict"
    "view       clrender_fuzz_view_request view   view.dict"
    "obj        clrender_fuzz_obj_reader   obj    obj.dict"
)

# The fuzzers load scenes, whose images would otherwise go to the user's decoded-image cache.
export CLRENDER_CACHE_DIR=off
# The sanitizers stop at the first report; leaks count as findings too. libFuzzer's own
# limits: 16 KiB inputs (larger than any seed, large enough for deep JSON nesting and
# multi-chunk images); 30 s per input, a hang (several times what the slowest valid input, a
# JPEG of the largest size clrender reads, 8192 x 8192, takes under the sanitizers:
# docs/benchmarks.md, Figures behind design choices); and 2 GiB of
# memory in use, above which an input is an out-of-memory finding. A single allocation may
# reach 4 GiB: stb_image reserves up to 2 GiB, untouched, for a PNG whose IDAT chunk claims
# more bytes than the file has, then fails cleanly (docs/robustness.md).
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:symbolize=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"

failed=()
summary=()
total=0
for entry in "${targets[@]}"; do
    read -r name binary seeds dictionary <<<"$entry"
    corpus="$work/corpus/$name"
    findings="$work/findings/$name"
    log="$work/logs/$name.log"
    mkdir -p "$corpus" "$findings"
    echo "fuzz: $name for ${seconds}s"
    status=0
    # The first folder receives the new inputs; the seeds stay as generated.
    "$build/fuzz/$binary" "$corpus" "$work/seeds/$seeds" \
        -dict="$root/fuzz/dictionaries/$dictionary" -max_total_time="$seconds" -max_len=16384 \
        -timeout=30 -rss_limit_mb=2048 -malloc_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$findings/" \
        >"$log" 2>&1 || status=$?
    executions=$(sed -n 's/^stat::number_of_executed_units: *\([0-9]*\).*/\1/p' "$log" | tail -n 1)
    if [ -z "$executions" ]; then  # no final stats after a crash: the last status line counts
        executions=$(sed -n 's/^#\([0-9]*\).*/\1/p' "$log" | tail -n 1)
    fi
    executions="${executions:-0}"
    total=$((total + executions))
    corpus_size=$(find "$corpus" -type f | wc -l)
    if [ "$status" -ne 0 ]; then
        failed+=("$name")
        summary+=("$(printf '%-8s %12s executions  %5s corpus inputs  FAILED (exit %s)' "$name" "$executions" "$corpus_size" "$status")")
        echo "fuzz: $name FAILED; its log ($log) ends:" >&2
        tail -n 60 "$log" >&2
        echo "fuzz: the input is in $findings/" >&2
    else
        summary+=("$(printf '%-8s %12s executions  %5s corpus inputs  ok' "$name" "$executions" "$corpus_size")")
    fi
done

echo "fuzz: executions per target (${seconds}s each)"
printf '  %s\n' "${summary[@]}"
echo "fuzz: $total executions in total"
if [ ${#failed[@]} -gt 0 ]; then
    echo "fuzz: FAILED: ${failed[*]}" >&2
    exit 1
fi
