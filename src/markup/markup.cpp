#include "markup/markup.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace twinraster::markup {

std::string Escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      case '\t':
      case '\n':
      case '\r': out += c; break;
      default:
        // XML 1.0 has no other control characters, even escaped: a file name's \x01 becomes U+FFFD.
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
          out += "\xEF\xBF\xBD";
        else
          out += c;
    }
  }
  return out;
}

std::string Number(double value, int digits) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[128];
  digits = std::clamp(digits, 1, 40);
#if defined(__wasm__)
  // The browser module: libc++'s floating to_chars would add 119 KB of tables to every page, for
  // less gain than natively.
  const int written = std::snprintf(text, sizeof text, "%.*g", digits, value);
  return std::string(text, static_cast<std::size_t>(std::clamp(written, 0, static_cast<int>(sizeof text) - 1)));
#else
  // The standard defines this as printf's "%.*g" in the C locale, and it is faster than snprintf
  // (a mesh's page writes some 150,000 numbers).
  const auto written = std::to_chars(text, text + sizeof text, value, std::chars_format::general, digits);
  return std::string(text, written.ptr);
#endif
}

std::string Href(std::string_view relative_path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (const char c : relative_path) {
    const auto u = static_cast<unsigned char>(c);
    const bool safe = (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9') || c == '-' ||
                      c == '_' || c == '.' || c == '~' || c == '/';
    if (safe) {
      out += c;
    } else {
      out += '%';
      out += kHex[u >> 4];
      out += kHex[u & 15];
    }
  }
  return out;
}

std::string PageStart(std::string_view title) {
  // One style sheet for every page: readable without it, no web fonts, nothing fetched.
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         Escape(title) +
         "</title>\n<style>\n"
         "body{font:14px/1.4 system-ui,sans-serif;margin:1.5em;color:#222;background:#fff}\n"
         "h1{font-size:1.4em;margin:0 0 .5em}h2{font-size:1.15em;margin:1.5em 0 .4em}\n"
         "table{border-collapse:collapse}td,th{padding:3px 8px;border-bottom:1px solid "
         "#ddd;text-align:left;vertical-align:top}\n"
         "th{background:#f4f4f4}td.n,th.n{text-align:right;font-variant-numeric:tabular-nums}\n"
         "img{image-rendering:pixelated;border:1px solid #ccc;background:#eee}\n"
         ".none{color:#999}td.name{max-width:16em;overflow-wrap:anywhere}.path{font-size:11px;color:#666}td.details{"
         "font-size:12px;max-width:26em;color:#444}\n"
         "td.reason{max-width:24em}\n"
         ".verdict-identical{color:#17692b}.verdict-verified{color:#1a5a96}.verdict-rendered{color:#444}\n"
         ".verdict-inconclusive{color:#8a5a00;font-style:italic}\n"
         ".verdict-differing,.verdict-crashed,.verdict-error{color:#b00020;font-weight:bold}\n"
         ".summary td{font-size:1.1em}code,pre{font:12px/1.35 ui-monospace,monospace}\n"
         "pre{background:#f7f7f7;padding:6px 8px;margin:4px 0;overflow-x:auto}\n"
         "figure{display:inline-block;margin:0 1.5em 1.5em 0;vertical-align:top}figcaption{max-width:520px}\n"
         "</style>\n</head>\n<body>\n";
}

}  // namespace twinraster::markup
