#pragma once

#include "driver/registry.hpp"

namespace skein {

// Registers every back end shipped with skein, each through its own register function.
void register_builtin_targets(Registry& registry);

}  // namespace skein
