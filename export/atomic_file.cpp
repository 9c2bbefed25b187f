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
#include <vector>

namespace rise {
namespace {

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

std::string WriteFileAtomically(const std::string& path, std::string_view bytes) {
  if (std::string problem = CheckWritable(path); !problem.empty()) return problem;

  // mkstemp picks a name no other writer uses, even for the same destination.
  std::string tempName = path + ".tmp.XXXXXX";
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
