// The yarn links a knitter works at the corners between rows and rounds. A model's link there
// says little (a mesh marks shift-paths on rounds, and leaves the rest turns), so each one is
// read from what the yarn does next: a shift-path whose next stitches work the loops of the
// stitches just made (the yarn goes back over them, as where a round goes on into a flap's
// rows) turns the work, and a turn whose next stitch picks up along the edge of the stitch
// just made (a gusset's round going on from its flap's last row, down its edge) goes on into
// the round as a shift, flagged kRoundsACorner (a hand knitter says "do not turn" there), and
// so does a turn whose next rnd does not start on the stitch just made but ends on it (a band's
// or a face's last row, after an odd number of rows: the yarn goes on round the needle), flagged
// kGoesOnRound too. The schedule's turns and every target read the corrected links.
#pragma once

#include "knitgraph/knit_graph.hpp"

namespace skein {

// Linear in the number of stitches.
void correct_corner_links(KnitGraph& graph);

}  // namespace skein
