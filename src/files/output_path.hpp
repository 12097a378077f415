// The one rule for where an output may go, decided before any work: a file replaces nothing the
// user cannot write, sits in a directory (missing ones are made, by MakeMissingDirectories), and is
// not a directory itself. It writes no file (staged_file.hpp does) and knows nothing of options or
// of "-" (the command line's business).
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>

namespace twinraster::files {

// Mode bits as the owner's intent: a file or directory without any write bit (chmod a-w) is
// read-only even for root, whom access(2) lets write anything.
bool ReadOnlyByMode(mode_t mode);

// Why `file` cannot be written whole and renamed into place, or "" when it can: it names a
// directory, is not a regular file, is read-only, or its directory cannot be written or made.
// Directories missing on the way are not a problem: they will be made.
std::string FileTargetProblem(const std::filesystem::path& file);

// Why files cannot be written into `directory`, or "" when they can (missing: when it can be made).
std::string DirectoryTargetProblem(const std::filesystem::path& directory);

// Makes `directory` and its missing parents; throws FileError naming it.
void MakeMissingDirectories(const std::filesystem::path& directory);

}  // namespace twinraster::files
