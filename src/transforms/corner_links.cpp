#include "transforms/corner_links.hpp"

#include <algorithm>

namespace skein {
namespace {

// Does `taker` work a loop of the kind that `maker` made?
bool works_a_loop_of(const KnitGraph& g, StitchId taker, StitchId maker, LoopKind kind) {
  if (taker == kNoStitch || maker == kNoStitch) return false;
  auto taken = g.loops_taken_by(taker);
  return std::any_of(taken.begin(), taken.end(), [&](std::uint32_t l) {
    return g.loops[l].maker == maker && g.loops[l].kind == kind;
  });
}

bool works_the_wale_of(const KnitGraph& g, StitchId taker, StitchId maker) {
  return works_a_loop_of(g, taker, maker, LoopKind::wale);
}

// Does the stitch after `s` pick up the loop `s` makes across the edge, not work its wale?
bool picks_up_along_its_edge_next(const KnitGraph& g, StitchId s) {
  StitchId next = g.yarn_next[s];
  return works_a_loop_of(g, next, s, LoopKind::perpendicular) && !works_the_wale_of(g, next, s);
}

// Do the two stitches after `s` (after `before`, the one before it) along the yarn work the
// loops of `s` and of `before`: does the yarn go back over the sts just made?
bool goes_back_over_the_sts_just_made(const KnitGraph& g, StitchId before, StitchId s) {
  StitchId next = g.yarn_next[s];
  return next != kNoStitch && works_the_wale_of(g, next, s) &&
         works_the_wale_of(g, g.yarn_next[next], before);
}

// Does the stitch after `s` work the loop beside one that `s` took across a gap (a band's
// last row going on round the needle past the gap it decreased into, as letter-h's band does
// after an odd number of rows)? The yarn goes on in the same direction: no turn.
bool goes_on_past_the_gap_next(const KnitGraph& g, const std::vector<StitchId>& before,
                               StitchId s) {
  StitchId next = g.yarn_next[s];
  if (works_the_wale_of(g, next, s)) return false;
  auto taken = g.loops_taken_by(s);
  return std::any_of(taken.begin(), taken.end(), [&](std::uint32_t l) {
    const Loop& across = g.loops[l];
    return across.kind == LoopKind::perpendicular && across.maker != kNoStitch &&
           (works_the_wale_of(g, next, g.yarn_next[across.maker]) ||
            works_the_wale_of(g, next, before[across.maker]));
  });
}

}  // namespace

void correct_corner_links(KnitGraph& g) {
  std::vector<StitchId> before(g.size(), kNoStitch);
  for (StitchId s = 0; s < g.size(); ++s)
    if (g.yarn_next[s] != kNoStitch) before[g.yarn_next[s]] = s;
  for (StitchId s = 0; s < g.size(); ++s)
    if (g.yarn_link[s] == YarnLink::shift && goes_back_over_the_sts_just_made(g, before[s], s))
      g.yarn_link[s] = YarnLink::turn;
    else if (g.yarn_link[s] == YarnLink::turn && picks_up_along_its_edge_next(g, s))
      g.yarn_link[s] = YarnLink::shift, g.flags[s] |= kRoundsACorner;
    else if (g.yarn_link[s] == YarnLink::turn && goes_on_past_the_gap_next(g, before, s))
      g.yarn_link[s] = YarnLink::shift, g.flags[s] |= kRoundsACorner | kPastAGap;
}

}  // namespace skein
