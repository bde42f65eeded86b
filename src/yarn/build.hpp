// The yarn stage from end to end, run on request (`skein yarn`), not by compile_model: lay the
// stitches out (the relaxed stitch mesh, or an AutoKnit stitch graph's positions), lay yarn
// from the templates, and relax it.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "knitgraph/knit_graph.hpp"
#include "knitgraph/yarn_pieces.hpp"
#include "mesh/stitch_mesh.hpp"
#include "yarn/curves.hpp"
#include "yarn/mesh_relax.hpp"
#include "yarn/relax.hpp"

namespace skein {

struct YarnOptions {
  MeshRelaxOptions mesh;
  CurveOptions curves;
  RelaxOptions relax;
  bool relax_yarn = true;
};

struct YarnBuild {
  YarnModel model;
  Gauge gauge;
  RelaxReport relaxation;  // steps 0 when not relaxed
};

// Positions of an AutoKnit .st file's stitches (line order = stitch ids).
std::vector<std::array<double, 3>> read_stitch_positions(const std::string& path);

// From a knit graph and its stitch mesh (`mesh` may be null: then `positions` places the
// stitches, one per stitch).
YarnBuild build_yarn(const KnitGraph& graph, const YarnPieces& pieces, const StitchMesh* mesh,
                     const std::vector<std::array<double, 3>>& positions,
                     const YarnOptions& options = {});

}  // namespace skein
