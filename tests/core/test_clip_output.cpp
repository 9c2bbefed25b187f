// SPDX-License-Identifier: MIT
#include "core/clip_output.h"
#include "test_support.h"

#include <filesystem>
#include <fstream>

TEST_SUITE("clip_output") {
TEST_CASE("an output whose sidecar or itself is the input file is refused") {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "rise_clip_output_test";
  std::filesystem::create_directories(folder);
  const std::string input = (folder / "walk.meta.json").string();
  std::ofstream(input) << "{}";
  // walk.glb's metadata sidecar is walk.meta.json: the input.
  CHECK(rise::CheckOutputsSpareInput({(folder / "walk.glb").string()}, input).find("would overwrite the input") !=
        std::string::npos);
  // The same file reached through another spelling of the path.
  CHECK_FALSE(rise::CheckOutputsSpareInput({(folder / "." / "walk.bvh").string()}, input).empty());
  // Other names are fine, the common `walk.json -o walk.glb` among them.
  CHECK(rise::CheckOutputsSpareInput({(folder / "clip.glb").string(), (folder / "clip.bvh").string()}, input).empty());
  CHECK(rise::CheckOutputsSpareInput({(folder / "walk.glb").string()}, (folder / "walk.json").string()).empty());
  std::filesystem::remove_all(folder);
}
}
