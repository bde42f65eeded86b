#include "knitout/course_layout.hpp"

#include <fmt/format.h>

#include <array>
#include <optional>
#include <unordered_map>

#include "common/error.hpp"
#include "knitout/stitch_recipes.hpp"
#include "lowering/live_runs.hpp"

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
    case StitchType::sco:
    case StitchType::tnbo:
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

// Its loops are all taken by another yarn (which knits on from them).
bool left_to_another_yarn(const KnitGraph& g, const YarnPieces& yarns, StitchId s) {
  for (std::uint32_t loop : g.loops_made_by(s))
    if (yarns.piece_of[g.loops[loop].taker] == yarns.piece_of[s]) return false;
  return true;
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
    auto made = g.loops_made_by(s);
    if (g.type[s] == StitchType::sr5 && g.loops[made[0]].taker != g.loops[made[1]].taker)
      unsupported(g, "an sr5 whose two loops are not knit together by the stitch above", s);
  }
}

// The pieces' courses as the live-loop program gives them: one per course step, with its
// direction and stitches in working order. The program's runs are followed on LiveRuns (the
// lowering's own list of live loops) only for what the program does not say outright: where a
// tube's last full round started (a round that starts elsewhere is laid out from there) and
// which loop waits beyond a short row's turn (its wrap).
class ProgramLayouts {
 public:
  explicit ProgramLayouts(const Compilation& c)
      : g_(c.knit),
        p_(c.program),
        yarns_(c.yarns),
        runs_(c.knit),
        layout_of_(c.yarns.size(), kNoWrap),
        wrapped_(c.knit.loops.size(), 0),
        joined_to_(c.program.runs.size()),
        join_place_(c.program.runs.size(), kNoWrap),
        split_from_(c.program.runs.size(), kNoWrap) {
    for (std::uint32_t r = 0; r < joined_to_.size(); ++r) joined_to_[r] = r;
    for (const Step& step : p_.steps) {
      // A split's parts and a cast-on along a split's two sides stay in the layout of the tube
      // they part (the branches are knit where their loops wait).
      if (step.kind == StepKind::split || (step.kind == StepKind::cast_on && step.other.valid())) {
        RunId from = step.kind == StepKind::split ? p_.segments[step.reads.begin].run : step.run;
        for (RunId part : {step.run, step.other})
          if (part.valid() && part != from) {
            unite(part.index(), from.index());
            if (step.kind == StepKind::split) split_from_[part.index()] = from.index();
          }
      }
      if (step.kind == StepKind::three_needle_bind_off) place_bound_off_together(step);
      if (step.kind != StepKind::join) continue;
      for (std::uint32_t i = step.reads.begin; i < step.reads.end; ++i) {
        std::uint32_t run = p_.segments[i].run.index();
        unite(run, step.run.index());
        // A run split off another (a leg's outer arc, its inner one left for a crotch seam)
        // places the run it came from too.
        for (; run != kNoWrap; run = split_from_[run])
          if (join_place_[run] == kNoWrap) join_place_[run] = i - step.reads.begin;
      }
    }
  }

  std::vector<CourseLayout> run() && {
    for (const Step& step : p_.steps) take_step(step);
    for (std::uint32_t i = 0; i < layouts_.size(); ++i) finish(i);
    return std::move(layouts_);
  }

 private:
  // A short row's turn beside a waiting loop (`beyond`), which may take a wrap.
  struct Turn {
    std::uint32_t layout, course;
    StitchId turning;
    std::uint32_t beyond;
  };
  std::uint32_t index_of(const CourseLayout& l) const {
    return static_cast<std::uint32_t>(&l - layouts_.data());
  }

  struct Piece {
    std::uint32_t round_start = kNoWrap;  // the first loop of the last full round
    std::uint32_t on_bed = 0;             // live loops on the bed (every run of the layout)
    // The places in their join of the runs cast on so far (the leftmost and rightmost).
    std::uint32_t leftmost = kNoWrap, rightmost = 0;
    // The last cast-on along a split: the loop at the front's left end of the branch right of
    // the crotch, which the emitter lays out where the crotch's sts change beds (the first
    // side's loop just after that place when the first side is right, the other side's just
    // before it when the first side is left). When the branch knit first takes the round's
    // start with it (it is the left one), the other's rounds start there.
    std::array<std::uint32_t, 2> right_branch_start{kNoWrap, kNoWrap};
  };

  // Pieces knit apart and bound off together (a thumb's inner arc and the hand's) share the
  // bed: the piece cast on later goes beside the one cast on before, on the side its needle
  // holds in the bind-off (the first needle's left of the second's), and waits there knit
  // until the chain takes both.
  void place_bound_off_together(const Step& step) {
    std::uint32_t first = p_.segments[step.reads.begin].run.index();
    bool apart = false;
    for (std::uint32_t i = step.reads.begin; i < step.reads.end; ++i)
      apart |= root(p_.segments[i].run.index()) != root(first);
    if (!apart) return;  // a tube folded flat, or a piece and the yarn knit on from it
    for (std::uint32_t i = step.reads.begin; i < step.reads.end; ++i) {
      std::uint32_t run = p_.segments[i].run.index();
      unite(run, first);
      for (; run != kNoWrap; run = split_from_[run])
        if (join_place_[run] == kNoWrap) join_place_[run] = i - step.reads.begin;
    }
  }

  // The run a run is joined into at last (runs that a join takes share a layout).
  std::uint32_t root(std::uint32_t run) {
    while (joined_to_[run] != run) run = joined_to_[run] = joined_to_[joined_to_[run]];
    return run;
  }
  void unite(std::uint32_t run, std::uint32_t into) { joined_to_[root(run)] = root(into); }

  // A piece cast on while loops wait on the bed (a flap, a leg) goes left of them when the join
  // takes it before every run cast on so far, right of them when after; between them there is
  // no room. Tubes must be of one kind: a sheet beside a tube would need a layout of both.
  Beside side_of(const Step& step, const CourseLayout& l, Piece& piece, StitchId at) {
    std::uint32_t place = join_place_[step.run.index()];
    if (place == kNoWrap)
      unsupported(g_, "a piece cast on while another waits on the bed, which no course joins", at);
    if ((step.run_shape == RunShape::ring) != l.tube)
      unsupported(g_, "a sheet and a tube cast on side by side on the bed", at);
    if (place < piece.leftmost) return piece.leftmost = place, Beside::left;
    if (place > piece.rightmost) return piece.rightmost = place, Beside::right;
    unsupported(
        g_, fmt::format("a {} cast on between two pieces on the bed", l.tube ? "tube" : "sheet"),
        at);
  }

  // Runs taken up by one course become one (flaps into a sheet): the program's join, on the
  // lowering's list of live loops. The course after it knits across the pieces.
  void join(const Step& step) {
    note_arc_ends(step);
    for (std::uint32_t i = step.reads.begin; i < step.reads.end; ++i)
      turn_outer_arc_away(p_.segments[i]);
    for (std::uint32_t i = step.reads.begin; i < step.reads.end; ++i) {
      const Segment& seg = p_.segments[i];
      // Tubes side by side (legs) join where the round goes once round each of them: a tube's
      // loops taken in two places would put one leg between the halves of the other.
      bool whole_ring = seg.walk == Walk::forward && seg.count == runs_.size(seg.run);
      if (runs_.shape(seg.run) == RunShape::ring && !whole_ring)
        unsupported(g_,
                    "tubes joined on the bed by a round that takes one tube's loops in two "
                    "places (a thumb into a hand)",
                    first_stitch(step));
      runs_.open_at(seg.run, seg.first);
      if (i > step.reads.begin) runs_.append(step.run, seg.run);
    }
  }

  // A tube cast on beside another (a leg) is laid out from its cast-on turned so that the arc
  // the join takes (its outer arc) goes round its far fold, the right one when it lies right of
  // the others: the join's round then goes round the legs one way, and the arc it leaves (the
  // crotch) faces the other leg. The arc's middle loop is followed down its wales to the cast-on.
  void turn_outer_arc_away(const Segment& seg) {
    std::uint32_t run = seg.run.index();
    while (run != kNoWrap && !beside_cast_on_.count(run)) run = split_from_[run];
    if (run == kNoWrap) return;
    auto [layout, index] = beside_cast_on_[run];
    Course& c = layouts_[layout].courses[index];
    std::uint32_t middle = seg.first;
    for (std::uint32_t n = 0; n < seg.count / 2; ++n)
      middle = seg.walk == Walk::forward ? runs_.next(middle) : runs_.prev(middle);
    StitchId s = g_.loops[middle].maker;
    while (g_.type[s] != StitchType::co && !g_.loops_taken_by(s).empty())
      s = g_.loops[g_.loops_taken_by(s)[0]].maker;
    const CourseLayout& l = layouts_[layout];
    std::uint32_t n = c.end - c.begin, j = n;
    for (std::uint32_t i = c.begin; i < c.end; ++i)
      if (l.order[i] == s) j = c.left_to_right ? i - c.begin : c.end - 1 - i;
    if (j == n) return;  // the arc's wale does not reach the cast-on: left as it is
    // The left fold is where the layout starts (and ends), the right one half way round.
    c.layout_start = c.beside == Beside::right ? (j + n - n / 2) % n : j;
    beside_cast_on_.erase(run);
  }

  // A join that takes the first side of a cast-on along a split closes the first branch's ring
  // with it: the branch's loops before and after it are where the crotch is cast on.
  void note_arc_ends(const Step& step) {
    std::uint32_t n = step.reads.size();
    for (std::uint32_t i = 0; i < n; ++i) {
      auto crotch = crotch_course_.find(p_.segments[step.reads.begin + i].run.index());
      if (crotch == crotch_course_.end()) continue;
      const Segment& before = p_.segments[step.reads.begin + (i + n - 1) % n];
      const Segment& after = p_.segments[step.reads.begin + (i + 1) % n];
      Course& c = layouts_[crotch->second.first].courses[crotch->second.second];
      c.arc_end = runs_.walk_end(before);
      c.arc_start = after.first;
      crotch_course_.erase(crotch);
    }
  }

  void take_step(const Step& step) {
    switch (step.kind) {
      case StepKind::cast_on:
        return add_course(step);
      case StepKind::split:  // the branches are knit where their loops wait, in one layout
        note_whether_alone(p_.segments[step.reads.begin]);
        return runs_.cut(p_.segments[step.reads.begin], step.run, step.other);
      case StepKind::reverse:
        return runs_.reverse(step.run);
      case StepKind::course:
      case StepKind::bind_off:
        check_binds_off_once(step);
        return add_course(step);
      case StepKind::join:
        return join(step);
      case StepKind::three_needle_bind_off:
        return add_three_needle_bind_off(step);
      case StepKind::hold:
      case StepKind::resume:
        return;  // pieces apart are knit one after another
    }
  }

  // A course that binds off in two places parts its run into two lines (`other`): two runs on
  // the bed.
  void check_binds_off_once(const Step& step) const {
    if (step.other.valid() && !casts_on_along_split(step))
      unsupported(g_, "a course that binds off its run in two places (several runs on the bed)",
                  first_stitch(step));
  }

  // A cast-on along a split is followed by the split that parts the tube: the crotch may roll
  // the tube when the tube and the crotch's loops (those in runs of their own) are all that
  // is on its layout's bed (no branch of an earlier crotch waits beside it).
  void note_whether_alone(const Segment& seg) {
    if (!crotch_alone_) return;
    const PendingCrotch& k = *crotch_alone_;
    layouts_[k.layout].courses[k.course].alone =
        runs_.size(seg.run) + k.own_loops == pieces_[k.layout].on_bed;
    crotch_alone_.reset();
  }

  StitchId first_stitch(const Step& step) const {
    if (step.stitches.size()) return p_.stitches[step.stitches.begin].stitch;
    const Segment& seg = p_.segments[step.reads.begin];
    return g_.loops[seg.first].taker;
  }

  // The loops a course leaves in its run (or on the other side of a split), in run order.
  std::vector<std::uint32_t> left_in_run(Range stitches, bool left_to_right,
                                         LoopPlace place = LoopPlace::in_run) const {
    std::vector<std::uint32_t> loops;
    auto add = [&](std::uint32_t i) {
      for (std::uint32_t k = p_.made_at[i]; k < p_.made_at[i + 1]; ++k)
        if (p_.made[k].place == place) loops.push_back(p_.made[k].loop);
    };
    if (left_to_right)
      for (std::uint32_t i = stitches.begin; i < stitches.end; ++i) add(i);
    else
      for (std::uint32_t i = stitches.end; i-- > stitches.begin;) add(i);
    return loops;
  }

  // A yarn that casts on starts a layout; a yarn that starts on loops on the bed (a leg
  // knit on after the other's, as AutoKnit's test-C) joins the layout of the yarn that made
  // them: the pieces share the bed, each with its carrier. A course that takes loops of
  // another layout would join two pieces on the bed (a join step, refused before).
  std::uint32_t layout_of(const Step& step, StitchId at) {
    bool cast_on = step.kind == StepKind::cast_on;
    std::uint32_t& mine = layout_of_[step.yarn];
    if (cast_on) {
      std::uint32_t& group = layout_of_group_[root(step.run.index())];
      bool along_split = step.other.valid() && group != 0;  // in the tube it parts
      if (mine != kNoWrap && !(along_split && mine == group - 1))
        unsupported(g_, "a second cast-on in one yarn piece", at);
      if (group == 0) {
        layouts_.emplace_back();
        pieces_.emplace_back();
        group = static_cast<std::uint32_t>(layouts_.size());
      }
      return mine = group - 1;
    }
    const Segment& seg = p_.segments[step.reads.begin];
    std::uint32_t theirs = layout_of_[yarns_.piece_of[g_.loops[seg.first].maker]];
    if (mine == kNoWrap) mine = theirs;
    if (mine != theirs)
      unsupported(g_,
                  fmt::format("pieces joined on the bed (yarn {} takes loops of another piece, as "
                              "a sweater's yoke takes its sleeves)",
                              step.yarn + 1),
                  at);
    return mine;
  }

  // A course that binds off some of its stitches is knit as blocks: the machine's bind-off is
  // a chain of its own, so each run of bind-offs (and each run of other stitches) along the
  // yarn is a course here, taking its loops from the run in place.
  void add_course(const Step& step) {
    StitchId first = first_stitch(step);
    bool cast_on = step.kind == StepKind::cast_on;
    std::uint32_t index = layout_of(step, first);
    CourseLayout& l = layouts_[index];
    Piece& piece = pieces_[index];
    bool left_to_right = step.direction != CourseDirection::right_to_left;
    if (cast_on && step.other.valid() && !l.courses.empty())
      return add_along_split(step, l, piece, left_to_right);
    if (!cast_on && step.other.valid()) return add_round_along_split(step, l, piece, left_to_right);
    if (cast_on) {
      std::vector<std::uint32_t> left = left_in_run(step.stitches, left_to_right);
      Beside beside = Beside::none;
      if (l.courses.empty())
        piece.leftmost = piece.rightmost = join_place_[step.run.index()];
      else
        beside = side_of(step, l, piece, first);
      l.tube = step.run_shape == RunShape::ring;
      runs_.start(step.run, left, step.run_shape);
      // The joined tube's rounds start where the leftmost tube's do (at the front's left end).
      if (beside != Beside::right) piece.round_start = left.empty() ? kNoWrap : left.front();
      piece.on_bed += static_cast<std::uint32_t>(left.size());
      Course& course = l.courses.emplace_back(append(l, step.stitches, left_to_right));
      course.cast_on = true;
      course.beside = beside;
      if (l.tube && beside != Beside::none)
        beside_cast_on_[step.run.index()] = {index,
                                             static_cast<std::uint32_t>(l.courses.size() - 1)};
      return;
    }
    bool second_taken = false;
    for (std::uint32_t begin = step.stitches.begin; begin < step.stitches.end;) {
      std::uint32_t end = begin + 1;
      BlockKind kind = block_kind(p_.stitches[begin].stitch);
      while (end < step.stitches.end && block_kind(p_.stitches[end].stitch) == kind) ++end;
      if (kind == BlockKind::bound_off_together) {
        // The second needle's loops all go with the one block (the program reads them as
        // one walk per needle, in the course's order).
        if (second_taken)
          unsupported(g_, "a row that binds off with a second needle's in two places",
                      p_.stitches[begin].stitch);
        take_second_needles(step, piece);
        second_taken = true;
      }
      add_block(l, piece, {begin, end}, left_to_right, step.shape);
      begin = end;
    }
  }

  // A course's blocks: sts knit on, bound off, or bound off with a second needle's loops.
  enum class BlockKind : std::uint8_t { knit, bound_off, bound_off_together };
  BlockKind block_kind(StitchId s) const {
    return g_.type[s] == StitchType::tnbo ? BlockKind::bound_off_together
           : is_bind_off(g_, s)           ? BlockKind::bound_off
                                          : BlockKind::knit;
  }

  // A three-needle bind-off takes the second needle's loops off the bed with the chain.
  void take_second_needles(const Step& step, Piece& piece) {
    for (std::uint32_t i = step.reads.begin + 1; i < step.reads.end; ++i)
      take_off(p_.segments[i], piece);
  }
  void take_off(Segment seg, Piece& piece) {
    if (seg.walk == Walk::backward) seg.first = runs_.walk_end(seg);
    seg.walk = Walk::forward;
    piece.on_bed -= seg.count;
    runs_.replace(seg, {}, RowShape::short_row, runs_.leaves_tail(seg) ? tail_run() : RunId());
  }

  // A three-needle bind-off: a chain whose sts each take a loop of the run worked and one of
  // the second needle's run (the emitter lands that one on the first's needle). Both runs
  // must wait on the bed in this layout (a tube's two halves folded together, a piece and
  // the yarn knit on from its sts); each second loop lies where the course meets it. A course
  // that knits some of its sts (a thumb's round binding off its inner arc with the hand's) is
  // knit as blocks, as a course that binds off some of its sts.
  void add_three_needle_bind_off(const Step& step) {
    StitchId first = first_stitch(step);
    std::uint32_t index = layout_of(step, first);
    CourseLayout& l = layouts_[index];
    for (std::uint32_t i = step.reads.begin; i < step.reads.end; ++i) {
      const Segment& seg = p_.segments[i];
      StitchId maker = g_.loops[seg.first].maker;
      if (layout_of_[yarns_.piece_of[maker]] != index)
        unsupported(g_,
                    fmt::format("a three-needle bind-off of two pieces knit apart (the loops of {} "
                                "are not on the bed with those of {})",
                                g_.describe(maker),
                                g_.describe(g_.loops[p_.segments[step.reads.begin].first].maker)),
                    first);
    }
    for (std::uint32_t i = step.stitches.begin; i < step.stitches.end; ++i)
      if (g_.type[p_.stitches[i].stitch] != StitchType::tnbo) {
        if (casts_on_along_split(step))
          unsupported(g_, "a round that casts on along a split and binds off with a second needle",
                      first);
        check_binds_off_once(step);
        return add_course(step);
      }
    Piece& piece = pieces_[index];
    for (std::uint32_t i = step.reads.begin; i < step.reads.end; ++i)
      take_off(p_.segments[i], piece);
    bool left_to_right = step.direction != CourseDirection::right_to_left;
    if (continues_chain(l, step.stitches)) {
      l.courses.back().end = append(l, step.stitches, left_to_right).end;
      return;
    }
    Course& course = l.courses.emplace_back(append(l, step.stitches, left_to_right));
    course.partial = piece.on_bed > 0;
  }

  // A cast-on along a split: its two sides are runs of their own, the first taken by the join
  // that closes the first branch (which says where its arc ends), the other by the second's.
  void add_along_split(const Step& step, CourseLayout& l, Piece& piece, bool left_to_right) {
    if (!l.tube) unsupported(g_, "a cast-on along a split of a sheet", first_stitch(step));
    std::vector<std::uint32_t> first = left_in_run(step.stitches, left_to_right, LoopPlace::in_run),
                               second =
                                   left_in_run(step.stitches, left_to_right, LoopPlace::other_side);
    runs_.start(step.run, first, RunShape::line);
    runs_.start(step.other, second, RunShape::line);
    piece.on_bed += static_cast<std::uint32_t>(first.size() + second.size());
    note_right_branch_starts(piece, first, second);
    Course& course = l.courses.emplace_back(append(l, step.stitches, left_to_right));
    course.along_split = true;
    crotch_alone_ = PendingCrotch{index_of(l), static_cast<std::uint32_t>(l.courses.size() - 1),
                                  static_cast<std::uint32_t>(first.size() + second.size())};
    crotch_course_[step.run.index()] = {index_of(l),
                                        static_cast<std::uint32_t>(l.courses.size() - 1)};
  }

  static void note_right_branch_starts(Piece& piece, const std::vector<std::uint32_t>& first,
                                       const std::vector<std::uint32_t>& second) {
    auto k = crotch_sts_on_end_bed(static_cast<std::uint32_t>(first.size()));
    piece.right_branch_start = {k < first.size() ? first[k] : kNoWrap, second[k - 1]};
  }

  bool is_sco(std::uint32_t worked) const {
    return g_.type[p_.stitches[worked].stitch] == StitchType::sco;
  }
  bool casts_on_along_split(const Step& step) const {
    for (std::uint32_t i = step.stitches.begin; i < step.stitches.end; ++i)
      if (is_sco(i)) return true;
    return false;
  }

  // A round of a branch worked with the yarn of the round (own yarn) that casts on along the
  // split as it goes: its sts over the branch's arc are knit where their loops wait, its sco
  // sts cast on as a course of their own between the branches. The arc's ends are the loops
  // beside them in the branch's ring (a loop made after them by the loop it is knit from).
  void add_round_along_split(const Step& step, CourseLayout& l, Piece& piece, bool left_to_right) {
    if (!l.tube) unsupported(g_, "a cast-on along a split of a sheet", first_stitch(step));
    Segment seg = segment_of(step.stitches, left_to_right);
    std::vector<std::uint32_t> left = left_in_run(step.stitches, left_to_right, LoopPlace::in_run),
                               second =
                                   left_in_run(step.stitches, left_to_right, LoopPlace::other_side);
    for (std::uint32_t loop = seg.first, n = 0; n < seg.count; ++n, loop = runs_.next(loop))
      if (loop == piece.round_start) piece.round_start = kNoWrap;  // the branch takes it along
    piece.on_bed += static_cast<std::uint32_t>(left.size() + second.size()) - seg.count;
    runs_.replace(seg, left, step.shape);
    runs_.start(step.other, second, RunShape::line);
    std::vector<std::uint32_t> first;  // the sco sts' loops on the first side
    for (std::uint32_t loop : left)
      if (g_.type[g_.loops[loop].maker] == StitchType::sco) first.push_back(loop);
    note_right_branch_starts(piece, first, second);
    std::uint32_t crotch = kNoWrap;
    Range sco;
    for (std::uint32_t begin = step.stitches.begin; begin < step.stitches.end;) {
      std::uint32_t end = begin + 1;
      while (end < step.stitches.end && is_sco(end) == is_sco(begin)) ++end;
      Course& course = l.courses.emplace_back(append(l, {begin, end}, left_to_right));
      course.partial = true;
      course.along_split = is_sco(begin);
      if (course.along_split) {
        if (crotch != kNoWrap)
          unsupported(g_, "a round that casts on along a split twice", first_stitch(step));
        crotch = static_cast<std::uint32_t>(l.courses.size() - 1);
        sco = {begin, end};
      }
      begin = end;
    }
    crotch_alone_ = PendingCrotch{index_of(l), crotch, static_cast<std::uint32_t>(second.size())};
    note_arc_ends_in_round(l.courses[crotch], sco, left);
  }
  void note_arc_ends_in_round(Course& c, Range sco, const std::vector<std::uint32_t>& ring) const {
    auto n = static_cast<std::uint32_t>(ring.size());
    std::uint32_t first = 0, last = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
      StitchId maker = g_.loops[ring[i]].maker;
      if (g_.type[maker] != StitchType::sco) continue;
      if (g_.type[g_.loops[ring[(i + n - 1) % n]].maker] != StitchType::sco) first = i;
      if (g_.type[g_.loops[ring[(i + 1) % n]].maker] != StitchType::sco) last = i;
    }
    c.arc_end = where_it_waits(ring[(first + n - 1) % n], sco);
    c.arc_start = where_it_waits(ring[(last + 1) % n], sco);
  }
  // A loop the round makes after its sco sts is not on the bed when they are cast on: the loop
  // it is knit from waits where it will be.
  std::uint32_t where_it_waits(std::uint32_t loop, Range crotch) const {
    StitchId maker = g_.loops[loop].maker;
    if (p_.worked_at[maker] < crotch.end) return loop;
    auto taken = g_.loops_taken_by(maker);
    return taken.empty() ? loop : taken[stacking_order(g_.type[maker])[0]];
  }

  Course append(CourseLayout& l, Range stitches, bool left_to_right) const {
    Course course;
    course.row = g_.row[p_.stitches[stitches.begin].stitch];
    course.begin = static_cast<std::uint32_t>(l.order.size());
    for (std::uint32_t i = stitches.begin; i < stitches.end; ++i)
      l.order.push_back(p_.stitches[i].stitch);
    course.end = static_cast<std::uint32_t>(l.order.size());
    course.left_to_right = left_to_right;
    course.yarn = yarns_.piece_of[p_.stitches[stitches.begin].stitch];
    return course;
  }

  // The loops a block of a course takes, as a forward segment of their run (a three-needle
  // bind-off's first needle's: each st's first loop).
  Segment segment_of(Range stitches, bool left_to_right) const {
    std::uint32_t count = 0;
    for (std::uint32_t i = stitches.begin; i < stitches.end; ++i)
      count += g_.type[p_.stitches[i].stitch] == StitchType::tnbo ? 1 : p_.stitches[i].taken;
    std::uint32_t leftmost = left_to_right ? stitches.begin : stitches.end - 1;
    std::uint32_t first = p_.taken[p_.taken_at[leftmost]];
    return {runs_.run_of(first), first, count, Walk::forward};
  }

  void add_block(CourseLayout& l, Piece& piece, Range stitches, bool left_to_right,
                 RowShape shape) {
    Segment seg = segment_of(stitches, left_to_right);
    std::vector<std::uint32_t> left = left_in_run(stitches, left_to_right);
    bool whole = seg.count == runs_.size(seg.run);
    bool others_wait = piece.on_bed > runs_.size(seg.run);  // another piece's loops
    piece.on_bed = piece.on_bed + static_cast<std::uint32_t>(left.size()) - seg.count;
    // A branch's round (others wait) takes the round's start only where it holds that loop.
    bool takes_start = whole && !others_wait;
    if (l.tube && piece.round_start == kNoWrap && takes_start) {
      piece.round_start = seg.first;
      for (std::uint32_t loop : piece.right_branch_start)
        if (loop != kNoWrap && runs_.run_of(loop) == seg.run) piece.round_start = loop;
    }
    for (std::uint32_t loop = seg.first, n = 0; n < seg.count; ++n, loop = runs_.next(loop))
      takes_start |= loop == piece.round_start;
    RunId tail = runs_.leaves_tail(seg) && left.empty() ? tail_run() : RunId();
    if (continues_chain(l, stitches)) {  // the chain goes on into this course's bind-offs
      runs_.replace(seg, left, shape, tail);
      l.courses.back().end = append(l, stitches, left_to_right).end;
      return;
    }
    Course& course = l.courses.emplace_back(append(l, stitches, left_to_right));
    course.partial = !whole || others_wait;
    course.rotated = l.tube && whole && !others_wait && seg.first != piece.round_start;
    if (course.rotated)
      course.layout_start = taker_of_round_start(g_, l, course, piece.round_start);
    std::uint32_t before = whole ? kNoWrap : runs_.prev(seg.first);
    std::uint32_t after = whole ? kNoWrap : runs_.next(runs_.walk_end(seg));
    runs_.replace(seg, left, shape, tail);
    if (takes_start) piece.round_start = left.empty() ? after : new_round_start(piece, course);
    StitchId last = l.order[course.end - 1];
    bool turns_next = g_.yarn_link[last] == YarnLink::turn && g_.yarn_next[last] != kNoStitch;
    if (course.partial && turns_next && !left.empty())
      turns_.push_back({index_of(l), static_cast<std::uint32_t>(l.courses.size() - 1), last,
                        left_to_right ? after : before});
  }

  // A block of bind-offs straight after the bind-offs that ended the course before, along the
  // yarn (a stitch graph's helix may step up inside a bind-off): one chain, one course.
  bool continues_chain(const CourseLayout& l, Range stitches) const {
    StitchId s = p_.stitches[stitches.begin].stitch;
    if (!is_bind_off(g_, s) || l.courses.empty()) return false;
    StitchId last = l.order[l.courses.back().end - 1];
    return is_bind_off(g_, last) && g_.yarn_next[last] == s;
  }

  // A run for the loops beyond a bind-off in the middle of a line (numbered after the
  // program's, which the target never meets again).
  RunId tail_run() { return RunId(static_cast<std::uint32_t>(p_.runs.size() + tails_++)); }

  // The round's start moves to the loop made at its place: the leftmost loop of the stitch
  // that takes it (an sr5's own loop, not its turn loop), which is knit where the start was.
  std::uint32_t new_round_start(const Piece& piece, const Course& c) const {
    StitchId taker = g_.loops[piece.round_start].taker;
    auto made = g_.loops_made_by(taker);
    if (made.empty()) return piece.round_start;
    bool sr5 = g_.type[taker] == StitchType::sr5;
    return made[sr5 ? knit_slot(StitchType::sr5, c.left_to_right) : 0];
  }

  void finish(std::uint32_t index) {
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
  void wrap_turns(std::uint32_t index) {
    CourseLayout& l = layouts_[index];
    std::vector<std::uint32_t> course_of(g_.size(), kNoWrap);
    for (std::uint32_t i = 0; i < l.courses.size(); ++i)
      for (std::uint32_t k = l.courses[i].begin; k < l.courses[i].end; ++k)
        course_of[l.order[k]] = i;
    for (const Turn& t : turns_) {
      if (t.layout != index) continue;
      std::uint32_t across = t.beyond == kNoWrap ? kNoWrap : course_of[g_.loops[t.beyond].taker];
      if (across != kNoWrap && l.courses[across].yarn == l.courses[t.course].yarn &&
          takes_loops_made_since(l, l.courses[across], t.course, course_of))
        choose_wrap(g_, t.turning, t.beyond, l.courses[t.course], wrapped_);
    }
  }
  bool takes_loops_made_since(const CourseLayout& l, const Course& c, std::uint32_t since,
                              const std::vector<std::uint32_t>& course_of) const {
    for (std::uint32_t k = c.begin; k < c.end; ++k)
      for (std::uint32_t loop : g_.loops_taken_by(l.order[k])) {
        std::uint32_t made_in = course_of[g_.loops[loop].maker];
        if (made_in != kNoWrap && made_in >= since) return true;
      }
    return false;
  }

  // Each yarn's first and last course in the layout.
  void mark_yarn_ends(CourseLayout& l) const {
    std::vector<std::uint32_t> last(yarns_.size(), kNoWrap);
    for (std::uint32_t i = 0; i < l.courses.size(); ++i) {
      Course& c = l.courses[i];
      c.first_of_yarn = last[c.yarn] == kNoWrap;
      last[c.yarn] = i;
    }
    for (std::uint32_t i : last)
      if (i != kNoWrap) l.courses[i].last_of_yarn = true;
  }

  const KnitGraph& g_;
  const Program& p_;
  const YarnPieces& yarns_;
  LiveRuns runs_;
  std::vector<std::uint32_t> layout_of_;  // per yarn piece: its layout (kNoWrap: none yet)
  std::vector<CourseLayout> layouts_;
  std::vector<Piece> pieces_;              // per layout
  std::vector<std::uint8_t> wrapped_;      // per loop: a short row's turn wraps it
  std::vector<Turn> turns_;                // in knitting order
  std::vector<std::uint32_t> joined_to_;   // per run of the program: a run it is joined into
  std::vector<std::uint32_t> join_place_;  // per run: its place in the first join taking it
  std::vector<std::uint32_t> split_from_;  // per run: the run it was split off (kNoWrap: none)
  std::unordered_map<std::uint32_t, std::uint32_t> layout_of_group_;  // root run -> layout + 1
  // Per tube cast on beside others, until the join that takes it: its layout and course.
  std::unordered_map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> beside_cast_on_;
  // Per first side of a cast-on along a split not yet joined: its layout and course.
  std::unordered_map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> crotch_course_;
  std::uint32_t tails_ = 0;
  // The last cast-on along a split, until the split after it: its layout, course, and the
  // loops it put in runs of their own.
  struct PendingCrotch {
    std::uint32_t layout, course, own_loops;
  };
  std::optional<PendingCrotch> crotch_alone_;
};

}  // namespace

std::vector<CourseLayout> lay_out_pieces(const Compilation& c) {
  const KnitGraph& g = c.knit;
  if (g.size() == 0) throw Error("the model has no stitches: nothing to knit");
  check_stitches(g);
  for (std::uint32_t piece = 0; piece < c.yarns.size(); ++piece)
    if (c.yarns.ring[piece]) unsupported(g, "a yarn that closes on itself", c.yarns.first[piece]);
  if (!c.program.complete())
    unsupported(g, fmt::format("a course the lowering could not lower ({})", c.program.gap->why),
                c.program.gap->stitch);
  return ProgramLayouts(c).run();
}

}  // namespace skein::knitout
