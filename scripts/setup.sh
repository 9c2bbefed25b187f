#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# README command 1: install dependencies, build, and run the main job on a bundled sample.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh
mkdir -p out
./build/cli/rise-gen demo-drop
