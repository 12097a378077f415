// Checked reading of a parsed JSON document: every accessor knows its JSON path, so any problem
// becomes a SceneError naming the file, the path and what was expected.
#pragma once

#include "base/closest_match.hpp"
#include "scene/scene_error.hpp"

#include <nlohmann/json_fwd.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace twinraster {

// Numbers beyond this magnitude are rejected as absurd: far past anything a scene can mean,
// and where squaring them in double would start to lose the chain's precision.
inline constexpr double kMaxMagnitude = 1e12;
// Sizes and distances that must be positive must also be at least this: smaller ones make the
// projection's entries overflow or underflow once rounded to float. With both bounds every entry
// of F stays below about 1e34, inside float's range (3.4e38).
inline constexpr double kMinPositive = 1e-9;

class JsonReader {
 public:
  JsonReader(const nlohmann::json& value, std::string file, std::string path)
      : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

  const std::string& path() const { return path_; }
  const nlohmann::json& json() const { return *value_; }

  [[noreturn]] void Fail(const std::string& problem) const;

  bool IsObject() const;
  bool IsArray() const;
  bool IsString() const;
  bool IsNumber() const;

  // An object whose keys must all be among `allowed`; an unknown key is an error that names the
  // closest allowed key.
  void ExpectObject(std::initializer_list<std::string_view> allowed) const;
  void ExpectObject() const;  // any keys
  std::optional<JsonReader> Find(std::string_view key) const;
  JsonReader Required(std::string_view key) const;

  std::size_t ExpectArray() const;  // returns the size
  std::size_t ExpectArray(std::size_t size) const;
  JsonReader operator[](std::size_t index) const;

  std::string String() const;
  bool Boolean() const;
  double Number() const;  // finite, |x| <= kMaxMagnitude
  double Positive() const;  // > 0 and >= kMinPositive
  std::int64_t Integer(std::int64_t min, std::int64_t max) const;
  glm::dvec3 Vec3() const;

 private:
  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
};

std::string TypeName(const nlohmann::json& value);

}  // namespace twinraster
