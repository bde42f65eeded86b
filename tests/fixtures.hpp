// Small stitch meshes built in code for tests: unit squares on a grid, each with its stitch
// type and edge roles given as in the file format (bottom, right, top, left edge order).
#pragma once

#include <string>
#include <vector>

#include "driver/pipeline.hpp"
#include "mesh/stitch_mesh.hpp"

namespace skein::testing {

struct Square {
  int x, y;           // lower-left corner
  StitchType type;
  std::string roles;  // four letters for the lower, right, upper and left edges: b t i o
};

struct YarnMark {
  int x0, y0, x1, y1;  // the edge between two grid points
  MismatchYarn::Kind kind;
  int own_square = -1;  // index into the squares, with Kind::own
};

StitchMesh grid_mesh(int width, int height, const std::vector<Square>& squares,
                     const std::vector<YarnMark>& yarn = {});

// The paper's Fig. 13: two groups of joining edges on one row, one knit with the upper
// side's yarn and one with the lower side's: a dependency cycle.
StitchMesh fig13_deadlock_mesh();

// One small mesh per mismatched direction (paper Fig. 5), three stitches wide where it can be.
// `yarn` applies to every mismatched edge (joins and splits); `own_upper` picks the side.
StitchMesh join_mesh(MismatchYarn::Kind yarn = MismatchYarn::Kind::by_default, bool own_upper = false);
StitchMesh split_mesh(MismatchYarn::Kind yarn = MismatchYarn::Kind::by_default, bool own_upper = false);
StitchMesh contracting_mesh();
StitchMesh expanding_mesh();

}  // namespace skein::testing
