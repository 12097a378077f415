#include "cli/output_paths.hpp"

#include "files/output_path.hpp"
#include "files/staged_file.hpp"

namespace twinraster::cli {

namespace {

[[noreturn]] void Refuse(const std::string& option, const std::filesystem::path& path, const std::string& problem) {
  // "-o x.png: x-gpu.png: ..." names the file derived from the argument; "-o x.png: ..." is enough otherwise.
  const bool derived = option.size() < path.string().size() ||
                       option.compare(option.size() - path.string().size(), std::string::npos, path.string()) != 0;
  throw files::FileError(option + ": " + (derived ? path.string() + ": " : "") + problem);
}

}  // namespace

void OutputPaths::File(const std::string& option, const std::filesystem::path& file) {
  if (const std::string problem = files::FileTargetProblem(file); !problem.empty()) Refuse(option, file, problem);
  const std::filesystem::path parent = file.parent_path();
  if (!parent.empty()) directories_.push_back(parent);
}

void OutputPaths::Directory(const std::string& option, const std::filesystem::path& directory) {
  if (const std::string problem = files::DirectoryTargetProblem(directory); !problem.empty()) {
    Refuse(option, directory, problem);
  }
  directories_.push_back(directory);
}

void OutputPaths::MakeDirectories() const {
  for (const std::filesystem::path& directory : directories_) files::MakeMissingDirectories(directory);
}

bool NamesDirectory(const std::string& argument) {
  std::error_code ignored;
  return !argument.empty() && (argument.back() == '/' || std::filesystem::is_directory(argument, ignored));
}

}  // namespace twinraster::cli
