// The markup every page shares, on its own: escaping and links.
#include "markup/markup.hpp"

#include "support/catch.hpp"

using namespace twinraster::markup;

TEST_CASE("Escape: markup, quotes, ampersands and control characters come out as text", "[markup]") {
  CHECK(Escape("<script>alert(\"x\")</script>") == "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt;");
  CHECK(Escape("a&b 'c'") == "a&amp;b &#39;c&#39;");
  CHECK(Escape("tab\there\x01") == "tab\there\xEF\xBF\xBD");
  CHECK(Escape("plain") == "plain");
}

TEST_CASE("Href: file names become links that point at themselves", "[markup]") {
  CHECK(Href("../out/a b#1.png") == "../out/a%20b%231.png");
  CHECK(Href("thumbs/<x>\".png") == "thumbs/%3Cx%3E%22.png");
  CHECK(Href("x-y_z.~1/2.png") == "x-y_z.~1/2.png");
}
