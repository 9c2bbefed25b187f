#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs everything rise-gen needs from Debian 12 packages (idempotent).
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PACKAGES=(cmake g++ make libglm-dev libtinygltf-dev libcli11-dev nlohmann-json3-dev doctest-dev libstb-dev)
# Tools that check written clips in CI: node + npm run the Khronos glTF-Validator
# (tools/validate_gltf.js); Blender (with numpy for its glTF add-on) imports
# the sample clips headless. A node that is already installed (e.g. from
# NodeSource, which bundles npm) is kept rather than replaced by Debian's.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then PACKAGES+=(nodejs npm); fi
PACKAGES+=(blender python3-numpy)
# The fuzz job (scripts/fuzz.sh): clang with libFuzzer, whose runtime Debian ships in
# libclang-rt-14-dev (only recommended by clang, so named here).
PACKAGES+=(clang libclang-rt-14-dev)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
# The validator's exact version is pinned by tools/gltf-validator/package-lock.json.
(cd "$(dirname "$0")/../tools/gltf-validator" && npm ci --no-audit --no-fund --loglevel=error)
