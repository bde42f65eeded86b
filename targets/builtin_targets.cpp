#include "builtin_targets.hpp"

#include "hand/hand_target.hpp"
#include "knitout/knitout_target.hpp"
#include "schedule/schedule_target.hpp"

namespace skein {

void register_builtin_targets(Registry& registry) {
  register_schedule_target(registry);
  register_knitout_target(registry);
  register_hand_target(registry);
}

}  // namespace skein
