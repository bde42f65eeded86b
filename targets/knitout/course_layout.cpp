#include "knitout/course_layout.hpp"

#include <fmt/format.h>

#include "common/error.hpp"
#include "knitout/stitch_recipes.hpp"

namespace skein::knitout {
namespace {

[[noreturn]] void unsupported(const KnitGraph& g, const std::string& what, StitchId s) {
  throw UnsupportedError(
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
    case StitchType::sr4:
    case StitchType::sr5:
    case StitchType::tuck:
    case StitchType::sl:
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
  }
  for (const Loop& l : g.loops) {
    StitchId at = l.taker != kNoStitch ? l.taker : l.maker;
    if (l.kind != LoopKind::wale) unsupported(g, "mismatched edges (a loop across a mismatch)", at);
    if (l.maker == kNoStitch || l.taker == kNoStitch) unsupported(g, "a loop with an open end", at);
  }
}

bool is_bind_off(const KnitGraph& g, StitchId s) {
  return g.type[s] == StitchType::bo;
}

// A course ends where the yarn turns or crosses a shift-path. A row with short rows inside
// (a heel's) is knit in several courses; a course never spans two rows of a sheet or tube. A
// bind-off is a course of its own, knit where its loops wait: in a stitch graph (whose rows
// are inferred when it is read) it may start in the row of the st a helix steps up by, and go
// on round past that st's row into the next.
std::vector<Course> split_into_courses(const KnitGraph& g, const std::vector<StitchId>& order) {
  std::vector<Course> courses;
  for (std::uint32_t i = 0; i < order.size(); ++i) {
    StitchId s = order[i];
    bool after_bind_off = i > 0 && is_bind_off(g, order[i - 1]);
    bool bind_off_goes_on = after_bind_off && is_bind_off(g, s);
    bool starts = courses.empty() || (is_bind_off(g, s) && !after_bind_off) ||
                  (!bind_off_goes_on && (g.yarn_link[order[i - 1]] == YarnLink::turn ||
                                         g.yarn_link[order[i - 1]] == YarnLink::shift));
    if (starts) {
      courses.emplace_back();
      courses.back().row = g.row[s];
      courses.back().begin = i;
    }
    if (!starts && !bind_off_goes_on && g.row[s] != courses.back().row)
      unsupported(g, "a row that ends without a turn or a shift-path", s);
    courses.back().end = i + 1;
  }
  return courses;
}

// A bind-off course may come before the last (part of the work bound off, as a tube's first
// leg, while the rest waits and is knit on after it); the last course is all bind-off.
void check_borders(const KnitGraph& g, const CourseLayout& l) {
  const Course& first = l.courses.front();
  for (const Course& c : l.courses) {
    bool bind_off = is_bind_off(g, l.order[c.begin]), last = &c == &l.courses.back();
    for (std::uint32_t i = c.begin; i < c.end; ++i) {
      StitchId s = l.order[i];
      bool in_first = i < first.end;
      if (in_first != (g.type[s] == StitchType::co))
        unsupported(g,
                    in_first ? "a first row that is not all cast-on stitches"
                             : "a cast-on stitch above the first row",
                    s);
      if (last && !is_bind_off(g, s))
        unsupported(g, "a last row that is not all bind-off stitches", s);
      if (bind_off != is_bind_off(g, s))
        unsupported(g, "a bind-off and other stitches in one course, with no turn between", s);
    }
  }
  if (l.tube) return;
  for (std::size_t c = 1; c < l.courses.size(); ++c)
    if (g.yarn_link[l.order[l.courses[c].begin - 1]] != YarnLink::turn)
      unsupported(g, "a row that does not start with a turn", l.order[l.courses[c].begin]);
}

template <typename F>
void each_left_to_right(const CourseLayout& l, const Course& c, F f) {
  if (c.left_to_right)
    for (std::uint32_t i = c.begin; i < c.end; ++i) f(l.order[i]);
  else
    for (std::uint32_t i = c.end; i-- > c.begin;) f(l.order[i]);
}

// A run of loops on the needles, left to right.
struct Run {
  std::uint32_t first = kNoWrap, last = kNoWrap, count = 0;
};

// The loops on the needles, left to right along the fabric (a ring on a tube), as a linked
// list: each course takes a run of them and leaves its own loops in their place, in time linear
// in the loops it takes and makes.
class LiveLoops {
 public:
  LiveLoops(const KnitGraph& g, bool ring)
      : g_(g),
        ring_(ring),
        next_(g.loops.size(), kNoWrap),
        prev_(g.loops.size(), kNoWrap),
        live_(g.loops.size(), 0) {}
  std::size_t size() const { return size_; }

  void start(const CourseLayout& l, const Course& c) {
    start_ = link_made(l, c, kNoWrap, kNoWrap).first;
  }
  // The first loop of the last full round (or of what replaced it in place): where a round
  // that does not drift starts.
  std::uint32_t round_start() const { return start_; }

  // Whether the loops `c` takes, left to right, are live and follow each other; gives the
  // run's ends and length.
  bool find_run(const CourseLayout& l, const Course& c, Run& run) const {
    run = Run{};
    bool in_order = true;
    each_left_to_right(l, c, [&](StitchId s) {
      for (std::uint32_t loop : g_.loops_taken_by(s)) {
        in_order &= live_[loop] && (run.count == 0 || next_[run.last] == loop);
        if (run.count++ == 0) run.first = loop;
        run.last = loop;
      }
    });
    return in_order && run.count > 0 && run.count <= size_;
  }

  // Puts the loops `c` makes in place of the run; returns the loop waiting just beyond the
  // course's last stitch along the yarn (kNoWrap at a sheet's edge or when nothing waits).
  std::uint32_t replace_run(const CourseLayout& l, const Course& c, const Run& run) {
    bool whole = run.count == size_;
    std::uint32_t before = whole ? kNoWrap : prev_[run.first];
    std::uint32_t after = whole ? kNoWrap : next_[run.last];
    bool takes_start = whole;
    for (std::uint32_t loop = run.first, n = 0; n < run.count; ++n, loop = next_[loop]) {
      live_[loop] = 0;
      takes_start |= loop == start_;
    }
    size_ -= run.count;
    auto [first, last] = link_made(l, c, before, after);
    if (takes_start) move_start(c);
    if (first == kNoWrap) {  // nothing made (a bind-off): the neighbours close up
      if (before != kNoWrap) next_[before] = after;
      if (after != kNoWrap) prev_[after] = before;
      if (takes_start) start_ = after;  // the rest's rounds start where the bind-off ended
      return kNoWrap;
    }
    return c.left_to_right ? after : before;
  }

 private:
  // The round's start moves to the loop made at its place: the leftmost loop of the stitch
  // that takes it (an sr5's own loop, not its turn loop), which is knit where the start was.
  void move_start(const Course& c) {
    StitchId taker = g_.loops[start_].taker;
    auto made = g_.loops_made_by(taker);
    if (made.empty()) return;  // a bind-off: see replace_run
    bool sr5 = g_.type[taker] == StitchType::sr5;
    start_ = made[sr5 ? knit_slot(StitchType::sr5, c.left_to_right) : 0];
  }

  // Links the loops `c` makes, left to right, between `before` and `after` (a ring closes on
  // itself when both are absent); returns the first and last.
  std::pair<std::uint32_t, std::uint32_t> link_made(const CourseLayout& l, const Course& c,
                                                    std::uint32_t before, std::uint32_t after) {
    std::uint32_t first = kNoWrap, last = before;
    each_left_to_right(l, c, [&](StitchId s) {
      for (std::uint32_t loop : g_.loops_made_by(s)) {
        live_[loop] = 1;
        ++size_;
        prev_[loop] = last;
        if (last != kNoWrap) next_[last] = loop;
        if (first == kNoWrap) first = loop;
        last = loop;
      }
    });
    if (first == kNoWrap) return {kNoWrap, kNoWrap};
    next_[last] = after;
    if (after != kNoWrap) prev_[after] = last;
    if (ring_ && before == kNoWrap && after == kNoWrap) {
      next_[last] = first;
      prev_[first] = last;
    }
    return {first, last};
  }

  const KnitGraph& g_;
  bool ring_;
  std::vector<std::uint32_t> next_, prev_;  // per loop, along the fabric (kNoWrap: an edge)
  std::vector<std::uint8_t> live_;          // per loop: on the needles now
  std::size_t size_ = 0;
  std::uint32_t start_ = kNoWrap;
};

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

// Gives each course a direction, starting with `first`: a turn reverses it, a shift-path keeps
// it. Returns the index of the first course whose stitches do not take a run of the loops on
// the needles in order, or 0 when all do; marks short rows and the loops their turns wrap.
std::size_t assign_directions(const KnitGraph& g, CourseLayout& l, bool first) {
  LiveLoops live(g, l.tube);
  std::vector<std::uint8_t> wrapped(g.loops.size(), 0);
  l.courses[0].left_to_right = first;
  live.start(l, l.courses[0]);
  for (std::size_t c = 1; c < l.courses.size(); ++c) {
    Course& course = l.courses[c];
    bool turned = g.yarn_link[l.order[course.begin - 1]] == YarnLink::turn;
    course.left_to_right = l.courses[c - 1].left_to_right != turned;
    Run run;
    if (!live.find_run(l, course, run)) return c;
    course.partial = run.count < live.size();
    course.rotated = l.tube && !course.partial && run.first != live.round_start();
    if (course.rotated)
      course.layout_start = taker_of_round_start(g, l, course, live.round_start());
    std::uint32_t beyond = live.replace_run(l, course, run);
    bool turns_next =
        c + 1 < l.courses.size() && g.yarn_link[l.order[course.end - 1]] == YarnLink::turn;
    if (course.partial && turns_next)
      choose_wrap(g, l.order[course.end - 1], beyond, course, wrapped);
  }
  return 0;
}

// An sr5's turn loop waits on the facing needle until one decrease knits it with the sr5's loop.
void check_sr5_turn_loops(const KnitGraph& g, const CourseLayout& l) {
  for (StitchId s : l.order) {
    auto made = g.loops_made_by(s);
    if (g.type[s] == StitchType::sr5 && g.loops[made[0]].taker != g.loops[made[1]].taker)
      unsupported(g, "an sr5 whose two loops are not knit together by the stitch above", s);
  }
}

// Several yarn pieces are knit one after another, each from cast-on to bind-off; a piece that
// takes loops of another would have to wait for it on the bed.
void check_pieces_apart(const KnitGraph& g, const YarnPieces& yarns) {
  for (const Loop& l : g.loops) {
    std::uint32_t maker = yarns.piece_of[l.maker], taker = yarns.piece_of[l.taker];
    if (maker != taker)
      unsupported(g,
                  fmt::format("pieces joined on the bed (yarn {} takes loops made by yarn {}, as "
                              "a sweater's yoke takes its sleeves)",
                              taker + 1, maker + 1),
                  l.taker);
  }
}

CourseLayout lay_out_piece(const KnitGraph& g, std::vector<StitchId> order) {
  CourseLayout l;
  l.order = std::move(order);
  l.courses = split_into_courses(g, l.order);
  l.tube = g.row_shape[l.courses.front().row] == RowShape::closed;
  for (const Course& course : l.courses) {
    RowShape shape = g.row_shape[course.row];
    if (shape != RowShape::short_row && (shape == RowShape::closed) != l.tube)
      unsupported(g, "a mix of open rows and closed rounds", l.order[course.begin]);
  }
  if (l.courses.size() < 2) unsupported(g, "a piece with fewer than two rows", l.order.front());
  check_borders(g, l);
  std::size_t bad = assign_directions(g, l, true);
  if (bad && assign_directions(g, l, false))
    unsupported(g, "a row whose stitches do not take the loops below in order",
                l.order[l.courses[bad].begin]);
  check_sr5_turn_loops(g, l);
  l.left_to_right.assign(g.size(), 1);
  for (const Course& course : l.courses)
    for (std::uint32_t i = course.begin; i < course.end; ++i)
      l.left_to_right[l.order[i]] = course.left_to_right;
  return l;
}

}  // namespace

std::vector<CourseLayout> lay_out_pieces(const Compilation& c) {
  const KnitGraph& g = c.knit;
  if (g.size() == 0) throw Error("the model has no stitches: nothing to knit");
  check_stitches(g);
  check_pieces_apart(g, c.yarns);
  // Each piece's stitches in schedule order; the pieces in the order the schedule starts them.
  std::vector<std::vector<StitchId>> orders(c.yarns.size());
  std::vector<std::uint32_t> sequence;
  for (const Event& e : c.schedule.events) {
    if (e.kind != EventKind::stitch) continue;
    std::uint32_t piece = c.yarns.piece_of[e.stitch];
    if (orders[piece].empty()) {
      sequence.push_back(piece);
      orders[piece].reserve(c.yarns.length[piece]);
    }
    orders[piece].push_back(e.stitch);
  }
  std::vector<CourseLayout> layouts;
  for (std::uint32_t piece : sequence) {
    if (c.yarns.ring[piece]) unsupported(g, "a yarn that closes on itself", c.yarns.first[piece]);
    layouts.push_back(lay_out_piece(g, std::move(orders[piece])));
  }
  return layouts;
}

}  // namespace skein::knitout
