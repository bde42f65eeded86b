// How a knitter works one model stitch: the hand operations for its type with a side facing,
// and the short-row rules (a turn's loop worked as one with its st: `k DS`, `kw`; a st with a
// yo laid over it: `brk`). Both pattern builders write stitches through these.
#pragma once

#include <vector>

#include "hand/pattern_model.hpp"
#include "knitgraph/knit_graph.hpp"
#include "knitgraph/worked_by_hand.hpp"

namespace skein::hand {

// Throws UnsupportedError naming the first stitch whose type hand patterns do not cover, or
// an sr5 whose two loops no one decrease above knits as one (a DS or a wrap with its st).
void check_stitch_types(const KnitGraph& g);

// Does `s` work the loop a short row turned at?
bool works_a_turn(const KnitGraph& g, StitchId s);

// kw / pw (wrap and turn) or k DS / p DS (German short rows) for the plain st that works the
// loop a short row turned at. Throws UnsupportedError for any other op.
HandOp resolving(const KnitGraph& g, HandOp plain, StitchId s, TurnMethod turns);

// Does `s` work a st with a yo laid over it (a tuck's, or one slipped since)?
bool works_a_st_with_its_yo(const KnitGraph& g, StitchId s);

// The ops a knitter works the ordinary stitch `s` with (its type as worked by hand, mirrored
// when the pattern knits the mirror image), `side` facing, appended to `ops`: the turn of a
// short row (w&t; for German short rows the st worked before `turn`), or the st and its
// make-one. Sets `wraps_again` when a w&t wraps a st wrapped before.
void append_stitch_ops(const KnitGraph& g, StitchId s, Side side, bool mirror, TurnMethod turns,
                       std::vector<HandOp>& ops, bool& wraps_again);

// A make-one lifts the strand to the next stitch: the last stitch of a flat row has none.
// Throws UnsupportedError naming `last`.
void check_make_one_has_a_strand(const KnitGraph& g, StitchId last);

}  // namespace skein::hand
