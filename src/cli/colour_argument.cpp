#include "cli/colour_argument.hpp"

#include "base/usage_error.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <vector>

namespace twinraster::cli {

namespace {

[[noreturn]] void Bad(const std::string& option, const std::string& value, const std::string& expects) {
  throw UsageError(option + ": expects " + expects + ", not \"" + value + "\"");
}

bool ParseByte(const std::string& text, int base, std::uint8_t& out) {
  if (text.empty()) return false;
  unsigned v = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v, base);
  if (error != std::errc{} || end != text.data() + text.size() || v > 255) return false;
  out = std::uint8_t(v);
  return true;
}

std::string Trimmed(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

}  // namespace

Rgb8 ParseColourArgument(const std::string& option, const std::string& value) {
  const char* expects = "a colour as R,G,B (each 0..255) or #rrggbb";
  Rgb8 c;
  if (!value.empty() && value[0] == '#') {
    const std::string hex = value.substr(1);
    for (const char ch : hex) {
      if (!std::isxdigit(static_cast<unsigned char>(ch))) Bad(option, value, expects);
    }
    if (hex.size() != 6 || !ParseByte(hex.substr(0, 2), 16, c.r) || !ParseByte(hex.substr(2, 2), 16, c.g) ||
        !ParseByte(hex.substr(4, 2), 16, c.b)) {
      Bad(option, value, expects);
    }
    return c;
  }
  std::vector<std::string> parts(1);
  for (const char ch : value) {
    if (ch == ',')
      parts.emplace_back();
    else
      parts.back() += ch;
  }
  if (parts.size() != 3) Bad(option, value, expects);
  for (std::string& p : parts) {
    p = Trimmed(p);
    for (const char ch : p) {
      if (!std::isdigit(static_cast<unsigned char>(ch))) Bad(option, value, expects);  // no sign, no fraction
    }
  }
  if (!ParseByte(parts[0], 10, c.r) || !ParseByte(parts[1], 10, c.g) || !ParseByte(parts[2], 10, c.b)) {
    Bad(option, value, expects);
  }
  return c;
}

double ParsePercentArgument(const std::string& option, const std::string& value) {
  const std::string text = Trimmed(value);
  double v = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size() || !std::isfinite(v) || v < 0 ||
      v > 100) {
    Bad(option, value, "a percentage from 0 to 100");
  }
  return v;
}

}  // namespace twinraster::cli
