// Labeling (paper §3.4): give every coarse face its wale and course directions. It starts from
// open boundaries (or interior edges: a cast-on along them) and propagates row by row, exactly
// as clicking an edge in the paper labels a row: the row walks sideways across wale edges, and
// each labelled row seeds the faces above its top edges. Triangles are short-row ends; the
// edges where labels disagree become the mismatched edges of the stitch mesh (§3.2).
#pragma once

#include <cstdint>
#include <vector>

#include "common/error.hpp"
#include "labeling/coarse_mesh.hpp"
#include "labeling/project.hpp"

namespace skein {

// What an edge is for its face, in the face's own frame (wale up, right side facing): the
// bottom runs left to right, the right side up, the top right to left, the left side down.
// The course direction of a face is left to right; rows may be knit either way.
enum class CoarseRole : std::uint8_t { none, bottom, right, top, left };
inline bool is_side(CoarseRole r) {
  return r == CoarseRole::left || r == CoarseRole::right;
}

struct Labeling {
  std::vector<CoarseRole> role;         // per coarse halfedge (none on unlabelled faces)
  std::vector<std::uint8_t> short_row;  // per face: 1 for a short-row face
  std::vector<CoarseRole> wide_side;    // per short-row face: the side with the extra rows
  std::vector<std::uint32_t> order;     // per face: 0, 1, 2... in labelling order
  std::vector<std::uint8_t> row_break;  // per halfedge: a project mismatch mark stops rows here

  CoarseRole operator[](CoarseHalfedge h) const { return role[h.index()]; }
  // The face's halfedge with the given role (invalid if it has none, e.g. a triangle's
  // missing side).
  CoarseHalfedge find(const CoarseMesh& mesh, CoarseFace f, CoarseRole r) const;
};

// Throws LabelingError naming the faces left over, where they are, and why.
Labeling label_coarse_mesh(const CoarseMesh& mesh, const Project& project);

class LabelingError : public Error {
 public:
  using Error::Error;
};

// The coarse halfedge a project file names (from ref.a to ref.b, or its twin if only that
// exists); throws Error naming the project's line when the mesh has no such edge.
CoarseHalfedge find_project_edge(const CoarseMesh& mesh, const Project& project,
                                 const CoarseEdgeRef& ref);

}  // namespace skein
