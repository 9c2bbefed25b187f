// SPDX-License-Identifier: MIT
// A contact sheet of a clip, to browse a library at a glance: key frames of the
// motion in a grid, each drawn as the body's boxes standing on a ground grid,
// with the time and the controller phase written under each frame.
//
// What is drawn:
// - keyFrames frames evenly spaced over the clip, the first and the last included;
// - every frame from the same fixed three-quarter camera (from the character's
//   front-left, 55 deg round from its facing, 20 deg above the ground, higher
//   on a slope that rises towards it) with an orthographic view that frames
//   the whole motion, so frames compare in size and position;
// - the bone boxes flat-shaded under one fixed light and z-buffered, outlined
//   where one box meets another; the ground (y = 0 or a slope) as a grid of
//   0.5 m squares with the boxes' shadows straight below;
// - colours: left limbs orange, right limbs blue, trunk teal, head sand. The body
//   is drawn in saturated colours and everything else (background, ground,
//   grid, text) in neutral greys, so the body stays easy to pick out;
// - under each frame its time, frame number and phase (clip.metadata.phases),
//   and a title line on top.
// A skeleton without boxes (another tool's clip) is drawn with a thin box along
// each bone instead.
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "export/clip.h"

namespace rise {

struct PreviewOptions {
  int keyFrames = 8;     // frames shown; fewer when the clip has fewer frames
  int columns = 4;       // frames per row
  int cellWidth = 320;   // pixels per frame, including its margin
  int cellHeight = 300;  // pixels per frame, including the label lines under it
  std::string title;     // empty: "RISE-GEN PREVIEW" and the clip's length
  // The ground: the plane through groundPoint with normal groundNormal (y = 0
  // by default; a slope clip passes its slope so the grid lies under the body).
  glm::vec3 groundPoint{0.0f};
  glm::vec3 groundNormal{0.0f, 1.0f, 0.0f};  // need not be unit length
};

// Sheet size in pixels for a clip of `frameCount` frames: columns * cellWidth
// wide, a title band plus rows * cellHeight high.
int PreviewSheetWidth(const PreviewOptions& options, int frameCount);
int PreviewSheetHeight(const PreviewOptions& options, int frameCount);

// Renders the sheet and writes it as an RGB PNG at pngPath, all or nothing
// (export/atomic_file.h). Returns an empty string on success, otherwise what
// went wrong (invalid clip or options, file not writable).
std::string WritePreviewSheet(const Clip& clip, const PreviewOptions& options, const std::string& pngPath);

}  // namespace rise
