// The short-row rules of an sr5 (paper Fig. 10b: the turn's loop a loop of its own, which the
// stitch above knits together with the sr5's), stated once for the targets that make stitches
// and for the judges that prove them: a judge reads the rule here, never from a generator.
#pragma once

#include <cstdint>
#include <span>

#include "knitgraph/knit_graph.hpp"

namespace skein {

// The stitch that takes both loops of the sr5 `s` (its st's and the turn's), or kNoStitch when
// no one stitch does. A machine keeps the turn's loop on its needle until that stitch.
StitchId taker_of_both_sr5_loops(const KnitGraph& g, StitchId s);

// Is `s` a k2tog, ssk or p2tog that takes the two loops of one sr5, and no other?
bool knits_an_sr5_as_one(const KnitGraph& g, StitchId s);

// A knitter's short-row turn (a DS, a wrap) holds the turn's loop on its st, so the model's sr5
// is worked as an sr4, and the decrease that takes both of its loops alone as the plain st of
// `k DS` / `kw` (a p2tog, seen from the RS, as `p DS` / `pw`). The stitch type a knitter works
// `s` as; the model's own elsewhere.
StitchType worked_by_hand(const KnitGraph& g, StitchId s);

// The sts a knitter counts on the needle for `loops`: an sr5's two loops are one st.
std::uint32_t hand_stitch_count(const KnitGraph& g, std::span<const std::uint32_t> loops);

}  // namespace skein
