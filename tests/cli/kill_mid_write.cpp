// SPDX-License-Identifier: MIT
// Never lose work (issue 8 §3): SIGKILL a real rise-gen process while it writes, over and over,
// and check that every output is then byte for byte the complete old file or the complete new one.
//
//   kill_mid_write <rise-gen> <input.json> <manifest.json> <work folder>
//
// Part 1, one clip: a good old out.glb/out.bvh/out.meta.json (from --seed 1) is overwritten by a run
// with --seed 2. Most kills wait for the moment rise-gen creates the temporary file of a chosen
// output (inotify reports it within microseconds) and then a random 0-2 ms, so they land inside
// the write itself; the others land at a random time of the whole run. After each kill every
// output must equal the old or the new reference and read back as a clip. How many kills caught
// a half-written temporary file is printed: the proof that the writes were really interrupted.
// Part 2, a batch: the tiny library is killed at random times, resumed and killed again; after
// each kill index.json (when there is one) parses, every clip it lists as finished has files
// that read back, and every clip file in the folder reads back. A last uninterrupted run must
// then give exactly the files and index of a clean run.
//
// Kill times come from a fixed seed, and the invariant holds for every kill time, so the test
// cannot flake; only how many kills land mid-write (printed) varies with timing. At least half the
// runs must really be killed (the rest may have finished first).
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "export/bvh_reader.h"
#include "export/gltf_reader.h"

extern char** environ;

namespace fs = std::filesystem;

namespace {

int failures = 0;

void Fail(const std::string& what) {
  std::printf("RISE_KILL_FAILED: %s\n", what.c_str());
  ++failures;
}

std::string Bytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

pid_t Spawn(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// Waits for the process; returns its exit code, or 128 + signal.
int Wait(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int RunToEnd(const std::vector<std::string>& args) {
  const pid_t pid = Spawn(args);
  return pid < 0 ? -1 : Wait(pid);
}

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// "" when `path` reads back as a clip of its kind, otherwise why not.
std::string ReadBack(const fs::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".glb") {
    rise::Clip clip;
    return rise::ReadGltf(path.string(), clip);
  }
  if (ext == ".bvh") {
    rise::BvhMotion motion;
    return rise::ReadBvh(path.string(), rise::BvhFormat{}, motion);
  }
  return nlohmann::json::accept(Bytes(path)) ? "" : "not JSON";
}

void RemoveTemporaries(const fs::path& folder) {
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().filename().string().find(".tmp.") != std::string::npos) fs::remove(entry.path());
  }
}

// Blocks until a file whose name starts with `prefix` is created in the watched folder, or the
// process ends (checked every 10 ms). Returns whether it was seen.
bool WaitForCreate(int inotify, const std::string& prefix, pid_t pid) {
  alignas(inotify_event) char buffer[4096];
  for (;;) {
    pollfd p{inotify, POLLIN, 0};
    if (poll(&p, 1, 10) > 0) {
      const ssize_t n = read(inotify, buffer, sizeof buffer);
      for (ssize_t at = 0; at < n;) {
        const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
        if (event->len > 0 && std::string(event->name).rfind(prefix, 0) == 0) return true;
        at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
      }
    }
    if (waitpid(pid, nullptr, WNOHANG) != 0) return false;
  }
}

void OneClip(const std::string& riseGen, const std::string& input, const fs::path& work) {
  const fs::path oldDir = work / "old", newDir = work / "new", out = work / "out";
  for (const fs::path& dir : {oldDir, newDir, out}) fs::create_directories(dir);
  const std::vector<std::string> names = {"clip.glb", "clip.bvh", "clip.meta.json"};
  // 240 fps over 10 s: multi-megabyte files whose writes take long enough to be hit.
  auto command = [&](const fs::path& dir, const char* seed) {
    return std::vector<std::string>{riseGen,
                                    input,
                                    "-o",
                                    (dir / "clip.glb").string(),
                                    "-o",
                                    (dir / "clip.bvh").string(),
                                    "--fps",
                                    "240",
                                    "--max-duration",
                                    "10",
                                    "--seed",
                                    seed,
                                    "-q"};
  };
  const auto start = std::chrono::steady_clock::now();
  for (const auto& [dir, seed] : {std::pair{oldDir, "1"}, std::pair{newDir, "2"}}) {
    const int code = RunToEnd(command(dir, seed));
    if (code != 0 && code != 1) return Fail("reference run exited " + std::to_string(code));
  }
  const double runSeconds = Seconds(start) / 2.0;
  for (const std::string& name : names) {
    for (const fs::path& dir : {oldDir, newDir}) {
      if (const std::string problem = ReadBack(dir / name); !problem.empty()) return Fail("reference " + problem);
    }
    if (Bytes(oldDir / name) == Bytes(newDir / name)) return Fail("old and new " + name + " are the same bytes");
  }
  std::printf("one clip: %zu + %zu bytes (glb + bvh), %.2f s per run\n", Bytes(newDir / "clip.glb").size(),
              Bytes(newDir / "clip.bvh").size(), runSeconds);

  std::mt19937 rng(8);
  int midWrite = 0, kills = 0;
  const int kTrials = 12;
  for (int trial = 0; trial < kTrials; ++trial) {
    RemoveTemporaries(out);
    for (const std::string& name : names)
      fs::copy_file(oldDir / name, out / name, fs::copy_options::overwrite_existing);
    const int inotify = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    inotify_add_watch(inotify, out.c_str(), IN_CREATE);
    const pid_t pid = Spawn(command(out, "2"));
    // Trials cycle: kill in the glb's write, in the bvh's write, in the sidecar's, at a random time.
    const int mode = trial % 4;
    bool seen = true;
    if (mode < 3) {
      seen = WaitForCreate(inotify, names[mode] + ".tmp.", pid);
      std::this_thread::sleep_for(std::chrono::microseconds(std::uniform_int_distribution<int>(0, 2000)(rng)));
    } else {
      std::this_thread::sleep_for(
          std::chrono::duration<double>(std::uniform_real_distribution<double>(0.0, runSeconds)(rng)));
    }
    close(inotify);
    if (!seen) Fail("trial " + std::to_string(trial) + ": the process ended before writing " + names[mode]);
    kill(pid, SIGKILL);
    kills += Wait(pid) == 128 + SIGKILL ? 1 : 0;
    std::string state;
    for (const std::string& name : names) {
      const std::string now = Bytes(out / name);
      const bool isOld = now == Bytes(oldDir / name), isNew = now == Bytes(newDir / name);
      if (!isOld && !isNew)
        Fail("trial " + std::to_string(trial) + ": " + name + " is neither the old nor the new file");
      if (const std::string problem = ReadBack(out / name); !problem.empty()) Fail(name + " does not read: " + problem);
      state += " " + name + "=" + (isOld ? "old" : isNew ? "new" : "BROKEN");
    }
    for (const auto& entry : fs::directory_iterator(out)) {
      const std::string file = entry.path().filename().string();
      const size_t tmp = file.find(".tmp.");
      if (tmp == std::string::npos) continue;
      const bool partial = fs::file_size(entry.path()) < Bytes(newDir / file.substr(0, tmp)).size();
      midWrite += partial ? 1 : 0;
      state += " (left " + file.substr(0, tmp) + (partial ? " temporary half written)" : " temporary complete)");
    }
    std::printf("trial %d (%s):%s\n", trial, mode == 3 ? "random time" : ("in " + names[mode]).c_str(), state.c_str());
  }
  RemoveTemporaries(out);
  std::printf("one clip: %d SIGKILLs, %d caught a half-written temporary, every output old or new\n", kills, midWrite);
  // A kill can come after the run's last write (then both outputs are simply new); most may not.
  if (kills < kTrials / 2) Fail("only " + std::to_string(kills) + " of the runs were killed");
}

// Every clip file in `folder` reads back; index.json, when there, parses and its finished clips'
// files read back.
void CheckBatchFolder(const fs::path& folder, int trial) {
  const std::string label = "batch trial " + std::to_string(trial) + ": ";
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string file = entry.path().filename().string();
    if (file.find(".tmp.") != std::string::npos) continue;
    if (const std::string problem = ReadBack(entry.path()); !problem.empty()) Fail(label + file + ": " + problem);
  }
  if (!fs::exists(folder / "index.json")) return;
  const nlohmann::json index = nlohmann::json::parse(Bytes(folder / "index.json"), nullptr, false);
  if (index.is_discarded() || !index.contains("clips")) return Fail(label + "index.json does not parse");
  for (const nlohmann::json& clip : index["clips"]) {
    if (clip.value("status", "") == "pending") continue;
    for (const auto& [kind, name] : clip["files"].items()) {
      if (!fs::exists(folder / name.get<std::string>())) Fail(label + "finished clip file " + name.dump() + " missing");
    }
  }
}

void Batch(const std::string& riseGen, const std::string& manifest, const fs::path& work) {
  const fs::path clean = work / "batch_clean", out = work / "batch_out";
  fs::create_directories(clean);
  fs::create_directories(out);
  auto command = [&](const fs::path& dir) {
    return std::vector<std::string>{riseGen, "batch", manifest, "-o", dir.string(), "--jobs", "2", "-q"};
  };
  const auto start = std::chrono::steady_clock::now();
  if (RunToEnd(command(clean)) > 1) return Fail("clean batch run failed");
  const double runSeconds = Seconds(start);
  std::mt19937 rng(9);
  const int kTrials = 8;
  for (int trial = 0; trial < kTrials; ++trial) {
    const pid_t pid = Spawn(command(out));
    std::this_thread::sleep_for(
        std::chrono::duration<double>(std::uniform_real_distribution<double>(0.0, runSeconds)(rng)));
    kill(pid, SIGKILL);
    const int code = Wait(pid);
    CheckBatchFolder(out, trial);
    std::printf("batch trial %d: %s\n", trial, code == 128 + SIGKILL ? "killed" : "had finished");
    // Every third trial starts from nothing again, so early kills stay in the mix.
    if (trial % 3 == 2) {
      fs::remove_all(out);
      fs::create_directories(out);
    }
  }
  if (RunToEnd(command(out)) > 1) return Fail("resumed batch run failed");
  RemoveTemporaries(out);
  std::vector<std::string> cleanFiles, outFiles;
  for (const auto& entry : fs::directory_iterator(clean)) cleanFiles.push_back(entry.path().filename().string());
  for (const auto& entry : fs::directory_iterator(out)) outFiles.push_back(entry.path().filename().string());
  std::sort(cleanFiles.begin(), cleanFiles.end());
  std::sort(outFiles.begin(), outFiles.end());
  if (cleanFiles != outFiles) return Fail("the resumed folder holds other files than a clean run");
  for (const std::string& file : cleanFiles) {
    if (Bytes(clean / file) != Bytes(out / file)) Fail("resumed " + file + " differs from a clean run's");
  }
  std::printf(
      "batch: %d SIGKILLs at random times (clean run %.2f s), index and files valid after each; "
      "the resumed run equals a clean one (%zu files)\n",
      kTrials, runSeconds, cleanFiles.size());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: kill_mid_write <rise-gen> <input.json> <manifest.json> <work folder>\n");
    return 2;
  }
  const fs::path work = argv[4];
  fs::remove_all(work);
  fs::create_directories(work);
  OneClip(argv[1], argv[2], work);
  Batch(argv[1], argv[3], work);
  if (failures == 0) std::printf("never lose work: every check held\n");
  return failures == 0 ? 0 : 1;
}
