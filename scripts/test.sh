#!/usr/bin/env bash
# Sets up everything, builds the tests and runs them all (gtest suites and
# build checks) through ctest: non-zero on any failure, ctest's summary last.
set -euo pipefail
source "$(dirname "$0")/common.sh"
rbs_install_packages
rbs_build
rbs_build tests
ctest --test-dir "$RBS_WS/build" --output-on-failure -j2
