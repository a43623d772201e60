#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/: the URDF loader, the config parser,
# the mesh loader, each then the model's validation and a few steps) with
# clang under ASan and UBSan, and runs them at once for RBS_FUZZ_SECONDS (default 60)
# from the seed corpus: fuzz/seeds/<kind>/ and the package's own files.
# Non-zero when a target crashes, leaks, trips a sanitizer or hangs (a unit
# slower than 10 s); the failing input is saved in .ws/fuzz/artifacts/.
#
#   bash scripts/fuzz.sh                          # CI: a minute
#   RBS_FUZZ_SECONDS=3600 bash scripts/fuzz.sh    # a long run: an hour
#   RBS_FUZZ_TARGETS=urdf_fuzzer bash scripts/fuzz.sh
set -euo pipefail
source "$(dirname "$0")/common.sh"
seconds=${RBS_FUZZ_SECONDS:-60}
targets=(${RBS_FUZZ_TARGETS:-urdf_fuzzer config_fuzzer mesh_fuzzer})
rbs_install_packages "${RBS_APT_PACKAGES[@]}" "${RBS_FUZZ_PACKAGES[@]}"
dir=$RBS_WS/fuzz
mkdir -p "$dir/build" "$dir/artifacts"
# OSS-Fuzz's optimisation and debug info (-O1, line tables only): builds in
# less time than -O2 -g and still names the line.
rbs_phase "building the fuzzers with clang into ${dir#"$PWD"/} (about 3 minutes the first time)" fuzz_build.log \
  bash -c "CXX=clang++-14 cmake -S '$RBS_ROOT/fuzz' -B '$dir/build' -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    '-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG' && cmake --build '$dir/build' -j2"
declare -A seeds=([urdf_fuzzer]="fuzz/seeds/urdf urdf" [config_fuzzer]="fuzz/seeds/config config"
                  [mesh_fuzzer]="fuzz/seeds/mesh")
status=0
# The targets run at once, each for $seconds of wall time, sharing the cores.
declare -A pids=()
for t in "${targets[@]}"; do
  corpus=$dir/corpus/$t  # what the run finds: kept between runs, never in git
  mkdir -p "$corpus"
  echo "fuzz: $t for $seconds s (log: ${dir#"$PWD"/}/$t.log)" >&2
  # Leak checks stay on (but for assimp's own, fuzz/lsan.supp); -rss_limit_mb
  # bounds a unit's memory, -timeout its time, -max_len lets an input be long enough to declare many sensors.
  (cd "$RBS_ROOT" && LSAN_OPTIONS=suppressions=$RBS_ROOT/fuzz/lsan.supp "$dir/build/$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix="$dir/artifacts/$t-" -print_final_stats=1 "$corpus" ${seeds[$t]}) >"$dir/$t.log" 2>&1 &
  pids[$t]=$!
done
for t in "${targets[@]}"; do
  wait "${pids[$t]}" || {
    status=$?
    echo "fuzz: $t FAILED ($status); the sanitizer's report (its stack first) and the end of the log:" >&2
    # The report's first lines name the access and its stack; the shadow
    # map after them says little. CI keeps only what is printed here.
    grep -m1 -A45 -E "^==[0-9]+==ERROR|^SUMMARY|deadly signal|timeout after" "$dir/$t.log" | grep -v "^  0x" >&2 || true
    tail -n 12 "$dir/$t.log" >&2
    # The failing input, as hex, so it can be rebuilt from CI's output.
    for a in "$dir/artifacts/$t-"*; do [ -f "$a" ] && { echo "fuzz: input $a:" >&2; od -An -tx1 -v "$a" | head -n 200 >&2; }; done
    continue
  }
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$dir/$t.log" | tr '\n' ' ' | sed "s/^/fuzz: $t: /" >&2
  echo >&2
done
exit "$status"
