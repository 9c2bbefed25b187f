#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# README command 2 (and CI): install dependencies, build with warnings as errors, run the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh -DRISE_WARNINGS_AS_ERRORS=ON
cd build
ctest --output-on-failure -j"$(nproc)"
