// Following the live-loop program: each step taken in turn, courses and their blocks laid out
// (program_layouts.hpp says how the work is split).
#include "knitout/program_layouts.hpp"

#include <fmt/format.h>

#include "common/error.hpp"
#include "knitout/stitch_recipes.hpp"

namespace skein::knitout::layout {

ProgramLayouts::ProgramLayouts(const Compilation& c)
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

void ProgramLayouts::take_step(const Step& step) {
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
void ProgramLayouts::check_binds_off_once(const Step& step) const {
  if (step.other.valid() && !casts_on_along_split(step))
    unsupported(g_, "a course that binds off its run in two places (several runs on the bed)",
                first_stitch(step));
}

StitchId ProgramLayouts::first_stitch(const Step& step) const {
  if (step.stitches.size()) return p_.stitches[step.stitches.begin].stitch;
  const Segment& seg = p_.segments[step.reads.begin];
  return g_.loops[seg.first].taker;
}

// The loops a course leaves in its run (or on the other side of a split), in run order.
std::vector<std::uint32_t> ProgramLayouts::left_in_run(Range stitches, bool left_to_right,
                                                       LoopPlace place) const {
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
std::uint32_t ProgramLayouts::layout_of(const Step& step, StitchId at) {
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
void ProgramLayouts::add_course(const Step& step) {
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
      beside_cast_on_[step.run.index()] = {index, static_cast<std::uint32_t>(l.courses.size() - 1)};
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

ProgramLayouts::BlockKind ProgramLayouts::block_kind(StitchId s) const {
  return g_.type[s] == StitchType::tnbo ? BlockKind::bound_off_together
         : is_bind_off(g_, s)           ? BlockKind::bound_off
                                        : BlockKind::knit;
}

// A three-needle bind-off takes the second needle's loops off the bed with the chain.
void ProgramLayouts::take_second_needles(const Step& step, Piece& piece) {
  for (std::uint32_t i = step.reads.begin + 1; i < step.reads.end; ++i)
    take_off(p_.segments[i], piece);
}

void ProgramLayouts::take_off(Segment seg, Piece& piece) {
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
void ProgramLayouts::add_three_needle_bind_off(const Step& step) {
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
  for (std::uint32_t i = step.reads.begin; i < step.reads.end; ++i) take_off(p_.segments[i], piece);
  bool left_to_right = step.direction != CourseDirection::right_to_left;
  if (continues_chain(l, step.stitches)) {
    l.courses.back().end = append(l, step.stitches, left_to_right).end;
    return;
  }
  Course& course = l.courses.emplace_back(append(l, step.stitches, left_to_right));
  course.partial = piece.on_bed > 0;
}

Course ProgramLayouts::append(CourseLayout& l, Range stitches, bool left_to_right) const {
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
Segment ProgramLayouts::segment_of(Range stitches, bool left_to_right) const {
  std::uint32_t count = 0;
  for (std::uint32_t i = stitches.begin; i < stitches.end; ++i)
    count += g_.type[p_.stitches[i].stitch] == StitchType::tnbo ? 1 : p_.stitches[i].taken;
  std::uint32_t leftmost = left_to_right ? stitches.begin : stitches.end - 1;
  std::uint32_t first = p_.taken[p_.taken_at[leftmost]];
  return {runs_.run_of(first), first, count, Walk::forward};
}

void ProgramLayouts::add_block(CourseLayout& l, Piece& piece, Range stitches, bool left_to_right,
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
  if (course.rotated) course.layout_start = taker_of_round_start(g_, l, course, piece.round_start);
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
bool ProgramLayouts::continues_chain(const CourseLayout& l, Range stitches) const {
  StitchId s = p_.stitches[stitches.begin].stitch;
  if (!is_bind_off(g_, s) || l.courses.empty()) return false;
  StitchId last = l.order[l.courses.back().end - 1];
  return is_bind_off(g_, last) && g_.yarn_next[last] == s;
}

// The round's start moves to the loop made at its place: the leftmost loop of the stitch
// that takes it (an sr5's own loop, not its turn loop), which is knit where the start was.
std::uint32_t ProgramLayouts::new_round_start(const Piece& piece, const Course& c) const {
  StitchId taker = g_.loops[piece.round_start].taker;
  auto made = g_.loops_made_by(taker);
  if (made.empty()) return piece.round_start;
  bool sr5 = g_.type[taker] == StitchType::sr5;
  return made[sr5 ? knit_slot(StitchType::sr5, c.left_to_right) : 0];
}

}  // namespace skein::knitout::layout

namespace skein::knitout {

std::vector<CourseLayout> lay_out_pieces(const Compilation& c) {
  const KnitGraph& g = c.knit;
  if (g.size() == 0) throw Error("the model has no stitches: nothing to knit");
  layout::check_stitches(g);
  for (std::uint32_t piece = 0; piece < c.yarns.size(); ++piece)
    if (c.yarns.ring[piece])
      layout::unsupported(g, "a yarn that closes on itself", c.yarns.first[piece]);
  if (!c.program.complete())
    layout::unsupported(
        g, fmt::format("a course the lowering could not lower ({})", c.program.gap->why),
        c.program.gap->stitch);
  return layout::ProgramLayouts(c).run();
}

}  // namespace skein::knitout
