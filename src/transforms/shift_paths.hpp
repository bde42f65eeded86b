// Shift-paths (paper §3.1): the wale edges where each closed row (round) begins, chained up a
// tube so the rounds become one helix. Marks given in the mesh are checked; closed rows left
// without one get a path placed automatically, traced up and down from one wale edge as a user's
// single click would, repeated until every closed row is covered (a path that starts inside an
// increase or ends inside a decrease leaves rows for another path, Fig. 3f). Short rows between
// rounds whose yarn closes into a ring (a heel) are cut like rounds, by a path through them.
#pragma once

#include <cstdint>

#include "mesh/stitch_mesh.hpp"

namespace skein {

struct ShiftPathSummary {
  std::uint32_t paths = 0;          // separate paths (chains of marked edges)
  std::uint32_t placed = 0;         // of those, placed by skein
  std::uint32_t reversed_rows = 0;  // rows whose course direction the shift option turned
};

// Throws MeshError naming the edge when a mark sits on an open row or a closed row has two.
// Then applies each path's shift option: rounds run the way the option says, so the rows on a
// path whose labelled course direction disagrees are turned around (the yarn-entry and exit
// edges of every stitch swap). Changes only marks and wale roles.
ShiftPathSummary place_shift_paths(StitchMesh& mesh);

}  // namespace skein
