// The few pieces every page and SVG shares: escaping any text that came from a scene file or a
// path, numbers written the same way everywhere, and the page's head with its one style sheet.
// It writes no page of its own: run_report/, explain_report/ and bench_report/ do.
#pragma once

#include <string>
#include <string_view>

namespace twinraster::markup {

// Text safe inside an element or a quoted attribute, in HTML, SVG and XML alike: & < > " ' escaped,
// and control characters XML cannot hold replaced by U+FFFD.
std::string Escape(std::string_view text);

// `value` with `digits` significant digits, as %g writes it ("0.000123", "1.5e+06"); NaN and
// infinities as "nan", "inf".
std::string Number(double value, int digits = 4);

// A relative URL for a file name: each path segment percent-encoded where it is not a URL-safe
// character, so that "a b#1.png" links to itself and never breaks out of the attribute.
std::string Href(std::string_view relative_path);

// "<!DOCTYPE html>...<body>": UTF-8, the page's title (escaped) and the shared style sheet.
std::string PageStart(std::string_view title);
inline constexpr std::string_view kPageEnd = "</body>\n</html>\n";

}  // namespace twinraster::markup
