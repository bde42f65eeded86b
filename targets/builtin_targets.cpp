#include "builtin_targets.hpp"

#include "hand/hand_target.hpp"
#include "hand_web/hand_web_target.hpp"
#include "knitout/knitout_target.hpp"
#include "schedule/schedule_target.hpp"

namespace skein {

void register_builtin_targets(Registry& registry) {
  register_schedule_target(registry);
  register_knitout_target(registry);
  register_hand_target(registry);
  register_hand_web_target(registry);  // the page shows the hand target's text
}

}  // namespace skein
