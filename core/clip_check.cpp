// SPDX-License-Identifier: MIT
// Quality check of clip files; see clip_check.h.
#include "core/clip_check.h"

#include <cstdio>

#include "core/biped.h"
#include "export/bvh_reader.h"
#include "export/gltf_reader.h"
#include "export/joint_names.h"

namespace rise {

QualityOptions QualityOptionsFor(const Clip& clip) {
  QualityOptions options;
  const nlohmann::json parameters = nlohmann::json::parse(clip.metadata.parametersJson, nullptr, false);
  if (parameters.is_object() && parameters.contains("terrain") && parameters["terrain"].is_object()) {
    const nlohmann::json& slope = parameters["terrain"].value("slope_deg", nlohmann::json(0.0));
    if (slope.is_number()) {
      const physics::PlaneShape ground = GroundPlane(slope.get<double>());
      options.groundNormal = ground.normal;
      options.groundPoint = ground.normal * ground.offset;
    }
  }
  return options;
}

std::string MissedBars(const QualityReport& quality) {
  if (!quality.error.empty()) return quality.error;
  std::string text;
  const std::pair<bool, const char*> bars[] = {{quality.startsLying, "starts lying"},
                                               {quality.endsStanding, "ends standing"},
                                               {quality.penetrationOk, "ground penetration"},
                                               {quality.slipOk, "contact slip"},
                                               {quality.jumpOk, "no teleport"}};
  for (const auto& bar : bars) {
    if (!bar.first) text += (text.empty() ? "" : ", ") + std::string(bar.second);
  }
  return text;
}

ClipCheck CheckClipFiles(const std::string& gltfPath, const std::string& bvhPath, const BvhFormat& bvhFormat) {
  ClipCheck check;
  check.error = ReadGltf(gltfPath, check.clip);
  if (!check.error.empty()) return check;
  check.quality = MeasureClip(check.clip, QualityOptionsFor(check.clip));
  if (!check.quality.error.empty()) {
    check.error = gltfPath + ": " + check.quality.error;
    return check;
  }
  if (!bvhPath.empty()) {
    BvhMotion motion;
    check.error = ReadBvh(bvhPath, bvhFormat, motion);
    if (!check.error.empty()) return check;
    check.hasBvh = true;
    // Joints are paired by canonical name, so the files may use different naming presets.
    const std::vector<std::vector<glm::vec3>> gltfPositions = JointPositionSequence(check.clip);
    std::vector<std::vector<glm::vec3>> fromGltf(gltfPositions.size()), fromBvh(motion.positions.size());
    for (int j = 0; j < static_cast<int>(motion.names.size()); ++j) {
      const std::optional<std::string> canonical = CanonicalJointName(motion.names[j]);
      const int k = check.clip.skeleton.Find(canonical.value_or(motion.names[j]));
      if (k < 0) continue;
      ++check.bvhJoints;
      for (size_t f = 0; f < fromGltf.size(); ++f) fromGltf[f].push_back(gltfPositions[f][k]);
      for (size_t f = 0; f < fromBvh.size(); ++f) fromBvh[f].push_back(motion.positions[f][j]);
    }
    const std::optional<double> distance = MaxPositionDistance(fromGltf, fromBvh);
    if (check.bvhJoints == 0) {
      check.bvhProblem = "no joint of the BVH file matches a joint of the glTF file";
    } else if (!distance) {
      check.bvhProblem = "the BVH file has " + std::to_string(fromBvh.size()) + " frames, the glTF file " +
                         std::to_string(fromGltf.size());
    } else {
      check.bvhDistance = *distance;
    }
    check.bvhOk = check.bvhProblem.empty() && check.bvhDistance <= kMaxBvhDistance;
  }
  check.passed = check.quality.passed && check.bvhOk;
  return check;
}

nlohmann::json ClipCheck::ToJson() const {
  nlohmann::json json;
  if (!error.empty()) {
    json["error"] = error;
    json["passed"] = false;
    return json;
  }
  json["quality"] = quality.ToJson();
  if (hasBvh) {
    json["bvh"] = {{"maxDistance", bvhDistance}, {"joints", bvhJoints}, {"ok", bvhOk}, {"limit", kMaxBvhDistance}};
    if (!bvhProblem.empty()) json["bvh"]["problem"] = bvhProblem;
  }
  json["passed"] = passed;
  return json;
}

std::string ClipCheck::Summary() const {
  if (!error.empty()) return error + "\n";
  std::string text = quality.Summary();
  if (!text.empty() && text.back() != '\n') text += "\n";
  if (hasBvh) {
    char line[200];
    if (bvhProblem.empty()) {
      std::snprintf(line, sizeof line, "%s BVH vs glTF: %.4f m over %d joints (limit %.2f m)\n",
                    bvhOk ? "PASS" : "FAIL", bvhDistance, bvhJoints, kMaxBvhDistance);
      text += line;
    } else {
      text += "FAIL BVH vs glTF: " + bvhProblem + "\n";
    }
    text += std::string(passed ? "PASS" : "FAIL") + " overall with the BVH\n";
  }
  return text;
}

}  // namespace rise
