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

// Does the rnd after `s` end on the st `s` made, without starting on it? The yarn goes on round
// the needle, no turn: a band's last row going on past the gap it decreased into (letter-h's
// after an odd number of rows), a face's last row going on into the rnd that places the other
// pieces' sts and comes round to the face's (the two bars').
bool comes_round_to_it(const KnitGraph& g, StitchId s) {
  StitchId last = g.yarn_next[s];
  if (last == kNoStitch || g.row_shape[g.row[last]] != RowShape::closed ||
      works_the_wale_of(g, last, s))
    return false;
  while (g.yarn_link[last] == YarnLink::course) last = g.yarn_next[last];
  return works_the_wale_of(g, last, s);
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
    else if (g.yarn_link[s] == YarnLink::turn && comes_round_to_it(g, s))
      g.yarn_link[s] = YarnLink::shift, g.flags[s] |= kRoundsACorner | kGoesOnRound;
}

}  // namespace skein
