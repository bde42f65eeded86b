// Where each stitch sits in space, for the yarn-level model: a frame per stitch (a cell one
// stitch wide and one row high, its course axis along the way the yarn travels, its normal
// towards the right side). Built from the relaxed stitch mesh's faces (yarn/mesh_relax), or,
// for a stitch graph without a mesh (AutoKnit .st), from each stitch's position and those of
// its yarn and loop neighbours.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "knitgraph/knit_graph.hpp"
#include "mesh/stitch_mesh.hpp"

namespace skein {

using Point3 = Eigen::Vector3f;

// A stitch's cell: point(x, y, z) = origin + x course + y wale + z normal, x and y in [0, 1]
// across the cell (x along the yarn's travel, y up the wale), z in model units.
struct StitchFrame {
  Point3 origin = Point3::Zero();
  Point3 course = Point3::UnitX();
  Point3 wale = Point3::UnitY();
  Point3 normal = Point3::UnitZ();  // unit, towards the right side
  Point3 at(float x, float y, float z) const { return origin + x * course + y * wale + z * normal; }
};

// The fabric's proportions in model units: the median stitch width and row height.
struct Gauge {
  float stitch_width = 1;
  float row_height = 1;
};

struct StitchLayout {
  Gauge gauge;
  std::vector<StitchFrame> frame;           // per stitch of the knit graph
  std::vector<std::uint8_t> right_to_left;  // per stitch: the yarn travels right to left (RS view)
};

// Frames from the faces of `mesh` at `positions` (one per mesh vertex: the relaxed ones); the
// stitches the transforms extruded along joins and splits get theirs from their neighbours.
StitchLayout layout_from_mesh(const StitchMesh& mesh, std::span<const Point3> positions,
                              const KnitGraph& graph);

// Frames from one position per stitch (an AutoKnit .st's x y z). Normals are made to agree
// between neighbours and to point away from the middle of the model (outwards on a tube).
StitchLayout layout_from_positions(const KnitGraph& graph,
                                   std::span<const std::array<double, 3>> positions);

}  // namespace skein
