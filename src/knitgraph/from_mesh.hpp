// Stitch mesh -> knit graph: one stitch per face, loops across course and perpendicular edges,
// yarn order along rows and from row to row (through shift-paths and turns, paper §4.2), and
// the dependencies that joins and splits knit with a side's own yarn add (paper §4.1).
#pragma once

#include <string>

#include "knitgraph/knit_graph.hpp"
#include "mesh/stitch_mesh.hpp"

namespace skein {

// The mesh must have passed validate(). Stitch ids equal face indices.
KnitGraph build_knit_graph(const StitchMesh& mesh, const std::string& source_name);

}  // namespace skein
