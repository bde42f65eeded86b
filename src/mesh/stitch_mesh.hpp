// The stitch mesh: a polygon mesh whose faces are stitches. Connectivity is stored once, as
// index arrays (faces own contiguous runs of halfedges, counter-clockwise seen from the right
// side of the fabric); everything else is typed per-element data beside it.
//
// Every halfedge says what its edge is *for its face* (EdgeRole): a bottom course edge (a loop
// the stitch consumes), a top course edge (a loop it makes), or the wale edge where its yarn
// enters or leaves. The two halfedges of one edge may disagree: that is how mismatched
// knitting directions are represented (paper §3.2).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mesh/handles.hpp"
#include "mesh/stitch_type.hpp"

namespace skein {

struct Vec3 {
  float x = 0, y = 0, z = 0;
  bool operator==(const Vec3&) const = default;
};

enum class EdgeRole : std::uint8_t {
  bottom,    // course edge at the bottom: a loop comes in (wale direction enters here)
  top,       // course edge at the top: a loop goes out
  wale_in,   // wale edge where the face's yarn enters (course direction starts here)
  wale_out,  // wale edge where the face's yarn leaves
};
inline bool is_course(EdgeRole r) {
  return r == EdgeRole::bottom || r == EdgeRole::top;
}
inline bool is_wale(EdgeRole r) {
  return !is_course(r);
}
char role_letter(EdgeRole r);  // b, t, i, o: the letters of the file format
std::optional<EdgeRole> role_from_letter(char letter);  // empty for any other letter

// How the two faces of an interior edge relate (paper §3.2, Fig. 5).
enum class EdgeKind : std::uint8_t {
  border,                     // one face only
  course,                     // top of one face, bottom of the other: a loop passes
  wale,                       // yarn leaves one face and enters the other
  join,                       // both faces' wale directions point at it (three-needle bind-off)
  split,                      // both point away from it (cast-on along it)
  contracting_perpendicular,  // top course edge of one face, wale edge of the other
  expanding_perpendicular,    // bottom course edge of one face, wale edge of the other
  conflicting_wale,           // yarn leaves (or enters) both faces here: invalid
};
const char* edge_kind_name(EdgeKind kind);
inline bool is_mismatch(EdgeKind k) {
  return k == EdgeKind::join || k == EdgeKind::split || k == EdgeKind::contracting_perpendicular ||
         k == EdgeKind::expanding_perpendicular;
}

// Fig. 3's four shift operations on a shift-path edge: which side of the path slides, and
// which way. 0 means the edge is not on a shift-path. Up-right and down-left make rounds run
// left to right across the path (seen on the right side, wales up); the other two right to left.
enum ShiftOption : std::uint8_t {
  kNotShifted = 0,
  kShiftUpRight = 1,  // the default
  kShiftUpLeft = 2,
  kShiftDownRight = 3,
  kShiftDownLeft = 4,
};
const char* shift_option_name(ShiftOption option);  // "up-right", ...
inline bool runs_left_to_right(ShiftOption option) {
  return option == kShiftUpRight || option == kShiftDownLeft;
}

// Which yarn knits the stitches along a join or split edge (paper §3.2).
struct MismatchYarn {
  enum class Kind : std::uint8_t { by_default, extra, own };
  Kind kind = Kind::by_default;
  Face side;  // with `own`: the face whose yarn is used (ignored otherwise)
  bool operator==(const MismatchYarn& o) const {
    return kind == o.kind && (kind != Kind::own || side == o.side);
  }
};

inline constexpr std::uint32_t kNoPart = 0xffffffffu;

class StitchMesh {
 public:
  // --- sizes and ranges ---
  std::uint32_t num_vertices() const { return static_cast<std::uint32_t>(position.size()); }
  std::uint32_t num_faces() const { return static_cast<std::uint32_t>(stitch.size()); }
  std::uint32_t num_halfedges() const { return static_cast<std::uint32_t>(he_tail_.size()); }
  std::uint32_t num_edges() const { return static_cast<std::uint32_t>(edge_halfedge_.size()); }
  HandleRange<Vertex> vertices() const { return {0, num_vertices()}; }
  HandleRange<Face> faces() const { return {0, num_faces()}; }
  HandleRange<Edge> edges() const { return {0, num_edges()}; }
  HandleRange<Halfedge> halfedges(Face f) const {
    return {face_first_[f.index()], face_first_[f.index() + 1]};
  }

  // --- navigation ---
  std::uint32_t degree(Face f) const { return halfedges(f).size(); }
  Face face(Halfedge h) const { return he_face_[h]; }
  Vertex tail(Halfedge h) const { return he_tail_[h]; }
  Vertex head(Halfedge h) const { return tail(next(h)); }
  Halfedge next(Halfedge h) const;
  Halfedge prev(Halfedge h) const;
  Halfedge twin(Halfedge h) const { return he_twin_[h]; }  // invalid on the border
  Edge edge(Halfedge h) const { return he_edge_[h]; }
  Halfedge halfedge(Edge e) const { return edge_halfedge_[e]; }  // the first face's side
  bool is_border(Edge e) const { return !twin(halfedge(e)).valid(); }
  std::span<const Halfedge> outgoing(Vertex v) const;  // halfedges whose tail is v
  Edge find_edge(Vertex a, Vertex b) const;            // invalid if a and b share no edge
  EdgeKind kind(Edge e) const;
  // The face's wale halfedge where its yarn enters / leaves.
  Halfedge wale_in(Face f) const;
  Halfedge wale_out(Face f) const;
  // The face on the other side of h, or invalid on the border.
  Face neighbour(Halfedge h) const;
  // The ends of a wale halfedge beside its face's top and bottom course edges (invalid where
  // none: the side-by-side wale edges of a short-row face meet at one end).
  Vertex wale_top(Halfedge h) const;
  Vertex wale_bottom(Halfedge h) const;
  // True when the face's yarn leaves through its right-hand wale edge (wale up, right side).
  bool runs_left_to_right(Face f) const;

  // --- typed per-element data ---
  VertexData<Vec3> position;
  FaceData<StitchType> stitch;
  FaceData<std::uint32_t> row;  // filled by assign_rows(); rows numbered in knitting order
  HalfedgeData<EdgeRole> role;
  EdgeData<std::uint8_t> shift_path;  // a ShiftOption; non-zero on shift-path wale edges
  EdgeData<MismatchYarn> mismatch_yarn;
  // The named parts of the garment ("Thumb", "Left leg": a coarse mesh's OBJ groups) and per
  // face the part it belongs to (kNoPart for none). Both empty when the input names no parts.
  std::vector<std::string> part_names;
  FaceData<std::uint32_t> part;

 private:
  friend class StitchMeshBuilder;
  std::vector<std::uint32_t> face_first_;  // size F+1: face f owns halfedges [first[f], first[f+1])
  HalfedgeData<Face> he_face_;
  HalfedgeData<Vertex> he_tail_;
  HalfedgeData<Halfedge> he_twin_;
  HalfedgeData<Edge> he_edge_;
  EdgeData<Halfedge> edge_halfedge_;
  std::vector<std::uint32_t> vertex_first_;  // size V+1: CSR of outgoing halfedges
  std::vector<Halfedge> vertex_out_;
};

// Builds a StitchMesh face by face, then links twins and edges in linear time.
class StitchMeshBuilder {
 public:
  explicit StitchMeshBuilder(std::string source_name = "<memory>");
  void reserve(std::size_t vertices, std::size_t faces, std::size_t halfedges);
  Vertex add_vertex(Vec3 p);
  // Vertices counter-clockwise; roles[i] is the role of the edge from vertices[i] to
  // vertices[i+1].
  Face add_face(std::span<const Vertex> vertices, std::span<const EdgeRole> roles, StitchType type);
  std::uint32_t num_vertices() const { return mesh_.num_vertices(); }
  std::uint32_t num_faces() const { return mesh_.num_faces(); }
  // Throws MeshError on an edge shared by more than two faces or by two faces running the
  // same way. Rows are assigned; shift-path marks and yarn choices are set on the result.
  StitchMesh build() &&;

 private:
  StitchMesh mesh_;
  std::string source_;
};

// Groups faces linked through their wale edges into rows and numbers the rows in knitting
// order (a row comes after every row whose loops it consumes; ties by lowest face index).
void assign_rows(StitchMesh& mesh);

// Checks every invariant of a stitch mesh; throws MeshError naming the face or edge.
void validate(const StitchMesh& mesh);

// What a row is (paper §4.2): a closed ring (a round), a short row (it starts or ends at a
// short-row face), or an open row (both ends on a border or a perpendicular mismatch).
enum class RowKind : std::uint8_t { open, closed, short_row };
std::vector<RowKind> row_kinds(const StitchMesh& mesh);

// "face 12 (k, row 7)": how reports name a face (1-based like the file format).
std::string describe(const StitchMesh& mesh, Face f);
std::string describe(const StitchMesh& mesh, Edge e);

}  // namespace skein
