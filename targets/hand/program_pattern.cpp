// The hand pattern built on the lowering's live-loop program (issue 13): runs of live loops
// are mapped onto needles, holders, spare needles and provisional cast-ons' chains; each course
// is a row or a rnd with the side facing that its direction gives (right to left seen from the
// RS: the RS faces the knitter; left to right: the WS), its stitches in the course's working
// order. Nothing here votes on a direction or cuts rows from the schedule. A course that takes
// loops from more than one place gathers them first (slips what it leaves to holders, joins a
// yarn to a holder, places the others into the rnd) and checks the needle then holds its loops
// in the order it meets them. Steps the hand vocabulary cannot say yet are refused by name,
// before any text.
//
// This file: the walk over the program's steps, pieces and their sections, cast-ons and
// three-needle bind-offs; the builder's members and why they are so: program_builder.hpp.
#include "hand/program_pattern.hpp"

#include <algorithm>

#include "hand/marker_plan.hpp"
#include "hand/piece_names.hpp"
#include "hand/program_builder.hpp"
#include "hand/region_markers.hpp"
#include "hand/stitch_working.hpp"

namespace skein::hand {
namespace from_program {

ProgramPatternBuilder::ProgramPatternBuilder(const Compilation& c, const Program& program,
                                             TurnMethod turns, bool mirror)
    : g_(c.knit),
      p_(program),
      places_(c.knit.loops.size()),
      needle_of_yarn_(c.yarns.size(), kNone),
      yarn_of_(c.yarns.piece_of) {
  out_.source = c.input;
  out_.turns = turns;
  out_.mirror = mirror;
  for (const Event& e : c.schedule.events)
    if (e.kind == EventKind::marker && e.marker != MarkerKind::beginning_of_round)
      marked_[e.stitch] = e.marker;
}

HandPattern ProgramPatternBuilder::run() && {
  if (p_.gap)
    unsupported(fmt::format("the live-loop program stops at {}: {}", g_.describe(p_.gap->stitch),
                            p_.gap->why));
  index_loops_met();
  for (step_ = 0; step_ < p_.steps.size(); ++step_) {
    const Step& s = p_.steps[step_];
    switch (s.kind) {
      case StepKind::cast_on:  // one that picks up along an edge is worked as a row
        if (s.picked_up == 0) {
          cast_on(s);
          break;
        }
        [[fallthrough]];
      case StepKind::course:
      case StepKind::bind_off:
        course(s);
        break;
      case StepKind::hold:
        set_aside(s);
        break;
      case StepKind::resume:
        take_up(s);
        break;
      case StepKind::split:  // the loops stay where they are: the course that takes them
      case StepKind::join:   // gathers them
      case StepKind::reverse:
        break;
      case StepKind::three_needle_bind_off:
        three_needle_bind_off(s);
        break;
    }
  }
  end_section();
  return std::move(out_);
}

void ProgramPatternBuilder::not_yet(const Step& s, const std::string& what) const {
  std::string where = s.stitches.size() > 0
                          ? fmt::format(" at {}", g_.describe(p_.stitches[s.stitches.begin].stitch))
                          : "";
  unsupported(fmt::format("step {} ({} of yarn {}{}) {}", step_ + 1, step_kind_name(s.kind),
                          s.yarn + 1, where, what));
}

std::vector<std::uint32_t> ProgramPatternBuilder::loops_met(const Step& s) const {
  std::vector<std::uint32_t> met;
  for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i)
    for_each_met(taken_by(i), s.direction, [&](std::uint32_t l) { met.push_back(l); });
  return met;
}

void ProgramPatternBuilder::end_section(bool set_aside) {
  if (!working()) return;
  Needle& n = needle();
  end_row_the_yarn_leaves();
  PatternSection& sec = section();
  sec.end_row = static_cast<std::uint32_t>(out_.rows.size());
  sec.set_aside = set_aside;
  sec.left_live = !set_aside && n.live != 0;
  sec.live_at_end = n.live;
  std::vector<std::uint32_t> spare = counted_on_spare_needle(n);
  if (sec.left_live) {
    places_.leave(n.section, Place::spare, std::move(spare));
    places_.set(n.ring, {Place::spare, n.section});
  }
  current_ = kNone;
}

void ProgramPatternBuilder::end_row_the_yarn_leaves() {
  // The work turns if the yarn comes back the other way.
  if (!row_open_) return;
  if (!turns_when_taken_up(section().yarn)) out_.ops.push_back(HandOp::no_turn);
  close_ring_row(p_.steps[step_], needle(), true);
}

void ProgramPatternBuilder::start_section(std::uint32_t yarn, std::uint32_t needle_index) {
  end_section();
  bool resumed = needle_index != kNone;
  PatternSection sec;
  if (resumed) {
    const PatternSection& before = out_.sections[needles_[needle_index].section];
    sec.piece = before.piece;
    sec.in_round = before.in_round;
    sec.resumed = true;
    sec.first_number = before.first_number + (before.end_row - before.first_row);
    std::copy(std::begin(before.last_row_ends), std::end(before.last_row_ends), sec.last_row_ends);
  } else {
    sec.piece = ++pieces_;
    needle_index = static_cast<std::uint32_t>(needles_.size());
    needles_.emplace_back();
  }
  sec.yarn = yarn;
  sec.first_row = sec.end_row = static_cast<std::uint32_t>(out_.rows.size());
  out_.sections.push_back(sec);
  current_ = needle_of_yarn_[yarn] = needle_index;
  needle().section = static_cast<std::uint32_t>(out_.sections.size() - 1);
}

bool ProgramPatternBuilder::turns_when_taken_up(std::uint32_t yarn) const {
  const Step* next = next_course_of(yarn);
  return !next || next->direction != row_dir_;
}

const Step* ProgramPatternBuilder::next_course_of(std::uint32_t yarn) const {
  for (std::size_t k = step_ + 1; k < p_.steps.size(); ++k) {
    const Step& next = p_.steps[k];
    bool works = next.kind == StepKind::course || next.kind == StepKind::bind_off ||
                 next.kind == StepKind::three_needle_bind_off;
    if (works && next.yarn == yarn) return &next;
  }
  return nullptr;
}

void ProgramPatternBuilder::set_aside(const Step& s) {
  if (!working() || section().yarn != s.yarn) not_yet(s, "sets aside a yarn not being worked");
  hold_what_others_take(s);
  end_section(true);
}

void ProgramPatternBuilder::hold_what_others_take(const Step& s) {
  Needle& n = needle();
  auto others_take = [&](std::uint32_t l) {
    return taker_step_[l] != kNone && p_.steps[taker_step_[l]].yarn != s.yarn;
  };
  bool worked_here = out_.rows.size() > section().first_row;
  if (!n.in_round || row_open_ || n.gap != 0 || !worked_here ||
      std::none_of(n.ring.begin(), n.ring.end(), others_take))
    return;
  for (std::uint32_t l : n.ring) in_met_[l] = !others_take(l);
  std::vector<std::uint32_t> stay = hold_what_it_leaves(s);
  for (std::uint32_t l : n.ring) in_met_[l] = 0;
  n.ring = std::move(stay);
  n.live = hand_stitch_count(g_, n.ring);
  index_ring(n);
}

void ProgramPatternBuilder::take_up(const Step& s) {
  std::uint32_t n = needle_of_yarn_[s.yarn];
  if (n == kNone || !out_.sections[needles_[n].section].set_aside)
    not_yet(s, "takes up a yarn that was not set aside");
  start_section(s.yarn, n);
}

void ProgramPatternBuilder::cast_on(const Step& s) {
  T type = g_.type[p_.stitches[s.stitches.begin].stitch];
  for (const WorkedStitch& w : stitches_of(s))
    if (g_.type[w.stitch] != type || (type != T::co && type != T::sco))
      not_yet(s, fmt::format("casts on with {}, which the program's pattern builder does not "
                             "write yet",
                             g_.describe(w.stitch)));
  if (needle_of_yarn_[s.yarn] != kNone) return cast_on_aside(s, type == T::sco);
  start_section(s.yarn, kNone);
  auto count = static_cast<std::uint32_t>(s.stitches.size());
  PatternSection& sec = section();
  sec.cast_on = count;
  sec.stitches = count;
  sec.provisional = type == T::sco;
  sec.in_round = s.run_shape == RunShape::ring;
  sec.last_row_ends[0] = p_.stitches[s.stitches.begin].stitch;
  sec.last_row_ends[1] = p_.stitches[s.stitches.end - 1].stitch;
  Needle& n = needle();
  n.live = n.behind = count;
  n.in_round = sec.in_round;
  n.last = n.rnds = s.direction;
  // Joined in the rnd, the first rnd begins with the first st cast on.
  std::vector<std::uint32_t> chain;
  for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i)
    for (const PlacedLoop& m : made_by(i)) {
      if (m.place == LoopPlace::along_edge) {
        note_cast_on_end(p_.stitches[i].stitch, s.direction);
        places_.set({&m.loop, 1}, {Place::edge, n.section});
        continue;
      }
      (m.place == LoopPlace::in_run ? n.ring : chain).push_back(m.loop);
    }
  if (!n.in_round) {  // a line, left to right seen from the RS; the yarn at its end
    if (s.direction == CourseDirection::right_to_left) std::reverse(n.ring.begin(), n.ring.end());
    n.gap = s.direction == CourseDirection::right_to_left ? 0 : count;
  }
  index_ring(n);
  places_.set(n.ring, {Place::needle, current_});
  if (!chain.empty()) places_.leave(n.section, Place::chain, std::move(chain));
}

void ProgramPatternBuilder::cast_on_aside(const Step& s, bool provisional) {
  if (current_ != needle_of_yarn_[s.yarn] || out_.rows.size() + row_open_ == section().first_row)
    not_yet(s, "casts on with a yarn that worked before, away from the end of a row it worked");
  // The yarn goes on from the last st cast on along the yarn's next course, which must go the
  // cast-on's way (the simulator reads it so).
  if (next_course_of(s.yarn) && next_course_of(s.yarn)->direction != s.direction)
    not_yet(s, "casts on aside sts and then turns back");
  end_row_the_yarn_leaves();
  PatternSection& sec = section();
  if (provisional && has_chain(sec.piece))
    not_yet(s, "casts on a second provisional cast-on with one yarn (one chain per piece)");
  std::vector<std::uint32_t> on_needle, chain;
  for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i)
    for (const PlacedLoop& m : made_by(i)) {
      if (m.place == LoopPlace::along_edge)
        not_yet(s, "casts on aside sts whose loops wait along an edge");
      (m.place == LoopPlace::in_run ? on_needle : chain).push_back(m.loop);
    }
  PatternSection::CastOnAside c;
  c.after_row = static_cast<std::uint32_t>(out_.rows.size() - 1);
  c.count = static_cast<std::uint32_t>(s.stitches.size());
  c.holder = places_.hold(on_needle, needle().section);
  c.provisional = provisional;
  sec.casts_on_aside.push_back(c);
  sec.stitches += c.count;
  if (!chain.empty()) places_.leave(needle().section, Place::chain, std::move(chain));
}

bool ProgramPatternBuilder::has_chain(std::uint32_t piece) const {
  for (std::uint32_t k = 0; k < out_.sections.size(); ++k)
    if (out_.sections[k].piece == piece && !places_.loops_of({Place::chain, k}).empty())
      return true;
  return false;
}

std::vector<std::uint32_t> ProgramPatternBuilder::counted_on_spare_needle(const Needle& n) const {
  std::vector<std::uint32_t> ring = n.ring;
  if (!n.in_round && n.last == CourseDirection::right_to_left)
    std::reverse(ring.begin(), ring.end());
  if (!n.in_round || !n.worked || out_.rows.empty() || out_.rows.back().round) return ring;
  // After a row in the rnd: round from its first st, the way it went.
  if (n.last != n.rnds) std::reverse(ring.begin(), ring.end());
  StitchId first = section().last_row_ends[0];
  auto at = std::find_if(ring.begin(), ring.end(),
                         [&](std::uint32_t l) { return g_.loops[l].maker == first; });
  if (at == ring.end()) return {};
  std::rotate(ring.begin(), at, ring.end());
  return ring;
}

std::optional<PatternSection::Fold> ProgramPatternBuilder::fold_of(
    const std::vector<std::uint32_t> (&side)[2], std::uint32_t& section) const {
  // Round the needle once folded: the front run, then the back one coming back.
  std::vector<std::uint32_t> round(side[0]);
  round.insert(round.end(), side[1].rbegin(), side[1].rend());
  const auto n = static_cast<std::uint32_t>(round.size());
  LoopAt spare{}, held{};
  for (std::uint32_t l : round) {
    LoopAt at = places_.at(l);
    LoopAt& slot = at.place == Place::spare ? spare : held;
    if ((at.place != Place::spare && at.place != Place::holder) ||
        (slot.place != Place::none && slot != at))
      return std::nullopt;
    slot = at;
  }
  auto on_one = [&](const std::vector<std::uint32_t>& loops) {
    return std::all_of(loops.begin(), loops.end(),
                       [&](std::uint32_t l) { return places_.at(l) == places_.at(loops[0]); });
  };
  bool two_needles =
      on_one(side[0]) && on_one(side[1]) && places_.at(side[0][0]) != places_.at(side[1][0]);
  if (spare.place == Place::none || two_needles) return std::nullopt;
  std::vector<std::uint32_t> needle = places_.loops_of(spare);
  std::erase_if(needle, [&](std::uint32_t l) { return places_.at(l) != spare; });
  // Round the needle from its first st, the way its sts go: the holder's sts one run there.
  auto p = static_cast<std::uint32_t>(std::find(round.begin(), round.end(), needle.front()) -
                                      round.begin());
  std::vector<std::uint32_t> ring, on_spare;
  for (bool up : {true, false}) {
    ring.clear();
    for (std::uint32_t k = 0; k < n; ++k) ring.push_back(round[up ? (p + k) % n : (p + n - k) % n]);
    on_spare.clear();
    std::copy_if(ring.begin(), ring.end(), std::back_inserter(on_spare),
                 [&](std::uint32_t l) { return places_.at(l) == spare; });
    if (on_spare == needle) break;
  }
  if (on_spare != needle) return std::nullopt;
  auto is_held = [&](std::uint32_t l) { return places_.at(l) != spare; };
  auto first_held = std::find_if(ring.begin(), ring.end(), is_held);
  auto end_held = std::find_if_not(first_held, ring.end(), is_held);
  if (std::find_if(end_held, ring.end(), is_held) != ring.end()) return std::nullopt;
  PatternSection::Fold fold;
  fold.sts = n;
  fold.after = static_cast<std::uint32_t>(first_held - ring.begin());
  if (held.place == Place::holder) {
    std::vector<std::uint32_t> arc(first_held, end_held), on_holder = places_.loops_of(held);
    fold.held_from_last = on_holder.front() != arc.front();
    if (fold.held_from_last) std::reverse(on_holder.begin(), on_holder.end());
    if (on_holder != arc) return std::nullopt;
    fold.holder = held.index;
    fold.held = static_cast<std::uint32_t>(arc.size());
  }
  for (int k : {0, 1}) {
    auto at =
        static_cast<std::uint32_t>(std::find(ring.begin(), ring.end(), side[k][0]) - ring.begin());
    fold.tip[k] = at + 1;
    fold.down[k] = side[k].size() > 1 && ring[(at + n - 1) % n] == side[k][1];
    for (std::uint32_t i = 0; i < side[k].size(); ++i)
      if (ring[fold.down[k] ? (at + n - i % n) % n : (at + i) % n] != side[k][i])
        return std::nullopt;
  }
  section = spare.index;
  return fold;
}

void ProgramPatternBuilder::three_needle_bind_off(const Step& s) {
  bool all_pairs = std::all_of(stitches_of(s).begin(), stitches_of(s).end(),
                               [&](const WorkedStitch& w) { return g_.type[w.stitch] == T::tnbo; });
  std::uint32_t own = needle_of_yarn_[s.yarn];
  bool all_of_its_sts =
      own != kNone && current_ == own && !row_open_ && needles_[own].live == s.stitches.size();
  if (!all_pairs || (own != kNone && !all_of_its_sts)) return course(s);
  std::vector<std::uint32_t> side[2];
  for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
    auto taken = all_taken_by(i);
    for (int k : {0, 1}) side[k].push_back(taken[k]);
  }
  // Its own sts bound off with those of several pieces held behind, one after another: a rnd
  // of three-needle bind-off ("Hold the 7 sts of Piece 1 behind the needle. Hold the 21 sts
  // of Piece 2 behind ...").
  auto other_place = [&](std::uint32_t l) { return places_.at(l) != places_.at(side[1][0]); };
  if (own != kNone && std::any_of(side[1].begin(), side[1].end(), other_place)) return course(s);
  std::uint32_t joined = own == kNone ? kNone : needles_[own].section;
  end_section();
  PatternSection join;
  join.yarn = s.yarn;
  join.joins = true;
  join.own_yarn = own != kNone;
  std::uint32_t folded = 0;
  if (!join.own_yarn) join.fold = fold_of(side, folded);
  if (join.fold) join.front = join.back = folded;
  for (int k = 0; k < 2 && !join.fold; ++k) {
    LoopAt source = places_.at(side[k].front());
    std::optional<Lie> lie = places_.lie(source, side[k]);
    bool nameable = source.place == Place::holder || source.place == Place::spare;
    // A needle may begin in the middle of a piece's last rnd, going round; but the front piece
    // worked with its own yarn begins where the yarn is, at an end.
    bool own_front = k == 0 && join.own_yarn;
    bool begins_well = lie && (lie->at == 0 || !own_front);
    if (!nameable || !begins_well || (own_front && source.place != Place::spare))
      not_yet(s,
              "binds off sts that do not wait on one spare needle or holder each, from an "
              "end");
    bool holder = source.place == Place::holder;
    (k == 0 ? join.front : join.back) =
        holder ? places_.holder_section(source.index) : source.index;
    join.holders[k] = holder ? source.index : 0;
    join.from_last[k] = lie->from_last;
    join.tips[k] = lie->at;
  }
  join.pairs = static_cast<std::uint32_t>(s.stitches.size());
  for (int k : {0, 1})
    for (std::uint32_t l : side[k]) places_.take(l);
  if (join.own_yarn) return bind_off_with_its_yarn(join, joined);
  join.piece = ++pieces_;
  join.stitches = join.pairs;
  join.first_row = join.end_row = static_cast<std::uint32_t>(out_.rows.size());
  out_.sections.push_back(join);
}

void ProgramPatternBuilder::bind_off_with_its_yarn(const PatternSection& join,
                                                   std::uint32_t section) {
  PatternSection& sec = out_.sections[section];
  if (join.front != section) unsupported("a piece's yarn binds off sts that are not its own");
  sec.joins = true;
  sec.own_yarn = true;
  sec.front = join.front;
  sec.back = join.back;
  std::copy(std::begin(join.from_last), std::end(join.from_last), sec.from_last);
  std::copy(std::begin(join.holders), std::end(join.holders), sec.holders);
  std::copy(std::begin(join.tips), std::end(join.tips), sec.tips);
  sec.pairs = join.pairs;
  sec.stitches += join.pairs;
  sec.left_live = false;
  sec.live_at_end = 0;
}

}  // namespace from_program

HandPattern build_hand_pattern(const Compilation& c, TurnMethod turns, Rounds rounds) {
  check_stitch_types(c.knit);
  bool mirror = rounds == Rounds::mirror_most &&
                stitches_in_rounds_going(c.program, CourseDirection::left_to_right) >
                    stitches_in_rounds_going(c.program, CourseDirection::right_to_left);
  HandPattern pattern =
      mirror ? from_program::ProgramPatternBuilder(c, mirror_image(c.knit, c.program), turns, true)
                   .run()
             : from_program::ProgramPatternBuilder(c, c.program, turns, false).run();
  name_pieces(c.knit, c.yarns, pattern);
  place_section_markers(pattern);
  place_region_markers(pattern);
  return pattern;
}

}  // namespace skein::hand
