#include "knitgraph/worked_by_hand.hpp"

namespace skein {

StitchId taker_of_both_sr5_loops(const KnitGraph& g, StitchId s) {
  auto made = g.loops_made_by(s);
  StitchId taker = g.loops[made[0]].taker;
  return g.loops[made[1]].taker == taker ? taker : kNoStitch;
}

bool knits_an_sr5_as_one(const KnitGraph& g, StitchId s) {
  auto taken = g.loops_taken_by(s);
  StitchType t = g.type[s];
  if (taken.size() != 2 ||
      (t != StitchType::k2tog && t != StitchType::ssk && t != StitchType::p2tog))
    return false;
  StitchId maker = g.loops[taken[0]].maker;
  return maker != kNoStitch && g.type[maker] == StitchType::sr5 && g.loops[taken[1]].maker == maker;
}

StitchType worked_by_hand(const KnitGraph& g, StitchId s) {
  if (g.type[s] == StitchType::sr5) return StitchType::sr4;
  if (knits_an_sr5_as_one(g, s))
    return g.type[s] == StitchType::p2tog ? StitchType::p : StitchType::k;
  return g.type[s];
}

std::uint32_t hand_stitch_count(const KnitGraph& g, std::span<const std::uint32_t> loops) {
  std::uint32_t sr5 = 0;
  for (std::uint32_t l : loops)
    sr5 += g.loops[l].maker != kNoStitch && g.type[g.loops[l].maker] == StitchType::sr5;
  return static_cast<std::uint32_t>(loops.size()) - sr5 / 2;
}

}  // namespace skein
