#!/usr/bin/env bash
# Names the tests that CTest ran again after a failure (--repeat until-pass, scripts/test.sh
# and scripts/sanitize.sh) from its output: a test that then passed is flaky and is named as
# such, so that a retry never hides it.
#   scripts/name-retried-tests.sh CTEST_OUTPUT_FILE
set -euo pipefail
log="$1"
[ -f "$log" ] || exit 0
# CTest prints "Test #N: NAME ...***Failed" (or ***Exception, ***Timeout) for each failed try.
{ grep -E '^ *([0-9]+/[0-9]+ )?Test +#[0-9]+: .*\*\*\*(Failed|Exception|Timeout)' "$log" || true; } |
    sed -E 's/^ *([0-9]+\/[0-9]+ )?Test +#[0-9]+: ([^ ]+).*/\2/' | sort -u |
    while IFS= read -r name; do
        if grep -qE "Test +#[0-9]+: $(printf '%s' "$name" | sed 's/[][\.*^$/]/\\&/g') .*Passed" "$log"; then
            echo "retried test: $name failed once and passed when run again (flaky: see its log above)"
        else
            echo "failed test: $name failed twice"
        fi
    done
