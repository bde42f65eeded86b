// How each stitch type is made on a v-bed, as facts both the emitter and the fabric proof use.
// Slots count a stitch's loops left to right in its own frame (as in the knit graph).
#pragma once

#include <cstdint>

#include "mesh/stitch_type.hpp"

namespace skein::knitout {

// Stitches that do not knit their loop off: a tuck adds its loop to the needle over the loop it
// takes, a slip leaves the needle as it is; the stitch above takes the needle's loops together.
inline bool keeps_loop_below(StitchType t) {
  return t == StitchType::tuck || t == StitchType::sl;
}

// Bound off by the chain: a bind-off, and a three-needle bind-off (its two loops, one from each
// needle, stacked on one). Each one's loop is pulled through the loops it takes and the chain's
// loop before it, which is moved onto its needle, and nothing takes it but the next link.
inline bool chained_off(StitchType t) {
  return t == StitchType::bo || t == StitchType::tnbo;
}

// The made slot whose loop is pulled through the stitch's taken loop (for an increase the other
// one is a new loop: kfb pulls both through, yo/m1l/m1r make the other by a tuck). The yarn
// makes kfb's and yo's knit loop first; m1l's new loop lies left of it, m1r's right. An sr5
// knits its loop and, turning, makes the turn's loop on the side the yarn came from (by a
// tuck on the facing needle).
inline std::uint8_t knit_slot(StitchType t, bool left_to_right) {
  switch (t) {
    case StitchType::kfb:
    case StitchType::yo:
      return left_to_right ? 0 : 1;
    case StitchType::sr5:
      return left_to_right ? 1 : 0;
    case StitchType::m1l:
      return 1;
    default:
      return 0;
  }
}
inline bool made_slot_pulled_through(StitchType t, std::uint8_t slot, bool left_to_right) {
  return t == StitchType::kfb || slot == knit_slot(t, left_to_right);
}

// The slot of the i-th loop a stitch's yarn makes (slots count left to right in its frame): the
// yarn crosses the stitch in its course's direction, except an sr5's, which comes back.
inline std::uint8_t made_slot_along_yarn(StitchType t, bool left_to_right, std::uint8_t i,
                                         std::uint8_t count) {
  bool forward = left_to_right != (t == StitchType::sr5);
  return forward ? i : static_cast<std::uint8_t>(count - 1 - i);
}

}  // namespace skein::knitout
