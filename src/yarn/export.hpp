// Writing a yarn model for other programs: Wavefront OBJ polylines (one `l` element per yarn
// piece) or a tube mesh, and PLY (vertices and edges, binary little-endian).
#pragma once

#include <iosfwd>

#include "yarn/curves.hpp"

namespace skein {

void write_yarn_obj(const YarnModel& model, std::ostream& out);
// Each piece swept by a `sides`-gon of the yarn's radius along rotation-minimising frames
// (double reflection, Wang et al. 2008); quads as OBJ faces.
void write_yarn_tubes_obj(const YarnModel& model, std::ostream& out, int sides = 6);
void write_yarn_ply(const YarnModel& model, std::ostream& out);

}  // namespace skein
