// The checks on the knit graph (every stitch has a machine recipe) and on each finished
// layout: its borders, its short rows' wraps, its yarns' first and last courses
// (program_layouts.hpp).
#include "knitout/program_layouts.hpp"

#include <fmt/format.h>

#include "common/error.hpp"
#include "knitgraph/worked_by_hand.hpp"
#include "knitout/stitch_recipes.hpp"

namespace skein::knitout::layout {
namespace {

// Its loops are all taken by another yarn (which knits on from them).
bool left_to_another_yarn(const KnitGraph& g, const YarnPieces& yarns, StitchId s) {
  for (std::uint32_t loop : g.loops_made_by(s))
    if (yarns.piece_of[g.loops[loop].taker] == yarns.piece_of[s]) return false;
  return true;
}

}  // namespace

[[noreturn]] void unsupported(const KnitGraph& g, const std::string& what, StitchId s) {
  throw UnsupportedError(
      fmt::format("not yet supported by the knitout target: {}, at {}", what, g.describe(s)));
}

void check_stitches(const KnitGraph& g) {
  for (StitchId s = 0; s < g.size(); ++s) {
    if (!worked_by(g.type[s], by_machine))
      unsupported(
          g, fmt::format("the {} stitch ({})", info(g.type[s]).name, abbreviation(g.type[s])), s);
  }
  for (const Loop& l : g.loops) {
    StitchId at = l.taker != kNoStitch ? l.taker : l.maker;
    bool crotch = l.kind == LoopKind::split && l.maker != kNoStitch &&
                  g.type[l.maker] == StitchType::sco;  // a cast-on along a split's
    bool joined = l.kind == LoopKind::joined && l.taker != kNoStitch &&
                  g.type[l.taker] == StitchType::tnbo;  // a three-needle bind-off's
    if (l.kind != LoopKind::wale && !crotch && !joined)
      unsupported(g, "mismatched edges (a loop across a mismatch)", at);
    if (l.maker == kNoStitch || l.taker == kNoStitch) unsupported(g, "a loop with an open end", at);
  }
}

bool is_bind_off(const KnitGraph& g, StitchId s) {
  return chained_off(g.type[s]);
}

// A bind-off course may come before the last (part of the work bound off, as a tube's first
// leg, while the rest waits and is knit on after it); a yarn's last course is all bind-off, or
// leaves its loops to another yarn (a flap's, before the course that joins it).
void check_borders(const KnitGraph& g, const YarnPieces& yarns, const CourseLayout& l) {
  for (const Course& c : l.courses) {
    for (std::uint32_t i = c.begin; i < c.end; ++i) {
      StitchId s = l.order[i];
      if (c.cast_on != (g.type[s] == StitchType::co))
        unsupported(g,
                    c.cast_on ? "a first row that is not all cast-on stitches"
                              : "a cast-on stitch above the first row",
                    s);
      if (c.last_of_yarn && !is_bind_off(g, s) && !left_to_another_yarn(g, yarns, s))
        unsupported(g, "a last row that is not all bind-off stitches", s);
    }
  }
  if (l.tube) return;
  std::unordered_map<std::uint32_t, StitchId> last_of;  // per yarn: its course before
  for (const Course& c : l.courses) {
    StitchId s = l.order[c.begin];
    auto before = last_of.find(c.yarn);
    // After binding off part of the work (a flap) the yarn goes on to the rest without a turn.
    if (before != last_of.end() && g.yarn_link[before->second] != YarnLink::turn &&
        !is_bind_off(g, before->second))
      unsupported(g, "a row that does not start with a turn", s);
    last_of[c.yarn] = l.order[c.end - 1];
  }
}

// The wrap of a short row's turn after `turning`: over the waiting loop `beyond`; or, when
// another turn already wrapped it, over the turning stitch's own loop on the way back (so no
// needle gathers two wraps). An sr5 makes the turn's loop itself; a loop that a tuck or slip
// takes next is left unwrapped (the stitch above those takes the needle's loops).
bool wrappable(const KnitGraph& g, std::uint32_t loop) {
  return loop != kNoWrap && !keeps_loop_below(g.type[g.loops[loop].taker]);
}
void choose_wrap(const KnitGraph& g, StitchId turning, std::uint32_t beyond, Course& course,
                 std::vector<std::uint8_t>& wrapped) {
  if (g.type[turning] == StitchType::sr5 || !wrappable(g, beyond)) return;
  auto own = g.loops_made_by(turning);
  course.wrap_back = wrapped[beyond] != 0;
  course.wrap = !course.wrap_back                         ? beyond
                : own.size() == 1 && wrappable(g, own[0]) ? own[0]
                                                          : kNoWrap;
  if (course.wrap != kNoWrap) wrapped[course.wrap] = 1;
}

// Where a round that starts elsewhere than the round below it is laid out from: its stitch
// (counted left to right) that takes the loop where the round below started. A decrease across
// that start (a stitch graph's k2tog) is laid out there when the start is its bottom loop: its
// other loop comes over the tube's left fold onto it.
std::uint32_t taker_of_round_start(const KnitGraph& g, const CourseLayout& l, const Course& c,
                                   std::uint32_t start) {
  StitchId taker = g.loops[start].taker;
  auto taken = g.loops_taken_by(taker);
  if (taken[0] != start && taken[stacking_order(g.type[taker])[0]] != start)
    unsupported(g,
                "a decrease whose top loop is where the round below started, in a round that "
                "starts elsewhere",
                taker);
  std::uint32_t i = c.begin;
  while (l.order[i] != taker) ++i;
  return c.left_to_right ? i - c.begin : c.end - 1 - i;
}

// An sr5's turn loop waits on the facing needle until one decrease knits it with the sr5's loop.
void check_sr5_turn_loops(const KnitGraph& g, const CourseLayout& l) {
  for (StitchId s : l.order) {
    if (g.type[s] == StitchType::sr5 && taker_of_both_sr5_loops(g, s) == kNoStitch)
      unsupported(g, "an sr5 whose two loops are not knit together by the stitch above", s);
  }
}

void ProgramLayouts::finish(std::uint32_t index) {
  CourseLayout& l = layouts_[index];
  for (const Course& course : l.courses) {
    RowShape shape = g_.row_shape[course.row];
    if (course.along_split) continue;  // a line of sts between two branches of the tube
    // A tube folded flat and bound off across its halves: one line of sts.
    if (g_.type[l.order[course.begin]] == StitchType::tnbo) continue;
    if (shape != RowShape::short_row && (shape == RowShape::closed) != l.tube)
      unsupported(g_, "a mix of open rows and closed rounds", l.order[course.begin]);
  }
  if (l.courses.size() < 2) unsupported(g_, "a piece with fewer than two rows", l.order.front());
  mark_yarn_ends(l);
  wrap_turns(index);
  check_borders(g_, yarns_, l);
  check_sr5_turn_loops(g_, l);
  l.left_to_right.assign(g_.size(), 1);
  for (const Course& course : l.courses)
    for (std::uint32_t i = course.begin; i < course.end; ++i)
      l.left_to_right[l.order[i]] = course.left_to_right;
}

// A turn's wrap closes the gap beside a short row, which a later course knits across: the
// course that takes the waiting loop beyond the turn takes loops made since the turn too.
// Beside a slit (a sheet parted into flaps, each knit on its own) the course that takes the
// other flap's loop takes none: a wrap there would join the flaps, so the turn goes unwrapped;
// so too where another yarn takes the waiting loop (a branch knit on with a yarn of its own):
// the turn's yarn never comes back to knit its wrap.
void ProgramLayouts::wrap_turns(std::uint32_t index) {
  CourseLayout& l = layouts_[index];
  std::vector<std::uint32_t> course_of(g_.size(), kNoWrap);
  for (std::uint32_t i = 0; i < l.courses.size(); ++i)
    for (std::uint32_t k = l.courses[i].begin; k < l.courses[i].end; ++k) course_of[l.order[k]] = i;
  for (const Turn& t : turns_) {
    if (t.layout != index) continue;
    std::uint32_t across = t.beyond == kNoWrap ? kNoWrap : course_of[g_.loops[t.beyond].taker];
    if (across != kNoWrap && l.courses[across].yarn == l.courses[t.course].yarn &&
        takes_loops_made_since(l, l.courses[across], t.course, course_of))
      choose_wrap(g_, t.turning, t.beyond, l.courses[t.course], wrapped_);
  }
}

bool ProgramLayouts::takes_loops_made_since(const CourseLayout& l, const Course& c,
                                            std::uint32_t since,
                                            const std::vector<std::uint32_t>& course_of) const {
  for (std::uint32_t k = c.begin; k < c.end; ++k)
    for (std::uint32_t loop : g_.loops_taken_by(l.order[k])) {
      std::uint32_t made_in = course_of[g_.loops[loop].maker];
      if (made_in != kNoWrap && made_in >= since) return true;
    }
  return false;
}

// Each yarn's first and last course in the layout.
void ProgramLayouts::mark_yarn_ends(CourseLayout& l) const {
  std::vector<std::uint32_t> last(yarns_.size(), kNoWrap);
  for (std::uint32_t i = 0; i < l.courses.size(); ++i) {
    Course& c = l.courses[i];
    c.first_of_yarn = last[c.yarn] == kNoWrap;
    last[c.yarn] = i;
  }
  for (std::uint32_t i : last)
    if (i != kNoWrap) l.courses[i].last_of_yarn = true;
}

}  // namespace skein::knitout::layout
