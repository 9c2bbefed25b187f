#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# CI sanitizer job: builds the asan-ubsan preset (AddressSanitizer + UndefinedBehaviorSanitizer,
# every UB finding fatal) in build-asan/ and runs the whole CTest suite under it.
# Expects scripts/deps.sh to have run. Extra arguments go to ctest (e.g. -R cli).
set -euo pipefail
cd "$(dirname "$0")/.."
# Benchmarks are left out to save build time; so is the stress run (label stress), which needs
# bench/stress_runner and runs in the Release suite.
cmake --preset asan-ubsan -DRISE_WARNINGS_AS_ERRORS=ON -DRISE_BUILD_BENCH=OFF
cmake --build build-asan -j"$(nproc)"
# halt_on_error: the first report fails the test. detect_leaks: a leak is a finding too.
export ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# A hang fails the job instead of stalling CI: 900 s per test, where the slowest case under the
# sanitizers (cli.batch_shards, clips simulate about 8x slower) takes under a minute.
cd build-asan
ctest --output-on-failure -j"$(nproc)" --timeout 900 "$@"
