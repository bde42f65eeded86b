// The `knitout` target (machine knitting through a profile of machine_profiles/) and its
// simulator, the virtual v-bed, which replays any knitout file and proves it against the input.
#pragma once

#include "driver/registry.hpp"

namespace skein {

void register_knitout_target(Registry& registry);

}  // namespace skein
