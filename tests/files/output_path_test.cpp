// The rule for where an output may go (image/output_path.hpp), and StagedFile keeping to it: a
// read-only file is never replaced, even by root, whom access(2) lets write anything (CI runs
// as root, so these tests decide by the mode bits a user set, and pass or fail alike for anyone).
#include "files/output_path.hpp"

#include "files/staged_file.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <string>

using namespace twinraster;

TEST_CASE("ReadOnlyByMode: no write bit for anyone is read-only, any write bit is for the system to judge",
          "[image][output]") {
  CHECK(files::ReadOnlyByMode(S_IFREG | 0444));
  CHECK(files::ReadOnlyByMode(S_IFREG | 0555));
  CHECK(files::ReadOnlyByMode(S_IFDIR | 0500));
  CHECK_FALSE(files::ReadOnlyByMode(S_IFREG | 0644));
  CHECK_FALSE(files::ReadOnlyByMode(S_IFREG | 0200));
  CHECK_FALSE(files::ReadOnlyByMode(S_IFREG | 0464));
  CHECK_FALSE(files::ReadOnlyByMode(S_IFDIR | 0777));
}

TEST_CASE("A read-only file is refused as a target, and StagedFile leaves it as it was", "[image][output]") {
  const test::TempDir dir;
  const auto golden = dir / "golden.png";
  test::WriteFile(golden, "protected");
  std::filesystem::permissions(golden, std::filesystem::perms(0444));
  CHECK_THAT(files::FileTargetProblem(golden), HasSubstring("read-only"));
  CHECK_THROWS_WITH(files::StagedFile(golden, "new"), HasSubstring(golden.string() + ": is read-only"));
  CHECK(test::ReadFile(golden) == "protected");
  CHECK((std::filesystem::status(golden).permissions() & std::filesystem::perms::all) == std::filesystem::perms(0444));
  CHECK(std::distance(std::filesystem::directory_iterator(dir.path()), {}) == 1);  // no temporary left

  std::filesystem::permissions(golden, std::filesystem::perms(0644));
  CHECK(files::FileTargetProblem(golden).empty());
  files::StagedFile(golden, "new").Commit();
  CHECK(test::ReadFile(golden) == "new");
}

TEST_CASE("A target's directory: missing ones are fine, a file or a read-only directory on the way is not",
          "[image][output]") {
  const test::TempDir dir;
  CHECK(files::FileTargetProblem(dir / "new" / "deeper" / "x.png").empty());
  CHECK(files::DirectoryTargetProblem(dir / "new" / "deeper").empty());
  CHECK_FALSE(std::filesystem::exists(dir / "new"));  // checking makes nothing

  test::WriteFile(dir / "plain", "x");
  CHECK(files::FileTargetProblem(dir / "plain" / "x.png") == (dir / "plain").string() + " is a file, not a directory");
  CHECK(files::DirectoryTargetProblem(dir / "plain" / "a" / "b") ==
        (dir / "plain").string() + " is a file, not a directory");
  CHECK(files::DirectoryTargetProblem(dir / "plain") == (dir / "plain").string() + " is a file, not a directory");

  std::filesystem::create_directory(dir / "locked");
  std::filesystem::permissions(dir / "locked", std::filesystem::perms(0555));
  CHECK_THAT(files::FileTargetProblem(dir / "locked" / "x.png"), HasSubstring("cannot write in the directory"));
  CHECK_THAT(files::FileTargetProblem(dir / "locked" / "sub" / "x.png"),
             HasSubstring("cannot write in the directory " + (dir / "locked").string() + " to make"));
  std::filesystem::permissions(dir / "locked", std::filesystem::perms(0755));

  CHECK(files::FileTargetProblem(dir.path()) == "is a directory, not a file name");
  CHECK(files::FileTargetProblem(dir / "x/") == "ends in /: a directory, not a file name");
  CHECK(files::FileTargetProblem("/dev/null") == "is not a regular file (a device, pipe or socket)");

  files::MakeMissingDirectories(dir / "new" / "deeper");
  CHECK(std::filesystem::is_directory(dir / "new" / "deeper"));
  CHECK_THROWS_AS(files::MakeMissingDirectories(dir / "plain" / "a"), files::FileError);
}
