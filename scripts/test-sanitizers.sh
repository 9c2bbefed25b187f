#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# CI sanitizer job: builds the asan-ubsan preset (AddressSanitizer + UndefinedBehaviorSanitizer,
# every UB finding fatal) in build-asan/ and runs the whole CTest suite under it.
# Expects scripts/deps.sh to have run. Extra arguments go to ctest (e.g. -R cli).
set -euo pipefail
cd "$(dirname "$0")/.."
# Benchmarks are not tests: left out to save build time.
cmake --preset asan-ubsan -DRISE_WARNINGS_AS_ERRORS=ON -DRISE_BUILD_BENCH=OFF
cmake --build build-asan -j"$(nproc)"
# halt_on_error: the first report fails the test. detect_leaks: a leak is a finding too.
export ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# Clips simulate about 10x slower under the sanitizers: CTest's default per-test timeout stays,
# so a hang still fails, but the slowest cases get room.
cd build-asan
ctest --output-on-failure -j"$(nproc)" --timeout 900 "$@"
