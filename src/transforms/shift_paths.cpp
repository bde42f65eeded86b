#include "transforms/shift_paths.hpp"

#include <fmt/format.h>

#include <vector>

#include "common/error.hpp"

namespace skein {
namespace {

// The option of the paths skein places itself: up-left, so that rounds run right to left seen
// from the right side, the way hands knit them, and a pattern need not knit the mirror image.
constexpr ShiftOption kShiftChosenBySkein = kShiftUpLeft;

// A wale edge where a row's yarn passes from one stitch to the next: the only place a shift-path
// may cut a round.
bool is_course_link(const StitchMesh& m, Halfedge h) {
  Halfedge t = m.twin(h);
  return t.valid() && is_wale(m.role[h]) && is_wale(m.role[t]) && m.role[h] != m.role[t];
}

class ShiftPaths {
 public:
  explicit ShiftPaths(StitchMesh& m)
      : m_(m),
        kinds_(row_kinds(m)),
        path_edge_(kinds_.size(), Edge()),
        ring_of_row_(kinds_.size(), kNoRing),
        reversed_(kinds_.size(), 0) {}

  ShiftPathSummary run() && {
    check_marks();
    find_short_row_rings();
    check_given_paths_chain();
    extend_given_paths();
    place_missing_paths();
    count_paths();
    apply_options();
    return summary_;
  }

 private:
  void check_marks() {
    for (Edge e : m_.edges()) {
      if (!m_.shift_path[e]) continue;
      std::uint32_t row = m_.row[m_.face(m_.halfedge(e))];
      if (kinds_[row] == RowKind::open)
        throw MeshError(
            fmt::format("{} is marked as a shift-path, but row {} is an open row: open "
                        "rows need no shift-path (the work turns at the border); "
                        "expected the mark on a round or a short row between rounds",
                        describe(m_, e), row + 1));
      if (path_edge_[row].valid())
        throw MeshError(
            fmt::format("row {} is cut by two shift-path edges, {} and {}; expected "
                        "one per round",
                        row + 1, describe(m_, path_edge_[row]), describe(m_, e)));
      path_edge_[row] = e;
    }
  }

  // Short rows between rounds can close on themselves (a heel round that turns twice and comes
  // back to where it began): such a ring of rows needs one cut, like a round, or its yarn has
  // no end. Each face lies on one yarn chain or ring, so every face is walked once.
  void find_short_row_rings() {
    std::vector<std::uint8_t> seen(m_.num_faces(), 0);
    std::vector<std::uint32_t> rows;
    for (Face f : m_.faces()) {
      if (kinds_[m_.row[f]] != RowKind::short_row || seen[f.index()]) continue;
      rows.clear();
      Face g = f;
      do {
        seen[g.index()] = 1;
        if (rows.empty() || rows.back() != m_.row[g]) rows.push_back(m_.row[g]);
        g = next_along_yarn(g);
      } while (g.valid() && g != f && !seen[g.index()]);
      if (g == f) add_ring(rows);
    }
  }

  // The next stitch of g's row, across a marked edge too; invalid at a border.
  Face next_along_yarn(Face g) const {
    Halfedge t = m_.twin(m_.wale_out(g));
    return t.valid() && m_.role[t] == EdgeRole::wale_in ? m_.face(t) : Face();
  }

  void add_ring(const std::vector<std::uint32_t>& rows) {
    auto ring = static_cast<std::uint32_t>(ring_cut_.size());
    ring_cut_.push_back(0);
    for (std::uint32_t row : rows) {
      ring_of_row_[row] = ring;
      if (path_edge_[row].valid()) ring_cut_[ring] = 1;
    }
  }

  // Where a path coming up could go on into the next round, a mark elsewhere on that round with
  // no yarn arriving at it breaks the helix for no reason: an edited mesh whose marks were not
  // moved. (Where tubes meet, a path may end in a row of open rows, and a round be started by
  // the yarn of another: both are chained by yarn that stops and starts at a corner.)
  void check_given_paths_chain() const {
    for (Edge e : path_edge_) {
      if (!e.valid()) continue;
      Edge up = next_on_path(e, /*up=*/true);
      if (!up.valid()) continue;
      Edge there = path_edge_[row_of(up)];
      if (!there.valid() || there == up || has_path_below(there) ||
          open_row_ends_at(m_.wale_bottom(m_.halfedge(there))) ||
          open_row_starts_at(m_.wale_top(m_.halfedge(e))))
        continue;
      throw MeshError(fmt::format(
          "{} is marked as the shift-path of row {}, but the path coming up from row {} ({}) "
          "goes on at {}; expected the marks of a path to chain, one per round, each starting "
          "where the one below ends (move the mark to {}, or remove it and let skein place it)",
          describe(m_, there), row_of(there) + 1, row_of(e) + 1, describe(m_, e), describe(m_, up),
          describe(m_, up)));
    }
  }

  // Does an open row's yarn stop (start) at v: a stitch whose yarn leaves (enters) there without
  // going on to (coming from) a stitch of its row?
  bool open_row_ends_at(Vertex v) const { return open_row_turns_at(v, EdgeRole::wale_out); }
  bool open_row_starts_at(Vertex v) const { return open_row_turns_at(v, EdgeRole::wale_in); }
  bool open_row_turns_at(Vertex v, EdgeRole role) const {
    if (!v.valid()) return false;
    for (Halfedge out : m_.outgoing(v))
      for (Halfedge c : {out, m_.prev(out)}) {
        if (m_.role[c] != role || kinds_[m_.row[m_.face(c)]] != RowKind::open) continue;
        Vertex end = role == EdgeRole::wale_out ? m_.wale_top(c) : m_.wale_bottom(c);
        if (end == v && !is_course_link(m_, c)) return true;
      }
    return false;
  }

  // Where tubes meet, several rounds end at one corner: the path goes on from the marked one.
  bool has_path_below(Edge e) const {
    return next_on_path(e, /*up=*/false, [&](Edge c) { return path_edge_[row_of(c)] == c; })
        .valid();
  }

  // One marked edge identifies a whole path: follow it up and down through unmarked rounds.
  void extend_given_paths() {
    std::vector<Edge> given;
    for (Edge e : path_edge_)
      if (e.valid()) given.push_back(e);
    for (Edge e : given) trace(e, static_cast<ShiftOption>(m_.shift_path[e]));
  }

  void place_missing_paths() {
    for (Face f : m_.faces()) {  // faces in order: lowest unmarked round first
      if (!needs_path(m_.row[f]) || is_cut(m_.row[f])) continue;
      Edge start = m_.edge(m_.wale_in(f));
      mark(start, kShiftChosenBySkein);
      trace(start, kShiftChosenBySkein);
      ++summary_.placed;
    }
  }

  void trace(Edge start, ShiftOption option) {
    for (bool up : {true, false})
      for (Edge e = next_on_path(start, up); e.valid() && !is_cut(row_of(e));
           e = next_on_path(e, up))
        mark(e, option);
  }

  // A path starts at every marked edge whose round below does not continue into it.
  void count_paths() {
    for (Edge e : path_edge_)
      if (e.valid() && !has_path_below(e)) ++summary_.paths;
  }

  void mark(Edge e, ShiftOption option) {
    m_.shift_path[e] = option;
    path_edge_[row_of(e)] = e;
    if (in_ring(row_of(e))) ring_cut_[ring_of_row_[row_of(e)]] = 1;
  }

  bool in_ring(std::uint32_t row) const { return ring_of_row_[row] != kNoRing; }
  bool needs_path(std::uint32_t row) const {
    return kinds_[row] == RowKind::closed || in_ring(row);
  }
  // A round is cut by its own path edge; a ring of short rows by one edge on any of its rows.
  bool is_cut(std::uint32_t row) const {
    return path_edge_[row].valid() || (in_ring(row) && ring_cut_[ring_of_row_[row]]);
  }

  std::uint32_t row_of(Edge e) const { return m_.row[m_.face(m_.halfedge(e))]; }

  // The wale edge of another round that continues the path from e's top end (up) or bottom
  // end (down), the first that `accept` takes; invalid where the path cannot go on (a
  // decrease or increase spans that corner).
  template <class Accept>
  Edge next_on_path(Edge e, bool up, Accept accept) const {
    Halfedge h = m_.halfedge(e);
    Vertex v = up ? m_.wale_top(h) : m_.wale_bottom(h);
    if (!v.valid()) return {};
    for (Halfedge out : m_.outgoing(v))
      for (Halfedge c : {out, m_.prev(out)}) {
        if (!is_course_link(m_, c) || m_.edge(c) == e || !needs_path(m_.row[m_.face(c)])) continue;
        if ((up ? m_.wale_bottom(c) : m_.wale_top(c)) == v && accept(m_.edge(c))) return m_.edge(c);
      }
    return {};
  }
  Edge next_on_path(Edge e, bool up) const {
    return next_on_path(e, up, [](Edge) { return true; });
  }

  // Each path's option says which way its rounds run; the rows of a path whose labelled
  // direction disagrees are turned, all of a path's rows alike. A ring of short rows keeps its
  // directions: its turns fix them.
  void apply_options() {
    for (std::uint32_t row = 0; row < kinds_.size(); ++row) {
      Edge e = path_edge_[row];
      if (!e.valid() || in_ring(row)) continue;
      auto option = static_cast<ShiftOption>(m_.shift_path[e]);
      if (runs_left_to_right(option) != labelled_left_to_right(e)) reverse(row);
    }
    for (Face f : m_.faces())
      if (reversed_[m_.row[f]]) swap_wale_roles(f);
  }

  // Across the path edge: does the yarn pass from the stitch on its left to the one on its right?
  bool labelled_left_to_right(Edge e) const {
    Halfedge h = m_.halfedge(e);
    bool on_right_of_face = m_.role[m_.prev(h)] == EdgeRole::bottom;  // h is its face's right edge
    return on_right_of_face == (m_.role[h] == EdgeRole::wale_out);
  }

  void reverse(std::uint32_t row) {
    reversed_[row] = 1;
    ++summary_.reversed_rows;
  }

  void swap_wale_roles(Face f) {
    for (Halfedge h : m_.halfedges(f)) {
      if (m_.role[h] == EdgeRole::wale_in)
        m_.role[h] = EdgeRole::wale_out;
      else if (m_.role[h] == EdgeRole::wale_out)
        m_.role[h] = EdgeRole::wale_in;
    }
  }

  StitchMesh& m_;
  std::vector<RowKind> kinds_;
  static constexpr std::uint32_t kNoRing = ~std::uint32_t{0};
  std::vector<Edge> path_edge_;             // per row: the shift-path edge that cuts it
  std::vector<std::uint32_t> ring_of_row_;  // per short row: the ring of short rows it is on
  std::vector<std::uint8_t> ring_cut_;      // per ring: cut by a path edge yet
  std::vector<std::uint8_t> reversed_;
  ShiftPathSummary summary_;
};

}  // namespace

ShiftPathSummary place_shift_paths(StitchMesh& mesh) {
  return ShiftPaths(mesh).run();
}

}  // namespace skein
