// SPDX-License-Identifier: MIT
// JSON text -> a parsed document with the input loader's syntax rules, for files that are not
// a single RiseSpec (batch manifests): syntax errors carry line and column, numbers too large
// for a double are named, and a key given twice in one object is an error, not a silent overwrite.
#pragma once

#include <nlohmann/json.hpp>
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

}  // namespace rise
