// SPDX-License-Identifier: MIT
#include <filesystem>
#include <fstream>
#include <string>

#include "core/batch_runner.h"
#include "core/input_json.h"
#include "export/gltf_reader.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;

// Three one-second clips (too short to stand): two of one body, one of another.
const char* const kManifest = R"({
  "formats": ["glb", "bvh"],
  "defaults": { "max_duration_s": 1, "fps": 20 },
  "clips": [ { "name": "small_side", "body": "small", "character": { "height_m": 1.5, "mass_kg": 50 },
               "start": { "posture": "side_left" } } ],
  "cross": { "starts": ["supine", "prone"] } })";

rise::LibraryManifest Manifest(const std::string& text = kManifest) {
  rise::Result<rise::LibraryManifest> result = rise::ParseLibraryManifest(text, "lib.json");
  REQUIRE(result.IsOk());
  return result.Value();
}

std::vector<size_t> All(const rise::LibraryManifest& manifest) {
  return rise::ShardClips(manifest.clips.size(), rise::Shard{});
}

// A fresh, empty folder for one test case.
std::string Folder(const std::string& name) {
  const fs::path dir = fs::path(RISE_BINARY_DIR) / "test_batch_runner" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

// Every file of folder a has a byte-identical twin in b and the reverse.
void CheckSameFolders(const std::string& a, const std::string& b) {
  size_t count = 0;
  for (const auto& entry : fs::directory_iterator(a)) {
    CAPTURE(entry.path().filename().string());
    const fs::path twin = fs::path(b) / entry.path().filename();
    REQUIRE(fs::exists(twin));
    CHECK(rise::test::FileContents(entry.path()) == rise::test::FileContents(twin));
    ++count;
  }
  CHECK(count == static_cast<size_t>(std::distance(fs::directory_iterator(b), fs::directory_iterator())));
}

rise::BatchOptions Options(const std::string& dir, int jobs) {
  rise::BatchOptions options;
  options.outDir = dir;
  options.jobs = jobs;
  options.manifestLabel = "lib.json";
  return options;
}

}  // namespace

TEST_SUITE("batch_runner") {
  TEST_CASE("one and two worker threads write byte-identical clips, libraries and index") {
    const rise::LibraryManifest manifest = Manifest();
    rise::BatchOptions one = Options(Folder("jobs1"), 1), two = Options(Folder("jobs2"), 2);
    one.libraryGlb = two.libraryGlb = true;
    const rise::BatchReport a = rise::RunBatch(manifest, All(manifest), one);
    const rise::BatchReport b = rise::RunBatch(manifest, All(manifest), two);
    CHECK(a.index == b.index);
    CheckSameFolders(one.outDir, two.outDir);
    CHECK(fs::exists(fs::path(one.outDir) / "library_small.glb"));
    CHECK(fs::exists(fs::path(one.outDir) / "library_default.glb"));
    REQUIRE(a.index["libraries"].size() == 2);
    CHECK(a.index["libraries"][1]["clips"] == nlohmann::ordered_json{"back_supine_s1", "stomach_prone_s1"});
    rise::Clip first;
    CHECK(rise::ReadGltf((fs::path(one.outDir) / "library_default.glb").string(), first).empty());
    CHECK(first.FrameCount() == 21);
  }

  TEST_CASE("an index entry holds the files, the full resolved input and the measured figures") {
    const rise::LibraryManifest manifest = Manifest();
    const rise::BatchOptions options = Options(Folder("entry"), 2);
    const rise::BatchReport report = rise::RunBatch(manifest, All(manifest), options);
    CHECK(report.progress.total == 3);
    CHECK(report.progress.finished == 3);
    CHECK(report.failed == 3);  // one second is too short to stand
    CHECK_FALSE(report.stopped);
    CHECK(report.ioError.empty());
    // The file on disk is the document the report holds.
    CHECK(nlohmann::ordered_json::parse(rise::test::FileContents(fs::path(options.outDir) / "index.json")) == report.index);
    CHECK(report.index["summary"]["clips"] == 3);
    CHECK(report.index["summary"]["failed"] == 3);
    const auto& entry = report.index["clips"][1];
    CHECK(entry["name"] == "back_supine_s1");
    CHECK(entry["category"] == "back");
    CHECK(entry["body"] == "default");
    CHECK(entry["status"] == "failed");
    CHECK(entry["error"].get<std::string>().find("ends standing") != std::string::npos);
    CHECK(entry["files"]["glb"] == "back_supine_s1.glb");
    CHECK(entry["files"]["bvh"] == "back_supine_s1.bvh");
    CHECK(entry["files"]["metadata"] == "back_supine_s1.meta.json");
    CHECK(entry["input"] == rise::RiseSpecToJson(manifest.clips[1].spec));
    CHECK(entry["input_hash"] == rise::InputHash(manifest.clips[1].spec));
    CHECK(entry["frames"] == 21);  // 1 s at 20 fps
    CHECK(entry["duration_s"].get<double>() == doctest::Approx(1.0));
    CHECK(entry["quality"]["passed"] == false);
    CHECK(entry["quality"]["bvh"]["maxDistance"].get<double>() < 0.01);
    rise::Clip clip;
    CHECK(rise::ReadGltf((fs::path(options.outDir) / "back_supine_s1.glb").string(), clip).empty());
    CHECK(clip.FrameCount() == 21);
  }

  TEST_CASE("a rerun skips up-to-date clips and regenerates only a clip whose input changed") {
    rise::LibraryManifest manifest = Manifest();
    const rise::BatchOptions options = Options(Folder("resume"), 2);
    const rise::BatchReport first = rise::RunBatch(manifest, All(manifest), options);
    const rise::BatchReport again = rise::RunBatch(manifest, All(manifest), options);
    CHECK(again.progress.skipped == 3);
    CHECK(again.index == first.index);

    manifest.clips[0].spec.seed = 5;
    const rise::BatchReport changed = rise::RunBatch(manifest, All(manifest), options);
    CHECK(changed.progress.skipped == 2);
    CHECK(changed.index["clips"][0]["input"]["seed"] == 5);
    CHECK(changed.index["clips"][1] == first.index["clips"][1]);

    // A clip another rise-gen version made is made anew: the same input may move otherwise now.
    const fs::path sidecar = fs::path(options.outDir) / changed.index["clips"][1]["files"]["metadata"].get<std::string>();
    std::string text;
    {
      std::ifstream in(sidecar);
      text.assign(std::istreambuf_iterator<char>(in), {});
    }
    const std::string generator = "\"rise-gen " RISE_VERSION "\"";
    REQUIRE(text.find(generator) != std::string::npos);
    text.replace(text.find(generator), generator.size(), "\"rise-gen 0.0.0-old\"");
    std::ofstream(sidecar) << text;
    const rise::BatchReport upgraded = rise::RunBatch(manifest, All(manifest), options);
    CHECK(upgraded.progress.skipped == 2);
    CHECK(upgraded.index == changed.index);
  }

  TEST_CASE("a rerun after a killed run clears the temporaries it left") {
    const rise::LibraryManifest manifest = Manifest();
    const std::string dir = Folder("abandoned");
    for (const char* name : {"index.json.tmp.k1LLed", "small_side.glb.tmp.k1LLed", "small_side.bvh.tmp.a0b1c2",
                             "library_small.glb.tmp.Zz9Zz9"}) {
      std::ofstream(fs::path(dir) / name) << "half";
    }
    rise::BatchOptions options = Options(dir, 1);
    options.libraryGlb = true;
    rise::RunBatch(manifest, All(manifest), options);
    for (const auto& entry : fs::directory_iterator(dir)) {
      CAPTURE(entry.path().filename().string());
      CHECK(entry.path().filename().string().find(".tmp.") == std::string::npos);
    }
    CHECK(fs::exists(fs::path(dir) / "small_side.glb"));
    CHECK(fs::exists(fs::path(dir) / "library_small.glb"));
  }
  TEST_CASE("a clip that cannot be written is an error entry with no files, and the others go on") {
    const rise::LibraryManifest manifest = Manifest();
    const rise::BatchOptions options = Options(Folder("write_error"), 2);
    // A folder where the clip's .bvh should go makes that write fail after the .glb succeeded.
    fs::create_directory(fs::path(options.outDir) / "back_supine_s1.bvh");
    const rise::BatchReport report = rise::RunBatch(manifest, All(manifest), options);
    CHECK(report.errors == 1);
    CHECK(report.failed == 2);
    const auto& entry = report.index["clips"][1];
    CHECK(entry["status"] == "error");
    CHECK(entry["error"].get<std::string>().find("back_supine_s1.bvh") != std::string::npos);
    CHECK_FALSE(fs::exists(fs::path(options.outDir) / "back_supine_s1.glb"));
    CHECK_FALSE(fs::exists(fs::path(options.outDir) / "back_supine_s1.meta.json"));
    CHECK(fs::exists(fs::path(options.outDir) / "stomach_prone_s1.glb"));
  }

  TEST_CASE("a stop request before the start leaves a valid index of pending clips and no clip files") {
    const rise::LibraryManifest manifest = Manifest();
    const std::atomic<bool> stop{true};
    rise::BatchOptions options = Options(Folder("stopped"), 2);
    options.stop = &stop;
    options.libraryGlb = true;
    const rise::BatchReport report = rise::RunBatch(manifest, All(manifest), options);
    CHECK(report.stopped);
    CHECK(report.pending == 3);
    const auto index = nlohmann::ordered_json::parse(rise::test::FileContents(fs::path(options.outDir) / "index.json"));
    CHECK(index["summary"]["pending"] == 3);
    CHECK(index["clips"][0]["status"] == "pending");
    CHECK_FALSE(index.contains("libraries"));
    CHECK(std::distance(fs::directory_iterator(options.outDir), fs::directory_iterator()) == 1);
  }

  TEST_CASE("a shard runs only its clips and names its index after the slice") {
    const rise::LibraryManifest manifest = Manifest();
    rise::BatchOptions options = Options(Folder("shard"), 1);
    options.indexName = "index-1-of-2.json";
    options.shardLabel = "1/2";
    const rise::BatchReport report = rise::RunBatch(manifest, rise::ShardClips(3, rise::Shard{1, 2}), options);
    REQUIRE(report.index["clips"].size() == 1);
    CHECK(report.index["clips"][0]["name"] == "back_supine_s1");
    CHECK(report.index["shard"] == "1/2");
    CHECK(fs::exists(fs::path(options.outDir) / "index-1-of-2.json"));
    CHECK_FALSE(fs::exists(fs::path(options.outDir) / "small_side.glb"));
  }

  TEST_CASE("the output folder is made with its missing parents; a file in the way is an error") {
    const std::string base = Folder("prepare");
    CHECK(rise::PrepareBatchOutDir(base).empty());
    const fs::path nested = fs::path(base) / "library" / "v1";
    CHECK(rise::PrepareBatchOutDir(nested.string()).empty());
    CHECK(fs::is_directory(nested));
    std::ofstream(fs::path(base) / "taken") << "a file";
    const std::string blocked = (fs::path(base) / "taken").string();
    CHECK(rise::PrepareBatchOutDir(blocked).rfind(blocked + ": cannot make the output folder", 0) == 0);
    CHECK(rise::PrepareBatchOutDir("").rfind("empty output folder", 0) == 0);
  }
}
