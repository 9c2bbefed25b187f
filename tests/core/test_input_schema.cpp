// SPDX-License-Identifier: MIT
// The JSON Schema and the loader must describe the same format: key sets, defaults, ranges, enums.
#include <fstream>
#include <set>
#include <sstream>

#include "core/biped_def.h"
#include "core/input_json.h"
#include "test_support.h"

namespace {

using Json = nlohmann::json;

Json LoadSchema() {
  std::ifstream in(std::string(RISE_SOURCE_DIR) + "/schema/rise-input.schema.json");
  REQUIRE(in.good());
  return Json::parse(in);
}

std::set<std::string> Keys(const Json& object) {
  std::set<std::string> keys;
  for (auto it = object.begin(); it != object.end(); ++it) keys.insert(it.key());
  return keys;
}

// A document with `leaf` at the object path `path` (e.g. {"terrain", "friction"}); a start
// posture of custom is added so every start key is allowed.
Json Document(const std::vector<std::string>& path, const Json& leaf) {
  Json doc = leaf;
  for (auto it = path.rbegin(); it != path.rend(); ++it) doc = Json{{*it, doc}};
  if (path.size() > 1 && path[0] == "start" && path[1] != "posture") doc["start"]["posture"] = "custom";
  return doc;
}

bool Accepts(const Json& doc) {
  return rise::RiseSpecFromJson(doc, "schema-test.json").IsOk();
}

// For a numeric leaf: the loader accepts the schema's minimum and maximum and rejects just beyond.
// `extra` is merged into each document (e.g. a body heavy enough for the largest segment mass).
void CheckRange(const std::vector<std::string>& path, const Json& node, const Json& extra = Json::object()) {
  const double lo = node.at("minimum").get<double>(), hi = node.at("maximum").get<double>();
  const double step = 1e-6 * std::max(1.0, hi - lo);
  auto with = [&](double v) {
    Json doc = Document(path, v);
    doc.merge_patch(extra);
    return doc;
  };
  CHECK(Accepts(with(lo)));
  CHECK(Accepts(with(hi)));
  CHECK_FALSE(Accepts(with(lo - step)));
  CHECK_FALSE(Accepts(with(hi + step)));
}

// Walks the schema's object properties and compares with the loader's resolved defaults.
void CompareObject(const Json& schemaNode, const Json& resolved, std::vector<std::string> path) {
  const Json& properties = schemaNode.at("properties");
  std::set<std::string> schemaKeys = Keys(properties);
  schemaKeys.erase("$schema");
  INFO("object " << (path.empty() ? std::string("<root>") : path.back()));
  CHECK(schemaKeys == Keys(resolved));
  for (const std::string& key : schemaKeys) {
    if (!resolved.contains(key)) continue;
    const Json& node = properties.at(key);
    INFO("key " << key);
    CHECK(node.contains("description"));
    std::vector<std::string> childPath = path;
    childPath.push_back(key);
    const std::string type = node.at("type").get<std::string>();
    if (type == "object" && node.contains("properties") && key != "joints_deg") {
      CompareObject(node, resolved.at(key), childPath);
      continue;
    }
    if (type == "number" || type == "integer") {
      CHECK(node.at("default").get<double>() == resolved.at(key).get<double>());
      if (key != "seed") CheckRange(childPath, node);
    } else if (type == "array") {
      CHECK(node.at("default") == resolved.at(key));
    } else if (type == "string" || type == "boolean") {
      CHECK(node.at("default") == resolved.at(key));
      if (node.contains("enum")) {
        for (const Json& value : node.at("enum")) CHECK(Accepts(Document(childPath, value)));
        CHECK_FALSE(Accepts(Document(childPath, "not-a-choice")));
      }
    }
  }
}

}  // namespace

TEST_SUITE("input_schema") {
  TEST_CASE("the schema is draft 2020-12 and every key, default and range agrees with the loader") {
    const Json schema = LoadSchema();
    CHECK(schema.at("$schema") == "https://json-schema.org/draft/2020-12/schema");
    Json resolved = Json::parse(rise::RiseSpecToJson(rise::RiseSpec{}).dump());
    // root_euler_deg is written only for posture custom; take its default from such a spec.
    rise::RiseSpec custom;
    custom.start.posture = rise::Posture::kCustom;
    resolved["start"]["root_euler_deg"] = Json::parse(rise::RiseSpecToJson(custom).dump())["start"]["root_euler_deg"];
    CompareObject(schema, resolved, {});
    // The root is closed, like the loader.
    CHECK(schema.at("additionalProperties") == false);
  }

  TEST_CASE("segment overrides: names and fields agree with BipedDef and the loader") {
    const Json segments = LoadSchema().at("properties").at("character").at("properties").at("segments");
    const std::vector<std::string> names = segments.at("propertyNames").at("enum").get<std::vector<std::string>>();
    CHECK(names == rise::SegmentNames());
    const Json& fields = segments.at("additionalProperties").at("properties");
    CHECK(Keys(fields) == std::set<std::string>{"length_m", "width_m", "depth_m", "mass_kg"});
    for (auto it = fields.begin(); it != fields.end(); ++it) {
      INFO(it.key());
      CheckRange({"character", "segments", "thigh_l", it.key()}, it.value(), {{"character", {{"mass_kg", 200}}}});
    }
  }

  TEST_CASE("joint angles: the schema lists each posable joint with the BipedDef limits") {
    const Json joints = LoadSchema().at("properties").at("start").at("properties").at("joints_deg").at("properties");
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
    std::set<std::string> posable;
    for (int i = 0; i < def.skeleton.JointCount(); ++i) {
      if (def.DofCount(i) > 0) posable.insert(def.skeleton.joints[i].name);
    }
    CHECK(Keys(joints) == posable);
    for (const std::string& name : posable) {
      const int joint = def.Find(name);
      const Json& items = joints.at(name).at("prefixItems");
      REQUIRE(static_cast<int>(items.size()) == def.DofCount(joint));
      for (int k = 0; k < def.DofCount(joint); ++k) {
        INFO(name << " dof " << k);
        CHECK(items[k].at("description") == def.bones[joint].dofs[k].name);
        CHECK(items[k].at("minimum").get<double>() == def.bones[joint].dofs[k].minDeg);
        CHECK(items[k].at("maximum").get<double>() == def.bones[joint].dofs[k].maxDeg);
      }
      // The loader accepts an array of the schema's size at the limits and rejects one value more.
      std::vector<double> at(def.DofCount(joint), 0.0);
      CHECK(Accepts(Document({"start", "joints_deg", name}, at)));
      at.push_back(0.0);
      CHECK_FALSE(Accepts(Document({"start", "joints_deg", name}, at)));
    }
  }

  TEST_CASE("disturbances: required keys and ranges agree with the loader") {
    const Json items = LoadSchema().at("properties").at("disturbances").at("items");
    const std::vector<std::string> required = items.at("required").get<std::vector<std::string>>();
    CHECK(std::set<std::string>(required.begin(), required.end()) == Keys(items.at("properties")));
    const Json push = {{"time_s", 1.0}, {"body", "chest"}, {"force_n", {150, 0, 0}}, {"duration_s", 0.2}};
    CHECK(Accepts(Json{{"disturbances", {push}}, {"max_duration_s", 120}}));
    for (const std::string& key : required) {
      Json missing = push;
      missing.erase(key);
      CHECK_FALSE(Accepts(Json{{"disturbances", {missing}}}));
    }
    for (const char* key : {"time_s", "duration_s"}) {
      const Json& node = items.at("properties").at(key);
      for (const double v : {node.at("minimum").get<double>(), node.at("maximum").get<double>()}) {
        Json ok = push;
        ok[key] = v;
        CHECK(Accepts(Json{{"disturbances", {ok}}, {"max_duration_s", 120}}));
      }
      Json below = push;
      below[key] = node.at("minimum").get<double>() - 1e-4;
      CHECK_FALSE(Accepts(Json{{"disturbances", {below}}, {"max_duration_s", 120}}));
    }
    CHECK(items.at("properties").at("body").at("enum").get<std::vector<std::string>>() == rise::SegmentNames());
  }
}
