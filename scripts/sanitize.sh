#!/usr/bin/env bash
# The tests under the sanitizers, each build in its own workspace under .ws/:
#  - .ws/asan: the whole package with AddressSanitizer and UndefinedBehaviorSanitizer,
#    every gtest suite and every rostest (the node runs instrumented);
#  - .ws/tsan: the core with ThreadSanitizer, the suites that step on several
#    threads (core_bodies_test, core_broad_phase_test, core_workspace_test, core_parallel_test).
# Non-zero on any report: leaks, out-of-bounds, undefined behaviour, races.
# Both are clang's (clang 14, as the fuzzers): it built the core under ASan
# and UBSan in two thirds of GCC's time (248 s of CPU to 369 s, 2026-12-04),
# and it holds to C++17 where GCC lets a lambda capture a structured binding.
#
#   bash scripts/sanitize.sh          # both (CI runs it; about 14 minutes on 2 cores)
#   bash scripts/sanitize.sh asan     # or tsan
set -euo pipefail
source "$(dirname "$0")/common.sh"
which=${1:-all}
rbs_install_packages "${RBS_APT_PACKAGES[@]}" "${RBS_FUZZ_PACKAGES[@]}"
root_ws=$RBS_WS
# A workspace first configured with another compiler (GCC's, before
# 2026-12-04) is built afresh: CMake keeps the compiler it first found.
export CXX=clang++-14
for ws in "$root_ws/asan" "$root_ws/tsan"; do
  if [ -f "$ws/build/CMakeCache.txt" ] && ! grep -q "^CMAKE_CXX_COMPILER:.*clang++-14" "$ws/build/CMakeCache.txt"; then
    rm -rf "$ws"
  fi
done
status=0
if [ "$which" = all ] || [ "$which" = asan ]; then
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:exitcode=23
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # Build type "Sanitize" has no flags of its own: -O1 and line tables only,
  # which build in about half the time of -O2 -g and still name the line
  # (the suites' own files at -O0: test/CMakeLists.txt). The libraries stay
  # at -O1: a CI run with them at -O0 (2026-11-27) failed two rostests whose
  # requests the slower node answered late. The suites' own files are under
  # ASan only: they set up and assert, the libraries they call carry UBSan,
  # and UBSan's checks cost a test file half its compile (ros/gazebo_plugins_test.cpp
  # 9.7 s with, 6.5 s without, 2026-12-03).
  RBS_CMAKE_ARGS=(-DRBS_LTO=OFF "-DRBS_TEST_OPTIONS=-O0;-fno-sanitize=undefined"
    "-DCMAKE_CXX_FLAGS=-O1 -gline-tables-only -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer")
  RBS_WS=$root_ws/asan RBS_BUILD_TYPE=Sanitize RBS_WERROR=OFF rbs_build tests
  echo "sanitize: every test under ASan and UBSan (ctest, 2 at a time)" >&2
  ctest --test-dir "$root_ws/asan/build" --output-on-failure -j2 >"$root_ws/asan/ctest.log" 2>&1 || status=$?
  grep -E "tests passed|tests failed" "$root_ws/asan/ctest.log" | tail -n 1 | sed 's/^/sanitize: asan: /' >&2
  # The failing tests, then each distinct failure line (a rostest repeats its verdicts).
  [ "$status" -eq 0 ] || grep -E "Failed|ERROR: |runtime error|\[FAILURE\]|Expected|actual: |Which is: |Value of: |evaluates to|\.cpp:[0-9]+$" \
    "$root_ws/asan/ctest.log" | awk '!seen[$0]++' | head -n 60 >&2
  unset ASAN_OPTIONS UBSAN_OPTIONS
fi
if [ "$which" = all ] || [ "$which" = tsan ]; then
  suites=(core_bodies_test core_broad_phase_test core_workspace_test core_parallel_test core_articulation_contacts_test core_scene_test)
  RBS_CMAKE_ARGS=(-DRBS_LTO=OFF "-DCMAKE_CXX_FLAGS=-O1 -gline-tables-only -fsanitize=thread")
  RBS_WS=$root_ws/tsan RBS_BUILD_TYPE=Sanitize RBS_WERROR=OFF rbs_build "${suites[@]}"
  echo "sanitize: the threaded core suites under TSan" >&2
  for s in "${suites[@]}"; do
    TSAN_OPTIONS=halt_on_error=1 RBS_THREADS=2 "$root_ws/tsan/devel/lib/rigid_body_sim/$s" >"$root_ws/tsan/$s.log" 2>&1 || {
      status=1
      echo "sanitize: tsan: $s FAILED; the end of its log:" >&2
      tail -n 30 "$root_ws/tsan/$s.log" >&2
      continue
    }
    echo "sanitize: tsan: $s passed" >&2
  done
fi
exit "$status"
