// SPDX-License-Identifier: MIT
// JSON text -> a parsed document with the input loader's syntax rules, for files that are not
// a single RiseSpec (batch manifests): syntax errors carry line and column, numbers too large
// for a double are named, and a key given twice in one object is an error, not a silent overwrite.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"

namespace rise {

// Parses `text`; fileName only labels error messages.
Result<nlohmann::json> ParseJsonText(const std::string& text, const std::string& fileName);

// The bytes of a file; an unreadable file is an InputError with no JSON path.
Result<std::string> ReadInputFile(const std::string& path);

// How a found value is named in a message: `"sitting" (a string)`, `an array of 3`, `2.5`.
std::string DescribeJsonValue(const nlohmann::json& value);

// The candidate closest to `name` by edit distance, or "" when none is close enough to be a typo.
std::string ClosestName(const std::string& name, const std::vector<std::string>& candidates);

// Names joined with ", " for "allowed: ..." messages.
std::string JoinNames(const std::vector<std::string>& names);

// The first key of an object that is not in `allowed`, and the message the loaders give for it:
// `unknown key "strat", did you mean "start"? allowed: character, start, ...`.
struct UnknownKey {
  std::string key;
  std::string message;
};
std::optional<UnknownKey> FindUnknownKey(const nlohmann::json& object, const std::vector<std::string>& allowed);

}  // namespace rise
