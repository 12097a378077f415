#include "scene/json_document.hpp"

#include "scene/scene_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iterator>
#include <optional>
#include <unordered_map>
#include <vector>

namespace twinraster {

namespace {

// Where the parser is in the text. nlohmann's SAX interface reports no positions for keys and
// values, so the characters it reads are counted as it reads them (see CountingIterator).
struct ReadPosition {
  std::size_t offset = 0;  // characters read so far
  std::size_t line = 1;
  std::size_t line_start = 0;  // offset of the current line's first character
};

// A forward iterator over the text that counts what the parser consumes. nlohmann's lexer reads
// one character at a time and never further than the end of the token it is scanning, so when
// the parser reports a key the count stands just past the key's closing quote.
class CountingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator() = default;
  CountingIterator(const char* at, ReadPosition* position) : at_(at), position_(position) {}
  reference operator*() const { return *at_; }
  CountingIterator& operator++() {
    if (position_ != nullptr) {
      ++position_->offset;
      if (*at_ == '\n') ++position_->line, position_->line_start = position_->offset;
    }
    ++at_;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  friend bool operator==(const CountingIterator& a, const CountingIterator& b) { return a.at_ == b.at_; }

 private:
  const char* at_ = nullptr;
  ReadPosition* position_ = nullptr;
};

std::string LineAndColumn(std::size_t line, std::size_t column) {
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

std::string LineAndColumnAt(std::string_view text, std::size_t offset) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n')
      ++line, column = 1;
    else
      ++column;
  }
  return LineAndColumn(line, column);
}

// "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error ..." keeps
// only what follows the position.
std::string ProblemOf(const std::string& what) {
  const std::size_t colon = what.find(": ");
  if (colon != std::string::npos) return what.substr(colon + 2);
  const std::size_t bracket = what.find("] ");
  return bracket == std::string::npos ? what : what.substr(bracket + 2);
}

using Json = nlohmann::ordered_json;

// Builds the document as nlohmann's own DOM parser would, fields in document order, and also
// knows the JSON path of the value being read and the line of every key of the objects still open.
class LocatingBuilder {
 public:
  LocatingBuilder(const std::string& file_name, const ReadPosition& position, JsonStrictness strictness)
      : file_name_(file_name), position_(position), strictness_(strictness) {}

  Json& result() { return root_; }
  // The problem to report when the parse fails: one kScene would have stopped at, if any came
  // first, else the one that ended the parse.
  const std::optional<SceneError>& error() const { return deferred_ ? deferred_ : error_; }

  bool null() { return Value(nullptr); }
  bool boolean(bool b) { return Value(b); }
  bool number_integer(Json::number_integer_t n) { return Value(n); }
  bool number_unsigned(Json::number_unsigned_t n) { return Value(n); }
  bool number_float(Json::number_float_t x, const std::string& literal) {
    // nlohmann reads an integer beyond 64 bits as a double; simdjson refuses it, and so does this.
    if (literal.find_first_of(".eE") == std::string::npos) {
      return Fail(PathOfNext(), "integer " + literal + " does not fit in 64 bits (" + LiteralPlace(literal) + ")");
    }
    return Value(x);
  }
  bool string(std::string& s) { return Value(std::move(s)); }
  bool binary(Json::binary_t&) { return Fail(PathOfNext(), "binary values are not JSON text"); }

  bool start_object(std::size_t) { return Open(Json::object()); }
  bool start_array(std::size_t) { return Open(Json::array()); }
  bool end_object() { return Close(); }
  bool end_array() { return Close(); }

  bool key(std::string& k) {
    Frame& frame = frames_.back();
    const std::size_t line = position_.line;
    const auto [it, inserted] = frame.key_lines.try_emplace(k, line);
    if (!inserted) {
      const bool go_on =
          Strict(JsonPathKey(frame.path, k), "duplicate key \"" + k + "\", on line " + std::to_string(it->second) +
                                                 " and again on line " + std::to_string(line));
      if (!go_on) return false;
    }
    frame.key = k;
    return true;
  }

  bool parse_error(std::size_t byte, const std::string&, const Json::exception& e) {
    const std::string problem = ProblemOf(e.what());
    if (e.id == 406) return NumberOutOfRange(e.what());
    syntax_error_byte_ = byte;
    syntax_problem_ = problem;
    return false;
  }

  // A syntax error: nlohmann's byte count, one past the offending character, and the problem.
  std::size_t syntax_error_byte() const { return syntax_error_byte_; }
  const std::string& syntax_problem() const { return syntax_problem_; }

 private:
  struct Frame {
    Json* container;
    std::string path;
    std::string key;  // the key whose value comes next (objects)
    std::unordered_map<std::string, std::size_t> key_lines;
  };

  // A number beyond double's range: named by the value it was meant to be, and located at its
  // first character (the lexer has read the literal and one character past it).
  bool NumberOutOfRange(const std::string& what) {
    const std::size_t open = what.find('\''), close = what.rfind('\'');
    const std::string literal = open < close ? what.substr(open + 1, close - open - 1) : std::string("number");
    return Fail(PathOfNext(), "number " + literal + " is out of range for a double (" + LiteralPlace(literal) + ")");
  }

  // Where the number just read starts: the lexer has read the literal and one character past it.
  std::string LiteralPlace(const std::string& literal) const {
    const std::size_t read = position_.offset - position_.line_start;
    const std::size_t column = read > literal.size() ? read - literal.size() : 1;
    return LineAndColumn(position_.line, column);
  }

  std::string PathOfNext() const {
    if (frames_.empty()) return "";
    const Frame& frame = frames_.back();
    return frame.container->is_object() ? JsonPathKey(frame.path, frame.key)
                                        : JsonPathIndex(frame.path, frame.container->size());
  }

  Json* Place(Json&& value) {
    if (frames_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Frame& frame = frames_.back();
    if (frame.container->is_object()) {
      // Appended, not looked up: key() has seen any repeat, and ordered_map's lookup is linear.
      Json::object_t::Container& fields = *frame.container->get_ptr<Json::object_t*>();
      fields.emplace_back(frame.key, std::move(value));
      return &fields.back().second;
    }
    frame.container->push_back(std::move(value));
    return &frame.container->back();
  }

  template <typename T>
  bool Value(T&& v) {
    Place(Json(std::forward<T>(v)));
    return true;
  }

  bool Open(Json&& empty) {
    if (frames_.size() >= kMaxJsonDepth) {
      const std::string problem = "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels";
      if (!Strict(PathOfNext(), problem)) return false;
      if (frames_.size() >= kMaxSimdjsonDepth) return Fail(PathOfNext(), problem);
    }
    std::string path = PathOfNext();
    Json* container = Place(std::move(empty));
    frames_.push_back(Frame{container, std::move(path), {}, {}});
    return true;
  }

  bool Close() {
    frames_.pop_back();
    return true;
  }

  bool Fail(const std::string& path, const std::string& problem) {
    error_.emplace(file_name_, path.empty() ? "(top level)" : path, problem);
    return false;
  }

  // A problem only kScene refuses: kScene stops; kGltf keeps the first and reads on.
  bool Strict(const std::string& path, const std::string& problem) {
    if (strictness_ == JsonStrictness::kScene) return Fail(path, problem);
    if (!deferred_) deferred_.emplace(file_name_, path.empty() ? "(top level)" : path, problem);
    return true;
  }

  const std::string& file_name_;
  const ReadPosition& position_;
  JsonStrictness strictness_;
  Json root_;
  std::vector<Frame> frames_;
  std::optional<SceneError> error_;
  std::optional<SceneError> deferred_;
  std::size_t syntax_error_byte_ = 0;
  std::string syntax_problem_;
};

}  // namespace

// A JSON text is UTF-8 without NUL bytes, starting (after white space and an optional byte-order
// mark) with a printable character. Anything else, a PNG or an executable handed over by mistake,
// is reported as what it is instead of as a puzzling syntax error deep inside it.
void RejectBinaryText(std::string_view text, const std::string& file_name) {
  std::size_t first = 0;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") first = 3;
  while (first < text.size() &&
         (text[first] == ' ' || text[first] == '\t' || text[first] == '\n' || text[first] == '\r'))
    ++first;
  std::optional<std::size_t> bad;
  if (first < text.size()) {
    const auto c = static_cast<unsigned char>(text[first]);
    if (c < 0x20 || c >= 0x7F) bad = first;
  }
  if (!bad) {
    const std::size_t nul = text.find('\0');
    if (nul != std::string_view::npos) bad = nul;
  }
  if (!bad) return;
  char byte[8];
  std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[*bad])));
  throw SceneError(file_name, LineAndColumnAt(text, *bad),
                   std::string("not JSON text: binary data (byte ") + byte + ")");
}

std::string JsonPathKey(const std::string& path, std::string_view key) {
  const bool plain = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  std::string quoted = "[\"" + std::string(key) + "\"]";
  if (path.empty()) return plain ? std::string(key) : quoted;
  return plain ? path + "." + std::string(key) : path + quoted;
}

std::string JsonPathIndex(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

Json ParseJsonDocument(std::string_view text, const std::string& file_name, JsonStrictness strictness) {
  RejectBinaryText(text, file_name);
  // nlohmann would skip it, simdjson refuses it. A scene file's is skipped before this.
  if (text.starts_with("\xEF\xBB\xBF")) {
    throw SceneError(file_name, LineAndColumn(1, 1), "a UTF-8 byte-order mark before the JSON text, where none may be");
  }
  // Said here, not by nlohmann, whose wording for an empty input changed between releases.
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    throw SceneError(file_name, LineAndColumnAt(text, text.empty() ? 0 : text.size() - 1),
                     "unexpected end of input: the file holds no JSON value");
  }
  ReadPosition position;
  LocatingBuilder builder(file_name, position, strictness);
  const CountingIterator begin(text.data(), &position), end(text.data() + text.size(), nullptr);
  const bool ok = Json::sax_parse(begin, end, &builder);
  if (ok) return std::move(builder.result());
  if (builder.error()) throw *builder.error();
  const std::size_t byte = builder.syntax_error_byte();
  throw SceneError(file_name, LineAndColumnAt(text, byte == 0 ? 0 : byte - 1), builder.syntax_problem());
}

void LocateJsonProblem(std::string_view text, const std::string& file_name) {
  (void)ParseJsonDocument(text, file_name);
}

}  // namespace twinraster
