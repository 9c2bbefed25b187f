// SPDX-License-Identifier: MIT
// JSON syntax checking shared by the manifest loader; see json_text.h.
#include "core/json_text.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "core/input_json.h"

namespace rise {
namespace {

using Json = nlohmann::json;

// Follows the parser's events to name the path of the first key repeated inside one object.
class DuplicateKeys {
 public:
  bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
      case Json::parse_event_t::array_start:
        frames_.push_back({event == Json::parse_event_t::array_start, 0, {}, {}});
        break;
      case Json::parse_event_t::key: {
        Frame& frame = frames_.back();
        frame.key = parsed.get<std::string>();
        if (!frame.keys.insert(frame.key).second && firstPath.empty()) firstPath = Path();
        break;
      }
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        frames_.pop_back();
        CountElement();
        break;
      case Json::parse_event_t::value:
        CountElement();
        break;
    }
    return true;
  }

  std::string firstPath;

 private:
  struct Frame {
    bool array;
    size_t index;  // next element of an array
    std::string key;
    std::set<std::string> keys;
  };

  void CountElement() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }

  std::string Path() const {
    std::string path;
    for (const Frame& frame : frames_) {
      if (frame.array) {
        path += "[" + std::to_string(frame.index) + "]";
      } else {
        path += (path.empty() ? "" : ".") + frame.key;
      }
    }
    return path;
  }

  std::vector<Frame> frames_;
};

}  // namespace

Result<Json> ParseJsonText(const std::string& text, const std::string& fileName) {
  DuplicateKeys duplicates;
  Json root;
  try {
    root = Json::parse(text, std::ref(duplicates));
  } catch (const Json::parse_error& e) {
    InputError error{fileName, "", "", 0, 0};
    TextPosition(text, e.byte > 0 ? e.byte - 1 : 0, error.line, error.column);
    // nlohmann's "[json.exception.parse_error.101] parse error at line L, column C: " repeats the position.
    const std::string what = e.what();
    const size_t colon = what.find(": ");
    error.message = "invalid JSON: " + (colon == std::string::npos ? what : what.substr(colon + 2));
    return error;
  } catch (const Json::exception& e) {
    InputError error{fileName, "", "invalid JSON: " + std::string(e.what()), 0, 0};
    const std::string what = e.what();
    const size_t open = what.find('\''), close = what.rfind('\'');
    if (open != std::string::npos && close > open) {
      const std::string literal = what.substr(open + 1, close - open - 1);
      const size_t at = text.find(literal);
      if (at != std::string::npos) TextPosition(text, at, error.line, error.column);
      error.message = "found the number " + literal + ", allowed: numbers a double can hold (about 1e308)";
    }
    return error;
  }
  if (!duplicates.firstPath.empty()) {
    return InputError{fileName, duplicates.firstPath, "found this key twice in the same object, allowed: once", 0, 0};
  }
  return root;
}

Result<std::string> ReadInputFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return InputError{path, "", "cannot open the file for reading", 0, 0};
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return InputError{path, "", "cannot read the file", 0, 0};
  return text.str();
}

std::string DescribeJsonValue(const Json& value) {
  switch (value.type()) {
    case Json::value_t::string:
      return "\"" + value.get<std::string>() + "\" (a string)";
    case Json::value_t::boolean:
      return value.get<bool>() ? "true (a boolean)" : "false (a boolean)";
    case Json::value_t::null:
      return "null";
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array:
      return "an array of " + std::to_string(value.size());
    case Json::value_t::number_float: {
      char text[32];
      std::snprintf(text, sizeof text, "%.6g", value.get<double>());
      return text;
    }
    default:
      return value.dump();
  }
}

std::string ClosestName(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best;
  int bestDistance = std::max(2, static_cast<int>(name.size()) / 3) + 1;
  for (const std::string& candidate : candidates) {
    const int d = EditDistance(name, candidate);
    if (d < bestDistance) {
      bestDistance = d;
      best = candidate;
    }
  }
  return best;
}

std::string JoinNames(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

std::optional<UnknownKey> FindUnknownKey(const Json& object, const std::vector<std::string>& allowed) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (std::find(allowed.begin(), allowed.end(), it.key()) != allowed.end()) continue;
    std::string message = "unknown key \"" + it.key() + "\"";
    const std::string guess = ClosestName(it.key(), allowed);
    if (!guess.empty()) message += ", did you mean \"" + guess + "\"?";
    return UnknownKey{it.key(), message + " allowed: " + JoinNames(allowed)};
  }
  return std::nullopt;
}

}  // namespace rise
