// Casts-on along a split: a tube parting into branches, the crotch cast on between them
// (program_layouts.hpp).
#include "knitout/program_layouts.hpp"

#include "knitout/stitch_recipes.hpp"

namespace skein::knitout::layout {

// A cast-on along a split is followed by the split that parts the tube: the crotch may roll
// the tube when the tube and the crotch's loops (those in runs of their own) are all that
// is on its layout's bed (no branch of an earlier crotch waits beside it).
void ProgramLayouts::note_whether_alone(const Segment& seg) {
  if (!crotch_alone_) return;
  const PendingCrotch& k = *crotch_alone_;
  layouts_[k.layout].courses[k.course].alone =
      runs_.size(seg.run) + k.own_loops == pieces_[k.layout].on_bed;
  crotch_alone_.reset();
}

// A cast-on along a split: its two sides are runs of their own, the first taken by the join
// that closes the first branch (which says where its arc ends), the other by the second's.
void ProgramLayouts::add_along_split(const Step& step, CourseLayout& l, Piece& piece,
                                     bool left_to_right) {
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

void ProgramLayouts::note_right_branch_starts(Piece& piece, const std::vector<std::uint32_t>& first,
                                              const std::vector<std::uint32_t>& second) {
  auto k = crotch_sts_on_end_bed(static_cast<std::uint32_t>(first.size()));
  piece.right_branch_start = {k < first.size() ? first[k] : kNoWrap, second[k - 1]};
}

bool ProgramLayouts::is_sco(std::uint32_t worked) const {
  return g_.type[p_.stitches[worked].stitch] == StitchType::sco;
}

bool ProgramLayouts::casts_on_along_split(const Step& step) const {
  for (std::uint32_t i = step.stitches.begin; i < step.stitches.end; ++i)
    if (is_sco(i)) return true;
  return false;
}

// A round of a branch worked with the yarn of the round (own yarn) that casts on along the
// split as it goes: its sts over the branch's arc are knit where their loops wait, its sco
// sts cast on as a course of their own between the branches. The arc's ends are the loops
// beside them in the branch's ring (a loop made after them by the loop it is knit from).
void ProgramLayouts::add_round_along_split(const Step& step, CourseLayout& l, Piece& piece,
                                           bool left_to_right) {
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

void ProgramLayouts::note_arc_ends_in_round(Course& c, Range sco,
                                            const std::vector<std::uint32_t>& ring) const {
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
std::uint32_t ProgramLayouts::where_it_waits(std::uint32_t loop, Range crotch) const {
  StitchId maker = g_.loops[loop].maker;
  if (p_.worked_at[maker] < crotch.end) return loop;
  auto taken = g_.loops_taken_by(maker);
  return taken.empty() ? loop : taken[stacking_order(g_.type[maker])[0]];
}

}  // namespace skein::knitout::layout
