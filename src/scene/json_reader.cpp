#include "scene/json_reader.hpp"

#include "scene/json_document.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace twinraster {

namespace {

std::string Quoted(std::string_view s) {
  std::string quoted(1, '"');
  quoted.append(s);
  quoted.push_back('"');
  return quoted;
}

}  // namespace

std::string JsonReader::path() const {
  if (parent_ == nullptr) return "";
  const std::string above = parent_->path();
  return index_ == kNotAnElement ? JsonPathKey(above, key_) : JsonPathIndex(above, index_);
}

void JsonReader::Fail(const std::string& problem) const {
  const std::string where = path();
  throw SceneError(*file_, where.empty() ? "(top level)" : where, problem);
}

bool JsonReader::IsObject() const { return value_.kind() == JsonKind::kObject; }
bool JsonReader::IsArray() const { return value_.kind() == JsonKind::kArray; }
bool JsonReader::IsString() const { return value_.kind() == JsonKind::kString; }
bool JsonReader::IsNumber() const { return value_.kind() == JsonKind::kNumber; }

std::string JsonReader::TypeName() const {
  switch (value_.kind()) {
    case JsonKind::kObject: return "an object";
    case JsonKind::kArray: return "an array";
    case JsonKind::kString: return "a string";
    case JsonKind::kBoolean: return "a boolean";
    case JsonKind::kNull: return "null";
    case JsonKind::kNumber: break;
  }
  return "a number";
}

void JsonReader::ExpectObject() const {
  if (!IsObject()) Fail("expected an object, found " + TypeName());
}

void JsonReader::ExpectObject(std::initializer_list<std::string_view> allowed) const {
  ExpectObject();
  value_.AnyField([&](std::string_view key, JsonValue) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) return false;
    std::string problem = "unknown key " + Quoted(key);
    const std::string suggestion = ClosestMatch(key, allowed);
    if (!suggestion.empty()) problem += " (did you mean " + Quoted(suggestion) + "?)";
    std::string valid;
    for (std::string_view k : allowed) valid += (valid.empty() ? "" : ", ") + std::string(k);
    problem += "; valid keys here: " + valid;
    Fail(problem);
  });
}

std::vector<std::string_view> JsonReader::Keys() const {
  ExpectObject();
  std::vector<std::string_view> keys;
  value_.AnyField([&](std::string_view key, JsonValue) {
    keys.push_back(key);
    return false;
  });
  std::sort(keys.begin(), keys.end());
  return keys;
}

std::optional<JsonReader> JsonReader::Find(std::string_view key) const& {
  ExpectObject();
  // The key as stored in the document, so that it outlives this call.
  std::optional<JsonReader> found;
  value_.AnyField([&](std::string_view field_key, JsonValue value) {
    if (field_key == key) found.emplace(JsonReader(value, *this, field_key));
    return found.has_value();
  });
  return found;
}

JsonReader JsonReader::Required(std::string_view key) const& {
  std::optional<JsonReader> found = Find(key);
  if (!found) Fail("missing required key " + Quoted(key));
  return *found;
}

std::size_t JsonReader::ExpectArray() const {
  if (!IsArray()) Fail(std::string("expected an array, found ") + TypeName());
  return value_.size();
}

std::size_t JsonReader::ExpectArray(std::size_t size) const {
  const std::size_t n = ExpectArray();
  if (n != size) {
    Fail("expected an array of " + std::to_string(size) + " elements, found " + std::to_string(n));
  }
  return n;
}

JsonReader JsonReader::operator[](std::size_t index) const& { return JsonReader(value_.element(index), *this, index); }

std::string JsonReader::String() const {
  if (!IsString()) Fail(std::string("expected a string, found ") + TypeName());
  return std::string(value_.string());
}

std::string JsonReader::LowercaseString() const {
  std::string text = String();
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool JsonReader::Boolean() const {
  if (value_.kind() != JsonKind::kBoolean) Fail(std::string("expected true or false, found ") + TypeName());
  return value_.boolean();
}

double JsonReader::Number() const {
  if (!IsNumber()) Fail(std::string("expected a number, found ") + TypeName());
  const double x = value_.number();
  if (!std::isfinite(x)) Fail("number is not finite");
  if (std::abs(x) > kMaxMagnitude) {
    std::ostringstream s;
    s << "number " << x << " is absurd (magnitude above " << kMaxMagnitude << ")";
    Fail(s.str());
  }
  return x;
}

double JsonReader::Positive() const {
  const double x = Number();
  if (!(x > 0)) {
    std::ostringstream s;
    s << "must be greater than 0, found " << x;
    Fail(s.str());
  }
  if (x < kMinPositive) {
    std::ostringstream s;
    s << "number " << x << " is absurdly small (below " << kMinPositive << ")";
    Fail(s.str());
  }
  return x;
}

std::int64_t JsonReader::Integer(std::int64_t min, std::int64_t max) const {
  const auto range = [&] { return " in " + std::to_string(min) + ".." + std::to_string(max); };
  if (!IsNumber()) Fail("expected an integer" + range() + ", found " + TypeName());
  const double x = value_.number();
  const bool integral = std::isfinite(x) && x == std::floor(x);
  if (!integral || x < static_cast<double>(min) || x > static_cast<double>(max)) {
    std::ostringstream s;
    s << "expected an integer" << range() << ", found " << x;
    Fail(s.str());
  }
  return static_cast<std::int64_t>(x);
}

glm::dvec3 JsonReader::Vec3() const {
  if (!IsArray()) Fail(std::string("expected [x, y, z], found ") + TypeName());
  ExpectArray(3);
  return glm::dvec3((*this)[0].Number(), (*this)[1].Number(), (*this)[2].Number());
}

}  // namespace twinraster
