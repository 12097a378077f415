#include "scene/json_value.hpp"
#include "scene/scene_error.hpp"

#include <algorithm>
#include <vector>

namespace twinraster {

static_assert(JsonText::kJsonPadding >= simdjson::SIMDJSON_PADDING);

namespace {

// True when some object repeats a key or the nesting is deep enough that the locating parser
// should look (it refuses kMaxJsonDepth levels; this errs on the side of looking). Depth first,
// one level of recursion per level of nesting (so at most kMaxJsonDepth), instead of a stack
// that would hold all of a million instances at once; keys[depth] is reused for every object at
// that depth.
bool NeedsLocatingParser(simdjson::dom::element element, std::size_t depth,
                         std::vector<std::vector<std::string_view>>& keys) {
  const bool nested = element.is_object() || element.is_array();
  if (!nested) return false;
  if (depth + 2 >= kMaxJsonDepth) return true;
  if (element.is_array()) {
    const simdjson::dom::array array = element.get_array().value_unsafe();
    for (const simdjson::dom::element child : array) {
      if (NeedsLocatingParser(child, depth + 1, keys)) return true;
    }
    return false;
  }
  if (keys.size() <= depth) keys.resize(depth + 1);
  const simdjson::dom::object object = element.get_object().value_unsafe();
  keys[depth].clear();
  for (const auto field : object) keys[depth].push_back(field.key);
  std::sort(keys[depth].begin(), keys[depth].end());
  if (std::adjacent_find(keys[depth].begin(), keys[depth].end()) != keys[depth].end()) return true;
  for (const auto field : object) {
    if (NeedsLocatingParser(field.value, depth + 1, keys)) return true;
  }
  return false;
}

bool NeedsLocatingParser(simdjson::dom::element root) {
  std::vector<std::vector<std::string_view>> keys;
  return NeedsLocatingParser(root, 1, keys);
}

}  // namespace

// simdjson reads well-formed text fast but says little about where a problem is. Whatever it
// rejects, and in a scene file what it does not look for (repeated keys, nesting deeper than
// kMaxJsonDepth), is parsed again by json_document's locating parser, whose message names the
// line or the path.
ParsedJson ParseJson(std::string_view text, const std::string& file_name, JsonStrictness strictness) {
  ParsedJson parsed;
  // Debian 13's simdjson skips a byte-order mark that Debian 12's (3.1) refused: the
  // locating parser refuses it on every release, as nlohmann's build does. (A scene file's is
  // skipped before this.)
  if (text.starts_with("\xEF\xBB\xBF")) LocateJsonProblem(text, file_name);
  // The padding past the text's end is there, so simdjson need not copy it.
  if (const simdjson::error_code error = parsed.parser().parse(text.data(), text.size(), false).error();
      error != simdjson::SUCCESS) {
    LocateJsonProblem(text, file_name);  // throws for every problem it can place
    const std::string problem = simdjson::error_message(error);
    throw SceneError(file_name, "(file)", strictness == JsonStrictness::kScene ? problem : "not JSON: " + problem);
  }
  if (strictness == JsonStrictness::kScene && NeedsLocatingParser(parsed.parser().doc.root())) {
    LocateJsonProblem(text, file_name);  // throws if it was a real problem
  }
  return parsed;
}

}  // namespace twinraster
