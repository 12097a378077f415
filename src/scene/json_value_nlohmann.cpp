#include "scene/json_value.hpp"

namespace twinraster {

// One parse, by json_document's locating parser, which builds the document as it checks it and
// reports its problems without throwing inside nlohmann (the WebAssembly build cannot catch).
ParsedJson ParseJson(std::string_view text, const std::string& file_name, JsonStrictness strictness) {
  return ParsedJson(ParseJsonDocument(text, file_name, strictness));
}

}  // namespace twinraster
