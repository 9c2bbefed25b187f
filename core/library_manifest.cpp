// SPDX-License-Identifier: MIT
// Batch manifest loading and clip naming; see library_manifest.h for the format.
#include "core/library_manifest.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/quaternion.hpp>
#include <map>
#include <optional>

#include "core/input_json.h"
#include "core/json_text.h"

namespace rise {
namespace {

using Json = nlohmann::json;

constexpr size_t kMaxClips = 100000;  // a guard against a typo like "count": 1e6
constexpr int kMaxRangeCount = 1000;

std::string Quote(const std::string& s) {
  return "\"" + s + "\"";
}

// Short decimal for names and range values: 1.75, 70, 1.6667.
std::string NameNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.5g", value);
  return text;
}

bool IsFileStem(const std::string& name) {
  if (name.empty() || name.size() > 200 || name[0] == '.') return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
           c == '.';
  });
}

// One entry of a cross-product axis: the part of its clips' names and the input keys it sets.
struct AxisEntry {
  std::string name;
  Json patch;        // an input-file object, e.g. {"character": {...}}
  std::string path;  // where the entry is, for errors: "cross.bodies[1]"
};

class ManifestReader {
 public:
  explicit ManifestReader(std::string file) : file_(std::move(file)) {}

  std::optional<InputError> error;

  bool Fail(const std::string& path, const std::string& message) {
    if (!error) error = InputError{file_, path, message, 0, 0};
    return false;
  }

  bool Keys(const Json& value, const std::string& path, const std::vector<std::string>& allowed) {
    if (!value.is_object()) return Fail(path, "found " + DescribeJsonValue(value) + ", allowed: an object");
    if (const std::optional<UnknownKey> unknown = FindUnknownKey(value, allowed)) {
      return Fail(path.empty() ? unknown->key : path + "." + unknown->key, unknown->message);
    }
    return true;
  }

  // Applies an input patch to `base`. The loader reports paths inside the patch; the part
  // `inner` ("start", "character.height_m", ...) is where the manifest holds it, `outer`.
  bool Apply(const Json& patch, const std::string& inner, const std::string& outer, RiseSpec& spec) {
    Result<RiseSpec> result = RiseSpecFromJson(patch, file_, "", spec);
    if (result) {
      spec = result.Value();
      return true;
    }
    InputError e = result.Error();
    const std::string& p = e.jsonPath;
    if (p.compare(0, inner.size(), inner) == 0 &&
        (p.size() == inner.size() || p[inner.size()] == '.' || p[inner.size()] == '[')) {
      e.jsonPath = outer + p.substr(inner.size());
    }
    if (!error) error = e;
    return false;
  }

  // A name field: present, a string, a usable file stem.
  bool Name(const Json& object, const std::string& path, std::string& out) {
    if (!object.contains("name")) return Fail(path, "missing key \"name\" (the name used in clip file names)");
    return FileStem(object["name"], path + ".name", out);
  }

  bool FileStem(const Json& value, const std::string& path, std::string& out) {
    if (!value.is_string() || !IsFileStem(value.get<std::string>())) {
      return Fail(path, "found " + DescribeJsonValue(value) +
                            ", allowed: a string of letters, digits, '_', '-' and '.' (a file name)");
    }
    out = value.get<std::string>();
    return true;
  }

  // A whole number inside [lo, hi] at object[key].
  bool Count(const Json& object, const std::string& path, const char* key, double lo, double hi, double& out) {
    const std::string at = path + "." + key;
    if (!object.contains(key)) return Fail(path, "missing key " + Quote(key));
    const Json& v = object[key];
    const std::string allowed = "a whole number from " + NameNumber(lo) + " to " + NameNumber(hi);
    if (!v.is_number() || std::floor(v.get<double>()) != v.get<double>() || v.get<double>() < lo ||
        v.get<double>() > hi) {
      return Fail(at, "found " + DescribeJsonValue(v) + ", allowed: " + allowed);
    }
    out = v.get<double>();
    return true;
  }

  // A body range {from, to, count} -> count evenly spaced numbers from `from` to `to`.
  bool Range(const Json& value, const std::string& path, std::vector<double>& out) {
    if (!Keys(value, path, {"from", "to", "count"})) return false;
    double count = 0;
    for (const char* key : {"from", "to"}) {
      if (!value.contains(key) || !value[key].is_number()) {
        return Fail(value.contains(key) ? path + "." + key : path,
                    value.contains(key) ? "found " + DescribeJsonValue(value[key]) + ", allowed: a number"
                                        : "missing key " + Quote(key) + "; a range needs from, to and count");
      }
    }
    if (!Count(value, path, "count", 1, kMaxRangeCount, count)) return false;
    const double from = value["from"].get<double>(), to = value["to"].get<double>();
    out.clear();
    for (int i = 0; i < static_cast<int>(count); ++i) {
      const double t = count > 1 ? i / (count - 1) : 0.0;
      // Rounded to 0.1 mm / 0.1 g so names and resolved inputs read cleanly.
      out.push_back(std::round((from + (to - from) * t) * 1e4) / 1e4);
    }
    return true;
  }

  bool Starts(const Json& axis, const std::string& path, std::vector<AxisEntry>& out) {
    if (!NonEmptyArray(axis, path, "posture names or start objects")) return false;
    for (size_t i = 0; i < axis.size(); ++i) {
      const std::string at = path + "[" + std::to_string(i) + "]";
      Json start = axis[i].is_string() ? Json{{"posture", axis[i]}} : axis[i];
      std::string name;
      if (start.is_object() && start.contains("name")) {
        if (!Name(start, at, name)) return false;
        start.erase("name");
      }
      // Validate now, so a bad posture is reported at this entry.
      RiseSpec probe;
      if (!Apply(Json{{"start", start}}, "start", at, probe)) return false;
      if (name.empty()) name = PostureName(probe.start.posture);
      out.push_back({name, Json{{"start", start}}, at});
    }
    return true;
  }

  bool Bodies(const Json& axis, const std::string& path, std::vector<AxisEntry>& out) {
    if (!NonEmptyArray(axis, path, "character objects with a \"name\"")) return false;
    for (size_t i = 0; i < axis.size(); ++i) {
      const std::string at = path + "[" + std::to_string(i) + "]";
      if (!axis[i].is_object()) return Fail(at, "found " + DescribeJsonValue(axis[i]) + ", allowed: an object");
      std::string name;
      if (!Name(axis[i], at, name)) return false;
      Json character = axis[i];
      character.erase("name");
      std::vector<double> heights{0.0}, masses{0.0};
      const bool heightRange = character.contains("height_m") && character["height_m"].is_object();
      const bool massRange = character.contains("mass_kg") && character["mass_kg"].is_object();
      if (heightRange && !Range(character["height_m"], at + ".height_m", heights)) return false;
      if (massRange && !Range(character["mass_kg"], at + ".mass_kg", masses)) return false;
      for (double height : heights) {
        for (double mass : masses) {
          Json body = character;
          std::string bodyName = name;
          if (heightRange) body["height_m"] = height, bodyName += "_h" + NameNumber(height);
          if (massRange) body["mass_kg"] = mass, bodyName += "_m" + NameNumber(mass);
          RiseSpec probe;
          if (!Apply(Json{{"character", body}}, "character", at, probe)) return false;
          out.push_back({bodyName, Json{{"character", body}}, at});
        }
      }
    }
    return true;
  }

  bool Styles(const Json& axis, const std::string& path, std::vector<AxisEntry>& out) {
    if (!NonEmptyArray(axis, path, "style objects with a \"name\"")) return false;
    for (size_t i = 0; i < axis.size(); ++i) {
      const std::string at = path + "[" + std::to_string(i) + "]";
      if (!axis[i].is_object()) return Fail(at, "found " + DescribeJsonValue(axis[i]) + ", allowed: an object");
      std::string name;
      if (!Name(axis[i], at, name)) return false;
      Json style = axis[i];
      style.erase("name");
      RiseSpec probe;
      if (!Apply(Json{{"style", style}}, "style", at, probe)) return false;
      out.push_back({name, Json{{"style", style}}, at});
    }
    return true;
  }

  bool Seeds(const Json& axis, const std::string& path, std::vector<AxisEntry>& out) {
    std::vector<Json> seeds;
    if (axis.is_object()) {
      if (!Keys(axis, path, {"from", "count"})) return false;
      double from = 0, count = 0;
      if (!Count(axis, path, "from", 0, 9007199254740992.0, from)) return false;
      if (!Count(axis, path, "count", 1, kMaxRangeCount, count)) return false;
      for (int i = 0; i < static_cast<int>(count); ++i) seeds.push_back(static_cast<uint64_t>(from) + i);
    } else {
      if (!NonEmptyArray(axis, path, "whole numbers, or { \"from\": n, \"count\": k }")) return false;
      seeds.assign(axis.begin(), axis.end());
    }
    for (size_t i = 0; i < seeds.size(); ++i) {
      const std::string at = axis.is_object() ? path : path + "[" + std::to_string(i) + "]";
      RiseSpec probe;
      if (!Apply(Json{{"seed", seeds[i]}}, "seed", at, probe)) return false;
      out.push_back({"s" + std::to_string(probe.seed), Json{{"seed", seeds[i]}}, at});
    }
    return true;
  }

 private:
  bool NonEmptyArray(const Json& value, const std::string& path, const std::string& of) {
    if (value.is_array() && !value.empty()) return true;
    return Fail(path, "found " + DescribeJsonValue(value) + ", allowed: a non-empty array of " + of);
  }

  std::string file_;
};

}  // namespace

const char* StartCategoryName(StartCategory category) {
  switch (category) {
    case StartCategory::kBack:
      return "back";
    case StartCategory::kStomach:
      return "stomach";
    case StartCategory::kSide:
      return "side";
  }
  return "back";
}

StartCategory CategoryOf(const StartSpec& start) {
  switch (start.posture) {
    case Posture::kSupine:
      return StartCategory::kBack;
    case Posture::kProne:
      return StartCategory::kStomach;
    case Posture::kSideLeft:
    case Posture::kSideRight:
      return StartCategory::kSide;
    case Posture::kCustom:
      break;
  }
  // The same intrinsic X-Y-Z rotation the biped's start pose uses (core/biped.cpp).
  const auto radians = [](double deg) { return static_cast<float>(deg * 3.14159265358979323846 / 180.0); };
  const glm::quat root = glm::angleAxis(radians(start.rootEulerDeg[0]), glm::vec3(1, 0, 0)) *
                         glm::angleAxis(radians(start.rootEulerDeg[1]), glm::vec3(0, 1, 0)) *
                         glm::angleAxis(radians(start.rootEulerDeg[2]), glm::vec3(0, 0, 1));
  const float frontUp = (root * glm::vec3(0, 0, 1)).y;
  // sin 30 deg: a front more than 30 deg above (below) level faces up (down).
  const float kSideways = 0.5f;
  if (frontUp > kSideways) return StartCategory::kBack;
  if (frontUp < -kSideways) return StartCategory::kStomach;
  return StartCategory::kSide;
}

Result<LibraryManifest> ParseLibraryManifest(const std::string& text, const std::string& fileName) {
  Result<Json> parsed = ParseJsonText(text, fileName);
  if (!parsed) return parsed.Error();
  const Json& root = parsed.Value();
  ManifestReader reader(fileName);
  auto failed = [&reader]() { return *reader.error; };
  if (!reader.Keys(root, "", {"$schema", "formats", "defaults", "clips", "cross"})) return failed();
  if (root.contains("$schema") && !root["$schema"].is_string()) {
    reader.Fail("$schema", "found " + DescribeJsonValue(root["$schema"]) + ", allowed: a string");
    return failed();
  }
  if (!root.contains("clips") && !root.contains("cross")) {
    reader.Fail("", "found no \"clips\" and no \"cross\", allowed: a manifest with at least one of them");
    return failed();
  }

  LibraryManifest manifest;
  if (root.contains("formats")) {
    const Json& formats = root["formats"];
    const std::vector<std::string> allowed{"glb", "gltf", "bvh"};
    if (!formats.is_array() || formats.empty()) {
      reader.Fail("formats",
                  "found " + DescribeJsonValue(formats) + ", allowed: a non-empty array of " + JoinNames(allowed));
      return failed();
    }
    manifest.formats.clear();
    for (size_t i = 0; i < formats.size(); ++i) {
      const std::string at = "formats[" + std::to_string(i) + "]";
      const bool known = formats[i].is_string() &&
                         std::find(allowed.begin(), allowed.end(), formats[i].get<std::string>()) != allowed.end();
      if (!known) {
        reader.Fail(at, "found " + DescribeJsonValue(formats[i]) + ", allowed: " + JoinNames(allowed));
        return failed();
      }
      if (std::find(manifest.formats.begin(), manifest.formats.end(), formats[i]) != manifest.formats.end()) {
        reader.Fail(at, "found " + DescribeJsonValue(formats[i]) + " twice, allowed: each format once");
        return failed();
      }
      manifest.formats.push_back(formats[i].get<std::string>());
    }
    const auto gltfCount = std::count(manifest.formats.begin(), manifest.formats.end(), "glb") +
                           std::count(manifest.formats.begin(), manifest.formats.end(), "gltf");
    if (gltfCount != 1) {
      reader.Fail("formats",
                  std::string(gltfCount == 0 ? "found no" : "found both") +
                      " \"glb\" and \"gltf\", allowed: exactly one of them (the index measures the glTF file)");
      return failed();
    }
  }

  RiseSpec defaults;
  if (root.contains("defaults")) {
    Result<RiseSpec> spec = RiseSpecFromJson(root["defaults"], fileName, "defaults");
    if (!spec) return spec.Error();
    defaults = spec.Value();
  }

  std::vector<std::string> sources;  // JSON path each clip came from, for the body check below
  if (root.contains("clips")) {
    const Json& clips = root["clips"];
    if (!clips.is_array()) {
      reader.Fail("clips", "found " + DescribeJsonValue(clips) + ", allowed: an array of clip objects");
      return failed();
    }
    for (size_t i = 0; i < clips.size(); ++i) {
      const std::string at = "clips[" + std::to_string(i) + "]";
      ManifestClip clip;
      if (!clips[i].is_object()) {
        reader.Fail(at, "found " + DescribeJsonValue(clips[i]) + ", allowed: an object");
        return failed();
      }
      if (!reader.Name(clips[i], at, clip.name)) return failed();
      Json input = clips[i];
      input.erase("name");
      clip.body = "default";
      if (input.contains("body")) {
        if (!reader.FileStem(input["body"], at + ".body", clip.body)) return failed();
        input.erase("body");
      }
      Result<RiseSpec> spec = RiseSpecFromJson(input, fileName, at, defaults);
      if (!spec) return spec.Error();
      clip.spec = spec.Value();
      clip.category = CategoryOf(clip.spec.start);
      manifest.clips.push_back(clip);
      sources.push_back(at);
    }
  }

  if (root.contains("cross")) {
    const Json& cross = root["cross"];
    if (!reader.Keys(cross, "cross", {"starts", "bodies", "styles", "seeds"})) return failed();
    std::vector<AxisEntry> starts, bodies, styles, seeds;
    if (cross.contains("starts") && !reader.Starts(cross["starts"], "cross.starts", starts)) return failed();
    if (cross.contains("bodies") && !reader.Bodies(cross["bodies"], "cross.bodies", bodies)) return failed();
    if (cross.contains("styles") && !reader.Styles(cross["styles"], "cross.styles", styles)) return failed();
    if (cross.contains("seeds") && !reader.Seeds(cross["seeds"], "cross.seeds", seeds)) return failed();
    // A missing axis is one entry that changes nothing and adds nothing to names.
    const std::vector<AxisEntry> none{{"", Json::object(), ""}};
    if (starts.empty()) starts = {{PostureName(defaults.start.posture), Json::object(), ""}};
    const size_t count = starts.size() * (bodies.empty() ? 1 : bodies.size()) * (styles.empty() ? 1 : styles.size()) *
                         (seeds.empty() ? 1 : seeds.size());
    if (count + manifest.clips.size() > kMaxClips) {
      reader.Fail("cross", "found a cross product of " + std::to_string(count) + " clips, allowed: at most " +
                               std::to_string(kMaxClips));
      return failed();
    }
    for (const AxisEntry& start : starts) {
      for (const AxisEntry& body : bodies.empty() ? none : bodies) {
        for (const AxisEntry& style : styles.empty() ? none : styles) {
          for (const AxisEntry& seed : seeds.empty() ? none : seeds) {
            ManifestClip clip;
            clip.spec = defaults;
            for (const AxisEntry* entry : {&start, &body, &style, &seed}) {
              if (entry->patch.empty()) continue;
              if (!reader.Apply(entry->patch, entry->patch.begin().key(), entry->path, clip.spec)) return failed();
            }
            clip.category = CategoryOf(clip.spec.start);
            clip.body = body.name.empty() ? "default" : body.name;
            clip.name = std::string(StartCategoryName(clip.category)) + "_" + start.name;
            for (const AxisEntry* entry : {&body, &style}) {
              if (!entry->name.empty()) clip.name += "_" + entry->name;
            }
            clip.name += "_s" + std::to_string(clip.spec.seed);
            manifest.clips.push_back(clip);
            sources.push_back("cross");
          }
        }
      }
    }
  }

  // Names are file stems; bodies share a skeleton in a library file.
  std::map<std::string, size_t> byName, byBody;
  for (size_t i = 0; i < manifest.clips.size(); ++i) {
    const ManifestClip& clip = manifest.clips[i];
    if (clip.name == "index") {
      reader.Fail(sources[i] + ".name", "found \"index\", allowed: any other name (the batch writes index.json)");
      return failed();
    }
    const auto named = byName.emplace(clip.name, i);
    if (!named.second) {
      reader.Fail(sources[i], "found the clip name " + Quote(clip.name) + " a second time (first from " +
                                  sources[named.first->second] + "), allowed: unique names");
      return failed();
    }
    const auto body = byBody.emplace(clip.body, i);
    const ManifestClip& first = manifest.clips[body.first->second];
    const auto skeletonOf = [](const RiseSpec& spec) {
      return nlohmann::json(RiseSpecToJson(spec)["character"]).dump() + spec.output.names +
             (spec.output.rootMotion ? "1" : "0");
    };
    if (!body.second && skeletonOf(first.spec) != skeletonOf(clip.spec)) {
      reader.Fail(sources[i], "clip " + Quote(clip.name) + " of body " + Quote(clip.body) +
                                  " has another character or output.names/root_motion than clip " + Quote(first.name) +
                                  ", allowed: one skeleton per body name (give it its own body)");
      return failed();
    }
  }
  return manifest;
}

Result<LibraryManifest> LoadLibraryManifest(const std::string& path) {
  Result<std::string> text = ReadInputFile(path);
  if (!text) return text.Error();
  return ParseLibraryManifest(text.Value(), path);
}

Result<Shard> ParseShard(const std::string& text, const std::string& label) {
  const auto bad = [&](const std::string& why) {
    return InputError{label, "", "found " + Quote(text) + ", allowed: I/N with 0 <= I < N (" + why + ")", 0, 0};
  };
  const size_t slash = text.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == text.size()) return bad("no I/N");
  const std::string a = text.substr(0, slash), b = text.substr(slash + 1);
  const auto digits = [](const std::string& s) {
    return s.size() <= 6 && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  if (!digits(a) || !digits(b)) return bad("I and N are whole numbers");
  const Shard shard{std::stoi(a), std::stoi(b)};
  if (shard.count < 1) return bad("N is at least 1");
  if (shard.index >= shard.count) return bad("I counts from 0, so it is below N");
  return shard;
}

std::vector<size_t> ShardClips(size_t clipCount, const Shard& shard) {
  std::vector<size_t> indices;
  for (size_t i = static_cast<size_t>(shard.index); i < clipCount; i += static_cast<size_t>(shard.count)) {
    indices.push_back(i);
  }
  return indices;
}

std::string InputHashOfJson(const std::string& resolvedInputJson) {
  // Sorted keys: the same input hashes the same however its JSON text was ordered.
  const Json value = Json::parse(resolvedInputJson, nullptr, false);
  const std::string text = value.is_discarded() ? resolvedInputJson : value.dump();
  uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

std::string InputHash(const RiseSpec& spec) {
  return InputHashOfJson(RiseSpecToJson(spec).dump());
}

}  // namespace rise
