#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# CI fuzz job, and longer fuzzing by hand: builds the libFuzzer targets of tests/fuzz/ with clang
# (AddressSanitizer + UndefinedBehaviorSanitizer) in build-fuzz/ and runs each for a bounded time.
#   bash scripts/fuzz.sh            60 s per target (CI)
#   bash scripts/fuzz.sh 3600       an hour per target
#   bash scripts/fuzz.sh 600 fuzz_bvh_reader
# Each target starts from its committed seeds (tests/fuzz/corpus/<target>/) plus the inputs it
# found before (build-fuzz/corpus/<target>/, kept between runs, never committed). A crash stops
# the run with a non-zero exit and leaves the input in build-fuzz/crashes/<target>/; replay it with
# `build-fuzz/tests/fuzz/<target> <file>`, fix it and add it to the doctest suite as a regression
# test (as tests/export/test_bvh_reader_hostile.cpp does).
# Expects scripts/deps.sh to have run (clang and libclang-rt-14-dev).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
if [ "${#targets[@]}" -eq 0 ]; then targets=(fuzz_input_json fuzz_library_manifest fuzz_bvh_reader); fi

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DRISE_FUZZ=ON \
  -DRISE_BUILD_TESTS=OFF -DRISE_BUILD_BENCH=OFF
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]}"

export ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
total=0
for target in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$target
  crashes=build-fuzz/crashes/$target
  mkdir -p "$corpus" "$crashes"
  log=build-fuzz/$target.log
  echo "== $target: ${seconds} s"
  # -max_len 4096: inputs as big as real files; -timeout 10: an input taking longer is a hang.
  # -rss_limit_mb 2048: an input making the loader allocate more is a finding.
  status=0
  "build-fuzz/tests/fuzz/$target" "$corpus" "tests/fuzz/corpus/$target" -dict="tests/fuzz/$target.dict" \
    -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$crashes/" > "$log" 2>&1 || status=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  echo "$target: ${runs:-?} executions, exit $status"
  total=$((total + ${runs:-0}))
  if [ "$status" -ne 0 ]; then
    tail -n 60 "$log"
    echo "$target: FAILED; the input is in $crashes/" >&2
    exit 1
  fi
done
echo "fuzzing done: $total executions, no crash"
