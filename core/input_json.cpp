// SPDX-License-Identifier: MIT
// The JSON input loader and writer; see input_json.h for the rules.
#include "core/input_json.h"

#include "core/biped.h"
#include "core/json_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

namespace rise {
namespace {

using Json = nlohmann::json;

constexpr double kMaxSeed = 9007199254740992.0;  // 2^53: every integer up to it is exact in a double

std::string FormatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", value);
  return text;
}

// The shortest decimal that reads back as the same float, as a double: 0.4f -> 0.4, not
// 0.4000000059604645, so resolved inputs stay readable and still round-trip exactly.
double ShortestDouble(float value) {
  char text[32];
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(text, sizeof(text), "%.*g", digits, static_cast<double>(value));
    if (static_cast<float>(std::strtod(text, nullptr)) == value) return std::strtod(text, nullptr);
  }
  return value;
}

std::string Quote(const std::string& s) {
  return "\"" + s + "\"";
}

std::string JoinPath(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}
std::string IndexPath(const std::string& path, size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

// People name joints after the joint ("knee"), rise-gen after the bone it moves ("shin").
std::string BoneForJointWord(const std::string& name) {
  static const std::pair<const char*, const char*> kWords[] = {
      {"knee", "shin"},  {"elbow", "forearm"}, {"hip", "thigh"},     {"shoulder", "upper_arm"}, {"ankle", "foot"},
      {"wrist", "hand"}, {"neck", "head"},     {"spine", "abdomen"}, {"lumbar", "abdomen"},     {"thorax", "chest"}};
  for (const auto& word : kWords) {
    const std::string joint = word.first;
    if (name.rfind(joint, 0) == 0) return word.second + name.substr(joint.size());
  }
  return {};
}

struct Range {
  double lo, hi;
  const char* unit;  // appended after the range, e.g. "m"; may be empty
};

std::string RangeText(const Range& r) {
  std::string text = FormatNumber(r.lo) + " to " + FormatNumber(r.hi);
  return r.unit[0] ? text + " " + r.unit : text;
}

// The body every angle and segment name is checked against; names and limits do not depend on size.
const BipedDef& ReferenceBody() {
  static const BipedDef def = MakeBipedDef(1.75f, 70.0f);
  return def;
}

std::vector<std::string> PosedJointNames() {
  std::vector<std::string> names;
  const BipedDef& def = ReferenceBody();
  for (int i = 0; i < def.skeleton.JointCount(); ++i) {
    if (def.DofCount(i) > 0) names.push_back(def.skeleton.joints[i].name);
  }
  return names;
}

std::string DescribeDofs(const BipedDef& def, int joint) {
  std::string text;
  for (const JointDof& dof : def.bones[joint].dofs) {
    text += (text.empty() ? "" : ", ") + dof.name + " " + FormatNumber(dof.minDeg) + " to " + FormatNumber(dof.maxDeg);
  }
  return "[" + text + "] degrees";
}

// Reads one JSON document into a RiseSpec, stopping at the first mistake.
class Reader {
 public:
  Reader(std::string file, std::string prefix) : file_(std::move(file)), prefix_(std::move(prefix)) {}

  std::optional<InputError> error;

  bool Fail(const std::string& path, const std::string& message) {
    if (!error) error = InputError{file_, JoinPrefix(path), message, 0, 0};
    return false;
  }

  // `value` must be an object whose keys are all in `allowed`.
  bool Object(const Json& value, const std::string& path, const std::vector<std::string>& allowed) {
    if (!value.is_object()) return Fail(path, "found " + DescribeJsonValue(value) + ", allowed: an object");
    if (const std::optional<UnknownKey> unknown = FindUnknownKey(value, allowed)) {
      return Fail(JoinPath(path, unknown->key), unknown->message);
    }
    return true;
  }

  bool Required(const Json& object, const std::string& path, const std::vector<std::string>& keys) {
    for (const std::string& key : keys) {
      if (!object.contains(key)) return Fail(path, "missing key " + Quote(key) + "; required: " + JoinNames(keys));
    }
    return true;
  }

  bool Number(const Json& value, const std::string& path, const Range& range, double& out) {
    if (!value.is_number()) {
      return Fail(path, "found " + DescribeJsonValue(value) + ", allowed: a number from " + RangeText(range));
    }
    const double x = value.get<double>();
    if (!std::isfinite(x) || x < range.lo || x > range.hi) {
      return Fail(path, "found " + FormatNumber(x) + ", allowed: " + RangeText(range));
    }
    out = x;
    return true;
  }

  // Reads object[key] when present; leaves `out` (the default) alone otherwise.
  bool OptionalNumber(const Json& object, const std::string& path, const char* key, const Range& range, double& out) {
    const auto it = object.find(key);
    return it == object.end() || Number(*it, JoinPath(path, key), range, out);
  }

  bool OptionalInteger(const Json& object, const std::string& path, const char* key, double hi, uint64_t& out) {
    const auto it = object.find(key);
    if (it == object.end()) return true;
    const std::string at = JoinPath(path, key);
    const std::string allowed = "a whole number from 0 to " + FormatNumber(hi);
    if (!it->is_number()) return Fail(at, "found " + DescribeJsonValue(*it) + ", allowed: " + allowed);
    const double x = it->get<double>();
    if (!std::isfinite(x) || x < 0.0 || x > hi || std::floor(x) != x) {
      return Fail(at, "found " + (it->is_number_float() ? FormatNumber(x) : it->dump()) + ", allowed: " + allowed);
    }
    out = it->is_number_unsigned() ? it->get<uint64_t>() : static_cast<uint64_t>(x);
    return true;
  }

  bool OptionalBool(const Json& object, const std::string& path, const char* key, bool& out) {
    const auto it = object.find(key);
    if (it == object.end()) return true;
    if (!it->is_boolean()) return Fail(JoinPath(path, key), "found " + DescribeJsonValue(*it) + ", allowed: true or false");
    out = it->get<bool>();
    return true;
  }

  // A string that must be one of `names`; returns its index in `index`.
  bool Choice(const Json& value, const std::string& path, const std::vector<std::string>& names, int& index) {
    const std::string allowed = "allowed: " + JoinNames(names);
    if (!value.is_string()) return Fail(path, "found " + DescribeJsonValue(value) + ", " + allowed);
    const std::string text = value.get<std::string>();
    const auto it = std::find(names.begin(), names.end(), text);
    if (it != names.end()) {
      index = static_cast<int>(it - names.begin());
      return true;
    }
    const std::string guess = ClosestName(text, names);
    return Fail(
        path, "found " + Quote(text) + (guess.empty() ? "" : " (did you mean " + Quote(guess) + "?)") + ", " + allowed);
  }

  bool Vec3(const Json& value, const std::string& path, const Range& range, std::array<double, 3>& out) {
    if (!value.is_array() || value.size() != 3) {
      return Fail(path, "found " + DescribeJsonValue(value) + ", allowed: an array of 3 numbers, each " + RangeText(range));
    }
    for (size_t i = 0; i < 3; ++i) {
      if (!Number(value[i], IndexPath(path, i), range, out[i])) return false;
    }
    return true;
  }

  bool Spec(const Json& root, RiseSpec& spec) {
    if (!Object(root, "",
                {"$schema", "character", "start", "terrain", "style", "disturbances", "seed", "fps", "max_duration_s",
                 "output"})) {
      return false;
    }
    if (root.contains("$schema") && !root["$schema"].is_string()) {
      return Fail("$schema", "found " + DescribeJsonValue(root["$schema"]) + ", allowed: a string (the schema's URI)");
    }
    if (root.contains("character") && !Character(root["character"], "character", spec.character)) return false;
    if (root.contains("start") && !Start(root["start"], "start", spec.start)) return false;
    if (root.contains("terrain") && !Terrain(root["terrain"], "terrain", spec.terrain)) return false;
    if (root.contains("style") && !Style(root["style"], "style", spec.style)) return false;
    if (!OptionalInteger(root, "", "seed", kMaxSeed, spec.seed)) return false;
    if (!OptionalNumber(root, "", "fps", {1, 240, "frames per second"}, spec.fps)) return false;
    if (!OptionalNumber(root, "", "max_duration_s", {1, 120, "s"}, spec.maxDurationS)) return false;
    // Left out (here and in every patch before), it follows the start and style.
    spec.maxDurationGiven = spec.maxDurationGiven || root.contains("max_duration_s");
    if (!spec.maxDurationGiven) spec.maxDurationS = DefaultMaxDurationS(spec);
    if (root.contains("disturbances") && !Disturbances(root["disturbances"], "disturbances", spec)) return false;
    if (root.contains("output") && !Output(root["output"], "output", spec.output)) return false;
    return true;
  }

 private:
  std::string JoinPrefix(const std::string& path) const {
    if (prefix_.empty()) return path;
    if (path.empty()) return prefix_;
    return path[0] == '[' ? prefix_ + path : prefix_ + "." + path;
  }

  bool Character(const Json& value, const std::string& path, CharacterSpec& out) {
    if (!Object(value, path, {"height_m", "mass_kg", "segments"})) return false;
    if (!OptionalNumber(value, path, "height_m", {1.2, 2.3, "m"}, out.heightM)) return false;
    if (!OptionalNumber(value, path, "mass_kg", {30, 200, "kg"}, out.massKg)) return false;
    if (value.contains("segments") && !Segments(value["segments"], JoinPath(path, "segments"), out)) return false;
    return true;
  }

  bool Segments(const Json& value, const std::string& path, CharacterSpec& out) {
    if (!Object(value, path, SegmentNames())) return false;
    for (auto it = value.begin(); it != value.end(); ++it) {
      const std::string at = JoinPath(path, it.key());
      if (!Object(*it, at, {"length_m", "width_m", "depth_m", "mass_kg"})) return false;
      SegmentOverride& o = out.segments[it.key()] = SegmentOverride{};
      double x = 0.0;
      if (it->contains("length_m")) {
        if (!Number((*it)["length_m"], JoinPath(at, "length_m"), {0.02, 1.0, "m"}, x)) return false;
        o.lengthM = static_cast<float>(x);
      }
      if (it->contains("width_m")) {
        if (!Number((*it)["width_m"], JoinPath(at, "width_m"), {0.01, 0.6, "m"}, x)) return false;
        o.widthM = static_cast<float>(x);
      }
      if (it->contains("depth_m")) {
        if (!Number((*it)["depth_m"], JoinPath(at, "depth_m"), {0.01, 0.6, "m"}, x)) return false;
        o.depthM = static_cast<float>(x);
      }
      if (it->contains("mass_kg")) {
        if (!Number((*it)["mass_kg"], JoinPath(at, "mass_kg"), {0.1, 100, "kg"}, x)) return false;
        o.massKg = static_cast<float>(x);
      }
    }
    return true;
  }

  bool Start(const Json& value, const std::string& path, StartSpec& out) {
    if (!Object(value, path, {"posture", "heading_deg", "root_euler_deg", "joints_deg", "drop_height_m"})) return false;
    if (value.contains("posture")) {
      int index = 0;
      if (!Choice(value["posture"], JoinPath(path, "posture"), {"supine", "prone", "side_left", "side_right", "custom"},
                  index)) {
        return false;
      }
      out.posture = static_cast<Posture>(index);
    }
    if (!OptionalNumber(value, path, "heading_deg", {-360, 360, "degrees"}, out.headingDeg)) return false;
    if (value.contains("root_euler_deg")) {
      const std::string at = JoinPath(path, "root_euler_deg");
      if (out.posture != Posture::kCustom) {
        return Fail(at, std::string("found with posture ") + Quote(PostureName(out.posture)) +
                            ", allowed: only with posture \"custom\" (the other postures set the root themselves)");
      }
      if (!Vec3(value["root_euler_deg"], at, {-360, 360, "degrees"}, out.rootEulerDeg)) return false;
    }
    if (value.contains("joints_deg") && !JointsDeg(value["joints_deg"], JoinPath(path, "joints_deg"), out))
      return false;
    if (!OptionalNumber(value, path, "drop_height_m", {0, 2, "m"}, out.dropHeightM)) return false;
    return true;
  }

  bool JointsDeg(const Json& value, const std::string& path, StartSpec& out) {
    if (!value.is_object()) return Fail(path, "found " + DescribeJsonValue(value) + ", allowed: an object");
    const BipedDef& def = ReferenceBody();
    const std::vector<std::string> names = PosedJointNames();
    for (auto it = value.begin(); it != value.end(); ++it) {
      const std::string at = JoinPath(path, it.key());
      const int joint = def.Find(it.key());
      if (joint < 0 || def.DofCount(joint) == 0) {
        std::string message = "unknown joint " + Quote(it.key());
        const std::string bone = BoneForJointWord(it.key());
        std::string guess = def.Find(bone) >= 0 ? bone : ClosestName(it.key(), names);
        if (!bone.empty() && guess == bone) {
          message += "; joints are named after the bone they move: did you mean " + Quote(guess) + "?";
        } else if (!guess.empty()) {
          message += ", did you mean " + Quote(guess) + "?";
        }
        return Fail(at, message + " allowed: " + JoinNames(names));
      }
      const int dofs = def.DofCount(joint);
      const std::string shape = std::to_string(dofs) + (dofs == 1 ? " value " : " values ") + DescribeDofs(def, joint);
      if (!it->is_array() || static_cast<int>(it->size()) != dofs) {
        return Fail(at, "found " + DescribeJsonValue(*it) + ", allowed: an array of " + shape);
      }
      std::vector<double> angles(dofs);
      for (int i = 0; i < dofs; ++i) {
        const JointDof& dof = def.bones[joint].dofs[i];
        const std::string unit = "degrees (" + dof.name + ")";
        if (!Number((*it)[i], IndexPath(at, i), {dof.minDeg, dof.maxDeg, unit.c_str()}, angles[i])) return false;
      }
      out.jointsDeg[it.key()] = angles;
    }
    return true;
  }

  bool Terrain(const Json& value, const std::string& path, TerrainSpec& out) {
    if (!Object(value, path, {"slope_deg", "friction"})) return false;
    return OptionalNumber(value, path, "slope_deg", {0, 30, "degrees"}, out.slopeDeg) &&
           OptionalNumber(value, path, "friction", {0.05, 2, ""}, out.friction);
  }

  bool Style(const Json& value, const std::string& path, StyleSpec& out) {
    if (!Object(value, path,
                {"speed", "step_height_m", "stance_width_m", "sway", "tiredness", "look_around"})) {
      return false;
    }
    return OptionalNumber(value, path, "speed", {0.25, 3, "times the default pace"}, out.speed) &&
           OptionalNumber(value, path, "step_height_m", {0.02, 0.3, "m"}, out.stepHeightM) &&
           OptionalNumber(value, path, "stance_width_m", {0.1, 0.6, "m"}, out.stanceWidthM) &&
           OptionalNumber(value, path, "sway", {0, 1, ""}, out.sway) &&
           OptionalNumber(value, path, "tiredness", {0, 1, ""}, out.tiredness) &&
           OptionalNumber(value, path, "look_around", {0, 1, ""}, out.lookAround);
  }

  bool Disturbances(const Json& value, const std::string& path, RiseSpec& spec) {
    if (!value.is_array()) return Fail(path, "found " + DescribeJsonValue(value) + ", allowed: an array of pushes");
    spec.disturbances.clear();
    const std::vector<std::string> keys = {"time_s", "body", "force_n", "duration_s"};
    for (size_t i = 0; i < value.size(); ++i) {
      const std::string at = IndexPath(path, i);
      const Json& push = value[i];
      if (!Object(push, at, keys) || !Required(push, at, keys)) return false;
      Disturbance d;
      int body = 0;
      if (!Number(push["time_s"], JoinPath(at, "time_s"), {0, 120, "s"}, d.timeS) ||
          !Choice(push["body"], JoinPath(at, "body"), SegmentNames(), body) ||
          !Vec3(push["force_n"], JoinPath(at, "force_n"), {-5000, 5000, "N"}, d.forceN) ||
          !Number(push["duration_s"], JoinPath(at, "duration_s"), {0.001, 5, "s"}, d.durationS)) {
        return false;
      }
      d.body = SegmentNames()[body];
      spec.disturbances.push_back(d);
    }
    return true;
  }

  bool Output(const Json& value, const std::string& path, OutputSpec& out) {
    if (!Object(value, path, {"names", "root_motion"})) return false;
    if (value.contains("names")) {
      const std::vector<std::string> presets = {"default", "mixamo", "ue"};
      int index = 0;
      if (!Choice(value["names"], JoinPath(path, "names"), presets, index)) return false;
      out.names = presets[index];
    }
    return OptionalBool(value, path, "root_motion", out.rootMotion);
  }

  std::string file_;
  std::string prefix_;
};

// Checks that need several keys at once; run on the merged spec.
bool CheckConsistency(Reader& reader, const RiseSpec& spec) {
  double fixedMass = 0.0;
  for (const auto& entry : spec.character.segments) fixedMass += entry.second.massKg.value_or(0.0f);
  const double limit = 0.9 * spec.character.massKg;
  if (fixedMass >= limit) {
    return reader.Fail("character.segments", "found overridden masses summing to " + FormatNumber(fixedMass) +
                                                 " kg, allowed: less than 90 % of mass_kg (" + FormatNumber(limit) +
                                                 " kg), so the other segments keep a share");
  }
  size_t massOverrides = 0;
  for (const auto& entry : spec.character.segments) massOverrides += entry.second.massKg ? 1 : 0;
  if (massOverrides == SegmentNames().size()) {
    return reader.Fail("character.segments", "found a mass_kg for every segment, allowed: at most " +
                                                 std::to_string(SegmentNames().size() - 1) +
                                                 " (one must take the rest of mass_kg)");
  }
  // A start deep inside itself (legs crossed through each other, say) is pushed apart by the
  // contacts in its first steps, which flings a hand or foot at 10-13 m/s: 5 of the 6 stress
  // runs of seeds 1-300 over the 10 m/s bound began so.
  const BipedDef def = MakeBipedDef(spec.character);
  if (const std::optional<SelfOverlap> overlap = DeepestSelfOverlap(def, StartPose(def, spec.start, spec.terrain.slopeDeg));
      overlap && overlap->depthM > kMaxStartOverlapM) {
    const bool joints = !spec.start.jointsDeg.empty();
    return reader.Fail(joints ? "start.joints_deg" : "start",
                       "found a pose in which the " + overlap->boxA + " and " + overlap->boxB + " boxes pass " +
                           FormatNumber(std::round(overlap->depthM * 1000.0) / 10.0) +
                           " cm into each other, allowed: at most " + FormatNumber(kMaxStartOverlapM * 100.0f) +
                           " cm (a body cannot start inside itself; turn one of them clear)");
  }
  for (size_t i = 0; i < spec.disturbances.size(); ++i) {
    if (spec.disturbances[i].timeS > spec.maxDurationS) {
      return reader.Fail(IndexPath("disturbances", i) + ".time_s", "found " + FormatNumber(spec.disturbances[i].timeS) +
                                                                       ", allowed: 0 to max_duration_s (" +
                                                                       FormatNumber(spec.maxDurationS) + " s)");
    }
  }
  return true;
}

}  // namespace

int EditDistance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const int above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

void TextPosition(const std::string& text, size_t byteOffset, int& line, int& column) {
  line = 1;
  column = 1;
  for (size_t i = 0; i < byteOffset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
}

Result<RiseSpec> RiseSpecFromJson(const Json& value, const std::string& fileName, const std::string& pathPrefix,
                                  const RiseSpec& base) {
  Reader reader(fileName, pathPrefix);
  RiseSpec spec = base;
  if (!reader.Spec(value, spec) || !CheckConsistency(reader, spec)) return *reader.error;
  return spec;
}

Result<RiseSpec> ParseRiseSpec(const std::string& text, const std::string& fileName) {
  const Result<Json> root = ParseJsonText(text, fileName);
  if (!root) return root.Error();
  return RiseSpecFromJson(root.Value(), fileName);
}

Result<RiseSpec> LoadRiseSpec(const std::string& path) {
  const Result<std::string> text = ReadInputFile(path);
  if (!text) return text.Error();
  return ParseRiseSpec(text.Value(), path);
}

nlohmann::ordered_json RiseSpecToJson(const RiseSpec& spec) {
  using Ordered = nlohmann::ordered_json;
  Ordered segments = Ordered::object();
  for (const std::string& name : SegmentNames()) {
    const auto it = spec.character.segments.find(name);
    if (it == spec.character.segments.end()) continue;
    Ordered entry = Ordered::object();
    const SegmentOverride& o = it->second;
    if (o.lengthM) entry["length_m"] = ShortestDouble(*o.lengthM);
    if (o.widthM) entry["width_m"] = ShortestDouble(*o.widthM);
    if (o.depthM) entry["depth_m"] = ShortestDouble(*o.depthM);
    if (o.massKg) entry["mass_kg"] = ShortestDouble(*o.massKg);
    segments[name] = entry;
  }
  Ordered joints = Ordered::object();
  for (const std::string& name : PosedJointNames()) {
    const auto it = spec.start.jointsDeg.find(name);
    if (it != spec.start.jointsDeg.end()) joints[name] = it->second;
  }
  Ordered disturbances = Ordered::array();
  for (const Disturbance& d : spec.disturbances) {
    disturbances.push_back({{"time_s", d.timeS}, {"body", d.body}, {"force_n", d.forceN}, {"duration_s", d.durationS}});
  }
  Ordered start = {{"posture", PostureName(spec.start.posture)}, {"heading_deg", spec.start.headingDeg}};
  if (spec.start.posture == Posture::kCustom) start["root_euler_deg"] = spec.start.rootEulerDeg;
  start["joints_deg"] = joints;
  start["drop_height_m"] = spec.start.dropHeightM;
  return Ordered{
      {"character", {{"height_m", spec.character.heightM}, {"mass_kg", spec.character.massKg}, {"segments", segments}}},
      {"start", start},
      {"terrain", {{"slope_deg", spec.terrain.slopeDeg}, {"friction", spec.terrain.friction}}},
      {"style",
       {{"speed", spec.style.speed},
        {"step_height_m", spec.style.stepHeightM},
        {"stance_width_m", spec.style.stanceWidthM},
        {"sway", spec.style.sway},
        {"tiredness", spec.style.tiredness},
        {"look_around", spec.style.lookAround}}},
      {"disturbances", disturbances},
      {"seed", spec.seed},
      {"fps", spec.fps},
      {"max_duration_s", spec.maxDurationS},
      {"output", {{"names", spec.output.names}, {"root_motion", spec.output.rootMotion}}}};
}

}  // namespace rise
