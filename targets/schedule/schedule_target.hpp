// The `schedule` target: Algorithm 1's order as readable text, one stitch a line, and its
// simulator, which replays such a text against the input and proves that every stitch is
// worked exactly once, along its yarn, after everything it depends on.
#pragma once

#include "driver/registry.hpp"

namespace skein {

void register_schedule_target(Registry& registry);

}  // namespace skein
