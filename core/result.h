// SPDX-License-Identifier: MIT
// Result<T>: a value or the one mistake found in user data (tier 2 of the three error tiers).
//
// User data (input files, manifests, options) is never trusted, so a loader
// returns a Result instead of asserting. The error names where the mistake is
// (file, JSON path, and line/column for syntax errors) and says what was found
// and what is allowed, so the CLI can print it once and exit with code 2.
#pragma once

#include <string>
#include <utility>
#include <variant>

#include "base/assert.h"

namespace rise {

struct InputError {
  std::string file;      // as the user named it; may be empty for in-memory text
  std::string jsonPath;  // e.g. "start.posture" or "disturbances[0].force_n"; empty for syntax/I/O errors
  std::string message;   // what was found, what is allowed
  int line = 0;          // 1-based; 0 when the error is not about a text position
  int column = 0;        // 1-based

  // One line: `file:line:column: path: message`, leaving out the parts that are empty or 0.
  // Example: `in.json: start.posture: found "sitting", allowed: supine, prone, side_left, side_right, custom`.
  std::string Format() const {
    std::string text = file.empty() ? std::string("<input>") : file;
    if (line > 0) text += ":" + std::to_string(line) + ":" + std::to_string(column);
    text += ": ";
    if (!jsonPath.empty()) text += jsonPath + ": ";
    return text + message;
  }
};

template <typename T>
class Result {
 public:
  Result(T value) : state_(std::move(value)) {}           // NOLINT: implicit by design, `return value;`
  Result(InputError error) : state_(std::move(error)) {}  // NOLINT: implicit by design, `return error;`

  bool IsOk() const { return state_.index() == 0; }
  explicit operator bool() const { return IsOk(); }

  const T& Value() const {
    RISE_ASSERT_MSG(IsOk(), "Value() of a failed Result");
    return std::get<0>(state_);
  }
  T& Value() {
    RISE_ASSERT_MSG(IsOk(), "Value() of a failed Result");
    return std::get<0>(state_);
  }
  const InputError& Error() const {
    RISE_ASSERT_MSG(!IsOk(), "Error() of a successful Result");
    return std::get<1>(state_);
  }

 private:
  std::variant<T, InputError> state_;
};

}  // namespace rise
