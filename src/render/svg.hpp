// Pictures a person can read: a stitch mesh, or a labelled coarse mesh, drawn as SVG in an
// orthographic view from the front and a little above (back faces first, faded). Faces are
// coloured by kind in the paper's colours (shift-path green, split yellow, join blue,
// short-row red), each stitch carries a course arrow, and rows are numbered.
#pragma once

#include <iosfwd>
#include <string>

#include "labeling/coarse_mesh.hpp"
#include "labeling/labeling.hpp"
#include "mesh/stitch_mesh.hpp"

namespace skein {

void render_stitch_mesh_svg(const StitchMesh& mesh, const std::string& title, std::ostream& out);
void render_coarse_mesh_svg(const CoarseMesh& mesh, const Labeling& labeling,
                            const std::string& title, std::ostream& out);

// INPUT is a stitch mesh (.obj with the skein header), a project (.yaml: its generated stitch
// mesh, or with `coarse` its labelled coarse mesh) or a plain coarse OBJ (labelled from its
// lowest boundary). Writes the SVG to `out`; returns what it drew, for the success line ("the
// stitch mesh of sock.yaml, 4606 stitches").
std::string render_file(const std::string& input, bool coarse, std::ostream& out);

}  // namespace skein
