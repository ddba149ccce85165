#!/usr/bin/env bash
# Names the tests that CTest ran again after a failure (--repeat until-pass, scripts/test.sh
# and scripts/sanitize.sh) from its output: a test that then passed is flaky and is named as
# such, so that a retry never hides it.
#   scripts/name-retried-tests.sh CTEST_OUTPUT_FILE
set -euo pipefail
log="$1"
[ -f "$log" ] || exit 0
# CTest prints "[i/n] Test #N: NAME ... Passed" for a try that passed and "***Failed" (or
# ***Exception, ***Timeout) for one that did not; the name is the word after "#N:".
awk '
    match($0, /Test +#[0-9]+: [^ ]+/) {
        name = substr($0, RSTART, RLENGTH)
        sub(/^Test +#[0-9]+: /, "", name)
        if ($0 ~ /\*\*\*(Failed|Exception|Timeout)/) { failed[name] = 1 }
        else if ($0 ~ / Passed /) { passed[name] = 1 }
    }
    END {
        for (name in failed) {
            if (name in passed) print "retried test: " name " failed once and passed when run again (flaky: see its log above)"
            else print "failed test: " name " failed twice"
        }
    }' "$log" | sort
