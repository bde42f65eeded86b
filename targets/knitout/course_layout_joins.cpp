// Pieces on one bed: runs joined by a course, pieces bound off together, pieces cast on
// beside the loops on the bed (program_layouts.hpp).
#include "knitout/program_layouts.hpp"

#include <fmt/format.h>

#include "common/error.hpp"

namespace skein::knitout::layout {

// Pieces knit apart and bound off together (a thumb's inner arc and the hand's) share the
// bed: the piece cast on later goes beside the one cast on before, on the side its needle
// holds in the bind-off (the first needle's left of the second's), and waits there knit
// until the chain takes both.
void ProgramLayouts::place_bound_off_together(const Step& step) {
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
std::uint32_t ProgramLayouts::root(std::uint32_t run) {
  while (joined_to_[run] != run) run = joined_to_[run] = joined_to_[joined_to_[run]];
  return run;
}

// A piece cast on while loops wait on the bed (a flap, a leg) goes left of them when the join
// takes it before every run cast on so far, right of them when after; between them there is
// no room. Tubes must be of one kind: a sheet beside a tube would need a layout of both.
Beside ProgramLayouts::side_of(const Step& step, const CourseLayout& l, Piece& piece, StitchId at) {
  std::uint32_t place = join_place_[step.run.index()];
  if (place == kNoWrap)
    unsupported(g_, "a piece cast on while another waits on the bed, which no course joins", at);
  if ((step.run_shape == RunShape::ring) != l.tube)
    unsupported(g_, "a sheet and a tube cast on side by side on the bed", at);
  if (place < piece.leftmost) return piece.leftmost = place, Beside::left;
  if (place > piece.rightmost) return piece.rightmost = place, Beside::right;
  unsupported(
      g_, fmt::format("a {} cast on between two pieces on the bed", l.tube ? "tube" : "sheet"), at);
}

// Runs taken up by one course become one (flaps into a sheet): the program's join, on the
// lowering's list of live loops. The course after it knits across the pieces.
void ProgramLayouts::join(const Step& step) {
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
void ProgramLayouts::turn_outer_arc_away(const Segment& seg) {
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
void ProgramLayouts::note_arc_ends(const Step& step) {
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

}  // namespace skein::knitout::layout
