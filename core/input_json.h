// SPDX-License-Identifier: MIT
// The input file: JSON text -> RiseSpec, every mistake reported with file, JSON path, what was
// found and what is allowed; and RiseSpec -> JSON (the fully resolved input kept as clip metadata).
//
// Rules the loader enforces (the schema, schema/rise-input.schema.json, states the same):
// - every key is optional and has a default, except inside a disturbance, where all are required;
// - unknown keys and duplicate keys are errors (a typo must never silently become a default);
//   unknown keys get a "did you mean" hint by edit distance;
// - numbers must be finite and inside their documented range; whole numbers where a count is meant;
// - joint angles are checked against the joint's DOF count and limits (biped_def.h);
// - the first mistake found is the one reported.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/result.h"
#include "core/rise_spec.h"

namespace rise {

// Parses the text of an input file. fileName only labels error messages.
Result<RiseSpec> ParseRiseSpec(const std::string& text, const std::string& fileName);

// Reads and parses a file; an unreadable file is an InputError with no JSON path.
Result<RiseSpec> LoadRiseSpec(const std::string& path);

// Reads an already parsed JSON value, e.g. one clip of a batch manifest. Keys the value does
// not mention keep their value from `base`; a "segments" or "joints_deg" entry replaces that
// one entry, a "disturbances" array replaces the whole list. pathPrefix is put in front of every
// JSON path in errors (e.g. "clips[3]").
Result<RiseSpec> RiseSpecFromJson(const nlohmann::json& value, const std::string& fileName,
                                  const std::string& pathPrefix = "", const RiseSpec& base = RiseSpec{});

// The fully resolved input: every key with its value, in the file format, so that
// RiseSpecFromJson(RiseSpecToJson(spec)) == spec. Keys in the order of the schema.
nlohmann::ordered_json RiseSpecToJson(const RiseSpec& spec);

// 1-based line and column of a byte offset into text (the column counts bytes).
void TextPosition(const std::string& text, size_t byteOffset, int& line, int& column);

// Levenshtein distance, used for "did you mean" hints.
int EditDistance(const std::string& a, const std::string& b);

}  // namespace rise
