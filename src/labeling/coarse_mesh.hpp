// The coarse polygon mesh a designer models (paper Fig. 1a): quads, and triangles where short
// rows end. It is read from an ordinary OBJ file (tinyobjloader); OBJ groups (`g`/`o` names)
// name sets of faces for the project file's stitch patterns.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/handles.hpp"
#include "mesh/stitch_mesh.hpp"

namespace skein {

using CoarseVertex = Handle<struct CoarseVertexTag>;
using CoarseHalfedge = Handle<struct CoarseHalfedgeTag>;
using CoarseFace = Handle<struct CoarseFaceTag>;

// Halfedges of a face are contiguous and counter-clockwise; the edge between two faces is
// named by its two vertices, as in the file (1-based in every message).
class CoarseMesh {
 public:
  std::string source;                // file name, for messages
  std::vector<Vec3> position;        // per vertex
  std::vector<std::string> groups;   // OBJ group names ("" for faces before any group)
  std::vector<std::uint32_t> group;  // per face: index into groups

  std::uint32_t num_vertices() const { return static_cast<std::uint32_t>(position.size()); }
  std::uint32_t num_faces() const { return static_cast<std::uint32_t>(face_first_.size() - 1); }
  std::uint32_t num_halfedges() const { return static_cast<std::uint32_t>(tail_.size()); }
  HandleRange<CoarseFace> faces() const { return {0, num_faces()}; }
  HandleRange<CoarseHalfedge> halfedges() const { return {0, num_halfedges()}; }
  HandleRange<CoarseHalfedge> halfedges(CoarseFace f) const {
    return {face_first_[f.index()], face_first_[f.index() + 1]};
  }

  std::uint32_t degree(CoarseFace f) const { return halfedges(f).size(); }
  CoarseFace face(CoarseHalfedge h) const { return face_[h.index()]; }
  CoarseVertex tail(CoarseHalfedge h) const { return tail_[h.index()]; }
  CoarseVertex head(CoarseHalfedge h) const { return tail(next(h)); }
  CoarseHalfedge next(CoarseHalfedge h) const;
  CoarseHalfedge prev(CoarseHalfedge h) const;
  CoarseHalfedge twin(CoarseHalfedge h) const { return twin_[h.index()]; }  // invalid: border
  bool is_border(CoarseHalfedge h) const { return !twin(h).valid(); }
  // One halfedge per edge names the edge: the lower index of the pair.
  CoarseHalfedge canonical(CoarseHalfedge h) const {
    return is_border(h) || h < twin(h) ? h : twin(h);
  }
  CoarseHalfedge find_halfedge(CoarseVertex a, CoarseVertex b) const;  // a -> b, or invalid
  Vec3 at(CoarseVertex v) const { return position[v.index()]; }
  Vec3 centroid(CoarseFace f) const;
  float length(CoarseHalfedge h) const;

  std::string describe(CoarseHalfedge h) const;  // "edge 3-7"
  std::string describe(CoarseFace f) const;      // "face 12 at (1, 2.5, 0)"

 private:
  friend CoarseMesh build_coarse_mesh(std::string, std::vector<Vec3>,
                                      const std::vector<std::vector<std::uint32_t>>&);
  std::vector<std::uint32_t> face_first_{0};
  std::vector<CoarseVertex> tail_;
  std::vector<CoarseFace> face_;
  std::vector<CoarseHalfedge> twin_;
  std::vector<std::vector<CoarseHalfedge>> outgoing_;  // per vertex
};

// Links faces (0-based vertex indices, counter-clockwise) into a mesh. Throws MeshError on an
// edge used twice the same way, a face with fewer than 3 corners or a repeated corner.
CoarseMesh build_coarse_mesh(std::string source, std::vector<Vec3> positions,
                             const std::vector<std::vector<std::uint32_t>>& faces);

// Coordinates beyond this (in mesh units) are refused: far past any garment in any unit, and
// small enough that lengths and sums of them stay finite in float.
inline constexpr double kMaxCoordinate = 1e6;

// Reads OBJ text (v, f, g/o lines; everything else ignored); `name` is used in messages.
// Throws ParseError for a vertex that is not three finite coordinates (naming the line) and
// MeshError for a face with two corners at one point.
CoarseMesh parse_coarse_mesh(const std::string& text, const std::string& name);
// The same from a file: IoError if it cannot be read or is not a regular file.
CoarseMesh read_coarse_mesh(const std::string& path);

// Writes the mesh as OBJ, with `g` lines for its groups (what `skein new` produces).
void write_coarse_mesh(const CoarseMesh& mesh, std::ostream& out);

std::string format_point(Vec3 p);  // "(1, 2.5, 0)"

}  // namespace skein
