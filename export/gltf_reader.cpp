// SPDX-License-Identifier: MIT
// glTF 2.0 input through tinygltf (private to this library).
#include "export/gltf_reader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <map>
#include <set>

#include "export/clip_metadata_json.h"
#include "export/joint_names.h"
#include "export/rotation_track.h"

namespace rise {
namespace {

// Element `index` of an accessor as floats (normalised integers scaled to
// [0, 1] or [-1, 1] as the spec says; plain integers as they are).
class AccessorView {
 public:
  AccessorView(const tinygltf::Model& model, int accessorIndex) {
    if (accessorIndex < 0 || accessorIndex >= static_cast<int>(model.accessors.size())) return;
    const tinygltf::Accessor& accessor = model.accessors[accessorIndex];
    if (accessor.bufferView < 0 || accessor.sparse.isSparse) return;
    const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
    const tinygltf::Buffer& buffer = model.buffers[view.buffer];
    components_ = tinygltf::GetNumComponentsInType(accessor.type);
    componentType_ = accessor.componentType;
    componentSize_ = tinygltf::GetComponentSizeInBytes(componentType_);
    normalized_ = accessor.normalized;
    stride_ = view.byteStride != 0 ? view.byteStride : static_cast<size_t>(components_ * componentSize_);
    const size_t start = view.byteOffset + accessor.byteOffset;
    const size_t needed = accessor.count == 0 ? 0 : (accessor.count - 1) * stride_ + components_ * componentSize_;
    if (components_ <= 0 || componentSize_ <= 0 || start + needed > buffer.data.size()) return;
    data_ = buffer.data.data() + start;
    count_ = accessor.count;
  }

  bool Valid() const { return data_ != nullptr; }
  size_t Count() const { return count_; }
  int Components() const { return components_; }

  float Get(size_t index, int component) const {
    const unsigned char* p = data_ + index * stride_ + component * componentSize_;
    switch (componentType_) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return Load<float>(p, 1.0f);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return Load<uint8_t>(p, normalized_ ? 255.0f : 1.0f);
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return std::max(Load<int8_t>(p, normalized_ ? 127.0f : 1.0f), -1.0f);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return Load<uint16_t>(p, normalized_ ? 65535.0f : 1.0f);
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return std::max(Load<int16_t>(p, normalized_ ? 32767.0f : 1.0f), -1.0f);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return Load<uint32_t>(p, 1.0f);
      default:
        return 0.0f;
    }
  }

 private:
  template <typename T>
  static float Load(const unsigned char* p, float divisor) {
    T value;
    std::memcpy(&value, p, sizeof(T));
    return static_cast<float>(value) / divisor;
  }

  const unsigned char* data_ = nullptr;
  size_t count_ = 0;
  size_t stride_ = 0;
  int components_ = 0;
  int componentType_ = 0;
  int componentSize_ = 0;
  bool normalized_ = false;
};

struct Trs {
  glm::vec3 t{0.0f};
  glm::quat r{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 s{1.0f};

  glm::mat4 Matrix() const {
    return glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
  }
};

Trs RestTrs(const tinygltf::Node& node) {
  Trs trs;
  if (node.matrix.size() == 16) {
    // Decomposed once; animated nodes must use TRS per the spec anyway.
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(node.matrix[i]);
    trs.t = glm::vec3(m[3]);
    trs.s = glm::vec3(glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2])));
    trs.r = glm::quat_cast(glm::mat3(glm::vec3(m[0]) / trs.s.x, glm::vec3(m[1]) / trs.s.y, glm::vec3(m[2]) / trs.s.z));
    return trs;
  }
  if (node.translation.size() == 3) trs.t = glm::vec3(node.translation[0], node.translation[1], node.translation[2]);
  if (node.rotation.size() == 4) {
    trs.r = glm::normalize(glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                                     static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2])));
  }
  if (node.scale.size() == 3) trs.s = glm::vec3(node.scale[0], node.scale[1], node.scale[2]);
  return trs;
}

glm::quat RotationOf(const glm::mat4& m) {
  return glm::normalize(glm::quat_cast(
      glm::mat3(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])), glm::normalize(glm::vec3(m[2])))));
}

// One animated property of one joint.
struct Track {
  int joint = -1;
  enum Path { kTranslation, kRotation, kScale } path = kTranslation;
  std::vector<float> times;
  std::vector<glm::vec4> values;  // xyz(w)
  bool step = false;

  glm::vec4 Sample(float t) const {
    if (t <= times.front()) return values.front();
    if (t >= times.back()) return values.back();
    const size_t hi = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
    const size_t lo = hi - 1;
    if (step) return values[lo];
    const float a = (t - times[lo]) / (times[hi] - times[lo]);
    if (path != kRotation) return glm::mix(values[lo], values[hi], a);
    const glm::quat q0(values[lo].w, values[lo].x, values[lo].y, values[lo].z);
    const glm::quat q1 = ContinueRotationTrack(glm::quat(values[hi].w, values[hi].x, values[hi].y, values[hi].z), q0);
    const glm::quat q = glm::slerp(q0, q1, a);
    return glm::vec4(q.x, q.y, q.z, q.w);
  }
};

std::string ReadTracks(const tinygltf::Model& model, const tinygltf::Animation& animation,
                       const std::map<int, int>& jointOfNode, std::vector<Track>& tracks) {
  for (const tinygltf::AnimationChannel& channel : animation.channels) {
    const auto joint = jointOfNode.find(channel.target_node);
    if (joint == jointOfNode.end()) continue;
    Track track;
    track.joint = joint->second;
    if (channel.target_path == "translation")
      track.path = Track::kTranslation;
    else if (channel.target_path == "rotation")
      track.path = Track::kRotation;
    else if (channel.target_path == "scale")
      track.path = Track::kScale;
    else
      continue;
    if (channel.sampler < 0 || channel.sampler >= static_cast<int>(animation.samplers.size())) {
      return "an animation channel names a missing sampler";
    }
    const tinygltf::AnimationSampler& sampler = animation.samplers[channel.sampler];
    const AccessorView input(model, sampler.input), output(model, sampler.output);
    if (!input.Valid() || !output.Valid() || input.Count() == 0) return "an animation sampler has unreadable data";
    const bool cubic = sampler.interpolation == "CUBICSPLINE";
    track.step = sampler.interpolation == "STEP";
    if (output.Count() != input.Count() * (cubic ? 3 : 1))
      return "an animation sampler's output does not match its input";
    for (size_t k = 0; k < input.Count(); ++k) {
      track.times.push_back(input.Get(k, 0));
      // A cubic spline stores (in-tangent, value, out-tangent) per key.
      const size_t element = cubic ? 3 * k + 1 : k;
      glm::vec4 value(0.0f);
      for (int c = 0; c < std::min(output.Components(), 4); ++c) value[c] = output.Get(element, c);
      track.values.push_back(value);
    }
    tracks.push_back(std::move(track));
  }
  return {};
}

// Frame rate from key spacing: the median step of the densest track.
double EstimateFps(const std::vector<Track>& tracks) {
  const Track* densest = nullptr;
  for (const Track& track : tracks) {
    if (densest == nullptr || track.times.size() > densest->times.size()) densest = &track;
  }
  if (densest == nullptr || densest->times.size() < 2) return 30.0;
  std::vector<float> steps;
  for (size_t k = 1; k < densest->times.size(); ++k) steps.push_back(densest->times[k] - densest->times[k - 1]);
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  const double fps = 1.0 / steps[steps.size() / 2];
  const double whole = std::round(fps);
  return std::fabs(fps - whole) <= 0.005 * whole ? whole : fps;
}

}  // namespace

std::string ReadGltf(const std::string& path, Clip& clip) {
  const auto fail = [&](const std::string& what) { return "cannot read glTF '" + path + "': " + what; };
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  loader.SetStoreOriginalJSONForExtrasAndExtensions(true);
  std::string error, warning;
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  const bool loaded = ext == ".glb" ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                                    : loader.LoadASCIIFromFile(&model, &error, &warning, path);
  if (!loaded) return fail(error.empty() ? "tinygltf could not load it" : error);
  if (model.skins.empty()) return fail("it has no skin (no skeleton)");
  const tinygltf::Skin& skin = model.skins[0];
  if (skin.joints.empty()) return fail("its skin has no joints");

  // Parents of all nodes, then the skin's root joint(s).
  std::vector<int> parentOf(model.nodes.size(), -1);
  for (size_t n = 0; n < model.nodes.size(); ++n) {
    for (int child : model.nodes[n].children) {
      if (child >= 0 && child < static_cast<int>(model.nodes.size())) parentOf[child] = static_cast<int>(n);
    }
  }
  const std::set<int> jointNodes(skin.joints.begin(), skin.joints.end());
  std::vector<int> roots;
  for (int node : skin.joints) {
    if (node < 0 || node >= static_cast<int>(model.nodes.size())) return fail("a skin joint names a missing node");
    if (jointNodes.count(parentOf[node]) == 0) roots.push_back(node);
  }
  if (roots.size() != 1) return fail("its skin has " + std::to_string(roots.size()) + " root joints; one is needed");

  // Joints parents-first (depth-first from the root), with their nodes.
  std::vector<int> nodeOfJoint;
  std::vector<int> parentJoint;
  std::map<int, int> jointOfNode;
  std::vector<std::pair<int, int>> stack = {{roots[0], -1}};
  while (!stack.empty()) {
    const auto [node, parent] = stack.back();
    stack.pop_back();
    // A node listed twice (a malformed file with a cycle) is visited once.
    if (jointOfNode.count(node)) return fail("its node hierarchy has a cycle or a node with two parents");
    jointOfNode[node] = static_cast<int>(nodeOfJoint.size());
    nodeOfJoint.push_back(node);
    parentJoint.push_back(parent);
    const std::vector<int>& children = model.nodes[node].children;
    for (auto it = children.rbegin(); it != children.rend(); ++it) {
      if (jointNodes.count(*it)) stack.push_back({*it, jointOfNode[node]});
    }
  }
  const int count = static_cast<int>(nodeOfJoint.size());

  // The static transform above the root joint (armature node etc.).
  glm::mat4 above(1.0f);
  size_t depth = 0;
  for (int n = parentOf[roots[0]]; n >= 0; n = parentOf[n]) {
    if (++depth > model.nodes.size()) return fail("its node hierarchy has a cycle");
    above = RestTrs(model.nodes[n]).Matrix() * above;
  }

  // World matrices of every joint for local TRS `pose`.
  std::vector<glm::mat4> world(count);
  const auto forward = [&](const std::vector<Trs>& pose) {
    for (int j = 0; j < count; ++j) world[j] = (parentJoint[j] < 0 ? above : world[parentJoint[j]]) * pose[j].Matrix();
  };
  std::vector<Trs> rest(count);
  for (int j = 0; j < count; ++j) rest[j] = RestTrs(model.nodes[nodeOfJoint[j]]);
  forward(rest);
  std::vector<glm::mat4> restWorld = world;
  std::vector<glm::quat> bindRotationInverse(count);
  for (int j = 0; j < count; ++j) bindRotationInverse[j] = glm::inverse(RotationOf(restWorld[j]));

  Clip out;
  out.skeleton.joints.resize(count);
  std::vector<std::string> canonical;
  std::set<std::string> distinct;
  for (int j = 0; j < count; ++j) {
    SkeletonJoint& joint = out.skeleton.joints[j];
    joint.name =
        model.nodes[nodeOfJoint[j]].name.empty() ? "joint_" + std::to_string(j) : model.nodes[nodeOfJoint[j]].name;
    joint.parent = parentJoint[j];
    const glm::vec3 position(restWorld[j][3]);
    joint.restOffset = joint.parent < 0 ? position : position - glm::vec3(restWorld[joint.parent][3]);
    if (std::optional<std::string> name = CanonicalJointName(joint.name)) {
      canonical.push_back(*name);
      distinct.insert(*name);
    }
  }
  if (static_cast<int>(distinct.size()) == count && static_cast<int>(canonical.size()) == count) {
    for (int j = 0; j < count; ++j) out.skeleton.joints[j].name = canonical[j];
  }

  // Bone boxes from the skinned mesh through the inverse bind matrices.
  const AccessorView inverseBinds(model, skin.inverseBindMatrices);
  std::map<int, int> skinToJoint;
  for (size_t k = 0; k < skin.joints.size(); ++k) skinToJoint[static_cast<int>(k)] = jointOfNode[skin.joints[k]];
  std::vector<glm::vec3> lo(count, glm::vec3(1e30f)), hi(count, glm::vec3(-1e30f));
  for (const tinygltf::Node& node : model.nodes) {
    if (node.mesh < 0 || node.skin != 0 || node.mesh >= static_cast<int>(model.meshes.size())) continue;
    for (const tinygltf::Primitive& primitive : model.meshes[node.mesh].primitives) {
      const auto attribute = [&](const char* name) {
        const auto it = primitive.attributes.find(name);
        return AccessorView(model, it == primitive.attributes.end() ? -1 : it->second);
      };
      const AccessorView positions = attribute("POSITION"), joints = attribute("JOINTS_0"),
                         weights = attribute("WEIGHTS_0");
      if (!positions.Valid() || !joints.Valid() || !weights.Valid()) continue;
      for (size_t v = 0; v < positions.Count() && v < joints.Count() && v < weights.Count(); ++v) {
        int best = 0;
        for (int c = 1; c < 4; ++c) best = weights.Get(v, c) > weights.Get(v, best) ? c : best;
        const int skinJoint = static_cast<int>(joints.Get(v, best));
        const auto found = skinToJoint.find(skinJoint);
        if (found == skinToJoint.end()) continue;
        const int j = found->second;
        glm::mat4 inverseBind(1.0f);
        if (inverseBinds.Valid() && static_cast<size_t>(skinJoint) < inverseBinds.Count()) {
          for (int i = 0; i < 16; ++i) glm::value_ptr(inverseBind)[i] = inverseBinds.Get(skinJoint, i);
        }
        // Mesh space -> joint node space -> world at rest. Our joint frame is
        // the world's axes at the joint (its rest rotation removed), so the
        // box coordinates are plain world offsets from the joint.
        const glm::vec4 mesh(positions.Get(v, 0), positions.Get(v, 1), positions.Get(v, 2), 1.0f);
        const glm::vec3 worldPoint(restWorld[j] * (inverseBind * mesh));
        const glm::vec3 local = worldPoint - glm::vec3(restWorld[j][3]);
        lo[j] = glm::min(lo[j], local);
        hi[j] = glm::max(hi[j], local);
      }
    }
  }
  for (int j = 0; j < count; ++j) {
    if (lo[j].x > hi[j].x) continue;
    SkeletonJoint& joint = out.skeleton.joints[j];
    joint.hasBox = true;
    joint.box.center = 0.5f * (lo[j] + hi[j]);
    joint.box.halfExtents = 0.5f * (hi[j] - lo[j]);
  }

  // Motion: sample the first animation at its own frame rate.
  std::vector<Track> tracks;
  if (!model.animations.empty()) {
    if (std::string problem = ReadTracks(model, model.animations[0], jointOfNode, tracks); !problem.empty()) {
      return fail(problem);
    }
    // Only rise-gen's own extras follow our metadata document.
    const std::string& extras = model.animations[0].extras_json_string;
    if (!extras.empty() && model.asset.generator.rfind("rise-gen", 0) == 0) {
      if (std::string problem = MetadataFromJson(extras, out.metadata); !problem.empty()) return fail(problem);
    }
  }
  float start = tracks.empty() ? 0.0f : tracks[0].times.front();
  float end = start;
  for (const Track& track : tracks) {
    start = std::min(start, track.times.front());
    end = std::max(end, track.times.back());
  }
  out.fps = EstimateFps(tracks);
  const int frames = static_cast<int>(std::lround((end - start) * out.fps)) + 1;
  out.rootTranslation.resize(frames);
  out.rotations.assign(count, std::vector<glm::quat>(frames));
  std::vector<std::vector<glm::vec3>> translations(count, std::vector<glm::vec3>(frames));
  std::vector<bool> translationMoves(count, false);
  for (int f = 0; f < frames; ++f) {
    const float t = std::min(start + static_cast<float>(f / out.fps), end);
    std::vector<Trs> pose = rest;
    for (const Track& track : tracks) {
      const glm::vec4 value = track.Sample(t);
      if (track.path == Track::kTranslation) pose[track.joint].t = glm::vec3(value);
      if (track.path == Track::kRotation)
        pose[track.joint].r = glm::normalize(glm::quat(value.w, value.x, value.y, value.z));
      if (track.path == Track::kScale) pose[track.joint].s = glm::vec3(value);
    }
    forward(pose);
    // Our joint frame = node frame with its rest world rotation removed.
    std::vector<glm::quat> ours(count);
    for (int j = 0; j < count; ++j) {
      ours[j] = RotationOf(world[j]) * bindRotationInverse[j];
      const int parent = parentJoint[j];
      if (parent < 0) {
        out.rootTranslation[f] = glm::vec3(world[j][3]);
        out.rotations[j][f] = ours[j];
        continue;
      }
      out.rotations[j][f] = glm::inverse(ours[parent]) * ours[j];
      translations[j][f] = glm::inverse(ours[parent]) * (glm::vec3(world[j][3]) - glm::vec3(world[parent][3]));
      if (glm::length(translations[j][f] - out.skeleton.joints[j].restOffset) > 1e-4f) translationMoves[j] = true;
    }
  }
  for (std::vector<glm::quat>& track : out.rotations) MakeRotationTrackContinuous(track);
  if (std::find(translationMoves.begin(), translationMoves.end(), true) != translationMoves.end()) {
    out.translations.assign(count, {});
    for (int j = 1; j < count; ++j) {
      if (translationMoves[j]) out.translations[j] = std::move(translations[j]);
    }
  }
  clip = std::move(out);
  return {};
}

}  // namespace rise
