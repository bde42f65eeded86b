// The hand pattern, built on the lowering's live-loop program: runs of live loops mapped onto
// needles, spare needles and holders, courses onto rows and rnds with the side their direction
// gives; the target derives no row, direction or loop order of its own. Where most rnds run left to
// right (seen from the RS) and `rounds` says mirror, it knits the model's mirror image, so that
// rnds are worked right to left, RS facing, as hands knit. Throws UnsupportedError naming the step
// where the hand vocabulary cannot say it yet.
#pragma once

#include "hand/pattern_model.hpp"

namespace skein::hand {

HandPattern build_hand_pattern(const Compilation& compilation,
                               TurnMethod turns = TurnMethod::german,
                               Rounds rounds = Rounds::mirror_most);

}  // namespace skein::hand
