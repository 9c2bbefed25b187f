// SPDX-License-Identifier: MIT
// All-or-nothing file output: a reader (or a crashed run) never sees half a
// clip. The bytes go to a temporary file in the destination's own folder (so
// the final rename stays on one filesystem and is atomic) and replace the
// destination only once they are completely written.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rise {

// Writes `bytes` to `path`. Returns an empty string on success, otherwise a
// message naming the path and the cause (missing folder, not writable, path is
// a folder or malformed). On failure no file is left behind: neither the
// temporary nor a partial `path`; an existing `path` is left untouched.
std::string WriteFileAtomically(const std::string& path, std::string_view bytes);

// Removes the temporaries of `paths` that writers killed mid-write left in their folders
// (regular files named `<file name>.tmp.` plus mkstemp's six characters), reading each folder
// once. Only for paths no other process is writing at the same time: its temporary would go
// too, and its rename fail.
void RemoveAbandonedTemporaries(const std::vector<std::string>& paths);

// Why `path` cannot be written ("" when, as far as can be told before writing, it can), in the
// words of WriteFileAtomically's messages: the path is empty or names a folder, its folder is
// missing or not writable, or the folder or an existing file at `path` is read-only. Read-only
// means no write permission for this process, or none for anyone: a protection the user set,
// honoured here even for root, whom the system would let through. WriteFileAtomically checks it
// first; callers check it before long work so a bad path costs no time.
std::string CheckWritable(const std::string& path);

}  // namespace rise
