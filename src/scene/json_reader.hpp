// Checked reading of a parsed JSON document (through json_value's seam, on either DOM): every
// accessor knows its JSON path, so any problem becomes a SceneError naming the file, the path and
// what was expected. Paths are built only when something fails: a reader refers to the reader it
// came from. It does not parse: ParseJson does.
#pragma once

#include "base/closest_match.hpp"
#include "scene/json_value.hpp"
#include "scene/scene_error.hpp"

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
  // The document's root; `file` must outlive every reader made from this one.
  JsonReader(JsonValue value, const std::string& file) : value_(value), file_(&file) {}

  std::string path() const;  // e.g. "instances[1].transform.scale"; "" at the root
  const std::string& file() const { return *file_; }

  [[noreturn]] void Fail(const std::string& problem) const;

  bool IsObject() const;
  bool IsArray() const;
  bool IsString() const;
  bool IsNumber() const;
  std::string TypeName() const;  // "an object", "a string", ... for messages

  // An object whose keys must all be among `allowed`; an unknown key is an error that names the
  // closest allowed key.
  void ExpectObject(std::initializer_list<std::string_view> allowed) const;
  void ExpectObject() const;                   // any keys
  std::vector<std::string_view> Keys() const;  // an object's keys, sorted

  // A child refers to its parent, so children of temporaries are not allowed.
  std::optional<JsonReader> Find(std::string_view key) const&;
  std::optional<JsonReader> Find(std::string_view key) const&& = delete;
  JsonReader Required(std::string_view key) const&;
  JsonReader Required(std::string_view key) const&& = delete;

  std::size_t ExpectArray() const;  // returns the size
  std::size_t ExpectArray(std::size_t size) const;
  JsonReader operator[](std::size_t index) const&;  // walks the array from its start: for short arrays
  JsonReader operator[](std::size_t index) const&& = delete;
  // fn(const JsonReader& element) for each element in order, for arrays of any length.
  template <class Fn>
  void ForEachElement(Fn&& fn) const {
    ExpectArray();
    std::size_t index = 0;
    value_.ForEachElement([&](JsonValue element) {
      const JsonReader child(element, *this, index++);
      fn(child);
    });
  }

  std::string String() const;
  // A name read in any case ("Y", "Red"), in lower case; ASCII letters only are folded.
  std::string LowercaseString() const;
  bool Boolean() const;
  double Number() const;    // finite, |x| <= kMaxMagnitude
  double Positive() const;  // > 0 and >= kMinPositive
  std::int64_t Integer(std::int64_t min, std::int64_t max) const;
  glm::dvec3 Vec3() const;

 private:
  JsonReader(JsonValue value, const JsonReader& parent, std::string_view key)
      : value_(value), file_(parent.file_), parent_(&parent), key_(key) {}
  JsonReader(JsonValue value, const JsonReader& parent, std::size_t index)
      : value_(value), file_(parent.file_), parent_(&parent), index_(index) {}

  JsonValue value_;
  const std::string* file_;
  const JsonReader* parent_ = nullptr;
  std::string_view key_;               // this value's key in its parent object, or
  std::size_t index_ = kNotAnElement;  // its index in its parent array
  static constexpr std::size_t kNotAnElement = static_cast<std::size_t>(-1);
};

}  // namespace twinraster
