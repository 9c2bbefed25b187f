// SPDX-License-Identifier: MIT
#include <algorithm>

#include "export/atomic_file.h"
#include "export/biped_fixture.h"
#include "test_support.h"

TEST_SUITE("atomic_file") {
  TEST_CASE("writes the bytes, replaces an existing file and leaves no temporary behind") {
    rise::test::TempFolder folder;
    const std::string path = folder.File("clip.glb");
    REQUIRE(rise::WriteFileAtomically(path, std::string("first\0binary", 12)).empty());
    CHECK(rise::test::FileContents(path) == std::string("first\0binary", 12));
    REQUIRE(rise::WriteFileAtomically(path, "second").empty());
    CHECK(rise::test::FileContents(path) == "second");
    CHECK(folder.Files() == std::vector<std::string>{"clip.glb"});
  }
  TEST_CASE("the temporaries a killed writer left are removed, and nothing else") {
    rise::test::TempFolder folder;
    for (const char* name : {"clip.glb", "clip.glb.tmp.Ab3xQ9", "clip.glb.tmp.zz0000", "clip.glb.tmp.short",
                             "other.glb.tmp.Ab3xQ9", "clip.glb.tmp.Ab3xQ9.keep"}) {
      REQUIRE(rise::WriteFileAtomically(folder.File(name), "x").empty());
    }
    std::filesystem::create_directory(folder.Path() / "clip.glb.tmp.folder");
    rise::RemoveAbandonedTemporaries({folder.File("clip.glb")});
    std::vector<std::string> left = folder.Files();
    std::sort(left.begin(), left.end());
    CHECK(left == std::vector<std::string>{"clip.glb", "clip.glb.tmp.Ab3xQ9.keep", "clip.glb.tmp.folder",
                                                     "clip.glb.tmp.short", "other.glb.tmp.Ab3xQ9"});
  }
  TEST_CASE("a missing folder gives a clear error and creates nothing") {
    rise::test::TempFolder folder;
    const std::string path = folder.File("missing/clip.glb");
    const std::string error = rise::WriteFileAtomically(path, "data");
    CHECK(error.find("does not exist") != std::string::npos);
    CHECK(error.find(path) != std::string::npos);
    CHECK(folder.Files().empty());
  }
  TEST_CASE("a path naming a folder, an empty path and a trailing slash are rejected") {
    rise::test::TempFolder folder;
    std::filesystem::create_directory(folder.Path() / "out.glb");
    CHECK(rise::WriteFileAtomically(folder.File("out.glb"), "data").find("folder") != std::string::npos);
    CHECK(std::filesystem::is_directory(folder.Path() / "out.glb"));
    CHECK(rise::WriteFileAtomically("", "data").find("empty") != std::string::npos);
    CHECK(rise::WriteFileAtomically(folder.File("sub") + "/", "data").find("folder") != std::string::npos);
    CHECK(folder.Files() == std::vector<std::string>{"out.glb"});
  }
  TEST_CASE("a read-only folder or file is refused, for root too, and nothing changes") {
    namespace fs = std::filesystem;
    rise::test::TempFolder folder;
    fs::create_directory(folder.Path() / "locked");
    fs::permissions(folder.Path() / "locked", fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                    fs::perm_options::remove);
    const std::string inLocked = folder.File("locked/clip.glb");
    CHECK(rise::CheckWritable(inLocked) == "cannot write '" + inLocked + "': folder '" + folder.File("locked") +
                                               "' is read-only");
    CHECK(rise::WriteFileAtomically(inLocked, "data") == rise::CheckWritable(inLocked));
    CHECK(fs::is_empty(folder.Path() / "locked"));
    fs::permissions(folder.Path() / "locked", fs::perms::owner_write, fs::perm_options::add);

    const std::string kept = folder.File("kept.glb");
    REQUIRE(rise::WriteFileAtomically(kept, "old").empty());
    fs::permissions(kept, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                    fs::perm_options::remove);
    CHECK(rise::WriteFileAtomically(kept, "new") == "cannot write '" + kept + "': the file is read-only");
    CHECK(rise::test::FileContents(kept) == "old");
    CHECK(rise::CheckWritable(folder.File("fresh.glb")).empty());
    CHECK(folder.Files().size() == 2);
  }
  TEST_CASE("an unwritable folder gives the system's reason and leaves no file") {
    // /proc refuses new files even to root, so this holds whoever runs the tests.
    const std::string path = "/proc/rise_clip.glb";
    const std::string error = rise::WriteFileAtomically(path, "data");
    CHECK_FALSE(error.empty());
    CHECK(error.find("cannot write '/proc/rise_clip.glb'") == 0);
    CHECK_FALSE(std::filesystem::exists(path));
  }
}
