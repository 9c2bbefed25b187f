#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# README command 1: install dependencies, build, and run the main job on a bundled sample.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh
mkdir -p out
# Exit code 1 means the clip was written but missed a quality bar; the summary
# line says which, and `rise-gen check out/prone.glb` lists every figure.
status=0
./build/cli/rise-gen samples/prone.json -o out/prone.glb -o out/prone.bvh || status=$?
if [ "$status" -gt 1 ]; then exit "$status"; fi
echo "Wrote out/prone.glb, out/prone.bvh and out/prone.meta.json (metadata sidecar)."
