// Mesh-based relaxation (paper §3.4, after Yuksel et al. 2012): springs on the stitch mesh's
// edges pull every face towards one stitch wide and one row high, so that yarn is laid on a
// surface of the right proportions. Rest lengths by edge kind, with the knittable stitch
// mesh's changes:
//   course edge (and a face's course edge on the border)   the stitch width w
//   wale edge (shift-path edges too: the helix's step is    the row height h
//     laid by the yarn, which climbs a row across the path)
//   perpendicular mismatch (course on one side, wale on     (w + h) / 2
//     the other)
//   the extra top edges of a short-row face with more than  0 (they collapse)
//     five edges (srn)
//   the wale edges of a face beside a join or split          h x 1.5 when an extra yarn works
//                                                            it, h x 0.5 with a side's own
// plus a shear spring across each quad's diagonals, a weak spring to where each vertex
// started that keeps the global shape (instead of sliding on a subdivision surface), and
// bending (a bi-Laplacian step) that unfolds what springs alone fold: where the input gives a
// band less room than its rows need, springs longer than the room buckle it like an accordion
// (the sweater's armpits, the letters' and the teapot's joins: 936 faces of the teapot turned
// over their neighbours).
#pragma once

#include <span>
#include <vector>

#include "mesh/stitch_mesh.hpp"
#include "yarn/layout.hpp"

namespace skein {

struct MeshRelaxOptions {
  int iterations = 60;
  // Pull back towards the input position per iteration; bi-Laplacian smoothing per iteration,
  // which unfolds creases and accordions. At 0.05 and 0.1 the sweater's yoke, folded in the
  // input (872 faces turned over a neighbour), kept 384 folded and the yarn there missed 70
  // loops; at 0.1 and 0.3 none (0.3 x the bi-Laplacian's largest eigenvalue, 4, stays under
  // the explicit step's limit of 2).
  float anchor = 0.1f;
  float bend = 0.3f;
};

// A spring between points a and b.
struct Spring {
  std::uint32_t a, b;
  float rest;
};

// Jacobi iterations of `springs` from `start`, each point pulled back towards its start by
// `options.anchor` per iteration and smoothed by `options.bend`. Linear in points and springs
// per iteration.
std::vector<Point3> relax_springs(const std::vector<Point3>& start, std::span<const Spring> springs,
                                  const MeshRelaxOptions& options);

// The input's gauge: median course and wale edge lengths (the mesh was generated at it).
Gauge stitch_mesh_gauge(const StitchMesh& mesh);

// The relaxed vertex positions. Linear in the mesh's size per iteration.
std::vector<Point3> relax_stitch_mesh(const StitchMesh& mesh, const Gauge& gauge,
                                      const MeshRelaxOptions& options = {});

// Faces of `mesh` at `positions` turned over a neighbour across an edge (their normals, by
// Newell's formula, point apart): where the surface folds back on itself.
std::uint32_t folded_faces(const StitchMesh& mesh, std::span<const Point3> positions);

}  // namespace skein
