// The skein stitch-mesh file: a Wavefront OBJ file whose stitch data (types, edge roles,
// shift-path marks, yarn choices) lives in '#~' comment lines, so any OBJ viewer shows the
// mesh. docs/formats.md describes the format.
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include "mesh/stitch_mesh.hpp"

namespace skein {

// Parses a stitch mesh. Throws ParseError (file_name, line, what was expected) on a malformed
// line and lets MeshError from StitchMeshBuilder::build() through (edges shared the wrong way).
// The result is not validate()d.
StitchMesh parse_stitch_mesh(std::string_view text, const std::string& file_name);

// Reads the whole file and parses it; throws IoError if it cannot be read.
StitchMesh read_stitch_mesh(const std::string& path);

// Writes the mesh so that parsing the output gives the same mesh back and writing that again
// gives the same bytes. Write failures are left in the stream's state, as with operator<<.
void write_stitch_mesh(const StitchMesh& mesh, std::ostream& out);

}  // namespace skein
