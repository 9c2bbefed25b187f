// SPDX-License-Identifier: MIT
// The clip's metadata as JSON (sidecar file and glTF extras).
#include "export/clip_metadata_json.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "export/atomic_file.h"

namespace rise {

std::string MetadataToJson(const Clip& clip) {
  const ClipMetadata& m = clip.metadata;
  nlohmann::json doc;
  // The version that made the clip; a clip made outside core/ has none and
  // is credited to this build.
  doc["generator"] = "rise-gen " + (m.generatorVersion.empty() ? std::string(RISE_VERSION) : m.generatorVersion);
  doc["fps"] = clip.fps;
  doc["frameCount"] = clip.FrameCount();
  doc["duration"] = clip.Duration();
  doc["rootMotion"] = m.rootMotion;
  doc["removedTravel"] = {m.removedTravel.x, m.removedTravel.y, m.removedTravel.z};
  doc["removedHeading"] = m.removedHeading;
  doc["seed"] = m.seed;
  doc["timeToStand"] = m.timeToStand;
  doc["phases"] = nlohmann::json::array();
  for (const PhaseSpan& p : m.phases) doc["phases"].push_back({{"name", p.name}, {"start", p.start}, {"end", p.end}});
  doc["contacts"] = nlohmann::json::array();
  for (const ContactSpan& c : m.contacts) {
    doc["contacts"].push_back({{"effector", c.effector}, {"start", c.start}, {"end", c.end}, {"footLock", c.locked}});
  }
  doc["peakTorques"] = nlohmann::json::array();
  for (const auto& [joint, torque] : m.peakTorques)
    doc["peakTorques"].push_back({{"joint", joint}, {"torque", torque}});
  // Parameters are stored as a JSON value, not a string inside JSON, so tools
  // can read them directly; text that does not parse is kept as a string.
  nlohmann::json parameters = nlohmann::json::parse(m.parametersJson, nullptr, false);
  doc["parameters"] = parameters.is_discarded() ? nlohmann::json(m.parametersJson) : parameters;
  return doc.dump();
}

std::string MetadataFromJson(const std::string& text, ClipMetadata& metadata) {
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return "clip metadata is not a JSON object";
  try {
    ClipMetadata m;
    if (doc.contains("generator")) {
      const std::string generator = doc["generator"].get<std::string>();
      const std::string prefix = "rise-gen ";
      m.generatorVersion = generator.rfind(prefix, 0) == 0 ? generator.substr(prefix.size()) : generator;
    }
    m.rootMotion = doc.value("rootMotion", m.rootMotion);
    if (doc.contains("removedTravel")) {
      const auto& t = doc["removedTravel"];
      m.removedTravel = glm::vec3(t.at(0).get<float>(), t.at(1).get<float>(), t.at(2).get<float>());
    }
    m.removedHeading = doc.value("removedHeading", 0.0);
    m.seed = doc.value("seed", 0ull);
    m.timeToStand = doc.value("timeToStand", -1.0);
    for (const auto& p : doc.value("phases", nlohmann::json::array())) {
      m.phases.push_back({p.at("name").get<std::string>(), p.at("start").get<double>(), p.at("end").get<double>()});
    }
    for (const auto& c : doc.value("contacts", nlohmann::json::array())) {
      m.contacts.push_back({c.at("effector").get<std::string>(), c.at("start").get<double>(), c.at("end").get<double>(),
                            c.value("footLock", false)});
    }
    for (const auto& t : doc.value("peakTorques", nlohmann::json::array())) {
      m.peakTorques.emplace_back(t.at("joint").get<std::string>(), t.at("torque").get<double>());
    }
    if (doc.contains("parameters")) {
      const auto& p = doc["parameters"];
      m.parametersJson = p.is_string() ? p.get<std::string>() : p.dump();
    }
    metadata = std::move(m);
  } catch (const nlohmann::json::exception& e) {
    return std::string("clip metadata is malformed: ") + e.what();
  }
  return {};
}

std::string SidecarPath(const std::string& clipPath) {
  return std::filesystem::path(clipPath).replace_extension(".meta.json").string();
}

std::string WriteMetadataSidecar(const Clip& clip, const std::string& clipPath) {
  return WriteFileAtomically(SidecarPath(clipPath), MetadataToJson(clip));
}

}  // namespace rise
