// The viewer's web files (render/viewer/viewer.html, viewer.css, viewer.js),
// embedded into the library at build time (render/CMakeLists.txt,
// cmake/embed_text.cmake): the page needs no file at run time. Internal to
// render/ (not installed); render/animation_page.hpp is the interface.
#pragma once

#include <string_view>

namespace gridlock::viewer {

// The page around the data: holds the markers animation_page.cpp replaces
// (the title, the stylesheet link, the data element, the script element).
extern const std::string_view html;
// Inlined into <style>: contains no "</style".
extern const std::string_view css;
// Inlined into <script>: contains no "</script" and no "<!--".
extern const std::string_view script;

}  // namespace gridlock::viewer
