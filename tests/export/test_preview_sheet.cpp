// SPDX-License-Identifier: MIT
#include "export/preview_sheet.h"
#include "fixture_clips.h"
#include "test_support.h"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#include <stb/stb_image.h>

#include <algorithm>
#include <filesystem>
#include <memory>

namespace {

namespace fs = std::filesystem;

struct Decoded {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

Decoded ReadPng(const std::string& path) {
  Decoded image;
  int channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> data(
      stbi_load(path.c_str(), &image.width, &image.height, &channels, 3), stbi_image_free);
  if (data) image.rgb.assign(data.get(), data.get() + size_t(image.width) * image.height * 3);
  return image;
}

// Body pixels are saturated; background, ground, grid and text are neutral
// greys (see preview_sheet.h).
bool IsBody(const Decoded& image, int x, int y) {
  const unsigned char* p = &image.rgb[(size_t(y) * image.width + x) * 3];
  const int high = std::max({p[0], p[1], p[2]}), low = std::min({p[0], p[1], p[2]});
  return high > 40 && high - low > 0.3 * high;
}

struct Extent {
  int pixels = 0, minX = 1 << 30, maxX = -1, minY = 1 << 30, maxY = -1;
  int Width() const { return maxX - minX + 1; }
  int Height() const { return maxY - minY + 1; }
};

Extent BodyExtent(const Decoded& image, int x0, int y0, int width, int height) {
  Extent extent;
  for (int y = y0; y < y0 + height; ++y) {
    for (int x = x0; x < x0 + width; ++x) {
      if (!IsBody(image, x, y)) continue;
      ++extent.pixels;
      extent.minX = std::min(extent.minX, x);
      extent.maxX = std::max(extent.maxX, x);
      extent.minY = std::min(extent.minY, y);
      extent.maxY = std::max(extent.maxY, y);
    }
  }
  return extent;
}

std::string TempPath(const char* name) {
  return (fs::temp_directory_path() / name).string();
}

}  // namespace

TEST_SUITE("preview_sheet") {
  TEST_CASE("a sheet of a rise shows the body lying wide in the first cell and standing tall in the last") {
    const rise::Clip clip = rise::test::RiseClip();
    const rise::PreviewOptions options;
    const std::string path = TempPath("rise_preview_sheet_test.png");
    fs::remove(path);
    REQUIRE(rise::WritePreviewSheet(clip, options, path) == "");
    const Decoded image = ReadPng(path);
    REQUIRE(!image.rgb.empty());
    // 8 key frames in 4 columns: 2 rows of 320 x 300 under the title band.
    CHECK(image.width == 4 * options.cellWidth);
    CHECK(image.width == rise::PreviewSheetWidth(options, clip.FrameCount()));
    CHECK(image.height == rise::PreviewSheetHeight(options, clip.FrameCount()));
    const int titleHeight = image.height - 2 * options.cellHeight;
    CHECK(titleHeight > 0);
    std::vector<Extent> cells;
    for (int k = 0; k < 8; ++k) {
      cells.push_back(BodyExtent(image, (k % 4) * options.cellWidth, titleHeight + (k / 4) * options.cellHeight,
                                 options.cellWidth, options.cellHeight));
      INFO("cell " << k);
      CHECK(cells.back().pixels > 500);
    }
    INFO("lying " << cells.front().Width() << " x " << cells.front().Height() << ", standing " << cells.back().Width()
                  << " x " << cells.back().Height());
    CHECK(cells.front().Width() > 1.5 * cells.front().Height());
    CHECK(cells.back().Height() > 1.5 * cells.back().Width());
    // The last cell holds the same body upright: taller than it was lying.
    CHECK(cells.back().Height() > 2 * cells.front().Height());
    fs::remove(path);
  }

  TEST_CASE("a short clip gets one cell per frame") {
    const rise::Clip clip = rise::test::StandingClip(3);
    rise::PreviewOptions options;
    options.cellWidth = 200;
    options.cellHeight = 220;
    const std::string path = TempPath("rise_preview_sheet_short.png");
    REQUIRE(rise::WritePreviewSheet(clip, options, path) == "");
    const Decoded image = ReadPng(path);
    CHECK(image.width == 3 * 200);
    CHECK(image.height == rise::PreviewSheetHeight(options, 3));
    for (int k = 0; k < 3; ++k) CHECK(BodyExtent(image, k * 200, image.height - 220, 200, 220).pixels > 200);
    fs::remove(path);
  }

  TEST_CASE("a skeleton without boxes is drawn along its bones") {
    rise::Clip clip = rise::test::RiseClip();
    for (auto& joint : clip.skeleton.joints) joint.hasBox = false;
    rise::PreviewOptions options;
    options.keyFrames = 2;
    options.cellWidth = 160;
    options.cellHeight = 200;
    const std::string path = TempPath("rise_preview_sheet_bones.png");
    REQUIRE(rise::WritePreviewSheet(clip, options, path) == "");
    const Decoded image = ReadPng(path);
    const Extent standing =
        BodyExtent(image, options.cellWidth, image.height - options.cellHeight, options.cellWidth, options.cellHeight);
    CHECK(standing.pixels > 300);
    CHECK(standing.Height() > 1.5 * standing.Width());
    fs::remove(path);
  }

  TEST_CASE("on a 25 deg slope the body still stands tall in the last cell") {
    rise::Clip clip = rise::test::RiseClip();
    const glm::quat slope = glm::angleAxis(glm::radians(-25.0f), glm::vec3(1, 0, 0));  // rises towards +Z
    for (int f = 0; f < clip.FrameCount(); ++f) {
      clip.rotations[0][f] = slope * clip.rotations[0][f];
      clip.rootTranslation[f] = slope * clip.rootTranslation[f];
    }
    rise::PreviewOptions options;
    options.keyFrames = 2;
    options.groundNormal = slope * glm::vec3(0, 1, 0);
    const std::string path = TempPath("rise_preview_sheet_slope.png");
    REQUIRE(rise::WritePreviewSheet(clip, options, path) == "");
    const Decoded image = ReadPng(path);
    const Extent lying = BodyExtent(image, 0, image.height - options.cellHeight, options.cellWidth, options.cellHeight);
    const Extent standing =
        BodyExtent(image, options.cellWidth, image.height - options.cellHeight, options.cellWidth, options.cellHeight);
    CHECK(lying.Width() > lying.Height());
    CHECK(standing.Height() > 1.5 * standing.Width());
    fs::remove(path);
    // A ground more than 60 deg from level is refused.
    options.groundNormal = glm::vec3(1, 0.5f, 0);
    CHECK(rise::WritePreviewSheet(clip, options, path).find("ground normal") != std::string::npos);
    CHECK_FALSE(fs::exists(path));
  }

  TEST_CASE("a path in a missing folder gives an error and no file") {
    const std::string path = TempPath("rise_no_such_folder/sheet.png");
    rise::PreviewOptions options;
    options.keyFrames = 1;
    const std::string error = rise::WritePreviewSheet(rise::test::RiseClip(), options, path);
    CHECK(error.find("rise_no_such_folder") != std::string::npos);
    CHECK_FALSE(fs::exists(path));
  }

  TEST_CASE("an invalid clip or zero key frames give an error and no file") {
    const std::string path = TempPath("rise_preview_sheet_invalid.png");
    fs::remove(path);
    rise::Clip clip = rise::test::RiseClip();
    clip.fps = 0.0;
    CHECK(rise::WritePreviewSheet(clip, {}, path).find("fps") != std::string::npos);
    rise::PreviewOptions options;
    options.keyFrames = 0;
    CHECK(rise::WritePreviewSheet(rise::test::RiseClip(), options, path) != "");
    CHECK_FALSE(fs::exists(path));
  }
}
