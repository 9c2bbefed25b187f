// SPDX-License-Identifier: MIT
// All-or-nothing file output: a reader (or a crashed run) never sees half a
// clip. The bytes go to a temporary file in the destination's own folder (so
// the final rename stays on one filesystem and is atomic) and replace the
// destination only once they are completely written.
#pragma once

#include <string>
#include <string_view>

namespace rise {

// Writes `bytes` to `path`. Returns an empty string on success, otherwise a
// message naming the path and the cause (missing folder, not writable, path is
// a folder or malformed). On failure no file is left behind: neither the
// temporary nor a partial `path`; an existing `path` is left untouched.
std::string WriteFileAtomically(const std::string& path, std::string_view bytes);

}  // namespace rise
