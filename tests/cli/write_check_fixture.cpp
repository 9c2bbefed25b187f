// SPDX-License-Identifier: MIT
// Writes a synthetic clip that meets every quality bar (tests/fixture_clips.h RiseClip) as
// <dir>/rise.glb and <dir>/rise.bvh, so the CLI tests can see `check` pass without depending on
// the controller's current tuning.
#include <cstdio>
#include <string>

#include "export/bvh_writer.h"
#include "export/gltf_writer.h"
#include "fixture_clips.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_check_fixture <existing folder>\n");
    return 2;
  }
  const rise::Clip clip = rise::test::RiseClip();
  const std::string dir = argv[1];
  std::string error = rise::WriteGltf(clip, dir + "/rise.glb");
  if (error.empty()) error = rise::WriteBvh(clip, dir + "/rise.bvh");
  if (!error.empty()) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  return 0;
}
