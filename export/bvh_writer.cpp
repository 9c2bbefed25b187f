// SPDX-License-Identifier: MIT
// BVH output (hierarchy + ZXY Euler motion).
#include "export/bvh_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <glm/gtc/matrix_access.hpp>
#include <glm/mat3x3.hpp>

#include "base/assert.h"
#include "export/atomic_file.h"
#include "export/clip_metadata_json.h"
#include "export/rotation_track.h"

namespace rise {
namespace {

constexpr float kPi = 3.14159265358979323846f;

struct Layout {
  std::vector<std::vector<int>> children;
  std::vector<int> endSiteOf;  // joint -> the leaf joint written as its End Site, or -1
  std::vector<bool> isEndSite;
  std::vector<int> order;  // written joints in HIERARCHY (depth-first) order
};

Layout MakeLayout(const Clip& clip) {
  const Skeleton& skeleton = clip.skeleton;
  const int count = skeleton.JointCount();
  Layout layout;
  layout.children.resize(count);
  layout.endSiteOf.assign(count, -1);
  layout.isEndSite.assign(count, false);
  for (int j = 1; j < count; ++j) layout.children[skeleton.joints[j].parent].push_back(j);
  for (int j = 1; j < count; ++j) {
    const int parent = skeleton.joints[j].parent;
    const bool movesAlone = !clip.translations.empty() && !clip.translations[j].empty();
    if (layout.children[j].empty() && !skeleton.joints[j].hasBox && !movesAlone &&
        layout.children[parent].size() == 1) {
      layout.endSiteOf[parent] = j;
      layout.isEndSite[j] = true;
    }
  }
  std::vector<int> stack = {0};
  while (!stack.empty()) {
    const int j = stack.back();
    stack.pop_back();
    layout.order.push_back(j);
    const std::vector<int>& kids = layout.children[j];
    for (auto it = kids.rbegin(); it != kids.rend(); ++it) {
      if (!layout.isEndSite[*it]) stack.push_back(*it);
    }
  }
  return layout;
}

bool HasPositionChannels(const Clip& clip, int joint) {
  return joint == 0 || (!clip.translations.empty() && !clip.translations[joint].empty());
}

void Append(std::string& out, float value) {
  char buffer[32];
  // 7 significant digits: 1 um at 1 m, 1e-4 degree at 100 degrees.
  // Adding +0 turns -0 into 0, which reads better and compares equal in text.
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value + 0.0f, std::chars_format::general, 7);
  out.append(buffer, result.ptr);
}

void AppendVec(std::string& out, const glm::vec3& v) {
  Append(out, v.x);
  out += ' ';
  Append(out, v.y);
  out += ' ';
  Append(out, v.z);
}

void WriteJoint(const Clip& clip, const Layout& layout, const BvhOptions& options, int j, int depth, std::string& out) {
  const std::string indent(2 * depth, ' ');
  const SkeletonJoint& joint = clip.skeleton.joints[j];
  const glm::vec3 offset = options.format.ToFile(joint.restOffset);
  out += indent + (j == 0 ? "ROOT " : "JOINT ") + PresetJointName(options.naming, joint.name) + "\n";
  out += indent + "{\n" + indent + "  OFFSET ";
  AppendVec(out, offset);
  out += HasPositionChannels(clip, j)
             ? "\n" + indent + "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
             : "\n" + indent + "  CHANNELS 3 Zrotation Xrotation Yrotation\n";
  bool wroteChild = false;
  for (int child : layout.children[j]) {
    if (layout.isEndSite[child]) continue;
    WriteJoint(clip, layout, options, child, depth + 1, out);
    wroteChild = true;
  }
  if (!wroteChild) {
    // BVH ends every chain with an End Site; without an end joint, the box's
    // far side along its centre gives the bone a plausible length.
    const int end = layout.endSiteOf[j];
    const glm::vec3 tip = end >= 0 ? clip.skeleton.joints[end].restOffset : 2.0f * joint.box.center;
    out += indent + "  End Site\n" + indent + "  {\n" + indent + "    OFFSET ";
    AppendVec(out, options.format.ToFile(tip));
    out += "\n" + indent + "  }\n";
  }
  out += indent + "}\n";
}

// R = Rz(z) Rx(x) Ry(y): the two Euler solutions, the one nearer `previous`
// (after moving each angle by whole turns towards it) wins.
glm::vec3 EulerZxy(const glm::quat& q, const glm::vec3& previous) {
  const glm::mat3 m = glm::mat3_cast(q);  // m[column][row]
  const float x = std::asin(std::clamp(m[1][2], -1.0f, 1.0f));
  const float z = std::atan2(-m[1][0], m[1][1]);
  const float y = std::atan2(-m[0][2], m[2][2]);
  const auto near = [](float angle, float reference) {
    return reference + std::remainder(angle - reference, 2.0f * kPi);
  };
  const glm::vec3 a(near(x, previous.x), near(y, previous.y), near(z, previous.z));
  const glm::vec3 b(near(kPi - x, previous.x), near(y + kPi, previous.y), near(z + kPi, previous.z));
  const glm::vec3 da = a - previous, db = b - previous;
  return glm::dot(da, da) <= glm::dot(db, db) ? a : b;
}

}  // namespace

std::string FormatBvh(const Clip& clip, const BvhOptions& options) {
  RISE_ASSERT_MSG(clip.Validate().empty(), "writing an invalid clip");
  const Layout layout = MakeLayout(clip);

  std::string out;
  out.reserve(256 * clip.skeleton.joints.size() + static_cast<size_t>(clip.FrameCount()) * layout.order.size() * 30);
  out += "HIERARCHY\n";
  WriteJoint(clip, layout, options, 0, 0, out);
  out += "MOTION\nFrames: " + std::to_string(clip.FrameCount()) + "\nFrame Time: ";
  {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), 1.0 / clip.fps, std::chars_format::general, 9);
    out.append(buffer, result.ptr);
  }
  out += '\n';

  // Rotations and position channels are converted to the file's axes like
  // offsets. Euler angles continue from the previous frame.
  std::vector<glm::vec3> previousEuler(clip.skeleton.joints.size(), glm::vec3(0.0f));
  std::vector<glm::quat> previousKey(clip.skeleton.joints.size(), glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
  for (int f = 0; f < clip.FrameCount(); ++f) {
    bool first = true;
    for (int j : layout.order) {
      if (!first) out += ' ';
      first = false;
      if (HasPositionChannels(clip, j)) {
        AppendVec(out, options.format.ToFile(clip.LocalTranslation(j, f)));
        out += ' ';
      }
      previousKey[j] = ContinueRotationTrack(clip.rotations[j][f], previousKey[j]);
      const glm::vec3 euler = EulerZxy(options.format.AxesToFile(previousKey[j]), previousEuler[j]);
      previousEuler[j] = euler;
      AppendVec(out, glm::vec3(glm::degrees(euler.z), glm::degrees(euler.x), glm::degrees(euler.y)));
    }
    out += '\n';
  }
  return out;
}

std::string WriteBvh(const Clip& clip, const std::string& path, const BvhOptions& options) {
  if (std::string error = WriteFileAtomically(path, FormatBvh(clip, options)); !error.empty()) return error;
  return options.writeSidecar ? WriteMetadataSidecar(clip, path) : std::string();
}

}  // namespace rise
