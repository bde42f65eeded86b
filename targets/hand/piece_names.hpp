// What a pattern calls its pieces: knitters name them after the part of the garment they make
// ("Thumb", "Left leg"), not by number.
#pragma once

#include <string>
#include <vector>

#include "hand/pattern_model.hpp"
#include "knitgraph/knit_graph.hpp"
#include "knitgraph/yarn_pieces.hpp"

namespace skein::hand {

// Names each piece (`piece_names`, by number - 1) after the part most of its stitches come
// from, with a number where pieces share a part ("Leg 1", "Leg 2"), and each section after the
// part most of its own are in (a piece set aside and taken up again may go on into another
// part: the palm's yarn works the thumb). "Piece N" where the model names no parts (a stitch
// mesh file, a stitch graph), only one, or none of the piece's stitches.
void name_pieces(const KnitGraph& graph, const YarnPieces& yarns, HandPattern& pattern);

}  // namespace skein::hand
