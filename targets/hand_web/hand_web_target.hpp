// The `hand-web` target: the knitting page (paper §5, Fig. 14). One self-contained HTML file
// that steps a knitter through the model stitch by stitch in the lowering's program order: the
// proven hand pattern's row with the current stitch's token marked, the stitch and repeat
// counts, and the model in 3D (three.js r111 from Debian's libjs-three, inlined) with the
// stitches done, the current one and those to do told apart. Its simulator replays the pattern
// the page embeds with the hand simulator.
#pragma once

#include "driver/registry.hpp"

namespace skein {

void register_hand_web_target(Registry& registry);

}  // namespace skein
