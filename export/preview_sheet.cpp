// SPDX-License-Identifier: MIT
// The contact sheet: a small software rasteriser (orthographic camera,
// flat-shaded z-buffered triangles, supersampled), the built-in font, and a PNG
// written through stb_image_write and an atomic rename.
#include "export/preview_sheet.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include "export/atomic_file.h"
#include "export/bitmap_font.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rise {
namespace {

constexpr int kTitleHeight = 36;         // pixels
constexpr int kLabelHeight = 50;         // pixels under each frame: two text lines
constexpr int kTextScale = 2;            // font pixels per glyph pixel
constexpr int kSupersample = 2;          // rendered pixels per output pixel along each axis
constexpr float kMarginPixels = 14;      // free space around the motion in a cell
constexpr float kAzimuthDeg = 55;        // camera round from the character's facing (+Z) towards +X
constexpr float kElevationDeg = 20;      // camera above the ground plane
constexpr float kGridSpacing = 0.5f;     // metres between ground lines
constexpr float kGroundPadding = 0.6f;   // metres of ground beyond the motion's footprint
constexpr float kBoneThickness = 0.03f;  // half size of the stand-in box of a bone without one

// Neutral colours (the body is saturated, see the header).
const glm::vec3 kSkyTop(0.80f, 0.81f, 0.83f);
const glm::vec3 kSkyBottom(0.95f, 0.95f, 0.95f);
const glm::vec3 kGround(0.86f, 0.86f, 0.85f);
const glm::vec3 kGridLine(0.62f, 0.62f, 0.62f);
const glm::vec3 kAxisLine(0.45f, 0.45f, 0.45f);
const glm::vec3 kText(0.12f, 0.12f, 0.12f);
const glm::vec3 kSubtleText(0.35f, 0.35f, 0.35f);
const glm::vec3 kCellBorder(0.70f, 0.70f, 0.70f);
const glm::vec3 kTitleBand(0.90f, 0.90f, 0.90f);
constexpr float kShadowFactor = 0.72f;
constexpr float kOutlineFactor = 0.45f;

const glm::vec3 kLeftLimb(0.95f, 0.55f, 0.20f);
const glm::vec3 kRightLimb(0.22f, 0.50f, 0.92f);
const glm::vec3 kTrunk(0.18f, 0.62f, 0.58f);
const glm::vec3 kHead(0.90f, 0.68f, 0.42f);

struct Image {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> rgb;  // 0..1 per channel, row-major from the top left

  Image(int w, int h, const glm::vec3& fill) : width(w), height(h), rgb(size_t(w) * h, fill) {}
  glm::vec3& At(int x, int y) { return rgb[size_t(y) * width + x]; }
};

// A box to draw: whose colour it takes and where it sits in that joint's frame.
struct DrawBox {
  int joint = 0;
  BoneBox box;
};

// The bone boxes, or for a skeleton without any a thin stand-in along every
// bone (joint frames are world-aligned in the bind pose, so an axis-aligned box
// in the parent's frame follows the bone).
std::vector<DrawBox> BoxesToDraw(const Skeleton& skeleton) {
  std::vector<DrawBox> boxes;
  for (int j = 0; j < skeleton.JointCount(); ++j) {
    if (skeleton.joints[j].hasBox) boxes.push_back({j, skeleton.joints[j].box});
  }
  if (!boxes.empty()) return boxes;
  for (int j = 1; j < skeleton.JointCount(); ++j) {
    const glm::vec3 offset = skeleton.joints[j].restOffset;
    boxes.push_back({skeleton.joints[j].parent, {0.5f * offset, 0.5f * glm::abs(offset) + kBoneThickness}});
  }
  return boxes;
}

std::string Lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

glm::vec3 ColourOf(const std::string& jointName) {
  const std::string name = Lower(jointName);
  auto endsWith = [&](const char* suffix) {
    const std::string s(suffix);
    return name.size() >= s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0;
  };
  if (endsWith("_l") || name.find("left") != std::string::npos) return kLeftLimb;
  if (endsWith("_r") || name.find("right") != std::string::npos) return kRightLimb;
  if (name.find("head") != std::string::npos || name.find("neck") != std::string::npos) return kHead;
  return kTrunk;
}

// One frame's boxes in world space: 8 corners each (BoneBox::Corner order) and the
// world rotation of each box.
struct PosedBoxes {
  std::vector<std::array<glm::vec3, 8>> corners;
  std::vector<glm::quat> rotations;
};

PosedBoxes Pose(const Clip& clip, const std::vector<DrawBox>& boxes, int frame) {
  const std::vector<glm::vec3> positions = clip.WorldPositions(frame);
  const std::vector<glm::quat> rotations = clip.WorldRotations(frame);
  PosedBoxes posed;
  for (const DrawBox& box : boxes) {
    std::array<glm::vec3, 8> corners;
    for (int c = 0; c < 8; ++c) corners[c] = positions[box.joint] + rotations[box.joint] * box.box.Corner(c);
    posed.corners.push_back(corners);
    posed.rotations.push_back(rotations[box.joint]);
  }
  return posed;
}

// Orthographic camera; screen x right, y down, depth grows away from the camera.
struct Camera {
  glm::vec3 right, up, forward;
  float scale = 1.0f;   // pixels per metre
  glm::vec2 origin{0};  // pixel where the world origin lands

  glm::vec3 Project(const glm::vec3& p) const {
    return {origin.x + glm::dot(p, right) * scale, origin.y - glm::dot(p, up) * scale, glm::dot(p, forward)};
  }
};

// The ground plane, with the unit tangents its grid lines run along.
struct GroundPlane {
  glm::vec3 point, normal, u, v;

  float Height(const glm::vec3& p) const { return glm::dot(p - point, normal); }
  // Straight below p along gravity (-Y), on the plane: where its shadow falls.
  glm::vec3 Below(const glm::vec3& p) const { return p - glm::vec3(0.0f, Height(p) / normal.y, 0.0f); }
  glm::vec2 Coordinates(const glm::vec3& p) const { return {glm::dot(p - point, u), glm::dot(p - point, v)}; }
};

GroundPlane MakeGroundPlane(const PreviewOptions& options) {
  GroundPlane plane;
  plane.point = options.groundPoint;
  plane.normal = glm::normalize(options.groundNormal);
  const glm::vec3 x(1.0f, 0.0f, 0.0f);
  plane.u = glm::normalize(x - glm::dot(x, plane.normal) * plane.normal);
  plane.v = glm::cross(plane.u, plane.normal);  // +Z on flat ground
  return plane;
}

Camera MakeCamera(const GroundPlane& ground) {
  // On a slope rising towards the camera the usual elevation would see the
  // ground edge-on; raise the camera until it looks down on the plane at least
  // as steeply as on flat ground.
  const float az = glm::radians(kAzimuthDeg);
  float el = glm::radians(kElevationDeg);
  auto towardCamera = [&](float elevation) {
    return glm::vec3(std::sin(az) * std::cos(elevation), std::sin(elevation), std::cos(az) * std::cos(elevation));
  };
  while (glm::dot(towardCamera(el), ground.normal) < std::sin(glm::radians(kElevationDeg)) - 1e-4f &&
         el < glm::radians(80.0f)) {
    el += glm::radians(1.0f);
  }
  Camera camera;
  camera.forward = -towardCamera(el);
  camera.right = glm::normalize(glm::cross(camera.forward, glm::vec3(0, 1, 0)));
  camera.up = glm::cross(camera.right, camera.forward);
  return camera;
}

// The hi-res render target of one cell.
struct Canvas {
  int width, height;
  std::vector<glm::vec3> colour;
  std::vector<float> depth;
  std::vector<int> id;         // -1 background, 0 ground, box index + 1 for the body
  std::vector<uint8_t> marks;  // scratch per pixel: shadowed, outlined

  // One canvas serves every cell: allocating a fresh one per cell cost more
  // than drawing it.
  Canvas(int w, int h)
      : width(w), height(h), colour(size_t(w) * h), depth(size_t(w) * h), id(size_t(w) * h), marks(size_t(w) * h) {}
  size_t Index(int x, int y) const { return size_t(y) * width + x; }

  // Clears to the background: a sky brightening towards the horizon.
  void Clear() {
    for (int y = 0; y < height; ++y) {
      const glm::vec3 sky = glm::mix(kSkyTop, kSkyBottom, float(y) / float(height));
      std::fill(colour.begin() + Index(0, y), colour.begin() + Index(0, y) + width, sky);
    }
    std::fill(depth.begin(), depth.end(), std::numeric_limits<float>::max());
    std::fill(id.begin(), id.end(), -1);
  }
};

float Edge(const glm::vec3& a, const glm::vec3& b, float x, float y) {
  return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
}

// Calls fill(index, depth) for every pixel centre inside the screen triangle.
template <typename Fill>
void Rasterise(const Canvas& canvas, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, Fill fill) {
  const float area = Edge(a, b, c.x, c.y);
  if (std::fabs(area) < 1e-8f) return;
  const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
  const int x1 = std::min(canvas.width - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
  const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}))));
  const int y1 = std::min(canvas.height - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const float px = x + 0.5f, py = y + 0.5f;
      // Barycentric weights; dividing by the signed area accepts either winding.
      const float wa = Edge(b, c, px, py) / area, wb = Edge(c, a, px, py) / area, wc = Edge(a, b, px, py) / area;
      if (wa < 0.0f || wb < 0.0f || wc < 0.0f) continue;
      fill(canvas.Index(x, y), wa * a.z + wb * b.z + wc * c.z);
    }
  }
}

// The ground patch around the motion's footprint, in plane coordinates.
struct GroundPatch {
  glm::vec2 min, max;
};

void DrawGround(Canvas& canvas, const Camera& camera, const GroundPlane& ground, const GroundPatch& patch) {
  // A pixel's ray meets the plane at a point linear in the pixel's screen
  // coordinates; the plane length of one pixel along u and v sets the line width.
  const glm::vec3 f = camera.forward, r = camera.right, u = camera.up;
  const float facing = glm::dot(f, ground.normal);
  auto planeAt = [&](float px, float py) {
    const float sx = (px - camera.origin.x) / camera.scale, sy = (camera.origin.y - py) / camera.scale;
    const glm::vec3 onScreen = sx * r + sy * u;
    const float t = -ground.Height(onScreen) / facing;
    return std::make_pair(ground.Coordinates(onScreen + t * f), glm::dot(onScreen, f) + t);
  };
  const auto [c00, d00] = planeAt(0.5f, 0.5f);
  const auto [c10, d10] = planeAt(1.5f, 0.5f);
  const auto [c01, d01] = planeAt(0.5f, 1.5f);
  const glm::vec2 stepX = c10 - c00, stepY = c01 - c00;
  const float depthX = d10 - d00, depthY = d01 - d00;
  const float xPerPixel = glm::length(glm::vec2(stepX.x, stepY.x));
  const float zPerPixel = glm::length(glm::vec2(stepX.y, stepY.y));
  // Anti-aliased line coverage from a pixel's distance to the line.
  auto cover = [](float distance, float perPixel) { return std::clamp(1.6f - distance / perPixel, 0.0f, 1.0f); };
  auto gridDistance = [](float coordinate) {
    return std::fabs(coordinate - kGridSpacing * std::round(coordinate / kGridSpacing));
  };
  for (int y = 0; y < canvas.height; ++y) {
    for (int x = 0; x < canvas.width; ++x) {
      const glm::vec2 p = c00 + float(x) * stepX + float(y) * stepY;
      if (p.x < patch.min.x || p.x > patch.max.x || p.y < patch.min.y || p.y > patch.max.y) continue;
      const float depth = d00 + float(x) * depthX + float(y) * depthY;
      const size_t i = canvas.Index(x, y);
      const float grid = std::max(cover(gridDistance(p.x), xPerPixel), cover(gridDistance(p.y), zPerPixel));
      // The lines through the origin drawn darker show how far the body travels.
      const float axis = std::max(cover(std::fabs(p.x), xPerPixel), cover(std::fabs(p.y), zPerPixel));
      glm::vec3 colour = glm::mix(kGround, kGridLine, grid);
      colour = glm::mix(colour, kAxisLine, axis);
      canvas.colour[i] = colour;
      canvas.depth[i] = depth;
      canvas.id[i] = 0;
    }
  }
}

void DrawShadows(Canvas& canvas, const Camera& camera, const GroundPlane& ground, const PosedBoxes& posed) {
  std::vector<uint8_t>& shadow = canvas.marks;
  std::fill(shadow.begin(), shadow.end(), 0);
  for (const auto& corners : posed.corners) {
    // The box's vertical projection is the hull of its flattened corners, which
    // the fan of flattened triangles from corner 0 covers.
    std::array<glm::vec3, 8> flat;
    for (int c = 0; c < 8; ++c) flat[c] = camera.Project(ground.Below(corners[c]));
    for (int b = 1; b < 8; ++b) {
      for (int c = b + 1; c < 8; ++c) {
        Rasterise(canvas, flat[0], flat[b], flat[c], [&](size_t i, float) { shadow[i] = 1; });
      }
    }
  }
  for (size_t i = 0; i < shadow.size(); ++i) {
    if (shadow[i] && canvas.id[i] == 0) canvas.colour[i] *= kShadowFactor;
  }
}

void DrawBody(Canvas& canvas, const Camera& camera, const PosedBoxes& posed, const std::vector<glm::vec3>& colours) {
  const glm::vec3 light = glm::normalize(-0.35f * camera.right + 0.8f * glm::vec3(0, 1, 0) - 0.5f * camera.forward);
  // Corner indices of the 6 faces (bit 0 = x, bit 1 = y, bit 2 = z), as quads.
  static constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  static const glm::vec3 kNormals[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  for (size_t b = 0; b < posed.corners.size(); ++b) {
    for (int face = 0; face < 6; ++face) {
      const glm::vec3 normal = posed.rotations[b] * kNormals[face];
      if (glm::dot(normal, camera.forward) >= 0.0f) continue;  // faces away; the z-buffer would hide it anyway
      const float shade = 0.42f + 0.58f * std::max(0.0f, glm::dot(normal, light));
      const glm::vec3 colour = colours[b] * shade;
      glm::vec3 quad[4];
      for (int k = 0; k < 4; ++k) quad[k] = camera.Project(posed.corners[b][kFaces[face][k]]);
      auto fill = [&](size_t i, float depth) {
        if (depth < canvas.depth[i]) {
          canvas.depth[i] = depth;
          canvas.colour[i] = colour;
          canvas.id[i] = int(b) + 1;
        }
      };
      Rasterise(canvas, quad[0], quad[1], quad[2], fill);
      Rasterise(canvas, quad[0], quad[2], quad[3], fill);
    }
  }
  // Darken body pixels next to another box or the background, so limbs read
  // against the trunk they cross.
  std::vector<uint8_t>& outlined = canvas.marks;
  std::fill(outlined.begin(), outlined.end(), 0);
  for (int y = 0; y < canvas.height; ++y) {
    for (int x = 0; x < canvas.width; ++x) {
      const size_t i = canvas.Index(x, y);
      if (canvas.id[i] <= 0) continue;
      bool edge = false;
      for (int d = 1; d <= kSupersample / 2 + 1 && !edge; ++d) {
        const int nx[4] = {x - d, x + d, x, x}, ny[4] = {y, y, y - d, y + d};
        for (int k = 0; k < 4 && !edge; ++k) {
          if (nx[k] < 0 || ny[k] < 0 || nx[k] >= canvas.width || ny[k] >= canvas.height) continue;
          const size_t n = canvas.Index(nx[k], ny[k]);
          // Another box, unless it is far behind (then this box is in front of it).
          edge = canvas.id[n] != canvas.id[i] && canvas.depth[n] > canvas.depth[i] - 0.02f;
        }
      }
      outlined[i] = edge ? 1 : 0;
    }
  }
  for (size_t i = 0; i < outlined.size(); ++i) {
    if (outlined[i]) canvas.colour[i] *= kOutlineFactor;
  }
}

void DrawText(Image& image, int x, int y, const std::string& text, const glm::vec3& colour, int scale) {
  for (size_t n = 0; n < text.size(); ++n) {
    const auto rows = GlyphRows(text[n]);
    const int left = x + int(n) * (kGlyphWidth + 1) * scale;
    for (int row = 0; row < kGlyphHeight; ++row) {
      for (int column = 0; column < kGlyphWidth; ++column) {
        if (!(rows[row] & (1 << (kGlyphWidth - 1 - column)))) continue;
        for (int dy = 0; dy < scale; ++dy) {
          for (int dx = 0; dx < scale; ++dx) {
            const int px = left + column * scale + dx, py = y + row * scale + dy;
            if (px >= 0 && py >= 0 && px < image.width && py < image.height) image.At(px, py) = colour;
          }
        }
      }
    }
  }
}

int TextWidth(const std::string& text, int scale) {
  return int(text.size()) * (kGlyphWidth + 1) * scale - scale;
}

std::string PhaseAt(const ClipMetadata& metadata, double time) {
  // At a boundary the later phase wins: it has begun.
  const PhaseSpan* found = nullptr;
  for (const PhaseSpan& phase : metadata.phases) {
    if (phase.start <= time + 1e-9 && time <= phase.end + 1e-9 && (!found || phase.start >= found->start)) {
      found = &phase;
    }
  }
  return found ? found->name : std::string();
}

std::string Printf(const char* format, double a, double b = 0.0, double c = 0.0) {
  char text[128];
  std::snprintf(text, sizeof text, format, a, b, c);
  return text;
}

int KeyFrameCount(const PreviewOptions& options, int frameCount) {
  return std::min(options.keyFrames, frameCount);
}

int RowCount(const PreviewOptions& options, int frameCount) {
  const int columns = std::min(options.columns, KeyFrameCount(options, frameCount));
  return (KeyFrameCount(options, frameCount) + columns - 1) / columns;
}

std::string EncodePng(const Image& image) {
  std::vector<unsigned char> bytes(size_t(image.width) * image.height * 3);
  for (size_t i = 0; i < image.rgb.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      bytes[3 * i + c] = static_cast<unsigned char>(std::lround(255.0f * std::clamp(image.rgb[i][c], 0.0f, 1.0f)));
  }
  std::string png;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
  };
  if (!stbi_write_png_to_func(append, &png, image.width, image.height, 3, bytes.data(), image.width * 3)) return {};
  return png;
}

}  // namespace

int PreviewSheetWidth(const PreviewOptions& options, int frameCount) {
  return std::min(options.columns, KeyFrameCount(options, frameCount)) * options.cellWidth;
}

int PreviewSheetHeight(const PreviewOptions& options, int frameCount) {
  return kTitleHeight + RowCount(options, frameCount) * options.cellHeight;
}

std::string WritePreviewSheet(const Clip& clip, const PreviewOptions& options, const std::string& pngPath) {
  if (std::string problem = clip.Validate(); !problem.empty()) return "cannot draw the clip: " + problem;
  if (options.keyFrames < 1 || options.columns < 1) return "a preview needs at least one frame and one column";
  // Up to 60 deg of slope: steeper ground is a wall, not ground.
  if (!(glm::length(options.groundNormal) > 0.0f) || !(glm::normalize(options.groundNormal).y >= 0.5f)) {
    return "the preview's ground normal must point up, at most 60 deg from +Y";
  }
  if (options.cellWidth < 64 || options.cellHeight < kLabelHeight + 64 || options.cellWidth > 4096 ||
      options.cellHeight > 4096) {
    return "preview cells must be 64 to 4096 pixels wide and " + std::to_string(kLabelHeight + 64) +
           " to 4096 pixels high";
  }
  const int frameCount = clip.FrameCount();
  const int keys = KeyFrameCount(options, frameCount);
  const int columns = std::min(options.columns, keys);
  std::vector<int> keyFrames(keys);
  for (int k = 0; k < keys; ++k)
    keyFrames[k] = keys == 1 ? 0 : int(std::lround(double(k) * (frameCount - 1) / (keys - 1)));

  const std::vector<DrawBox> boxes = BoxesToDraw(clip.skeleton);
  std::vector<glm::vec3> colours;
  for (const DrawBox& box : boxes) colours.push_back(ColourOf(clip.skeleton.joints[box.joint].name));

  // Frame the whole motion (every frame, not only the key frames, so sheets of
  // different key-frame counts agree) with its shadow on the ground.
  const GroundPlane ground = MakeGroundPlane(options);
  Camera camera = MakeCamera(ground);
  glm::vec2 screenMin(std::numeric_limits<float>::max()), screenMax(-std::numeric_limits<float>::max());
  GroundPatch patch{glm::vec2(std::numeric_limits<float>::max()), glm::vec2(-std::numeric_limits<float>::max())};
  std::vector<PosedBoxes> keyPoses;
  for (int f = 0; f < frameCount; ++f) {
    PosedBoxes posed = Pose(clip, boxes, f);
    for (const auto& corners : posed.corners) {
      for (const glm::vec3& p : corners) {
        for (const glm::vec3& q : {p, ground.Below(p)}) {
          const glm::vec2 s(glm::dot(q, camera.right), glm::dot(q, camera.up));
          screenMin = glm::min(screenMin, s);
          screenMax = glm::max(screenMax, s);
        }
        patch = {glm::min(patch.min, ground.Coordinates(p)), glm::max(patch.max, ground.Coordinates(p))};
      }
    }
    if (std::find(keyFrames.begin(), keyFrames.end(), f) != keyFrames.end()) keyPoses.push_back(std::move(posed));
  }
  patch = {patch.min - kGroundPadding, patch.max + kGroundPadding};
  const int drawWidth = options.cellWidth * kSupersample,
            drawHeight = (options.cellHeight - kLabelHeight) * kSupersample;
  const glm::vec2 extent = glm::max(screenMax - screenMin, glm::vec2(0.1f));
  const float margin = kMarginPixels * kSupersample;
  camera.scale = std::min((drawWidth - 2 * margin) / extent.x, (drawHeight - 2 * margin) / extent.y);
  const glm::vec2 centre = 0.5f * (screenMin + screenMax);
  camera.origin = {0.5f * drawWidth - centre.x * camera.scale, 0.5f * drawHeight + centre.y * camera.scale};

  Image sheet(PreviewSheetWidth(options, frameCount), PreviewSheetHeight(options, frameCount), kSkyBottom);
  for (int y = 0; y < kTitleHeight; ++y) {
    for (int x = 0; x < sheet.width; ++x) sheet.At(x, y) = kTitleBand;
  }
  const std::string title =
      options.title.empty()
          ? "RISE-GEN PREVIEW   " + Printf("%.2f S, %.0f FRAMES AT %g FPS", clip.Duration(), frameCount, clip.fps)
          : options.title;
  const int titleTop = (kTitleHeight - kGlyphHeight * kTextScale) / 2;
  DrawText(sheet, 12, titleTop, title, kText, kTextScale);
  // Legend on the right of the title band.
  const std::string legend[2] = {"LEFT", "RIGHT"};
  const glm::vec3 legendColour[2] = {kLeftLimb, kRightLimb};
  int legendX = sheet.width - 12;
  for (int k = 1; k >= 0; --k) {
    legendX -= TextWidth(legend[k], kTextScale);
    DrawText(sheet, legendX, titleTop, legend[k], kText, kTextScale);
    legendX -= 6 + kGlyphHeight * kTextScale;
    for (int y = 0; y < kGlyphHeight * kTextScale; ++y) {
      for (int x = 0; x < kGlyphHeight * kTextScale; ++x) {
        if (legendX + x >= 0) sheet.At(legendX + x, titleTop + y) = legendColour[k];
      }
    }
    legendX -= 16;
  }

  Canvas canvas(drawWidth, drawHeight);
  for (int k = 0; k < keys; ++k) {
    const int cellX = (k % columns) * options.cellWidth, cellY = kTitleHeight + (k / columns) * options.cellHeight;
    canvas.Clear();
    DrawGround(canvas, camera, ground, patch);
    DrawShadows(canvas, camera, ground, keyPoses[k]);
    DrawBody(canvas, camera, keyPoses[k], colours);
    // Box-filter the supersampled cell into the sheet.
    for (int y = 0; y < options.cellHeight - kLabelHeight; ++y) {
      for (int x = 0; x < options.cellWidth; ++x) {
        glm::vec3 sum(0.0f);
        for (int sy = 0; sy < kSupersample; ++sy) {
          for (int sx = 0; sx < kSupersample; ++sx) {
            sum += canvas.colour[canvas.Index(x * kSupersample + sx, y * kSupersample + sy)];
          }
        }
        sheet.At(cellX + x, cellY + y) = sum / float(kSupersample * kSupersample);
      }
    }
    const double time = keyFrames[k] / clip.fps;
    const std::string when = Printf("%.2f S   FRAME %.0f", time, keyFrames[k]);
    const std::string phase = PhaseAt(clip.metadata, time);
    const int labelTop = cellY + options.cellHeight - kLabelHeight + 7;
    DrawText(sheet, cellX + (options.cellWidth - TextWidth(when, kTextScale)) / 2, labelTop, when, kText, kTextScale);
    DrawText(sheet, cellX + (options.cellWidth - TextWidth(phase, kTextScale)) / 2,
             labelTop + (kGlyphHeight + 4) * kTextScale, phase, kSubtleText, kTextScale);
    // Cell borders: right and bottom edges.
    for (int y = cellY; y < cellY + options.cellHeight; ++y) sheet.At(cellX + options.cellWidth - 1, y) = kCellBorder;
    for (int x = cellX; x < cellX + options.cellWidth; ++x) sheet.At(x, cellY + options.cellHeight - 1) = kCellBorder;
  }

  const std::string png = EncodePng(sheet);
  if (png.empty()) return "cannot encode the preview of '" + pngPath + "' as PNG";
  return WriteFileAtomically(pngPath, png);
}

}  // namespace rise
