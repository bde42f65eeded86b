#include "yarn/build.hpp"

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "mesh/autoknit_st.hpp"

namespace skein {

std::vector<std::array<double, 3>> read_stitch_positions(const std::string& path) {
  std::vector<std::array<double, 3>> positions;
  parse_autoknit_st(read_file(path), path, &positions);
  return positions;
}

YarnBuild build_yarn(const KnitGraph& graph, const YarnPieces& pieces, const StitchMesh* mesh,
                     const std::vector<std::array<double, 3>>& positions,
                     const YarnOptions& options) {
  StitchLayout layout;
  if (mesh) {
    std::vector<Point3> relaxed = relax_stitch_mesh(*mesh, stitch_mesh_gauge(*mesh), options.mesh);
    layout = layout_from_mesh(*mesh, relaxed, graph);
  } else {
    SKEIN_ASSERT(positions.size() == graph.size(), "one position per stitch");
    layout = layout_from_positions(graph, positions);
  }
  YarnBuild build;
  build.gauge = layout.gauge;
  build.model = generate_yarn(graph, pieces, layout, options.curves);
  if (options.relax_yarn) build.relaxation = relax_yarn(build.model, options.relax);
  return build;
}

}  // namespace skein
