#include "knitout/course_layout.hpp"

#include <fmt/format.h>

#include "common/error.hpp"

namespace skein::knitout {
namespace {

[[noreturn]] void unsupported(const KnitGraph& g, const std::string& what, StitchId s) {
  throw Error(
      fmt::format("not yet supported by the knitout target: {}, at {}", what, g.describe(s)));
}

bool has_machine_recipe(StitchType t) {
  switch (t) {
    case StitchType::k:
    case StitchType::p:
    case StitchType::co:
    case StitchType::bo:
    case StitchType::kfb:
    case StitchType::m1l:
    case StitchType::m1r:
    case StitchType::yo:
    case StitchType::k2tog:
    case StitchType::ssk:
    case StitchType::p2tog:
    case StitchType::s2kp:
      return true;
    default:
      return false;
  }
}

void check_stitches(const KnitGraph& g) {
  for (StitchId s = 0; s < g.size(); ++s) {
    if (!has_machine_recipe(g.type[s]))
      unsupported(
          g, fmt::format("the {} stitch ({})", info(g.type[s]).name, abbreviation(g.type[s])), s);
    RowShape shape = g.row_shape[g.row[s]];
    if (shape == RowShape::unknown) unsupported(g, "a stitch graph without rows (.st import)", s);
    if (shape == RowShape::short_row) unsupported(g, "short rows", s);
  }
  for (const Loop& l : g.loops) {
    StitchId at = l.taker != kNoStitch ? l.taker : l.maker;
    if (l.kind != LoopKind::wale) unsupported(g, "mismatched edges (a loop across a mismatch)", at);
    if (l.maker == kNoStitch || l.taker == kNoStitch) unsupported(g, "a loop with an open end", at);
  }
}

std::vector<Course> split_into_courses(const KnitGraph& g, const std::vector<StitchId>& order) {
  std::vector<Course> courses;
  std::vector<std::uint8_t> seen(g.row_shape.size(), 0);
  for (std::uint32_t i = 0; i < order.size(); ++i) {
    std::uint32_t row = g.row[order[i]];
    if (courses.empty() || courses.back().row != row) {
      if (seen[row]) unsupported(g, "a row knit in several pieces", order[i]);
      seen[row] = 1;
      courses.push_back({row, i, i, true});
    }
    courses.back().end = i + 1;
  }
  return courses;
}

void check_borders(const KnitGraph& g, const CourseLayout& l) {
  const Course& first = l.courses.front();
  const Course& last = l.courses.back();
  for (std::uint32_t i = 0; i < l.order.size(); ++i) {
    StitchId s = l.order[i];
    bool in_first = i < first.end, in_last = i >= last.begin;
    if (in_first != (g.type[s] == StitchType::co))
      unsupported(g,
                  in_first ? "a first row that is not all cast-on stitches"
                           : "a cast-on stitch above the first row",
                  s);
    if (in_last != (g.type[s] == StitchType::bo))
      unsupported(g,
                  in_last ? "a last row that is not all bind-off stitches"
                          : "a bind-off stitch below the last row",
                  s);
  }
  for (std::size_t c = 1; c < l.courses.size(); ++c) {
    StitchId end = l.order[l.courses[c].begin - 1];
    YarnLink link = g.yarn_link[end];
    if (link != (l.tube ? YarnLink::shift : YarnLink::turn))
      unsupported(g,
                  l.tube ? "a round that does not continue the helix across a shift-path"
                         : "a row that does not start with a turn",
                  l.order[l.courses[c].begin]);
  }
}

template <typename F>
void each_left_to_right(const CourseLayout& l, const Course& c, F f) {
  if (c.left_to_right)
    for (std::uint32_t i = c.begin; i < c.end; ++i) f(l.order[i]);
  else
    for (std::uint32_t i = c.end; i-- > c.begin;) f(l.order[i]);
}

// Gives each course a direction, starting with `first`; returns the index of the first course
// that does not consume the loops of the one below left to right, or 0 when all do.
std::size_t assign_directions(const KnitGraph& g, CourseLayout& l, bool first,
                              std::vector<std::uint32_t>& position) {
  l.courses[0].left_to_right = first;
  for (std::size_t c = 1; c < l.courses.size(); ++c) {
    const Course& below = l.courses[c - 1];
    l.courses[c].left_to_right = l.tube ? below.left_to_right : !below.left_to_right;
    std::uint32_t p = 0;
    each_left_to_right(l, below, [&](StitchId s) {
      for (std::uint32_t loop : g.loops_made_by(s)) position[loop] = p++;
    });
    std::uint32_t expect = 0;
    bool in_order = true;
    each_left_to_right(l, l.courses[c], [&](StitchId s) {
      for (std::uint32_t loop : g.loops_taken_by(s)) in_order &= position[loop] == expect++;
    });
    if (!in_order) return c;
  }
  return 0;
}

}  // namespace

CourseLayout lay_out_courses(const Compilation& c) {
  const KnitGraph& g = c.knit;
  if (g.size() == 0) throw Error("the model has no stitches: nothing to knit");
  if (c.yarns.size() != 1)
    unsupported(g, fmt::format("several yarn pieces at once ({} pieces)", c.yarns.size()),
                c.yarns.first[1]);
  if (c.yarns.ring[0]) unsupported(g, "a yarn that closes on itself", c.yarns.first[0]);
  check_stitches(g);
  CourseLayout l;
  l.order.reserve(g.size());
  for (const Event& e : c.schedule.events)
    if (e.kind == EventKind::stitch) l.order.push_back(e.stitch);
  l.courses = split_into_courses(g, l.order);
  l.tube = g.row_shape[l.courses.front().row] == RowShape::closed;
  for (const Course& course : l.courses)
    if ((g.row_shape[course.row] == RowShape::closed) != l.tube)
      unsupported(g, "a mix of open rows and closed rounds", l.order[course.begin]);
  if (l.courses.size() < 2) unsupported(g, "a piece with fewer than two rows", l.order.front());
  check_borders(g, l);
  std::vector<std::uint32_t> position(g.loops.size(), 0);
  std::size_t bad = assign_directions(g, l, true, position);
  if (bad && assign_directions(g, l, false, position))
    unsupported(g, "a row whose stitches do not take the loops below in order",
                l.order[l.courses[bad].begin]);
  l.left_to_right.assign(g.size(), 1);
  for (const Course& course : l.courses)
    for (std::uint32_t i = course.begin; i < course.end; ++i)
      l.left_to_right[l.order[i]] = course.left_to_right;
  return l;
}

}  // namespace skein::knitout
