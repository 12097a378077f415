// Image hashes recorded from an earlier build, for tests that hold a picture to its bytes then:
// the hash, and a walk over the shipped scenes a table of such hashes names.
#pragma once

#include "image/image.hpp"
#include "support/test_support.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace twinraster::test {

// FNV-1a, 64 bits, over the RGBA bytes.
inline std::uint64_t ImageHash(const Image& image) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const std::uint8_t b : image.rgba) {
    h ^= b;
    h *= 0x100000001b3ull;
  }
  return h;
}

// Calls check(file, name, hash) for each shipped scene `recorded` names (its path under scenes/,
// without .json); scenes it does not name (lit ones, or ones added since) are passed over.
// Returns how many were checked.
template <class Check>
std::size_t ForEachRecordedScene(const std::map<std::string, std::uint64_t>& recorded, Check&& check) {
  std::size_t checked = 0;
  for (const auto& file : ShippedScenes()) {
    const std::string name = std::filesystem::relative(file, SourcePath("scenes")).replace_extension().generic_string();
    const auto it = recorded.find(name);
    if (it == recorded.end()) continue;
    check(file, name, it->second);
    ++checked;
  }
  return checked;
}

}  // namespace twinraster::test
