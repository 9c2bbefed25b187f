// SPDX-License-Identifier: MIT
// glTF 2.0 output through tinygltf (private to this library).
#include "export/gltf_writer.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/assert.h"
#include "export/atomic_file.h"
#include "export/clip_metadata_json.h"
#include "export/rotation_track.h"

namespace rise {
namespace {

constexpr int kArrayBuffer = TINYGLTF_TARGET_ARRAY_BUFFER;
constexpr int kElementArrayBuffer = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
constexpr int kNoTarget = 0;

// Appends typed arrays to buffer 0 and describes them with bufferViews and
// accessors. Views start on 4-byte boundaries, as accessors require.
class BufferBuilder {
 public:
  explicit BufferBuilder(tinygltf::Model& model) : model_(model) {
    if (model_.buffers.empty()) model_.buffers.emplace_back();
  }

  template <typename T>
  int AddAccessor(const std::vector<T>& values, int componentType, int type, size_t count, int target,
                  std::vector<double> min = {}, std::vector<double> max = {}) {
    std::vector<unsigned char>& data = model_.buffers[0].data;
    data.resize((data.size() + 3) & ~size_t{3}, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = values.size() * sizeof(T);
    if (target != kNoTarget) view.target = target;
    data.resize(data.size() + view.byteLength);
    std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
    model_.bufferViews.push_back(view);

    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model_.bufferViews.size()) - 1;
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    accessor.minValues = std::move(min);
    accessor.maxValues = std::move(max);
    model_.accessors.push_back(accessor);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

 private:
  tinygltf::Model& model_;
};

// tinygltf's extras are its own Value type; the metadata is built as JSON.
tinygltf::Value ToValue(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      tinygltf::Value::Object object;
      for (const auto& [key, value] : j.items()) object.emplace(key, ToValue(value));
      return tinygltf::Value(std::move(object));
    }
    case nlohmann::json::value_t::array: {
      tinygltf::Value::Array array;
      for (const auto& value : j) array.push_back(ToValue(value));
      return tinygltf::Value(std::move(array));
    }
    case nlohmann::json::value_t::string:
      return tinygltf::Value(j.get<std::string>());
    case nlohmann::json::value_t::boolean:
      return tinygltf::Value(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned: {
      // tinygltf integers are `int`; larger ones (a big seed) travel as double,
      // exact up to 2^53.
      const double value = j.get<double>();
      if (value >= INT_MIN && value <= INT_MAX) return tinygltf::Value(j.get<int>());
      return tinygltf::Value(value);
    }
    case nlohmann::json::value_t::number_float:
      return tinygltf::Value(j.get<double>());
    default:
      return tinygltf::Value();
  }
}

bool SameSkeleton(const Skeleton& a, const Skeleton& b) {
  if (a.JointCount() != b.JointCount()) return false;
  for (int j = 0; j < a.JointCount(); ++j) {
    const SkeletonJoint& x = a.joints[j];
    const SkeletonJoint& y = b.joints[j];
    if (x.name != y.name || x.parent != y.parent || x.restOffset != y.restOffset || x.hasBox != y.hasBox ||
        x.box.center != y.box.center || x.box.halfExtents != y.box.halfExtents) {
      return false;
    }
  }
  return true;
}

// Nodes 0..J-1 are the joints (node index = joint index), in rest pose = bind pose.
void AddJointNodes(const Skeleton& skeleton, NamingPreset naming, tinygltf::Model& model) {
  for (const SkeletonJoint& joint : skeleton.joints) {
    tinygltf::Node node;
    node.name = PresetJointName(naming, joint.name);
    node.translation = {joint.restOffset.x, joint.restOffset.y, joint.restOffset.z};
    model.nodes.push_back(node);
  }
  for (int j = 1; j < skeleton.JointCount(); ++j) model.nodes[skeleton.joints[j].parent].children.push_back(j);
}

// One box per bone in bind-pose world space, each face with its own four
// vertices so that normals are flat.
void AddSkinnedBoxMesh(const Skeleton& skeleton, BufferBuilder& buffers, tinygltf::Model& model) {
  struct Face {
    glm::vec3 n, u, v;  // u x v = n, so (-,-) (+,-) (+,+) (-,+) winds counter-clockwise from outside
  };
  static const Face kFaces[6] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}}, {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},
      {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
  };
  static const float kCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

  const std::vector<glm::vec3> bind = skeleton.BindPositions();
  std::vector<float> positions, normals, weights;
  std::vector<unsigned short> joints, indices;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (int j = 0; j < skeleton.JointCount(); ++j) {
    const SkeletonJoint& joint = skeleton.joints[j];
    if (!joint.hasBox) continue;
    const glm::vec3 center = bind[j] + joint.box.center;
    const glm::vec3 h = joint.box.halfExtents;
    for (const Face& face : kFaces) {
      const unsigned short base = static_cast<unsigned short>(positions.size() / 3);
      for (const auto& c : kCorner) {
        const glm::vec3 p = center + face.n * h + face.u * (c[0] * h) + face.v * (c[1] * h);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
        positions.insert(positions.end(), {p.x, p.y, p.z});
        normals.insert(normals.end(), {face.n.x, face.n.y, face.n.z});
        joints.insert(joints.end(), {static_cast<unsigned short>(j), 0, 0, 0});
        weights.insert(weights.end(), {1.0f, 0.0f, 0.0f, 0.0f});
      }
      indices.insert(indices.end(),
                     {base, static_cast<unsigned short>(base + 1), static_cast<unsigned short>(base + 2), base,
                      static_cast<unsigned short>(base + 2), static_cast<unsigned short>(base + 3)});
    }
  }
  RISE_ASSERT_MSG(!positions.empty(), "the skeleton has no bone boxes to skin");
  RISE_ASSERT_MSG(positions.size() / 3 <= 65535, "too many bone boxes for 16-bit indices");
  const size_t vertexCount = positions.size() / 3;

  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = 0;
  primitive.attributes["POSITION"] =
      buffers.AddAccessor(positions, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertexCount, kArrayBuffer,
                          {lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z});
  primitive.attributes["NORMAL"] =
      buffers.AddAccessor(normals, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertexCount, kArrayBuffer);
  primitive.attributes["JOINTS_0"] = buffers.AddAccessor(joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                                         TINYGLTF_TYPE_VEC4, vertexCount, kArrayBuffer);
  primitive.attributes["WEIGHTS_0"] =
      buffers.AddAccessor(weights, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, vertexCount, kArrayBuffer);
  primitive.indices = buffers.AddAccessor(indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR,
                                          indices.size(), kElementArrayBuffer);
  tinygltf::Mesh mesh;
  mesh.name = "body";
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);

  tinygltf::Material material;
  material.name = "body";
  material.pbrMetallicRoughness.baseColorFactor = {0.72, 0.74, 0.78, 1.0};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.8;
  model.materials.push_back(material);
}

void AddSkin(const Skeleton& skeleton, BufferBuilder& buffers, tinygltf::Model& model) {
  // Bind frames are aligned with the world axes, so each inverse bind matrix
  // is a pure translation by minus the joint's bind position (column-major).
  const std::vector<glm::vec3> bind = skeleton.BindPositions();
  std::vector<float> matrices;
  matrices.reserve(bind.size() * 16);
  for (const glm::vec3& p : bind) {
    matrices.insert(matrices.end(), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -p.x, -p.y, -p.z, 1});
  }
  tinygltf::Skin skin;
  skin.name = "skeleton";
  skin.skeleton = 0;
  for (int j = 0; j < skeleton.JointCount(); ++j) skin.joints.push_back(j);
  skin.inverseBindMatrices =
      buffers.AddAccessor(matrices, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_MAT4, bind.size(), kNoTarget);
  model.skins.push_back(skin);
}

void AddChannel(tinygltf::Animation& animation, int input, int output, int node, const char* path) {
  tinygltf::AnimationSampler sampler;
  sampler.input = input;
  sampler.output = output;
  sampler.interpolation = "LINEAR";
  animation.samplers.push_back(sampler);
  tinygltf::AnimationChannel channel;
  channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
  channel.target_node = node;
  channel.target_path = path;
  animation.channels.push_back(channel);
}

void AddAnimation(const std::string& name, const Clip& clip, BufferBuilder& buffers, tinygltf::Model& model) {
  const int frames = clip.FrameCount();
  tinygltf::Animation animation;
  animation.name = name;

  std::vector<float> times(frames);
  for (int f = 0; f < frames; ++f) times[f] = static_cast<float>(f / clip.fps);
  const int input = buffers.AddAccessor(times, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR, frames, kNoTarget,
                                        {0.0}, {times.back()});

  std::vector<float> values;
  const auto addTranslations = [&](const std::vector<glm::vec3>& track, int node) {
    values.clear();
    for (const glm::vec3& t : track) values.insert(values.end(), {t.x, t.y, t.z});
    AddChannel(animation, input,
               buffers.AddAccessor(values, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, frames, kNoTarget), node,
               "translation");
  };
  addTranslations(clip.rootTranslation, 0);
  for (int j = 1; j < static_cast<int>(clip.translations.size()); ++j) {
    if (!clip.translations[j].empty()) addTranslations(clip.translations[j], j);
  }
  for (int j = 0; j < clip.skeleton.JointCount(); ++j) {
    values.clear();
    glm::quat previous(1.0f, 0.0f, 0.0f, 0.0f);
    for (const glm::quat& key : clip.rotations[j]) {
      previous = ContinueRotationTrack(key, previous);
      values.insert(values.end(), {previous.x, previous.y, previous.z, previous.w});
    }
    AddChannel(animation, input,
               buffers.AddAccessor(values, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, frames, kNoTarget), j,
               "rotation");
  }
  animation.extras = ToValue(nlohmann::json::parse(MetadataToJson(clip)));
  model.animations.push_back(animation);
}

enum class Container { kGlb, kGltf, kUnknown };

Container ContainerOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".glb") return Container::kGlb;
  if (ext == ".gltf") return Container::kGltf;
  return Container::kUnknown;
}

std::string Save(tinygltf::Model& model, const std::string& path, Container container) {
  tinygltf::TinyGLTF gltf;
  std::ostringstream out;
  if (container == Container::kGlb) {
    gltf.WriteGltfSceneToStream(&model, out, false, true);
    return WriteFileAtomically(path, out.str());
  }
  // tinygltf embeds buffers as data URIs when writing to a stream; an external
  // .bin is what artists expect, so the buffer entry is written here instead.
  const std::filesystem::path binPath = std::filesystem::path(path).replace_extension(".bin");
  std::vector<unsigned char> bin = std::move(model.buffers[0].data);
  model.buffers.clear();
  gltf.WriteGltfSceneToStream(&model, out, true, false);
  nlohmann::json doc = nlohmann::json::parse(out.str());
  doc["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}, {"uri", binPath.filename().string()}}});
  if (std::string error =
          WriteFileAtomically(binPath.string(), {reinterpret_cast<const char*>(bin.data()), bin.size()});
      !error.empty()) {
    return error;
  }
  if (std::string error = WriteFileAtomically(path, doc.dump(2)); !error.empty()) {
    std::filesystem::remove(binPath);
    return error;
  }
  return {};
}

std::string WriteModel(const std::vector<NamedClip>& clips, const std::string& path, const GltfOptions& options) {
  RISE_ASSERT_MSG(!clips.empty(), "nothing to write");
  const Container container = ContainerOf(path);
  if (container == Container::kUnknown) {
    return "cannot write '" + path + "': the file name must end in .glb or .gltf";
  }
  const Skeleton& skeleton = clips[0].clip->skeleton;
  for (const NamedClip& entry : clips) {
    RISE_ASSERT(entry.clip != nullptr);
    RISE_ASSERT_MSG(entry.clip->Validate().empty(), "writing an invalid clip");
    if (!SameSkeleton(skeleton, entry.clip->skeleton)) {
      return "cannot write '" + path + "': clip '" + entry.name + "' has a different skeleton than '" + clips[0].name +
             "'; one file holds one skeleton";
    }
  }

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = std::string("rise-gen ") + RISE_VERSION;
  BufferBuilder buffers(model);
  AddJointNodes(skeleton, options.naming, model);
  AddSkinnedBoxMesh(skeleton, buffers, model);
  AddSkin(skeleton, buffers, model);

  tinygltf::Node meshNode;
  meshNode.name = "body";
  meshNode.mesh = 0;
  meshNode.skin = 0;
  model.nodes.push_back(meshNode);
  tinygltf::Scene scene;
  scene.name = "rise";
  scene.nodes = {0, static_cast<int>(model.nodes.size()) - 1};
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  for (const NamedClip& entry : clips) AddAnimation(entry.name, *entry.clip, buffers, model);
  return Save(model, path, container);
}

}  // namespace

std::string WriteGltf(const Clip& clip, const std::string& path, const GltfOptions& options) {
  const std::string name = std::filesystem::path(path).stem().string();
  if (std::string error = WriteModel({{name.empty() ? "rise" : name, &clip}}, path, options); !error.empty()) {
    return error;
  }
  return options.writeSidecar ? WriteMetadataSidecar(clip, path) : std::string();
}

std::string WriteGltfLibrary(const std::vector<NamedClip>& clips, const std::string& path, const GltfOptions& options) {
  return WriteModel(clips, path, options);
}

}  // namespace rise
