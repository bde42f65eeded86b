#include "labeling/stitch_generation.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <set>

#include "common/error.hpp"
#include "common/yaml_source.hpp"
#include "labeling/yarn_plan.hpp"

namespace skein {
namespace {

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::uint32_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

Vec3 lerp(Vec3 a, Vec3 b, float t) {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
}

// One stitch of a row: how many loops it consumes and makes.
struct Shape {
  std::uint8_t in = 1, out = 1;
};

// `count` of `n` positions, evenly spaced; odd rows shifted by half a step so shaping does
// not stack.
std::vector<std::uint8_t> spread(std::uint32_t n, std::uint32_t count, std::uint32_t row) {
  std::vector<std::uint8_t> marked(n, 0);
  double step = static_cast<double>(n) / count, phase = row % 2 ? 0.75 : 0.25;
  for (std::uint32_t j = 0; j < count; ++j)
    marked[std::min<std::uint32_t>(n - 1, static_cast<std::uint32_t>((j + phase) * step))] = 1;
  return marked;
}

// The stitches of a row that consumes `below` loops and makes `above` (left to right).
std::vector<Shape> row_shapes(std::uint32_t below, std::uint32_t above, std::uint32_t row) {
  if (above >= below) {
    std::vector<Shape> shapes(below);
    std::vector<std::uint8_t> inc = spread(below, above - below, row);
    for (std::uint32_t i = 0; i < below; ++i) shapes[i].out = inc[i] ? 2 : 1;
    return shapes;
  }
  std::uint32_t extra = below - above;  // loops to absorb: k2tog absorbs 1, s2kp 2
  std::uint32_t doubles = extra > above ? extra - above : 0, singles = extra - 2 * doubles;
  std::vector<Shape> shapes(above);
  std::vector<std::uint8_t> dec = spread(above, singles + doubles, row);
  for (std::uint32_t i = 0, d = 0; i < above; ++i)
    if (dec[i]) shapes[i].in = d++ < doubles ? 3 : 2;
  return shapes;
}

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

  GeneratedStitchMesh run() {
    choose_counts();
    plan_rows();
    add_vertices();
    for (CoarseFace f : m_.faces()) {
      if (L_.short_row[f.index()])
        add_short_row_face(f);
      else
        add_quad(f);
    }
    for (Vec3 p : positions_) builder_.add_vertex(p);
    GeneratedStitchMesh out{
        std::move(builder_).build(), std::move(origin_), {}, closed_rows_, open_rows_, chains_};
    for (CoarseHalfedge h : m_.halfedges()) out.segments.push_back(segments(h));
    for (const auto& [h, option] : shift_edges_) {
      std::uint8_t o = option;  // a lambda may not capture a structured binding before clang 16
      mark_edge(out.mesh, h, [&](Edge e) { out.mesh.shift_path[e] = o; });
    }
    choose_yarns(out);
    name_parts(out);
    return out;
  }

 private:
  // Each stitch belongs to its coarse face's OBJ group, the part of the garment a pattern names
  // ("left_leg" becomes "Left leg"); faces before any group belong to none.
  void name_parts(GeneratedStitchMesh& out) const {
    auto named = [](const std::string& group) { return !group.empty(); };
    if (m_.group.size() != m_.num_faces() ||
        std::none_of(m_.groups.begin(), m_.groups.end(), named))
      return;
    for (const std::string& group : m_.groups) out.mesh.part_names.push_back(knitters_name(group));
    out.mesh.part.resize(out.mesh.num_faces(), kNoPart);
    for (Face f : out.mesh.faces()) {
      std::uint32_t group = m_.group[out.coarse_face[f.index()]];
      if (named(m_.groups[group])) out.mesh.part[f] = group;
    }
  }

  static std::string knitters_name(std::string name) {
    std::replace_if(
        name.begin(), name.end(), [](char ch) { return ch == '_' || ch == '-'; }, ' ');
    if (!name.empty() && name[0] >= 'a' && name[0] <= 'z')
      name[0] = static_cast<char>(name[0] - 'a' + 'A');
    return name;
  }

  CoarseHalfedge side(CoarseFace f, CoarseRole r) const { return L_.find(m_, f, r); }
  std::uint32_t segments(CoarseHalfedge h) const { return count_[m_.canonical(h).index()]; }
  [[noreturn]] void fail(CoarseFace f, const std::string& what) const {
    throw Error(
        fmt::format("{}: cannot generate stitches for {}: {}", m_.source, m_.describe(f), what));
  }

  // ------------------------------------------------------------------ counts

  // One count per coarse edge: its length in stitches (course edges) or rows (sides), shared
  // where a quad's sides must agree; then the minimums shaping and short rows need.
  void choose_counts() {
    const double width = p_.stitch_width_in_units(), height = p_.stitch_height_in_units();
    const std::uint32_t n = m_.num_halfedges();
    UnionFind groups(n);
    for (CoarseFace f : m_.faces()) {
      if (!L_.short_row[f.index()]) {
        groups.unite(m_.canonical(side(f, CoarseRole::left)).index(),
                     m_.canonical(side(f, CoarseRole::right)).index());
      } else {
        groups.unite(m_.canonical(side(f, CoarseRole::bottom)).index(),
                     m_.canonical(side(f, CoarseRole::top)).index());
      }
    }
    std::vector<double> sum(n, 0), weight(n, 0);
    for (CoarseHalfedge h : m_.halfedges()) {
      std::uint32_t g = groups.find(m_.canonical(h).index());
      sum[g] += m_.length(h) / (is_side(L_[h]) ? height : width);
      weight[g] += 1;
    }
    count_.assign(n, 0);
    for (CoarseHalfedge h : m_.halfedges()) {
      std::uint32_t g = groups.find(m_.canonical(h).index());
      double count = std::round(sum[g] / weight[g]);
      if (!(count <= kMaxCountPerEdge)) too_many(h, count);
      count_[h.index()] = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(count));
    }
    auto group_count = [&](CoarseHalfedge h) -> std::uint32_t& {
      return count_[groups.find(m_.canonical(h).index())];
    };
    // Minimums, raised until they all hold. Each count only grows and is refused beyond
    // kMaxCountPerEdge, so this settles: the first pass that raises none ends it.
    for (bool changed = true; changed;) {
      changed = false;
      auto at_least = [&](CoarseHalfedge h, std::uint32_t minimum) {
        if (group_count(h) < minimum) {
          // Only short rows raise side counts without end: a cycle of them.
          if (minimum > kMaxCountPerEdge)
            fail(m_.face(h),
                 fmt::format("its rows keep growing past {}: short-row faces in one row whose "
                             "wide sides each ask the other's narrow side for more rows (mark "
                             "their wide_edge on the same side of the row)",
                             kMaxCountPerEdge));
          group_count(h) = minimum;
          changed = true;
        }
      };
      for (CoarseFace f : m_.faces()) {
        if (L_.short_row[f.index()]) {
          CoarseHalfedge wide = side(f, L_.wide_side[f.index()]);
          CoarseHalfedge narrow =
              side(f, L_.wide_side[f.index()] == CoarseRole::left ? CoarseRole::right
                                                                  : CoarseRole::left);
          if (narrow.valid() &&
              groups.find(m_.canonical(narrow).index()) == groups.find(m_.canonical(wide).index()))
            fail(f,
                 "a short-row face's wide side needs more rows than its narrow side, but the "
                 "quads of its row join the two (a quad's sides have the same rows); mark a "
                 "second short-row face in this row, or none");
          std::uint32_t base = narrow.valid() ? group_count(narrow) : 0;
          std::uint32_t w = std::max(group_count(wide), base + 2);
          at_least(wide, w + (w - base) % 2);
          continue;
        }
        at_least(side(f, CoarseRole::left), rows_needed(f, group_count));
      }
    }
    for (CoarseHalfedge h : m_.halfedges()) count_[h.index()] = group_count(h);
    check_total();
  }

  [[noreturn]] void too_many(CoarseHalfedge h, double count) const {
    throw Error(fmt::format(
        "{}: {} of face {} would have {:.0f} {}; at most {} are allowed per coarse edge (is the "
        "gauge or the unit right? docs/formats.md, \"Limits\")",
        m_.source, m_.describe(h), m_.face(h).index() + 1, count,
        is_side(L_[h]) ? "rows" : "stitches", kMaxCountPerEdge));
  }

  // The stitches the counts make, refused beyond kMaxStitches before any is made.
  void check_total() const {
    double total = 0;
    for (CoarseFace f : m_.faces()) {
      double rows = 0, width = 0;
      for (CoarseHalfedge h : m_.halfedges(f)) {
        double& extent = is_side(L_[h]) ? rows : width;
        extent = std::max<double>(extent, count_[h.index()]);
      }
      total += rows * width;
    }
    if (total > kMaxStitches)
      throw Error(
          fmt::format("{}: the stitch mesh would have about {:.0f} stitches; at most {} "
                      "are allowed (is the gauge or the unit right? docs/formats.md, "
                      "\"Limits\")",
                      m_.source, total, kMaxStitches));
  }

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
                                std::uint32_t taper) {
    return static_cast<std::uint32_t>(std::lround(nb + (double(nt) - nb) * i / taper));
  }
  static bool taper_fits(std::uint32_t nb, std::uint32_t nt, std::uint32_t taper) {
    for (std::uint32_t i = 1; i <= taper; ++i) {
      std::uint32_t below = width_at(nb, nt, i - 1, taper), above = width_at(nb, nt, i, taper);
      if (above > 2 * below || 3 * above < below) return false;
    }
    return true;
  }

  // ------------------------------------------------------------------ rows

  CoarseFace across(CoarseFace f, CoarseRole r, CoarseRole expected) const {
    CoarseHalfedge h = side(f, r);
    if (!h.valid() || m_.is_border(h) || L_.row_break[h.index()]) return {};
    CoarseHalfedge t = m_.twin(h);
    return L_[t] == expected ? m_.face(t) : CoarseFace();
  }

  // Every coarse row (faces joined through their sides), in labelling order, is walked by
  // the yarn to decide each row's direction and where short rows turn.
  void plan_rows() {
    rightward_.resize(m_.num_faces());
    tokens_.resize(m_.num_faces());
    offset_.assign(m_.num_faces(), 0);
    std::vector<CoarseFace> by_order(m_.num_faces());
    for (CoarseFace f : m_.faces()) by_order[L_.order[f.index()]] = f;
    std::vector<std::uint8_t> seen(m_.num_faces(), 0);
    std::vector<std::pair<std::vector<CoarseFace>, bool>> rows;  // faces left to right, closed
    for (CoarseFace start : by_order) {
      if (seen[start.index()]) continue;
      CoarseFace first = start;
      bool closed = false;
      for (CoarseFace g = across(first, CoarseRole::left, CoarseRole::right); g.valid();
           g = across(first, CoarseRole::left, CoarseRole::right)) {
        if (g == start) {
          closed = true;
          break;
        }
        first = g;
      }
      std::vector<CoarseFace> row{first};
      for (CoarseFace g = across(first, CoarseRole::right, CoarseRole::left);
           g.valid() && g != first; g = across(g, CoarseRole::right, CoarseRole::left))
        row.push_back(g);
      for (CoarseFace g : row) seen[g.index()] = 1;
      // An open row ending in a short-row triangle can only start at its other end.
      CoarseHalfedge left = side(row.front(), CoarseRole::left);
      CoarseHalfedge right = side(row.back(), CoarseRole::right);
      if (!closed && !left.valid() && !right.valid())
        fail(row.front(),
             "its open row ends in a point at both ends (a short-row triangle or a "
             "face without a side), so the yarn has no side to start it from");
      if (!closed && !left.valid()) wanted_starts_.push_back(m_.tail(right));
      if (!closed && !right.valid()) wanted_starts_.push_back(m_.head(left));
      rows.emplace_back(std::move(row), closed);
    }
    std::vector<PlannedRow> planned;
    for (const auto& [row, closed] : rows) planned.push_back(closed ? ring(row) : open_row(row));
    std::vector<RowEntry> entries = plan_row_entries(m_, L_, planned, p_.shift_option);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      if (rows[k].second) {
        ++closed_rows_;
        plan_closed_row(rows[k].first, entries[k]);
      } else {
        ++open_rows_;
        plan_open_row(rows[k].first, entries[k]);
      }
    }
    for (std::size_t k = 0; k < p_.shift_paths.size(); ++k)
      if (!used_shift_marks_.count(k))
        throw Error(
            fmt::format("{}:{}: {} is not a side of a ring of faces where rows can start; "
                        "a shift-path runs up a side edge of faces knit in the round",
                        p_.file, p_.shift_paths[k].edge.line,
                        m_.describe(find_project_edge(m_, p_, p_.shift_paths[k].edge))));
  }

  std::vector<Segment> cut(const std::vector<CoarseFace>& faces, CoarseHalfedge first_side) {
    std::vector<Segment> segs(1);
    segs.back().rows = first_side.valid() ? segments(first_side) : 0;
    for (CoarseFace f : faces) {
      if (!L_.short_row[f.index()]) {
        segs.back().quads.push_back(f);
        continue;
      }
      Segment& s = segs.emplace_back();
      s.short_row = true;
      s.face = f;
      s.wide_left = L_.wide_side[f.index()] == CoarseRole::left;
      CoarseHalfedge wide = side(f, L_.wide_side[f.index()]);
      CoarseHalfedge narrow = side(f, s.wide_left ? CoarseRole::right : CoarseRole::left);
      s.passes = narrow.valid() ? segments(narrow) : 0;
      s.pairs = (segments(wide) - s.passes) / 2;
      CoarseHalfedge right = side(f, CoarseRole::right);
      segs.emplace_back().rows = right.valid() ? segments(right) : 0;
    }
    return segs;
  }

  // An open row as the yarn planner sees it: where the yarn can enter it and where it then
  // stops; with no yarn arriving, it stops where a row above must start, so one yarn goes on.
  PlannedRow open_row(const std::vector<CoarseFace>& faces) {
    std::vector<Segment> segs = cut(faces, side(faces.front(), CoarseRole::left));
    CoarseHalfedge left = side(faces.front(), CoarseRole::left),
                   right = side(faces.back(), CoarseRole::right);
    bool can_left = segs.front().rows > 0, can_right = segs.back().rows > 0;
    if (!can_left && !can_right)
      fail(faces.front(), fmt::format("this row of faces ({} to {}) is closed at both ends by "
                                      "short-row triangles, so no row can start; give one end a "
                                      "row passing through it (a short-row quad)",
                                      faces.front().index() + 1, faces.back().index() + 1));
    // Where this row stops when it enters at the left (or right) end (nowhere if it cannot).
    auto stops_at = [&](bool left_end) {
      std::vector<Segment> trial = segs;
      try {
        return walk_yarn(trial, faces, false, left_end) ? m_.tail(left) : m_.head(right);
      } catch (const Error&) {
        return CoarseVertex();
      }
    };
    PlannedRow row;
    row.faces = faces;
    row.default_left = can_left;
    if (can_left) row.enter[0] = m_.head(left), row.stop[0] = stops_at(true);
    if (can_right) row.enter[1] = m_.tail(right), row.stop[1] = stops_at(false);
    auto wanted = [&](CoarseVertex v) {
      return std::count(wanted_starts_.begin(), wanted_starts_.end(), v) > 0;
    };
    if (can_left && can_right) row.default_left = wanted(row.stop[0]) || !wanted(row.stop[1]);
    return row;
  }

  void plan_open_row(const std::vector<CoarseFace>& faces, const RowEntry& entry) {
    std::vector<Segment> segs = cut(faces, side(faces.front(), CoarseRole::left));
    walk_yarn(segs, faces, false, entry.from_left);
    store(segs);
  }

  // A ring of faces as the yarn planner sees it: where a path may start, and the project's
  // mark (the last one naming a side of the ring).
  PlannedRow ring(const std::vector<CoarseFace>& faces) {
    PlannedRow ring;
    ring.faces = faces;
    ring.closed = true;
    ring.can_start.assign(faces.size(), 0);
    for (std::size_t i = 0; i < faces.size(); ++i) {
      if (among_short_rows(faces, i)) continue;
      ring.can_start[i] = 1;
      CoarseHalfedge h = side(faces[i], CoarseRole::left);
      for (std::size_t k = 0; k < p_.shift_paths.size(); ++k)
        if (m_.canonical(find_project_edge(m_, p_, p_.shift_paths[k].edge)) == m_.canonical(h)) {
          used_shift_marks_.insert(k);
          ring.mark = {i, p_.shift_paths[k].option};
        }
    }
    if (std::find(ring.can_start.begin(), ring.can_start.end(), 1) == ring.can_start.end())
      fail(faces.front(),
           "every side of this ring of faces has short rows turning at it, so no "
           "shift-path can run through it");
    return ring;
  }

  // Does the left side of ring face `i` lie where short rows go to and fro (between a short-row
  // face widening to the right and the next one widening to the left)? A round begun there
  // would have its short rows run back across its start.
  bool among_short_rows(const std::vector<CoarseFace>& faces, std::size_t i) const {
    CoarseFace f = faces[i];
    if (L_.short_row[f.index()]) return L_.wide_side[f.index()] == CoarseRole::left;
    for (std::size_t k = 1; k < faces.size(); ++k) {
      CoarseFace before = faces[(i + faces.size() - k) % faces.size()];
      if (L_.short_row[before.index()]) return L_.wide_side[before.index()] == CoarseRole::right;
    }
    return false;
  }

  void plan_closed_row(const std::vector<CoarseFace>& faces, const RowEntry& path) {
    if (!path.continued) ++chains_;
    std::vector<CoarseFace> rotated(faces.begin() + static_cast<std::ptrdiff_t>(path.face),
                                    faces.end());
    rotated.insert(rotated.end(), faces.begin(),
                   faces.begin() + static_cast<std::ptrdiff_t>(path.face));
    CoarseHalfedge shift = side(rotated.front(), CoarseRole::left);
    shift_edges_.push_back({shift, path.option});
    std::vector<Segment> segs = cut(rotated, shift);
    walk_yarn(segs, rotated, true, true);
    store(segs);
  }

  // Walks the yarn along the coarse row until every strip has its rows and every short-row
  // face its passes and pairs. Returns true when it stops at the left end.
  bool walk_yarn(std::vector<Segment>& segs, const std::vector<CoarseFace>& faces, bool closed,
                 bool from_left) {
    const std::size_t ends = segs.size();
    std::size_t b = from_left ? 0 : ends;  // boundary: segment s lies between s and s+1
    bool right = from_left;
    auto all_done = [&] {
      return std::all_of(segs.begin(), segs.end(), [](const Segment& s) { return s.complete(); });
    };
    std::uint64_t limit = 8;
    for (const Segment& s : segs) limit += 4ull * (s.rows + s.pairs + s.passes);
    for (std::uint64_t steps = 0;; ++steps) {
      SKEIN_ASSERT(steps < limit, "the yarn walk of a coarse row ends");
      if ((right && b == ends) || (!right && b == 0)) {
        if (all_done()) return b == 0;
        if (closed && !right)
          fail(faces.front(), "a short row would run backwards across the shift-path");
        if (closed)
          b = 0;
        else
          right = !right;
        continue;
      }
      Segment& s = segs[right ? b : b - 1];
      if (!s.short_row) {
        if (s.done == s.rows)
          fail(s.quads.empty() ? faces.front() : s.quads.front(),
               "its rows are used up while short rows beside it still need yarn; give the "
               "short-row faces of this row fewer rows or their narrow sides more");
        s.rightward.push_back(right);
        ++s.done;
        b = right ? b + 1 : b - 1;
        continue;
      }
      bool from_wide = right == s.wide_left;
      const std::uint32_t pairs_done = s.pairs_done, passes_done = s.passes_done;
      // Turn where the wide side needs rows, spread so that the pairs are done by the last pass.
      if (from_wide && pairs_done < s.pairs) {
        bool must_turn = (closed && !right) || passes_done == s.passes;
        if (must_turn || pairs_done * s.passes < s.pairs * (passes_done + 1)) {
          s.place({true, true, 0});
          right = !right;
          continue;
        }
      }
      if (passes_done == s.passes || (closed && !right))
        fail(s.face, "its short rows cannot all turn where the yarn reaches it");
      s.place({false, from_wide, 0});
      b = right ? b + 1 : b - 1;
    }
  }

  void store(std::vector<Segment>& segs) {
    std::uint32_t column = 0;
    for (Segment& s : segs) {
      if (!s.short_row) {
        for (CoarseFace f : s.quads) {
          rightward_[f.index()] = s.rightward;
          offset_[f.index()] = column;
          column += segments(side(f, CoarseRole::bottom));
        }
        continue;
      }
      offset_[s.face.index()] = column;
      column += segments(side(s.face, CoarseRole::bottom));
      // Turn depths rise to the narrow side and fall again, spreading the turns over the
      // columns (stacked only when there are more pairs than columns).
      std::uint32_t columns = segments(side(s.face, CoarseRole::bottom)), k = s.pairs;
      std::uint32_t peak = (k + 1) / 2, j = 0;
      for (Token& t : s.tokens) {
        if (!t.pair) continue;
        ++j;
        t.depth =
            j <= peak ? (columns - 1) * j / peak : (columns - 1) * (k + 1 - j) / (k + 1 - peak);
      }
      tokens_[s.face.index()] = std::move(s.tokens);
    }
  }

  // ------------------------------------------------------------------ vertices

  Vertex new_vertex(Vec3 p) {
    positions_.push_back(p);
    return Vertex(static_cast<std::uint32_t>(positions_.size() - 1));
  }
  Vec3 pos(Vertex v) const { return positions_[v.index()]; }

  // Coarse vertices keep their numbers; each coarse edge gets its stitch vertices once.
  void add_vertices() {
    positions_ = m_.position;
    edge_first_.assign(m_.num_halfedges(), 0);
    for (CoarseHalfedge h : m_.halfedges()) {
      if (m_.canonical(h) != h) continue;
      edge_first_[h.index()] = static_cast<std::uint32_t>(positions_.size());
      std::uint32_t n = segments(h);
      for (std::uint32_t i = 1; i < n; ++i)
        new_vertex(lerp(m_.at(m_.tail(h)), m_.at(m_.head(h)), static_cast<float>(i) / n));
    }
  }

  // The stitch vertices along a coarse halfedge, from its tail to its head.
  std::vector<Vertex> along(CoarseHalfedge h) const {
    CoarseHalfedge c = m_.canonical(h);
    std::uint32_t n = segments(h);
    std::vector<Vertex> v{Vertex(m_.tail(c).index())};
    for (std::uint32_t i = 1; i < n; ++i) v.push_back(Vertex(edge_first_[c.index()] + i - 1));
    v.push_back(Vertex(m_.head(c).index()));
    if (c != h) std::reverse(v.begin(), v.end());
    return v;
  }
  std::vector<Vertex> upward(CoarseHalfedge h, bool runs_down) const {
    std::vector<Vertex> v = along(h);
    if (runs_down) std::reverse(v.begin(), v.end());
    return v;
  }

  // A line of stitch vertices from `first` to `last` with `n` segments, new ones between
  // placed by `at(fraction)`.
  template <class At>
  std::vector<Vertex> line(Vertex first, Vertex last, std::uint32_t n, At at) {
    std::vector<Vertex> v{first};
    for (std::uint32_t i = 1; i < n; ++i) v.push_back(new_vertex(at(static_cast<float>(i) / n)));
    if (n > 0) v.push_back(last);
    return v;
  }
  std::vector<Vertex> line(Vertex first, Vertex last, std::uint32_t n) {
    Vec3 a = pos(first), b = pos(last);
    return line(first, last, n, [&](float u) { return lerp(a, b, u); });
  }

  // ------------------------------------------------------------------ faces

  StitchPattern pattern(CoarseFace f) const {
    auto it = p_.group_patterns.find(m_.groups[m_.group[f.index()]]);
    return it == p_.group_patterns.end() ? p_.pattern : it->second.pattern;
  }
  static bool purl_at(StitchPattern pattern, std::uint32_t column) {
    switch (pattern) {
      case StitchPattern::knit:
        return false;
      case StitchPattern::purl:
        return true;
      case StitchPattern::k1p1:
        return column % 2 == 1;
      case StitchPattern::k2p2:
        return column % 4 >= 2;
    }
    return false;
  }
  static StitchType type_of(Shape s, bool purl) {
    if (s.in == 3) return StitchType::s2kp;
    if (s.in == 2) return purl ? StitchType::p2tog : StitchType::k2tog;
    if (s.out == 2) return StitchType::kfb;
    return purl ? StitchType::p : StitchType::k;
  }

  void add_quad(CoarseFace f) {
    CoarseHalfedge hb = side(f, CoarseRole::bottom), hr = side(f, CoarseRole::right),
                   ht = side(f, CoarseRole::top), hl = side(f, CoarseRole::left);

    const std::uint32_t n = segments(hr), nb = segments(hb), nt = segments(ht);
    const bool cast_on = m_.is_border(hb), bind_off = m_.is_border(ht);
    std::vector<Vertex> left = upward(hl, true), right = upward(hr, false);
    std::vector<Vertex> below = along(hb), top = along(ht);
    std::reverse(top.begin(), top.end());
    const std::uint32_t a = cast_on, z = bind_off ? n - 1 : n;  // lines where shaping starts, ends
    const std::vector<std::uint8_t>& rightward = rightward_[f.index()];
    Vec3 bl = m_.at(m_.tail(hb)), br = m_.at(m_.head(hb)), tr = m_.at(m_.tail(ht)),
         tl = m_.at(m_.head(ht));
    SKEIN_ASSERT(rightward.size() == n, "every row of a quad has a direction");
    StitchPattern pat = pattern(f);
    for (std::uint32_t i = 1; i <= n; ++i) {
      std::uint32_t width = i <= a ? nb : i >= z ? nt : width_at(nb, nt, i - a, z - a);
      float t = static_cast<float>(i) / n;
      std::vector<Vertex> above = i == n ? top : line(left[i], right[i], width, [&](float u) {
        return lerp(lerp(bl, br, u), lerp(tl, tr, u), t);
      });
      bool first = i == 1 && cast_on, last = i == n && bind_off;
      std::vector<Shape> shapes =
          row_shapes(static_cast<std::uint32_t>(below.size() - 1), width, i);
      std::uint32_t u = 0, o = 0;
      for (Shape s : shapes) {
        StitchType type = first  ? StitchType::co
                          : last ? StitchType::bo
                                 : type_of(s, purl_at(pat, offset_[f.index()] + u));
        emit(f, {below.begin() + u, below.begin() + u + s.in + 1},
             {above.begin() + o, above.begin() + o + s.out + 1}, rightward[i - 1], type, false);
        u += s.in;
        o += s.out;
      }
      below = std::move(above);
    }
  }

  // A short-row face, built column by column from its wide side (the frame is mirrored when
  // the wide side is on the right, and the corners reversed back to counter-clockwise).
  void add_short_row_face(CoarseFace f) {
    const bool wide_left = L_.wide_side[f.index()] == CoarseRole::left;
    CoarseHalfedge hb = side(f, CoarseRole::bottom), ht = side(f, CoarseRole::top);
    CoarseHalfedge wide = side(f, L_.wide_side[f.index()]);
    CoarseHalfedge narrow = side(f, wide_left ? CoarseRole::right : CoarseRole::left);
    const std::uint32_t columns = segments(hb);
    std::vector<Vertex> bottom = along(hb), top = along(ht);
    if (!wide_left) std::reverse(bottom.begin(), bottom.end());
    if (wide_left) std::reverse(top.begin(), top.end());  // both now run from the wide side
    const std::vector<Token>& tokens = tokens_[f.index()];
    auto rows_at = [&](std::uint32_t x) {  // rows on the line x columns from the wide side
      std::uint32_t rows = 0;
      for (const Token& t : tokens) rows += !t.pair ? 1 : t.depth >= x ? 2 : 0;
      return rows;
    };
    std::vector<Vertex> w = upward(wide, wide_left);
    if (m_.is_border(hb) || m_.is_border(ht))
      fail(f, "a short-row face needs neighbours above and below (its bottom or top is open)");
    for (std::uint32_t x = 1; x <= columns; ++x) {
      std::vector<Vertex> p;
      if (x == columns)
        p = narrow.valid() ? upward(narrow, !wide_left) : std::vector<Vertex>{bottom.back()};
      else
        p = line(bottom[x], top[x], rows_at(x));
      if (x == columns && !narrow.valid())
        SKEIN_ASSERT(rows_at(x) == 0, "a triangle's point has no rows");
      add_column(f, tokens, w, p, x, !wide_left);
      w = std::move(p);
    }
  }

  // One column of a short-row face between line `w` (wide side) and `p` (narrow side).
  void add_column(CoarseFace f, const std::vector<Token>& tokens, const std::vector<Vertex>& w,
                  const std::vector<Vertex>& p, std::uint32_t x, bool mirrored) {
    std::size_t iw = 0, ip = 0;
    std::uint32_t columns = segments(side(f, CoarseRole::bottom));
    bool purl = purl_at(pattern(f), offset_[f.index()] + (mirrored ? columns - x : x - 1));
    std::vector<Vertex> run{w[0], p[0]};  // the bottom course run of the next face
    bool sr5 = p_.short_row_method == ShortRowMethod::sr5;
    for (std::size_t k = 0; k < tokens.size(); ++k) {
      const Token& t = tokens[k];
      auto regular = [&](bool toward) {
        std::vector<Vertex> top{w[iw + 1], p[ip + 1]};
        Shape s{static_cast<std::uint8_t>(run.size() - 1), 1};
        emit(f, run, top, toward, type_of(s, purl), mirrored);
        run = {w[iw + 1], p[ip + 1]};
        ++iw;
        ++ip;
      };
      if (!t.pair) {
        regular(t.toward_narrow);
      } else if (t.depth >= x) {
        regular(true);
        regular(false);
      } else if (t.depth + 1 == x) {
        // The turn: wale edges side by side on the wide side, its top on the narrow point.
        std::size_t up = k + 1;  // the next token with a face in this column
        while (up < tokens.size() && tokens[up].pair && tokens[up].depth + 1 < x) ++up;
        bool covered = up < tokens.size() && (!tokens[up].pair || tokens[up].depth >= x);
        std::vector<Vertex> top{w[iw + 2], p[ip]};
        if (sr5 && covered)
          top.insert(top.begin() + 1, new_vertex(lerp(pos(w[iw + 2]), pos(p[ip]), 0.5f)));
        corners_.assign(run.begin(), run.end());  // ends at the point, where the top starts
        corners_.insert(corners_.end(), top.rbegin() + 1, top.rend());
        corners_.push_back(w[iw + 1]);
        roles_.assign(run.size() - 1, EdgeRole::bottom);
        roles_.insert(roles_.end(), top.size() - 1, EdgeRole::top);
        roles_.push_back(EdgeRole::wale_out);
        roles_.push_back(EdgeRole::wale_in);
        emit_raw(f, top.size() == 3 ? StitchType::sr5 : StitchType::sr4, mirrored);
        run = top;
        iw += 2;
      }
    }
  }

  void emit(CoarseFace f, const std::vector<Vertex>& bottom, const std::vector<Vertex>& top,
            bool rightward, StitchType type, bool mirrored) {
    corners_.assign(bottom.begin(), bottom.end());
    corners_.insert(corners_.end(), top.rbegin(), top.rend());
    roles_.assign(bottom.size() - 1, EdgeRole::bottom);
    roles_.push_back(rightward ? EdgeRole::wale_out : EdgeRole::wale_in);
    roles_.insert(roles_.end(), top.size() - 1, EdgeRole::top);
    roles_.push_back(rightward ? EdgeRole::wale_in : EdgeRole::wale_out);
    emit_raw(f, type, mirrored);
  }

  // Adds corners_/roles_ as a face; a mirrored frame reverses the cycle (edge i keeps its role).
  void emit_raw(CoarseFace f, StitchType type, bool mirrored) {
    if (mirrored) {
      std::reverse(corners_.begin(), corners_.end());
      std::reverse(roles_.begin(), roles_.end());
      std::rotate(roles_.begin(), roles_.begin() + 1, roles_.end());
    }
    builder_.add_face(corners_, roles_, type);
    origin_.push_back(f.index());
  }

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
  void choose_yarns(GeneratedStitchMesh& out) const {
    StitchMesh& mesh = out.mesh;
    auto choice = [&](Edge e, YarnHandling use, std::optional<std::uint32_t> coarse_face) {
      EdgeKind k = mesh.kind(e);
      if (k != EdgeKind::join && k != EdgeKind::split) return false;
      if (use == YarnHandling::by_default) return true;
      Halfedge h = mesh.halfedge(e);
      Face a = mesh.face(h), b = mesh.face(mesh.twin(h));
      std::uint32_t ca = out.coarse_face[a.index()], cb = out.coarse_face[b.index()];
      Face own =
          coarse_face ? (*coarse_face == ca ? a : b) : (L_.order[ca] <= L_.order[cb] ? a : b);
      mesh.mismatch_yarn[e] = use == YarnHandling::extra
                                  ? MismatchYarn{MismatchYarn::Kind::extra, {}}
                                  : MismatchYarn{MismatchYarn::Kind::own, own};
      return true;
    };
    for (Edge e : mesh.edges()) choice(e, p_.default_yarn, std::nullopt);
    for (const YarnMark& y : p_.yarn_marks) {
      CoarseHalfedge h = find_project_edge(m_, p_, y.edge);
      bool any = false;
      mark_edge(mesh, h, [&](Edge e) { any |= choice(e, y.use, y.face); });
      if (!any)
        throw Error(
            fmt::format("{}:{}: {} is not a joining or splitting edge, so it takes no yarn "
                        "choice",
                        p_.file, y.edge.line, m_.describe(h)));
    }
  }

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

}  // namespace

namespace {

// A pattern for a group the mesh does not have would knit nothing: a misspelt name.
void check_group_names(const CoarseMesh& coarse, const Project& project) {
  std::vector<std::string_view> known;
  for (const std::string& g : coarse.groups)
    if (!g.empty()) known.push_back(g);
  for (const auto& [name, group] : project.group_patterns)
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw Error(fmt::format(
          "{}:{}: 'patterns' names the group '{}', but {} has {}", project.file, group.line, name,
          coarse.source,
          known.empty() ? std::string("no groups ('g' or 'o' lines)")
                        : fmt::format("no such group; did you mean '{}'? (groups: {})",
                                      nearest_name(name, known), fmt::join(known, ", "))));
}

}  // namespace

GeneratedStitchMesh generate_stitch_mesh(const CoarseMesh& coarse, const Labeling& labeling,
                                         const Project& project) {
  check_group_names(coarse, project);
  return Generator(coarse, labeling, project).run();
}

GeneratedStitchMesh build_project(const Project& project) {
  CoarseMesh coarse = read_coarse_mesh(project.mesh);
  return generate_stitch_mesh(coarse, label_coarse_mesh(coarse, project), project);
}

std::string describe_generation(const CoarseMesh& coarse, const Labeling& labeling,
                                const GeneratedStitchMesh& generated) {
  std::vector<std::uint32_t> stitches(coarse.num_faces(), 0);
  for (std::uint32_t f : generated.coarse_face) ++stitches[f];
  std::string out = fmt::format(
      "{} coarse faces -> {} stitches; coarse rows: {} closed, {} open; shift-paths: {}\n",
      coarse.num_faces(), generated.mesh.num_faces(), generated.closed_rows, generated.open_rows,
      generated.shift_paths);
  auto count = [&](CoarseHalfedge h) { return generated.segments[h.index()]; };
  for (CoarseFace f : coarse.faces()) {
    CoarseHalfedge b = labeling.find(coarse, f, CoarseRole::bottom),
                   t = labeling.find(coarse, f, CoarseRole::top),
                   l = labeling.find(coarse, f, CoarseRole::left),
                   r = labeling.find(coarse, f, CoarseRole::right);
    std::string rows = labeling.short_row[f.index()]
                           ? fmt::format("short rows: {} left, {} right", l.valid() ? count(l) : 0,
                                         r.valid() ? count(r) : 0)
                           : fmt::format("rows {}", count(l));
    out += fmt::format("face {}: labelled #{}, bottom {}, {}, stitches {} -> {}, {} faces\n",
                       f.index() + 1, labeling.order[f.index()] + 1, coarse.describe(b), rows,
                       count(b), count(t), stitches[f.index()]);
  }
  return out;
}

}  // namespace skein
