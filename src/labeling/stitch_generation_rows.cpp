// The stitch generator's rows: each coarse row cut into strips and short-row faces, open rows
// and rings, and the yarn's walk through them (stitch_generator.hpp).
#include "common/error.hpp"
#include "labeling/stitch_generator.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace skein::generation {

void Generator::plan_rows() {
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
    for (CoarseFace g = across(first, CoarseRole::right, CoarseRole::left); g.valid() && g != first;
         g = across(g, CoarseRole::right, CoarseRole::left))
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

std::vector<Segment> Generator::cut(const std::vector<CoarseFace>& faces,
                                    CoarseHalfedge first_side) {
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

PlannedRow Generator::open_row(const std::vector<CoarseFace>& faces) {
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

void Generator::plan_open_row(const std::vector<CoarseFace>& faces, const RowEntry& entry) {
  std::vector<Segment> segs = cut(faces, side(faces.front(), CoarseRole::left));
  walk_yarn(segs, faces, false, entry.from_left);
  store(segs);
}

bool Generator::among_short_rows(const std::vector<CoarseFace>& faces, std::size_t i) const {
  CoarseFace f = faces[i];
  if (L_.short_row[f.index()]) return L_.wide_side[f.index()] == CoarseRole::left;
  for (std::size_t k = 1; k < faces.size(); ++k) {
    CoarseFace before = faces[(i + faces.size() - k) % faces.size()];
    if (L_.short_row[before.index()]) return L_.wide_side[before.index()] == CoarseRole::right;
  }
  return false;
}

PlannedRow Generator::ring(const std::vector<CoarseFace>& faces) {
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

void Generator::plan_closed_row(const std::vector<CoarseFace>& faces, const RowEntry& path) {
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

bool Generator::walk_yarn(std::vector<Segment>& segs, const std::vector<CoarseFace>& faces,
                          bool closed, bool from_left) {
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

void Generator::store(std::vector<Segment>& segs) {
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
      t.depth = j <= peak ? (columns - 1) * j / peak : (columns - 1) * (k + 1 - j) / (k + 1 - peak);
    }
    tokens_[s.face.index()] = std::move(s.tokens);
  }
}

}  // namespace skein::generation
