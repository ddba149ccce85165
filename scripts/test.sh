#!/usr/bin/env bash
# The README's second command: install, build the tests (and the programs they run), and run
# the whole test suite with CTest. The benchmark programs are not built (scripts/bench.sh).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"

bash "$root/scripts/build.sh" --tests clrender_tests
cd "$build"
status=0
ctest --output-on-failure -j"$(nproc)" || status=$?
# A skipped test says why in its log; the reasons are printed here so that a skip is seen.
grep -h -E '^(SKIPPED: |slurm_cluster: cannot run)' Testing/Temporary/LastTest.log 2>/dev/null | sed 's/^/skip reason: /' || true
exit $status
