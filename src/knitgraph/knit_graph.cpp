#include "knitgraph/knit_graph.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "common/error.hpp"
#include "mesh/stitch_mesh.hpp"  // kNoPart

namespace skein {

const char* explain(DependencyReason reason) {
  switch (reason) {
    case DependencyReason::yarn:
      return "it comes next along the yarn";
    case DependencyReason::loop:
      return "it consumes its loop";
    case DependencyReason::perpendicular_loop:
      return "it consumes its loop across a perpendicular mismatched edge";
    case DependencyReason::joined_loop:
      return "it joins that stitch's loop in a three-needle bind-off";
    case DependencyReason::split_loop:
      return "it is pulled through the loop that stitch casts on along the split";
  }
  return "?";
}

const char* mismatch_kind_name(MismatchKind kind) {
  switch (kind) {
    case MismatchKind::join:
      return "joining";
    case MismatchKind::split:
      return "splitting";
    case MismatchKind::contracting:
      return "contracting perpendicular";
    case MismatchKind::expanding:
      return "expanding perpendicular";
  }
  return "?";
}

const char* row_shape_name(RowShape shape) {
  switch (shape) {
    case RowShape::open:
      return "open";
    case RowShape::closed:
      return "closed";
    case RowShape::short_row:
      return "short";
  }
  return "?";
}

const char* course_direction_name(CourseDirection direction) {
  switch (direction) {
    case CourseDirection::left_to_right:
      return "left to right";
    case CourseDirection::right_to_left:
      return "right to left";
    case CourseDirection::along_its_loops:
      return "along its loops";
  }
  return "?";
}

namespace {

// Counting sort of loop indices by stitch, then by slot within each stitch: linear.
void index_by(const std::vector<Loop>& loops, std::uint32_t stitches, StitchId Loop::*stitch,
              std::uint8_t Loop::*slot, std::vector<std::uint32_t>& first,
              std::vector<std::uint32_t>& index) {
  first.assign(stitches + 1, 0);
  for (const Loop& l : loops)
    if (l.*stitch != kNoStitch) ++first[l.*stitch + 1];
  for (std::uint32_t s = 0; s < stitches; ++s) first[s + 1] += first[s];
  index.assign(first.back(), 0);
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for (std::uint32_t i = 0; i < loops.size(); ++i)
    if (loops[i].*stitch != kNoStitch) index[fill[loops[i].*stitch]++] = i;
  for (std::uint32_t s = 0; s < stitches; ++s)
    std::sort(index.begin() + first[s], index.begin() + first[s + 1],
              [&](std::uint32_t a, std::uint32_t b) { return loops[a].*slot < loops[b].*slot; });
}

}  // namespace

void KnitGraph::index_loops() {
  index_by(loops, size(), &Loop::taker, &Loop::taker_slot, taken_first, taken);
  index_by(loops, size(), &Loop::maker, &Loop::maker_slot, made_first, made);
}

StitchId KnitGraph::add_stitch(StitchType t, std::uint32_t r, std::uint32_t src,
                               std::uint8_t stitch_flags, CourseDirection d) {
  type.push_back(t);
  row.push_back(r);
  source.push_back(src);
  yarn_next.push_back(kNoStitch);
  yarn_link.push_back(YarnLink::none);
  flags.push_back(stitch_flags);
  direction.push_back(d);
  if (!part.empty()) part.push_back(kNoPart);
  return size() - 1;
}

std::string KnitGraph::describe(StitchId s) const {
  if (flags[s] & kExtruded) {
    const MismatchEdge& e = mismatch_edges[extruded_at[s - first_extruded]];
    return fmt::format("extruded {} on edge {}-{} (row {})", abbreviation(type[s]), e.vertex[0] + 1,
                       e.vertex[1] + 1, row[s] + 1);
  }
  if (element == "face")
    return fmt::format("face {} ({}, row {})", source[s] + 1, abbreviation(type[s]), row[s] + 1);
  return fmt::format("{} {} ({})", element, source[s] + 1, abbreviation(type[s]));
}

void check_consistency(const KnitGraph& g) {
  const std::uint32_t n = g.size();
  SKEIN_ASSERT(g.row.size() == n && g.source.size() == n && g.yarn_next.size() == n &&
                   g.yarn_link.size() == n && g.flags.size() == n && g.direction.size() == n &&
                   g.taken_first.size() == n + 1 && g.made_first.size() == n + 1,
               "per-stitch arrays have one entry per stitch");
  std::vector<std::uint8_t> has_prev(n, 0);
  for (StitchId s = 0; s < n; ++s) {
    StitchId next = g.yarn_next[s];
    SKEIN_ASSERT((next == kNoStitch) == (g.yarn_link[s] == YarnLink::none),
                 "a yarn link exactly where there is a next stitch");
    if (next == kNoStitch) continue;
    SKEIN_ASSERT(next < n, "yarn_next in range");
    SKEIN_ASSERT(!has_prev[next],
                 fmt::format("{} follows two stitches along the yarn", g.describe(next)));
    has_prev[next] = 1;
  }
  // Every loop is made by one stitch and consumed by one (the transforms gave joins and
  // splits their stitches); each stitch takes as many loops as its type says. A loop across a
  // perpendicular edge is pulled through the side of its maker, not made at its top.
  std::vector<std::int32_t> made(n, 0), took(n, 0);
  for (const Loop& l : g.loops) {
    SKEIN_ASSERT(l.maker < n, "every loop has a maker in range");
    SKEIN_ASSERT(l.taker == kNoStitch || l.taker < n, "loop taker in range");
    SKEIN_ASSERT(l.maker != l.taker, "no stitch consumes its own loop");
    SKEIN_ASSERT(l.taker != kNoStitch || g.element == "line",
                 fmt::format("the loop {} makes is consumed or bound off", g.describe(l.maker)));
    if (l.kind != LoopKind::perpendicular) ++made[l.maker];
    if (l.taker != kNoStitch) ++took[l.taker];
  }
  for (StitchId s = 0; s < n; ++s) {
    // srn makes one loop per top edge, as many as its face has (Fig. 10c).
    SKEIN_ASSERT(
        made[s] <= info(g.type[s]).loops_out || info(g.type[s]).variable_course_edges,
        fmt::format("{} makes at most {} loops", g.describe(s), info(g.type[s]).loops_out));
    SKEIN_ASSERT(took[s] == info(g.type[s]).loops_in,
                 fmt::format("{} consumes {} loops", g.describe(s), info(g.type[s]).loops_in));
    SKEIN_ASSERT(g.loops_taken_by(s).size() >= static_cast<std::size_t>(took[s]),
                 "index_loops() ran after the last loop was added");
  }
}

}  // namespace skein
