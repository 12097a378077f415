#include "scene/json_reader.hpp"

#include "scene/json_document.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
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

std::string TypeName(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::boolean: return "a boolean";
    case nlohmann::json::value_t::null: return "null";
    default: return "a number";
  }
}

void JsonReader::Fail(const std::string& problem) const {
  throw SceneError(file_, path_.empty() ? "(top level)" : path_, problem);
}

bool JsonReader::IsObject() const { return value_->is_object(); }
bool JsonReader::IsArray() const { return value_->is_array(); }
bool JsonReader::IsString() const { return value_->is_string(); }
bool JsonReader::IsNumber() const { return value_->is_number(); }

void JsonReader::ExpectObject() const {
  if (!value_->is_object()) Fail("expected an object, found " + TypeName(*value_));
}

void JsonReader::ExpectObject(std::initializer_list<std::string_view> allowed) const {
  ExpectObject();
  for (const auto& [key, unused] : value_->items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string problem = "unknown key " + Quoted(key);
    const std::string suggestion = ClosestMatch(key, allowed);
    if (!suggestion.empty()) problem += " (did you mean " + Quoted(suggestion) + "?)";
    std::string valid;
    for (std::string_view k : allowed) valid += (valid.empty() ? "" : ", ") + std::string(k);
    problem += "; valid keys here: " + valid;
    Fail(problem);
  }
}

std::optional<JsonReader> JsonReader::Find(std::string_view key) const {
  ExpectObject();
  const auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return JsonReader(*it, file_, JsonPathKey(path_, key));
}

JsonReader JsonReader::Required(std::string_view key) const {
  std::optional<JsonReader> found = Find(key);
  if (!found) Fail("missing required key " + Quoted(key));
  return *found;
}

std::size_t JsonReader::ExpectArray() const {
  if (!value_->is_array()) Fail("expected an array, found " + TypeName(*value_));
  return value_->size();
}

std::size_t JsonReader::ExpectArray(std::size_t size) const {
  const std::size_t n = ExpectArray();
  if (n != size) {
    Fail("expected an array of " + std::to_string(size) + " elements, found " + std::to_string(n));
  }
  return n;
}

JsonReader JsonReader::operator[](std::size_t index) const {
  return JsonReader((*value_)[index], file_, JsonPathIndex(path_, index));
}

std::string JsonReader::String() const {
  if (!value_->is_string()) Fail("expected a string, found " + TypeName(*value_));
  return value_->get<std::string>();
}

bool JsonReader::Boolean() const {
  if (!value_->is_boolean()) Fail("expected true or false, found " + TypeName(*value_));
  return value_->get<bool>();
}

double JsonReader::Number() const {
  if (!value_->is_number()) Fail("expected a number, found " + TypeName(*value_));
  const double x = value_->get<double>();
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
  const std::string range = " in " + std::to_string(min) + ".." + std::to_string(max);
  if (!value_->is_number()) Fail("expected an integer" + range + ", found " + TypeName(*value_));
  const double x = value_->get<double>();
  const bool integral = std::isfinite(x) && x == std::floor(x);
  if (!integral || x < static_cast<double>(min) || x > static_cast<double>(max)) {
    std::ostringstream s;
    s << "expected an integer" << range << ", found " << x;
    Fail(s.str());
  }
  return static_cast<std::int64_t>(x);
}

glm::dvec3 JsonReader::Vec3() const {
  if (!value_->is_array()) Fail("expected [x, y, z], found " + TypeName(*value_));
  ExpectArray(3);
  return glm::dvec3((*this)[0].Number(), (*this)[1].Number(), (*this)[2].Number());
}

}  // namespace twinraster
