// The hand pattern built on the lowering's live-loop program (`--set builder=program`): runs
// of live loops mapped onto needles, courses onto rows and rnds with the side their direction
// gives. Where most rnds run left to right (seen from the RS) and `rounds` says mirror, it knits
// the model's mirror image, so that rnds are worked right to left, RS facing, as hands knit.
// Throws UnsupportedError naming the step where the hand vocabulary cannot say it yet.
#pragma once

#include "hand/pattern_model.hpp"

namespace skein::hand {

HandPattern build_pattern_from_program(const Compilation& compilation,
                                       TurnMethod turns = TurnMethod::german,
                                       Rounds rounds = Rounds::mirror_most);

}  // namespace skein::hand
