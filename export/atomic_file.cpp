// SPDX-License-Identifier: MIT
// All-or-nothing file output through a temporary file and a rename.
#include "export/atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

namespace rise {
namespace {

// A temporary is the destination's name, this, and mkstemp's six characters.
constexpr const char* kTemporaryInfix = ".tmp.";

std::string Failure(const std::string& path, const std::string& cause) {
  return "cannot write '" + path + "': " + cause;
}

// No write permission for this process, or none for anyone (see CheckWritable).
bool ReadOnly(const std::filesystem::path& path) {
  struct stat status {};
  return ::access(path.c_str(), W_OK) != 0 ||
         (::stat(path.c_str(), &status) == 0 && (status.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0);
}

}  // namespace

std::string CheckWritable(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) return Failure(path, "the path is empty");
  const fs::path target(path);
  if (!target.has_filename() || target.filename() == "." || target.filename() == "..") {
    return Failure(path, "the path names a folder, not a file");
  }
  std::error_code ec;
  if (fs::is_directory(target, ec)) return Failure(path, "a folder of that name exists");
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(folder, ec)) return Failure(path, "folder '" + folder.string() + "' does not exist");
  if (ReadOnly(folder)) return Failure(path, "folder '" + folder.string() + "' is read-only");
  if (fs::exists(target, ec) && ReadOnly(target)) return Failure(path, "the file is read-only");
  return {};
}

void RemoveAbandonedTemporaries(const std::vector<std::string>& paths) {
  namespace fs = std::filesystem;
  std::map<fs::path, std::set<std::string>> prefixesIn;  // folder -> "<file name>.tmp."
  for (const std::string& path : paths) {
    const fs::path target(path);
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    prefixesIn[folder].insert(target.filename().string() + kTemporaryInfix);
  }
  constexpr size_t kUniqueChars = 6;  // mkstemp's XXXXXX
  std::error_code ec;
  for (const auto& [folder, prefixes] : prefixesIn) {
    std::vector<fs::path> abandoned;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (name.size() <= kUniqueChars || !prefixes.count(name.substr(0, name.size() - kUniqueChars))) continue;
      if (it->is_regular_file(ec)) abandoned.push_back(it->path());
    }
    for (const fs::path& file : abandoned) fs::remove(file, ec);
  }
}

std::string WriteFileAtomically(const std::string& path, std::string_view bytes) {
  if (std::string problem = CheckWritable(path); !problem.empty()) return problem;

  // mkstemp picks a name no other writer uses, even for the same destination.
  std::string tempName = path + kTemporaryInfix + "XXXXXX";
  std::vector<char> tempPath(tempName.begin(), tempName.end());
  tempPath.push_back('\0');
  const int fd = mkstemp(tempPath.data());
  if (fd < 0) return Failure(path, std::strerror(errno));
  tempName.assign(tempPath.data());

  const char* data = bytes.data();
  size_t left = bytes.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      const std::string cause = written < 0 ? std::strerror(errno) : "nothing could be written";
      ::close(fd);
      std::remove(tempName.c_str());
      return Failure(path, cause);
    }
    data += written;
    left -= static_cast<size_t>(written);
  }
  // mkstemp creates 0600; a clip is an ordinary shared file (umask is not read:
  // changing it to read it would race with other threads creating files).
  (void)::fchmod(fd, 0644);
  // No fsync: the rename is atomic for every other process, which is the
  // promise; surviving a power cut is not worth its milliseconds per clip.
  if (::close(fd) != 0) {
    const std::string cause = std::strerror(errno);
    std::remove(tempName.c_str());
    return Failure(path, cause);
  }
  if (std::rename(tempName.c_str(), path.c_str()) != 0) {
    const std::string cause = std::strerror(errno);
    std::remove(tempName.c_str());
    return Failure(path, cause);
  }
  return {};
}

}  // namespace rise
