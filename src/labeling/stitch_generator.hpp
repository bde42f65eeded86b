// The generator of stitch_generation.hpp's stitch mesh, shared by the files that implement its
// stages: stitch counts per coarse edge (stitch_generation.cpp), rows and their yarn
// (stitch_generation_rows.cpp), vertices, faces and marks (stitch_generation_faces.cpp).
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "labeling/stitch_generation.hpp"
#include "labeling/yarn_plan.hpp"

namespace skein::generation {

// One stitch of a row: how many loops it consumes and makes.
struct Shape {
  std::uint8_t in = 1, out = 1;
};

// A short-row face's rows from its wide side, bottom to top: a row passing through, or a pair
// turning inside at `depth` columns from the wide side.
struct Token {
  bool pair = false;
  bool toward_narrow = false;  // a passing row's direction (a pair's lower row goes toward)
  std::uint32_t depth = 0;
};

// A coarse row cut into strips of quads with the same rows, and short-row faces between them.
struct Segment {
  bool short_row = false;
  CoarseFace face;                      // short-row face
  std::vector<CoarseFace> quads;        // strip
  std::uint32_t rows = 0, done = 0;     // strip: rows to knit and knit so far
  std::vector<std::uint8_t> rightward;  // strip: per row
  bool wide_left = false;               // short-row face: the wide side is the segment before
  std::uint32_t pairs = 0, passes = 0;  // short-row face: how many of each to place
  std::vector<Token> tokens;
  std::uint32_t pairs_done = 0, passes_done = 0;
  void place(Token t) {
    tokens.push_back(t);
    ++(t.pair ? pairs_done : passes_done);
  }
  bool complete() const {
    return short_row ? pairs_done == pairs && passes_done == passes : done == rows;
  }
};

class Generator {
 public:
  Generator(const CoarseMesh& coarse, const Labeling& labeling, const Project& project)
      : m_(coarse), L_(labeling), p_(project), builder_(coarse.source) {}

  GeneratedStitchMesh run();

 private:
  // Each stitch belongs to its coarse face's OBJ group, the part of the garment a pattern names
  // ("left_leg" becomes "Left leg"); faces before any group belong to none.
  void name_parts(GeneratedStitchMesh& out) const;

  static std::string knitters_name(std::string name);

  CoarseHalfedge side(CoarseFace f, CoarseRole r) const { return L_.find(m_, f, r); }
  std::uint32_t segments(CoarseHalfedge h) const { return count_[m_.canonical(h).index()]; }
  [[noreturn]] void fail(CoarseFace f, const std::string& what) const;

  // ------------------------------------------------------------------ counts

  // One count per coarse edge: its length in stitches (course edges) or rows (sides), shared
  // where a quad's sides must agree; then the minimums shaping and short rows need.
  void choose_counts();

  [[noreturn]] void too_many(CoarseHalfedge h, double count) const;

  // The stitches the counts make, refused beyond kMaxStitches before any is made.
  void check_total() const;

  // Cast-on and bind-off rows keep their width; the rows between must reach the top width
  // with at most a doubling (kfb) or a third (s2kp) per row.
  template <class Count>
  std::uint32_t rows_needed(CoarseFace f, Count& count) const {
    std::uint32_t nb = count(side(f, CoarseRole::bottom)), nt = count(side(f, CoarseRole::top));
    std::uint32_t fixed =
        m_.is_border(side(f, CoarseRole::bottom)) + m_.is_border(side(f, CoarseRole::top));
    std::uint32_t taper = nb == nt ? 0 : 1;
    while (!taper_fits(nb, nt, taper)) ++taper;
    return std::max<std::uint32_t>(1, fixed + taper);
  }

  static std::uint32_t width_at(std::uint32_t nb, std::uint32_t nt, std::uint32_t i,
                                std::uint32_t taper);
  static bool taper_fits(std::uint32_t nb, std::uint32_t nt, std::uint32_t taper);

  // ------------------------------------------------------------------ rows

  CoarseFace across(CoarseFace f, CoarseRole r, CoarseRole expected) const;

  // Every coarse row (faces joined through their sides), in labelling order, is walked by
  // the yarn to decide each row's direction and where short rows turn.
  void plan_rows();

  std::vector<Segment> cut(const std::vector<CoarseFace>& faces, CoarseHalfedge first_side);

  // An open row as the yarn planner sees it: where the yarn can enter it and where it then
  // stops; with no yarn arriving, it stops where a row above must start, so one yarn goes on.
  PlannedRow open_row(const std::vector<CoarseFace>& faces);

  void plan_open_row(const std::vector<CoarseFace>& faces, const RowEntry& entry);

  // A ring of faces as the yarn planner sees it: where a path may start, and the project's
  // mark (the last one naming a side of the ring).
  PlannedRow ring(const std::vector<CoarseFace>& faces);

  // Does the left side of ring face `i` lie where short rows go to and fro (between a short-row
  // face widening to the right and the next one widening to the left)? A round begun there
  // would have its short rows run back across its start.
  bool among_short_rows(const std::vector<CoarseFace>& faces, std::size_t i) const;

  void plan_closed_row(const std::vector<CoarseFace>& faces, const RowEntry& path);

  // Walks the yarn along the coarse row until every strip has its rows and every short-row
  // face its passes and pairs. Returns true when it stops at the left end.
  bool walk_yarn(std::vector<Segment>& segs, const std::vector<CoarseFace>& faces, bool closed,
                 bool from_left);

  void store(std::vector<Segment>& segs);

  // ------------------------------------------------------------------ vertices

  Vertex new_vertex(Vec3 p);
  Vec3 pos(Vertex v) const { return positions_[v.index()]; }

  // Coarse vertices keep their numbers; each coarse edge gets its stitch vertices once.
  void add_vertices();

  // The stitch vertices along a coarse halfedge, from its tail to its head.
  std::vector<Vertex> along(CoarseHalfedge h) const;
  std::vector<Vertex> upward(CoarseHalfedge h, bool runs_down) const;

  // A line of stitch vertices from `first` to `last` with `n` segments, new ones between
  // placed by `at(fraction)`.
  template <class At>
  std::vector<Vertex> line(Vertex first, Vertex last, std::uint32_t n, At at) {
    std::vector<Vertex> v{first};
    for (std::uint32_t i = 1; i < n; ++i) v.push_back(new_vertex(at(static_cast<float>(i) / n)));
    if (n > 0) v.push_back(last);
    return v;
  }
  std::vector<Vertex> line(Vertex first, Vertex last, std::uint32_t n);

  // ------------------------------------------------------------------ faces

  StitchPattern pattern(CoarseFace f) const;
  static bool purl_at(StitchPattern pattern, std::uint32_t column);
  static StitchType type_of(Shape s, bool purl);

  void add_quad(CoarseFace f);

  // A short-row face, built column by column from its wide side (the frame is mirrored when
  // the wide side is on the right, and the corners reversed back to counter-clockwise).
  void add_short_row_face(CoarseFace f);

  // One column of a short-row face between line `w` (wide side) and `p` (narrow side).
  void add_column(CoarseFace f, const std::vector<Token>& tokens, const std::vector<Vertex>& w,
                  const std::vector<Vertex>& p, std::uint32_t x, bool mirrored);

  void emit(CoarseFace f, const std::vector<Vertex>& bottom, const std::vector<Vertex>& top,
            bool rightward, StitchType type, bool mirrored);

  // Adds corners_/roles_ as a face; a mirrored frame reverses the cycle (edge i keeps its role).
  void emit_raw(CoarseFace f, StitchType type, bool mirrored);

  // ------------------------------------------------------------------ marks

  template <class Mark>
  void mark_edge(const StitchMesh& mesh, CoarseHalfedge h, Mark mark) const {
    std::vector<Vertex> v = along(h);
    for (std::size_t i = 0; i + 1 < v.size(); ++i) {
      Edge e = mesh.find_edge(v[i], v[i + 1]);
      SKEIN_ASSERT(e.valid(), "a coarse edge's stitch segments are edges");
      mark(e);
    }
  }

  // Joins and splits: the project's default, then its per-edge choices.
  void choose_yarns(GeneratedStitchMesh& out) const;

  const CoarseMesh& m_;
  const Labeling& L_;
  const Project& p_;
  StitchMeshBuilder builder_;
  std::vector<std::uint32_t> count_;       // per halfedge (group root first, then copied)
  std::vector<std::uint32_t> edge_first_;  // per canonical halfedge: first interior vertex
  std::vector<std::vector<std::uint8_t>> rightward_;  // per quad: direction of each row
  std::vector<std::vector<Token>> tokens_;            // per short-row face
  std::vector<CoarseVertex> wanted_starts_;           // bottom corners where open rows must start
  std::vector<std::pair<CoarseHalfedge, std::uint8_t>> shift_edges_;  // paths and their options
  std::set<std::size_t> used_shift_marks_;  // project shift_paths entries placed
  std::vector<std::uint32_t> origin_;
  std::vector<Vec3> positions_;
  std::vector<std::uint32_t> offset_;  // per coarse face: its first column in its coarse row
  std::vector<Vertex> corners_;
  std::vector<EdgeRole> roles_;
  std::uint32_t closed_rows_ = 0, open_rows_ = 0, chains_ = 0;
};

}  // namespace skein::generation
