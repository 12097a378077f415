# Writes a .cpp defining twinraster::moving_page::ChainPageScript() and ChainPageStyle() as the
# text of chain_page.js and chain_page.css, each in a raw string literal. A file holding the
# literal's closing delimiter would end it early, and a "</script" or "</style" would end the
# page's element early: either stops the build instead.
# Run as: cmake -DSCRIPT=<js> -DSTYLE=<css> -DOUTPUT=<cpp> -P page_assets.cmake
cmake_minimum_required(VERSION 3.25)
set(delimiter "twinraster_asset")
file(READ ${SCRIPT} script)
file(READ ${STYLE} style)
string(TOLOWER "${script}" lower_script)
string(TOLOWER "${style}" lower_style)
foreach(text end IN ZIP_LISTS "script;style" "</script;</style")
  string(FIND "${lower_${text}}" "${end}" found)
  if(NOT found EQUAL -1)
    message(FATAL_ERROR "page_assets.cmake: the ${text} holds \"${end}\", which would end its element in the page")
  endif()
endforeach()
foreach(text IN ITEMS script style)
  string(FIND "${${text}}" ")${delimiter}\"" found)
  if(NOT found EQUAL -1)
    message(FATAL_ERROR "page_assets.cmake: the ${text} holds \")${delimiter}\"\", which would end its literal")
  endif()
endforeach()
set(cpp "// Written by src/moving_page/page_assets.cmake from chain_page.js and chain_page.css: edit those.\n")
string(APPEND cpp "#include \"moving_page/page_assets.hpp\"\n\nnamespace twinraster::moving_page {\n\n")
string(APPEND cpp "std::string_view ChainPageScript() {\n  return R\"${delimiter}(${script})${delimiter}\";\n}\n\n")
string(APPEND cpp "std::string_view ChainPageStyle() {\n  return R\"${delimiter}(${style})${delimiter}\";\n}\n\n")
string(APPEND cpp "}  // namespace twinraster::moving_page\n")
# Rewritten only when the text changed, so that an unchanged script recompiles nothing.
file(WRITE ${OUTPUT}.new "${cpp}")
file(COPY_FILE ${OUTPUT}.new ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.new)
