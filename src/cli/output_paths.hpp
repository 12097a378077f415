// Every file and directory a command will write, checked together before any scene is read or
// drawn, then the missing directories made (all checks pass, or nothing is made): the rule of
// docs/commands.md's "Output paths" for every option that writes. "-" (standard output) is not a
// path: each command decides what it means before it gets here.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace twinraster::cli {

class OutputPaths {
 public:
  // A file `option` (as given: "-o x.png") will write, staged and renamed into place; throws
  // FileError "<option>: <file>: <problem>" (the file named again only when it is not the argument).
  void File(const std::string& option, const std::filesystem::path& file);
  // A directory `option` will write files into; throws FileError as File() does.
  void Directory(const std::string& option, const std::filesystem::path& directory);
  // Makes every directory named so far, and their parents, where missing; throws FileError.
  void MakeDirectories() const;

 private:
  std::vector<std::filesystem::path> directories_;
};

// Whether an output argument names a directory rather than a file: it ends in / or is one.
bool NamesDirectory(const std::string& argument);

}  // namespace twinraster::cli
