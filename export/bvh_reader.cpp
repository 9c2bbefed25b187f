// SPDX-License-Identifier: MIT
// A small BVH reader returning world joint positions per frame.
#include "export/bvh_reader.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <sstream>

namespace rise {
namespace {

enum class Channel { kXPos, kYPos, kZPos, kXRot, kYRot, kZRot };

struct Node {
  int parent = -1;
  glm::vec3 offset{0.0f};
  std::vector<Channel> channels;
};

class Tokens {
 public:
  explicit Tokens(const std::string& text) : text_(text) {}
  // The next whitespace-separated token, or "" at the end.
  std::string_view Next() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    const size_t start = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return std::string_view(text_).substr(start, pos_ - start);
  }
  // A number token that a float can hold (offsets and channel values become floats).
  bool Number(double& value) {
    const std::string token(Next());
    if (token.empty()) return false;
    char* end = nullptr;
    value = std::strtod(token.c_str(), &end);
    return end == token.c_str() + token.size() && std::isfinite(value) &&
           std::fabs(value) <= std::numeric_limits<float>::max();
  }
  // A whole number from 0 to max.
  bool Count(double max, double& value) {
    return Number(value) && value >= 0 && value <= max && value == std::floor(value);
  }
  // How many tokens are left, without reading them.
  size_t Remaining() const {
    Tokens rest = *this;
    size_t count = 0;
    while (!rest.Next().empty()) ++count;
    return count;
  }

 private:
  const std::string& text_;
  size_t pos_ = 0;
};

bool ParseChannel(std::string_view name, Channel& channel) {
  static const std::pair<std::string_view, Channel> kNames[] = {
      {"Xposition", Channel::kXPos}, {"Yposition", Channel::kYPos}, {"Zposition", Channel::kZPos},
      {"Xrotation", Channel::kXRot}, {"Yrotation", Channel::kYRot}, {"Zrotation", Channel::kZRot}};
  for (const auto& [text, value] : kNames) {
    if (name == text) {
      channel = value;
      return true;
    }
  }
  return false;
}

}  // namespace

int BvhMotion::Find(const std::string& name) const {
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::string ParseBvh(const std::string& text, const BvhFormat& format, const std::string& source, BvhMotion& motion) {
  const auto fail = [&](const std::string& what) { return "cannot read BVH '" + source + "': " + what; };
  Tokens tokens(text);
  if (tokens.Next() != "HIERARCHY") return fail("it does not start with HIERARCHY");

  BvhMotion out;
  std::vector<Node> nodes;
  std::vector<int> open;  // the joints whose block is not closed yet
  int pending = -1;       // joint named but whose '{' has not been read
  for (std::string_view token = tokens.Next();; token = tokens.Next()) {
    if (token.empty()) return fail("the file ends inside HIERARCHY");
    if (token == "MOTION") break;
    if (token == "ROOT" || token == "JOINT" || token == "End") {
      if (token == "ROOT" && !nodes.empty()) return fail("it holds more than one ROOT");
      if (token != "ROOT" && open.empty()) return fail("a JOINT lies outside the ROOT");
      const int parent = open.empty() ? -1 : open.back();
      std::string name;
      if (token == "End") {
        if (tokens.Next() != "Site") return fail("'End' must be followed by 'Site'");
        name = out.names[parent] + "_end";
      } else {
        name = std::string(tokens.Next());
      }
      out.names.push_back(name);
      out.parents.push_back(parent);
      nodes.push_back(Node{parent, glm::vec3(0.0f), {}});
      pending = static_cast<int>(nodes.size()) - 1;
    } else if (token == "{") {
      if (pending < 0) return fail("a '{' without a joint");
      open.push_back(pending);
      pending = -1;
    } else if (token == "}") {
      if (open.empty()) return fail("an unbalanced '}'");
      open.pop_back();
    } else if (token == "OFFSET") {
      if (open.empty()) return fail("an OFFSET outside a joint");
      double x, y, z;
      if (!tokens.Number(x) || !tokens.Number(y) || !tokens.Number(z)) return fail("an OFFSET needs three numbers");
      nodes[open.back()].offset = glm::vec3(x, y, z);
    } else if (token == "CHANNELS") {
      if (open.empty()) return fail("CHANNELS outside a joint");
      double count;
      if (!tokens.Count(6, count)) return fail("CHANNELS needs a count from 0 to 6");
      for (int c = 0; c < static_cast<int>(count); ++c) {
        Channel channel;
        if (!ParseChannel(tokens.Next(), channel))
          return fail("unknown channel in joint '" + out.names[open.back()] + "'");
        nodes[open.back()].channels.push_back(channel);
      }
    } else {
      return fail("unexpected '" + std::string(token) + "' in HIERARCHY");
    }
  }
  if (nodes.empty()) return fail("it has no ROOT");
  if (!open.empty()) return fail("a joint block is not closed");

  double frames = 0.0;
  const double kAnyCount = std::numeric_limits<float>::max();
  if (tokens.Next() != "Frames:" || !tokens.Count(kAnyCount, frames)) return fail("MOTION needs 'Frames: <count>'");
  if (tokens.Next() != "Frame" || tokens.Next() != "Time:" || !tokens.Number(out.frameTime) || !(out.frameTime > 0)) {
    return fail("MOTION needs 'Frame Time: <seconds>'");
  }
  // The frame count is checked against the values actually there before anything is allocated
  // for it, so a wrong count (or a hostile one) costs no memory.
  size_t channelCount = 0;
  for (const Node& node : nodes) channelCount += node.channels.size();
  if (frames > 0 && channelCount == 0) return fail("MOTION has frames but no joint has CHANNELS");
  if (frames * static_cast<double>(channelCount) > static_cast<double>(tokens.Remaining())) {
    return fail("MOTION holds fewer values than Frames x channels");
  }

  // Forward kinematics in file axes, converted to rise-gen's world at the end.
  const size_t count = nodes.size();
  std::vector<glm::vec3> world(count);
  std::vector<glm::quat> rotation(count);
  out.positions.resize(static_cast<size_t>(frames));
  for (auto& framePositions : out.positions) {
    framePositions.resize(count);
    for (size_t j = 0; j < count; ++j) {
      glm::vec3 local = nodes[j].offset;
      glm::quat turn(1.0f, 0.0f, 0.0f, 0.0f);
      for (Channel channel : nodes[j].channels) {
        double value;
        if (!tokens.Number(value)) return fail("MOTION holds a value that is not a number a float can hold");
        const float v = static_cast<float>(value);
        switch (channel) {
          case Channel::kXPos:
            local.x = v;
            break;
          case Channel::kYPos:
            local.y = v;
            break;
          case Channel::kZPos:
            local.z = v;
            break;
          case Channel::kXRot:
            turn = turn * glm::angleAxis(glm::radians(v), glm::vec3(1, 0, 0));
            break;
          case Channel::kYRot:
            turn = turn * glm::angleAxis(glm::radians(v), glm::vec3(0, 1, 0));
            break;
          case Channel::kZRot:
            turn = turn * glm::angleAxis(glm::radians(v), glm::vec3(0, 0, 1));
            break;
        }
      }
      const int parent = nodes[j].parent;
      world[j] = parent < 0 ? local : world[parent] + rotation[parent] * local;
      rotation[j] = parent < 0 ? turn : rotation[parent] * turn;
      framePositions[j] = format.FromFile(world[j]);
    }
  }
  if (!tokens.Next().empty()) return fail("MOTION holds more values than Frames x channels");
  motion = std::move(out);
  return {};
}

std::string ReadBvh(const std::string& path, const BvhFormat& format, BvhMotion& motion) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return "cannot read BVH '" + path + "': the file cannot be opened";
  std::ostringstream text;
  text << file.rdbuf();
  return ParseBvh(text.str(), format, path, motion);
}

}  // namespace rise
