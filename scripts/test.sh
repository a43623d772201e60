#!/usr/bin/env bash
# Sets up everything, builds the tests and runs them all (gtest suites,
# rostests and build checks) through ctest: non-zero on any failure, ctest's
# summary line last.
set -euo pipefail
source "$(dirname "$0")/common.sh"
rbs_install_packages
rbs_build
rbs_build tests
echo "test: running the tests (ctest, 2 at a time, about 3 minutes)" >&2
log="$RBS_WS/ctest.log"
status=0
ctest --test-dir "$RBS_WS/build" --output-on-failure -j2 2>&1 | tee "$log" || status=$?
# ctest's verdict line ("100% tests passed, 0 tests failed out of N") last.
grep -E "tests passed|tests failed" "$log" | tail -n 1
exit "$status"
