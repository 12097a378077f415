// The one seam between the scene readers and a JSON DOM: text held for parsing, a parsed document,
// and a view of one of its values with the few primitives JsonReader needs (its kind, a number as
// a double, a string, an object's fields in document order, an array's elements). simdjson's DOM
// natively; nlohmann's JSON when TWINRASTER_JSON_DOM_NLOHMANN is defined (the WebAssembly build,
// which has no simdjson). It does not check what a value means (JsonReader does) and says nothing
// of its own about bad text: both parsers' problems are located by json_document.
#pragma once

#include "scene/json_document.hpp"

#if defined(TWINRASTER_JSON_DOM_NLOHMANN)
#include <nlohmann/json.hpp>
#else
#include <simdjson.h>
#endif

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace twinraster {

enum class JsonKind { kObject, kArray, kString, kNumber, kBoolean, kNull };

// JSON text with kJsonPadding readable bytes past its end, which simdjson reads without copying.
class JsonText {
 public:
  static constexpr std::size_t kJsonPadding = 64;
  // The text's bytes are left for the caller to fill; only the padding is zeroed.
  explicit JsonText(std::size_t size) : bytes_(new char[size + kJsonPadding]), size_(size) {
    std::fill_n(bytes_.get() + size, kJsonPadding, '\0');
  }
  explicit JsonText(std::string_view text) : JsonText(text.size()) { text.copy(bytes_.get(), text.size()); }
  char* data() { return bytes_.get(); }
  std::string_view view() const { return {bytes_.get(), size_}; }

 private:
  std::unique_ptr<char[]> bytes_;
  std::size_t size_;
};

#if defined(TWINRASTER_JSON_DOM_NLOHMANN)

class JsonValue {
 public:
  explicit JsonValue(const nlohmann::ordered_json& value) : value_(&value) {}

  JsonKind kind() const {
    switch (value_->type()) {
      case nlohmann::json::value_t::object: return JsonKind::kObject;
      case nlohmann::json::value_t::array: return JsonKind::kArray;
      case nlohmann::json::value_t::string: return JsonKind::kString;
      case nlohmann::json::value_t::boolean: return JsonKind::kBoolean;
      case nlohmann::json::value_t::null: return JsonKind::kNull;
      default: return JsonKind::kNumber;
    }
  }
  // Callers checked the kind. An integer becomes the nearest double, as simdjson's does.
  bool boolean() const { return *value_->get_ptr<const bool*>(); }
  double number() const { return value_->get<double>(); }
  std::string_view string() const { return *value_->get_ptr<const std::string*>(); }
  std::size_t size() const { return value_->size(); }
  JsonValue element(std::size_t index) const { return JsonValue((*value_)[index]); }

  // fn(JsonValue) for each element in order.
  template <class Fn>
  void ForEachElement(Fn&& fn) const {
    for (const nlohmann::ordered_json& element : *value_) fn(JsonValue(element));
  }
  // fn(key, JsonValue) for each field in document order, a repeated key as often as written,
  // until fn returns true; says whether it did.
  template <class Fn>
  bool AnyField(Fn&& fn) const {
    for (const auto& [key, value] : *value_->get_ptr<const nlohmann::ordered_json::object_t*>()) {
      if (fn(std::string_view(key), JsonValue(value))) return true;
    }
    return false;
  }

 private:
  const nlohmann::ordered_json* value_;
};

class ParsedJson {
 public:
  explicit ParsedJson(nlohmann::ordered_json document) : document_(std::move(document)) {}
  JsonValue root() const { return JsonValue(document_); }

 private:
  nlohmann::ordered_json document_;
};

#else

class JsonValue {
 public:
  explicit JsonValue(simdjson::dom::element value) : value_(value) {}

  JsonKind kind() const {
    switch (value_.type()) {
      case simdjson::dom::element_type::OBJECT: return JsonKind::kObject;
      case simdjson::dom::element_type::ARRAY: return JsonKind::kArray;
      case simdjson::dom::element_type::STRING: return JsonKind::kString;
      case simdjson::dom::element_type::BOOL: return JsonKind::kBoolean;
      case simdjson::dom::element_type::NULL_VALUE: return JsonKind::kNull;
      default: return JsonKind::kNumber;
    }
  }
  // Callers checked the kind.
  bool boolean() const { return value_.get_bool().value_unsafe(); }
  double number() const { return value_.get_double().value_unsafe(); }
  std::string_view string() const { return value_.get_string().value_unsafe(); }
  std::size_t size() const { return Array().size(); }
  JsonValue element(std::size_t index) const { return JsonValue(Array().at(index).value_unsafe()); }

  template <class Fn>
  void ForEachElement(Fn&& fn) const {
    for (const simdjson::dom::element element : Array()) fn(JsonValue(element));
  }
  template <class Fn>
  bool AnyField(Fn&& fn) const {
    for (const auto field : Object()) {
      if (fn(field.key, JsonValue(field.value))) return true;
    }
    return false;
  }

 private:
  // Copies: iterating a temporary simdjson_result's value would dangle.
  simdjson::dom::object Object() const { return value_.get_object().value_unsafe(); }
  simdjson::dom::array Array() const { return value_.get_array().value_unsafe(); }

  simdjson::dom::element value_;
};

class ParsedJson {
 public:
  // The root is found again on each call: a parser's document moves with it.
  JsonValue root() const { return JsonValue(parser_.doc.root()); }
  simdjson::dom::parser& parser() { return parser_; }

 private:
  simdjson::dom::parser parser_;
};

#endif

// Parses `text`, which ends at the end of a JsonText, or throws the located SceneError.
// kScene refuses what json_document refuses (repeated keys, deep nesting); kGltf takes what
// simdjson takes, the first of a repeated key found.
ParsedJson ParseJson(std::string_view text, const std::string& file_name, JsonStrictness strictness);

}  // namespace twinraster
