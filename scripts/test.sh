#!/usr/bin/env bash
# The README's second command: install, build the tests (and the programs they run), and run
# the whole test suite with CTest. The benchmark programs are not built (scripts/bench.sh).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"

bash "$root/scripts/build.sh" --tests clrender_tests
cd "$build"
status=0
# A test that fails is run once more (a busy machine can starve one of the tests that start
# processes and time them); the run still fails when it fails twice, and every retried test
# is named below, so that a flaky test is seen and fixed, not hidden.
mkdir -p Testing
ctest --output-on-failure -j"$(nproc)" --repeat until-pass:2 2>&1 | tee Testing/ctest-output.log || status=$?
bash "$root/scripts/name-retried-tests.sh" Testing/ctest-output.log
# A skipped test says why in its log; the reasons are printed here so that a skip is seen.
grep -h -E '^(SKIPPED: |slurm_cluster: cannot run)' Testing/Temporary/LastTest.log 2>/dev/null | sed 's/^/skip reason: /' || true
exit $status
