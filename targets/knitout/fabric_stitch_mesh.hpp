// The fabric a knitout file makes, written as a skein stitch mesh (`.obj`, which `skein check`
// and `skein compile` read): the stitch graph of fabric_stitch_graph.hpp, read back as a knit
// graph, laid out row on row. A face per stitch: its bottom edges are the loops it takes from
// the row below, its top edges the loops it makes, its wale edges shared with its neighbours
// along the row (in chart order: left to right on the side facing the front bed).
//
// Built for what a stitch mesh of whole rows can say: one yarn piece worked flat (open rows)
// or round (closed rounds), cast on in its first row and bound off in its last, each row
// taking exactly the loops of the row below, side by side in their order. A fabric that is
// anything else (short rows, several yarn pieces, loops held over rows, crossed or
// yarned-over loops, wales ending inside it) is refused with UnsupportedError naming the row,
// and nothing is written: the stitch graph (`.st`) says it.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "knitout/vbed_simulator.hpp"

namespace skein::knitout {

// `border` as for write_fabric_stitch_graph.
void write_fabric_stitch_mesh(const Replay& replay, const std::string& file, std::ostream& out,
                              const std::vector<bool>* border = nullptr);

}  // namespace skein::knitout
