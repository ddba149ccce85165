#!/usr/bin/env bash
# Builds clrender and its test suite with AddressSanitizer and UndefinedBehaviorSanitizer
# (gcc, -DCLRENDER_SANITIZE=ON) into build-sanitize/ and runs the whole suite there with
# CTest (but for the farm's and the browser's tests, below). Tests that run the clrender binary
# run the sanitized binary, so its error paths are checked too. Any report fails the run. tests/sanitizers/lsan.supp may suppress leaks inside
# PoCL, never clrender's; none has been needed (docs/robustness.md).
#
#   scripts/sanitize.sh [CTEST ARGUMENTS...]      e.g. -R BadInput
#
# $CLRENDER_SANITIZE_BUILD_DIR overrides build-sanitize/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
suppressions="$root/tests/sanitizers"

bash "$root/scripts/install-deps.sh"
# -O1 keeps the stack traces readable and the suite fast enough; -g1 names the lines (the line
# tables are all a sanitizer's report reads; full debug information made host/view/view_routes.o
# 19 MB instead of 8, and its compile about a tenth slower). No program
# store: its builder would run sanitized at build time, before the options below are set, and
# the store's tests build stores of their own.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
    -DCLRENDER_SANITIZE=ON -DCLRENDER_PROGRAM_STORE_VARIANTS=none >/dev/null
# The test suite and what it runs (clrender_tests depends on the rest); the benchmark programs
# are left out.
cmake --build "$build" -j"$(nproc)" --target clrender_tests

# Every process the tests start inherits these. A sanitizer that stops a process exits with
# 86, a code clrender never uses, so that a report is never mistaken for one of clrender's
# documented exit codes (1 to 4) by a test that expects a failure.
#   ASan: check initialisation order and use after return too; leaks are checked at exit
#         (LSan). intercept_tls_get_addr=0 works around a bug of gcc 12's runtime with glibc
#         2.36: it records a bogus dynamic TLS block (at address 0x17a1) for a library that
#         PoCL opens, and LSan's scan at exit then crashes ("Tracer caught signal 11"),
#         failing tests that passed. LSan still scans each thread's static TLS and counts
#         the loader's blocks (dynamic TLS among them) as reachable; docs/robustness.md.
#         use_sigaltstack=0: clrender lists OpenCL devices on a short-lived thread while the
#         scene loads, and LLVM inside PoCL replaces that thread's alternate signal stack with
#         its own; ASan then fails to unmap "its" stack when the thread ends and aborts the
#         process. Without its own alternate stacks ASan has nothing to unmap.
#   UBSan: stop at the first report (the build also compiles it without recovery) with a
#          stack trace.
#   LSan: the suppressions file may name leaks of PoCL's, never clrender's (none so far).
export ASAN_OPTIONS="exitcode=86:detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0:use_sigaltstack=0"
export UBSAN_OPTIONS="exitcode=86:halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="exitcode=86:suppressions=$suppressions/lsan.supp:print_suppressions=0"

cd "$build"
# As in scripts/test.sh: a failed test runs once more, and a retried test is named.
status=0
mkdir -p Testing
# The render farm's two tests (labels farm: Slurm's daemons and batch scripts around clrender,
# about 12 minutes each under the sanitizers) and the viewer's page in Chromium (label browser,
# past its 5-minute limit under them) are left out: the clrender modes they run (--frames,
# --tiles, --crop, --join, --assemble, --resume; the viewer's routes) are run under the
# sanitizers by tests/app and tests/view. CLRENDER_SANITIZE_ALL=1 runs them too.
exclude=(-LE '^(farm|browser)$')
[ "${CLRENDER_SANITIZE_ALL:-}" = 1 ] && exclude=()
ctest --output-on-failure -j"$(nproc)" --repeat until-pass:2 "${exclude[@]}" "$@" 2>&1 | tee Testing/ctest-output.log || status=$?
bash "$root/scripts/name-retried-tests.sh" Testing/ctest-output.log
exit $status
