// Stitch-mesh generation at a gauge (the stitch mesh modeling framework the paper follows):
// every labelled coarse face becomes a grid of stitch faces.
//
// - Counts are chosen once per coarse edge: stitches along course edges, rows along sides,
//   from the edge lengths and the gauge; a quad's two sides share one row count, and a
//   short-row face's wide side has an even number of rows more than its narrow side.
// - Where a quad's bottom and top stitch counts differ, the change is spread over its rows
//   (linear widths) and along each row (evenly spaced, alternate rows offset by half a step).
// - Open bottoms are cast on (co), open tops bound off (bo).
// - Within a coarse row, a yarn walk decides which rows pass through each short-row face and
//   where pairs of short rows turn (sr4/sr5 faces, paper §3.3): turning where the wide side
//   needs rows, spread evenly between the passing rows; rows knit in the round never cross
//   the shift-path backwards.
// - Closed coarse rows get a shift-path along a coarse side edge, open rows an end to enter
//   at, chained so that the yarn stopping at the top of a row goes on into one row above
//   (yarn_plan.hpp): one chain, one yarn (paper §3.1, §4.2).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "labeling/coarse_mesh.hpp"
#include "labeling/labeling.hpp"
#include "labeling/project.hpp"
#include "mesh/stitch_mesh.hpp"

namespace skein {

// Limits on what a coarse mesh and gauge may ask for (docs/formats.md, "Limits"): stitches or
// rows along one coarse edge, and stitches in all.
inline constexpr std::uint32_t kMaxCountPerEdge = 100'000;
inline constexpr std::uint32_t kMaxStitches = 2'000'000;

struct GeneratedStitchMesh {
  StitchMesh mesh;
  std::vector<std::uint32_t> coarse_face;  // per stitch face: the coarse face it came from
  std::vector<std::uint32_t> segments;     // per coarse halfedge: stitches or rows along it
  std::uint32_t closed_rows = 0, open_rows = 0, shift_paths = 0;  // coarse rows and chains
};

// Throws Error (naming the coarse face or edge) when the labelled mesh cannot be generated,
// e.g. short rows that cannot turn where the yarn is.
GeneratedStitchMesh generate_stitch_mesh(const CoarseMesh& coarse, const Labeling& labeling,
                                         const Project& project);

// Reads the project's mesh, labels it and generates the stitch mesh.
GeneratedStitchMesh build_project(const Project& project);

// A readable account of the labelling and the counts, one line per coarse face (golden tests).
std::string describe_generation(const CoarseMesh& coarse, const Labeling& labeling,
                                const GeneratedStitchMesh& generated);

}  // namespace skein
