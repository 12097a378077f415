// The moving page's script and style sheet, chain_page.js and chain_page.css, as the build read
// them (page_assets.cmake writes their text into a .cpp): kept in files of their own so that they
// are read, reviewed and checked as JavaScript and CSS. It does not assemble the page.
#pragma once

#include <string_view>

namespace twinraster::moving_page {

std::string_view ChainPageScript();
std::string_view ChainPageStyle();

}  // namespace twinraster::moving_page
