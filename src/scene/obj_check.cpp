#include "scene/obj_check.hpp"

#include "base/counted.hpp"
#include "scene/json_reader.hpp"  // kMaxMagnitude: an OBJ's numbers are bounded as a scene's are
#include "scene/scene_error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

namespace twinraster {

namespace {

// Calls fn(line_number, line) for every line, split where tinyobjloader splits them: at "\n",
// "\r\n" or a lone "\r". A final line break starts no further line.
template <class Fn>
void ForEachLine(std::string_view text, Fn&& fn) {
  std::size_t number = 0, at = 0;
  while (at < text.size()) {
    const std::size_t end = text.find_first_of("\r\n", at);
    fn(++number, text.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at));
    if (end == std::string_view::npos) break;
    at = end + 1;
    if (text[end] == '\r' && at < text.size() && text[at] == '\n') ++at;
  }
}

bool IsBlank(char c) { return c == ' ' || c == '\t'; }

// The line's words, split at spaces and tabs (tinyobjloader's separators).
void SplitWords(std::string_view line, std::vector<std::string_view>& words) {
  words.clear();
  std::size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && IsBlank(line[at])) ++at;
    const std::size_t start = at;
    while (at < line.size() && !IsBlank(line[at])) ++at;
    if (at > start) words.push_back(line.substr(start, at - start));
  }
}

enum class Statement { kOther, kVertex, kNormal, kTexcoord, kFace };

// The statements twinraster reads (or must count, for indices: vt), by their keyword. A comment
// line starts with '#'.
Statement StatementOf(std::string_view keyword) {
  if (keyword == "v") return Statement::kVertex;
  if (keyword == "vn") return Statement::kNormal;
  if (keyword == "vt") return Statement::kTexcoord;
  if (keyword == "f") return Statement::kFace;
  return Statement::kOther;
}

std::string Quoted(std::string_view s) { return "\"" + std::string(s) + "\""; }

// A comment after a statement is a common slip; tinyobjloader would read its words as numbers.
std::string CommentHint(std::string_view word) {
  return !word.empty() && word[0] == '#' ? " (a comment must be on a line of its own)" : "";
}

std::string Count(std::size_t n, const char* singular, const char* plural) {
  return n == 0 ? std::string("no ") + plural : Counted(n, singular, plural);
}

// What an index refers to: the words for messages, and how many of them the file has.
struct IndexKind {
  const char* name;      // "vertex"
  const char* singular;  // "vertex (v line)"
  const char* plural;    // "vertices (v lines)"
  std::size_t total;     // in the whole file: what a positive index may reach
  std::size_t before;    // before this line: what a negative index may reach back to
};

class LineChecker {
 public:
  LineChecker(const std::string& file_name, const ObjCounts& totals) : file_name_(file_name), totals_(totals) {}

  void Check(std::size_t line_number, std::string_view line) {
    line_number_ = line_number;
    SplitWords(line, words_);
    if (words_.empty() || words_[0][0] == '#') return;
    switch (StatementOf(words_[0])) {
      case Statement::kVertex:
        // x y z, and optionally w (rational curves; ignored) or r g b (a common extension; ignored).
        CheckNumbers();  // first: a word that is no number is the likelier mistake than a count
        if (words_.size() != 4 && words_.size() != 5 && words_.size() != 7) {
          Fail("v: expected x y z (optionally followed by w, or by r g b), found " + NumbersFound());
        }
        ++seen_.vertices;
        break;
      case Statement::kNormal:
        CheckNumbers();
        if (words_.size() != 4) Fail("vn: expected x y z, found " + NumbersFound());
        ++seen_.normals;
        break;
      case Statement::kTexcoord:
        CheckNumbers();
        if (words_.size() < 2 || words_.size() > 4) Fail("vt: expected u, u v or u v w, found " + NumbersFound());
        ++seen_.texcoords;
        break;
      case Statement::kFace:
        CheckFace();
        ++seen_.faces;
        break;
      case Statement::kOther: break;
    }
  }

  const ObjCounts& seen() const { return seen_; }

 private:
  [[noreturn]] void Fail(const std::string& problem) const {
    throw SceneError(file_name_, "line " + std::to_string(line_number_), problem);
  }

  std::string NumbersFound() const {
    const std::size_t n = words_.size() - 1;
    return n == 0 ? "none" : Counted(n, "number");
  }

  void CheckNumbers() const {
    for (std::size_t i = 1; i < words_.size(); ++i) CheckNumber(words_[i]);
  }

  // A decimal number as tinyobjloader reads it (an optional sign, digits with an optional point,
  // an optional exponent) and nothing after it; finite, and within the bound a scene's numbers have.
  void CheckNumber(std::string_view word) const {
    std::string_view digits = word;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);  // from_chars takes no '+'
    double x = 0;
    const auto [end, error] =
        std::from_chars(digits.data(), digits.data() + digits.size(), x, std::chars_format::general);
    const bool whole = error == std::errc() && end == digits.data() + digits.size();
    if (error == std::errc::result_out_of_range && end == digits.data() + digits.size()) {
      Fail(std::string(Keyword()) + ": number " + std::string(word) + " is out of range for a double");
    }
    if (!whole) Fail(std::string(Keyword()) + ": " + Quoted(word) + " is not a number" + CommentHint(word));
    if (!std::isfinite(x)) Fail(std::string(Keyword()) + ": " + Quoted(word) + " is not a finite number");
    if (std::abs(x) > kMaxMagnitude) {
      std::ostringstream s;
      s << Keyword() << ": number " << word << " is absurd (magnitude above " << kMaxMagnitude << ")";
      Fail(s.str());
    }
  }

  std::string_view Keyword() const { return words_[0]; }

  void CheckFace() const {
    const std::size_t corners = words_.size() - 1;
    if (corners < 3) {
      Fail("f: a face needs at least 3 corners, found " +
           (corners == 0 ? std::string("none") : std::to_string(corners)));
    }
    const IndexKind vertex{"vertex", "vertex (v line)", "vertices (v lines)", totals_.vertices, seen_.vertices};
    const IndexKind texcoord{"texture coordinate", "texture coordinate (vt line)", "texture coordinates (vt lines)",
                             totals_.texcoords, seen_.texcoords};
    const IndexKind normal{"normal", "normal (vn line)", "normals (vn lines)", totals_.normals, seen_.normals};
    for (std::size_t c = 1; c <= corners; ++c) {
      const std::string_view corner = words_[c];
      // v, v/vt, v//vn or v/vt/vn: the parts between slashes, the vt part possibly empty.
      const auto slashes = static_cast<std::size_t>(std::count(corner.begin(), corner.end(), '/'));
      const std::size_t first = corner.find('/');
      const std::size_t second = slashes == 2 ? corner.find('/', first + 1) : std::string_view::npos;
      const std::string_view v = corner.substr(0, first);
      const std::string_view vt = slashes == 0 ? std::string_view() : corner.substr(first + 1, second - first - 1);
      const std::string_view vn = slashes == 2 ? corner.substr(second + 1) : std::string_view();
      const bool well_formed =
          slashes <= 2 && !v.empty() && (slashes != 1 || !vt.empty()) && (slashes != 2 || !vn.empty());
      const std::string which = "f: corner " + std::to_string(c) + " " + Quoted(corner);
      if (!well_formed) Fail(which + " is not v, v/vt, v//vn or v/vt/vn" + CommentHint(corner));
      CheckIndex(which, v, vertex);
      if (!vt.empty()) CheckIndex(which, vt, texcoord);
      if (!vn.empty()) CheckIndex(which, vn, normal);
    }
  }

  // An index as tinyobjloader reads it (an optional sign and digits), counting from 1, or back
  // from -1 (the last one written before this line); a positive index may also name one written
  // further on, as other readers allow.
  void CheckIndex(const std::string& which, std::string_view word, const IndexKind& kind) const {
    std::string_view digits = word;
    const bool negative = !digits.empty() && digits[0] == '-';
    if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) digits.remove_prefix(1);
    std::uint64_t magnitude = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), magnitude);
    const bool digits_only = !digits.empty() && end == digits.data() + digits.size() &&
                             (error == std::errc() || error == std::errc::result_out_of_range);
    if (!digits_only) Fail(which + ": " + Quoted(word) + " is not an index (an integer)");
    if (error == std::errc::result_out_of_range) magnitude = std::numeric_limits<std::uint64_t>::max();
    const std::string index = std::string(kind.name) + " index " + std::string(word);
    if (magnitude == 0) Fail(which + ": " + index + ": indices count from 1 (or back from -1)");
    if (!negative && magnitude > kind.total) {
      Fail(which + ": " + index + " is out of range: the file has " + Count(kind.total, kind.singular, kind.plural));
    }
    if (negative && magnitude > kind.before) {
      Fail(which + ": " + index + " is out of range: " + (kind.before == 0 ? "" : "only ") +
           Count(kind.before, kind.singular, kind.plural) + (kind.before == 1 ? " comes" : " come") +
           " before this line");
    }
  }

  const std::string& file_name_;
  const ObjCounts& totals_;
  ObjCounts seen_;
  std::size_t line_number_ = 0;
  std::vector<std::string_view> words_;
};

}  // namespace

ObjCounts CheckObjText(std::string_view text, const std::string& file_name) {
  // First the totals, which positive indices may reach; and no binary data, whose NUL bytes
  // tinyobjloader would take for the end of a line.
  ObjCounts totals;
  std::vector<std::string_view> words;
  ForEachLine(text, [&](std::size_t number, std::string_view line) {
    if (line.find('\0') != std::string_view::npos) {
      throw SceneError(file_name, "line " + std::to_string(number), "not an OBJ text file: binary data (a NUL byte)");
    }
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string_view::npos) return;
    const std::size_t end = line.find_first_of(" \t", start);
    switch (StatementOf(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start))) {
      case Statement::kVertex: ++totals.vertices; break;
      case Statement::kNormal: ++totals.normals; break;
      case Statement::kTexcoord: ++totals.texcoords; break;
      case Statement::kFace: ++totals.faces; break;
      case Statement::kOther: break;
    }
  });
  LineChecker checker(file_name, totals);
  ForEachLine(text, [&](std::size_t number, std::string_view line) { checker.Check(number, line); });
  if (totals.faces == 0) throw SceneError(file_name, "(file)", "no faces (f lines): nothing to draw");
  return totals;
}

}  // namespace twinraster
