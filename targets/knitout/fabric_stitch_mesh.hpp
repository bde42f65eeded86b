// The fabric a knitout file makes, written as a skein stitch mesh (`.obj`, which `skein check`
// and `skein compile` read): the stitch graph of fabric_stitch_graph.hpp, read back as a knit
// graph, each stitch a face glued to its neighbours where the fabric joins them: its bottom
// edges to the top edges of the stitches whose loops it takes, its wale edges to the stitches
// before and after it along the row. A short row's turn is a short-row face (its wrap folded
// into the wale it lies on), a tube's rounds a helix cut at a seam into rounds that close across
// a shift-path; docs/knitout.md says how each case is laid. A fabric whose stitches, so glued,
// would fold over each other, or that has a stitch no face says (a short row turning at a
// decrease, a decrease of four loops), is refused with UnsupportedError naming the stitch (its
// needle and its row in the stitch graph), and nothing is written: the stitch graph (`.st`) says
// it.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "knitout/vbed_simulator.hpp"

namespace skein::knitout {

// `border` as for write_fabric_stitch_graph. A refusal may come after `out` was written to:
// give a stream that is thrown away on a throw (write_file_atomically's).
void write_fabric_stitch_mesh(const Replay& replay, const std::string& file, std::ostream& out,
                              const std::vector<bool>* border = nullptr);

}  // namespace skein::knitout
