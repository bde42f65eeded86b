// The knitting page written out: one self-contained HTML file (style, data, three.js and the
// page's script inline) that works offline from a file:// URL.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>

#include "hand_web/page_data.hpp"

namespace skein::hand_web {

// Where Debian's libjs-three puts three.js r111 (three.min.js and
// examples/js/controls/OrbitControls.js); SKEIN_THREE_DIR overrides it.
inline constexpr const char* kThreeDir = "/usr/share/javascript/three";

// three.min.js and OrbitControls.js, read from SKEIN_THREE_DIR or kThreeDir; nullopt when
// libjs-three is not installed (the page then works without its 3D view, and says so).
struct ThreeJs {
  std::string library, orbit_controls, from;
};
std::optional<ThreeJs> find_three_js();

void write_page(const PageData& data, const ThreeJs* three, std::ostream& out);

// The pattern embedded in a page write_page wrote (what the page's simulator replays); nullopt
// when `html` holds none.
std::optional<std::string> embedded_pattern(std::string_view html);

// The page's own script and style (page_script.cpp).
extern const char* const kPageStyle;
extern const char* const kPageScript;

}  // namespace skein::hand_web
