// Stitch markers around the regions Algorithm 1's schedule marks (paper §5.1: "before and
// after a group of mismatched directions and the beginning and ending of short-rows"): a block
// of rows that work stitches beside mismatched edges or turn short, up to the first row after
// it that works every st with no turn left to resolve, gets a marker at each end of the span
// its marks cover. A marker is placed (pm) by the first row that goes on past its place,
// slipped (sm) by every later row of the block that passes it and removed (rm) by the last.
#pragma once

#include "hand/pattern_model.hpp"

namespace skein::hand {

// Rewrites the rows of each marked block with pm / sm / rm. A marker an operation would have
// to cross (a decrease over it), or one at the edge of the needle or the beginning of the rnd,
// is left out.
void place_region_markers(HandPattern& pattern);

}  // namespace skein::hand
