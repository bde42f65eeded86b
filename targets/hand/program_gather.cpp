// The hand pattern built on the live-loop program (program_pattern.cpp): a course that takes
// loops from more than one place gathers them first. It slips what it leaves to holders, joins a
// yarn to a holder, a spare needle or a provisional cast-on's chain, places the others into the
// rnd, and picks up loops that wait along another piece's edge (paper section 3.2); then the needle
// holds its loops in the order the course meets them. The members' why-comments:
// program_builder.hpp.
#include <algorithm>

#include "hand/program_builder.hpp"

namespace skein::hand::from_program {

Needle& ProgramPatternBuilder::needle_for(const Step& s, const std::vector<std::uint32_t>& met) {
  std::uint32_t own = needle_of_yarn_[s.yarn];
  if (own != kNone && current_ != own) not_yet(s, "works with a yarn set aside or ended");
  if (own != kNone && !needles_[own].in_round) hold_what_others_work(s, needles_[own]);
  bool on_needle = own != kNone && std::all_of(met.begin(), met.end(), [&](std::uint32_t l) {
                     return places_.at(l) == LoopAt{Place::needle, own};
                   });
  Needle* n = own == kNone ? nullptr : &needles_[own];
  bool leaves_some = n && n->in_round && s.shape == RowShape::closed && met.size() < n->live;
  if (!on_needle || leaves_some) gather(s, met);
  return needle();
}

void ProgramPatternBuilder::gather(const Step& s, std::vector<std::uint32_t> met) {
  bool round = works_a_whole_rnd(s);
  bool own = working() && needle().live > 0 && current_ == needle_of_yarn_[s.yarn];
  if (own && !round) {
    hold_what_others_take(s);
    put_on_spare_needles(s);
    met = on_the_needle(met);
    const LoopAt mine{Place::needle, current_};
    if (std::all_of(met.begin(), met.end(), [&](std::uint32_t l) { return places_.at(l) == mine; }))
      return;
  }
  if (own && needle().in_round) {
    if (!round) return place_into_ring_row(s, met);
    turn_in_ring(s, needle());
    begin_rnd_at_yarn(s, needle());
  }
  for (std::uint32_t l : met) in_met_[l] = 1;
  bool joined_here = own && round && !needle().in_round;
  std::vector<std::uint32_t> host = joined_here ? join_flat_piece_in_the_rnd(s, met)
                                    : !own      ? join_to_first_source(s, met, round)
                                    : round     ? hold_what_it_leaves(s)
                                                : row_ahead(s);
  place_the_others(s, met, host);
  for (std::uint32_t l : met) in_met_[l] = 0;
  if (!round) return lay_row_ahead(s, met, own);
  Needle& n = needle();
  n.ring = met;
  n.gap = 0;
  n.live = hand_stitch_count(g_, met);
  n.in_round = true;
  n.rnds = n.last = s.direction;
  n.worked = false;
  index_ring(n);
  places_.set(met, {Place::needle, current_});
}

void ProgramPatternBuilder::let_go_of_used_spare_needles() {
  for (std::uint32_t k : {0u, 1u})
    if (spare_queue_[k].empty()) spare_rows_[k] = {};
}

bool ProgramPatternBuilder::waits_for_rows(LoopAt at, const Step& s) const {
  for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
    std::span<const std::uint32_t> taken = taken_by(i);
    auto held = std::count_if(taken.begin(), taken.end(),
                              [&](std::uint32_t l) { return places_.at(l) == at; });
    if (held > 1 || (held == 1 && taken.size() == 1)) return false;
  }
  // The holder is used up by the rows (a spare needle keeps no sts for a rnd to place).
  std::vector<std::uint32_t> loops = places_.loops_of(at);
  return std::all_of(loops.begin(), loops.end(), [&](std::uint32_t other) {
    const Step* taker = taker_step_[other] == kNone ? nullptr : &p_.steps[taker_step_[other]];
    return taker && taker->yarn == s.yarn && taker->shape != RowShape::closed;
  });
}

void ProgramPatternBuilder::put_on_spare_needles(const Step& s) {
  for (std::uint32_t loop : loops_met(s)) {
    LoopAt source = places_.at(loop);
    bool holder = source.place == Place::holder;
    if ((!holder && source.place != Place::spare) || spare_slot(loop) != kNone ||
        !waits_for_rows(source, s))
      continue;
    if (needle().in_round) turn_in_ring(s, needle());
    if (row_open_) not_yet(s, "puts sts on a spare needle in the middle of a row");
    std::uint32_t k = spare_rows_[0].place == Place::none   ? 0
                      : spare_rows_[1].place == Place::none ? 1
                                                            : kNone;
    if (k == kNone) not_yet(s, "takes sts from a third spare needle");
    std::vector<std::uint32_t> loops = places_.loops_of(source);
    if (!holder) {
      slip_from_piece_left_on_spare_needle(s, source, k, loop);
      continue;
    }
    bool from_last = loops.front() != loop;
    if (from_last) std::reverse(loops.begin(), loops.end());
    if (loops.front() != loop) not_yet(s, "takes a holder's sts one at a time, not from an end");
    PatternSection::Placement p{places_.holder_section(source.index),
                                static_cast<std::uint32_t>(loops.size()), 0, from_last};
    p.before_row = static_cast<std::uint32_t>(out_.rows.size());
    p.holder = source.index;
    p.to_spare = true;
    p.second_spare = k == 1;
    section().placements.push_back(p);
    spare_rows_[k] = source;
    spare_queue_[k] = std::move(loops);
  }
}

void ProgramPatternBuilder::slip_from_piece_left_on_spare_needle(const Step& s, LoopAt spare,
                                                                 std::uint32_t k,
                                                                 std::uint32_t first) {
  // "Sl1 from spare" names no needle: it is the one piece that waits on one, its sts taken in
  // the order they were left there.
  if (k != 0 || places_.spare_needles_holding_sts() != 1)
    not_yet(s, "slips sts from a piece's spare needle while another piece waits on one");
  std::vector<std::uint32_t> loops = places_.loops_of(spare);
  std::erase_if(loops, [&](std::uint32_t l) { return places_.at(l) != spare; });
  if (loops.front() != first) not_yet(s, "takes a spare needle's sts from its far end");
  spare_rows_[k] = spare;
  spare_queue_[k] = std::move(loops);
}

std::uint32_t ProgramPatternBuilder::slip_from_spare_needles(std::uint32_t worked, Needle& n) {
  std::uint32_t j = 0, slipped = 0;  // j: the loop's place among the stitch's, as met
  for_each_met(taken_by(worked), p_.steps[step_].direction, [&](std::uint32_t loop) {
    bool behind = j++ > 0;  // worked after the st at the tip of the left needle
    std::uint32_t k = spare_slot(loop);
    if (k == kNone) return;
    if (spare_queue_[k].empty() || spare_queue_[k].front() != loop)
      not_yet(p_.steps[step_], "takes a spare needle's sts out of their order");
    spare_queue_[k].erase(spare_queue_[k].begin());
    out_.ops.push_back(
        k == 0 ? (behind ? HandOp::from_spare_behind : HandOp::from_spare)
               : (behind ? HandOp::from_second_spare_behind : HandOp::from_second_spare));
    ++n.live;
    ++slipped;
    if (!n.in_round) ++n.ahead;  // slipped onto the tip of the left needle
  });
  return slipped;
}

void ProgramPatternBuilder::place_into_ring_row(const Step& s,
                                                const std::vector<std::uint32_t>& met) {
  Needle& n = needle();
  if (row_open_ || n.gap != 0 || n.marker_off)
    not_yet(s, "takes sts from elsewhere into a row in the rnd, away from the marker");
  hold_what_others_take(s);
  const LoopAt own{Place::needle, current_};
  bool forward = s.direction == n.rnds;
  // The ring without its marker; blocks placed where the marker is go after the ring's last
  // st, and the marker may then sit before any of them.
  std::vector<std::uint32_t> ring = n.ring;
  std::vector<std::uint32_t> spots{0};  // where the marker may go: before ring[spot]
  std::vector<std::pair<LoopAt, std::vector<std::uint32_t>>> blocks;  // in ring order
  for (std::uint32_t i = 0; i < met.size();) {
    LoopAt source = places_.at(met[i]);
    if (source == own) {
      ++i;
      continue;
    }
    std::uint32_t end = i;
    while (end < met.size() && places_.at(met[end]) == source) ++end;
    bool run_first = i > 0;  // met after the st before it; else before the st after it
    if (!run_first && end == met.size()) not_yet(s, "takes sts from elsewhere only");
    std::vector<std::uint32_t> block = whole_source(source, {met.data() + i, end - i}, run_first);
    if (block.empty())
      not_yet(s, fmt::format("takes {} sts into a row in the rnd that are not all of a holder, "
                             "spare needle or chain, round from an end",
                             end - i));
    // In ring order; placed after the st before it (the course going the rnds' way) or before
    // the st after it.
    std::uint32_t beside = run_first ? met[i - 1] : met[end];
    if (!forward) std::reverse(block.begin(), block.end());
    bool after = run_first == forward;
    auto at =
        static_cast<std::uint32_t>(std::find(ring.begin(), ring.end(), beside) - ring.begin());
    if (at == ring.size()) not_yet(s, "takes sts from elsewhere beside no st on the needle");
    std::uint32_t into = after ? at + 1 : at;
    bool at_marker = into == 0 || into == ring.size();
    if (into == 0) into = static_cast<std::uint32_t>(ring.size());
    for (std::uint32_t& k : spots)
      if (k != 0 && k >= into) k += static_cast<std::uint32_t>(block.size());
    ring.insert(ring.begin() + into, block.begin(), block.end());
    if (at_marker) spots.push_back(static_cast<std::uint32_t>(ring.size() - block.size()));
    blocks.emplace_back(source, std::move(block));
    i = end;
  }
  // The row begins at the yarn, or one st behind it: the marker goes before or after that st.
  auto first =
      static_cast<std::uint32_t>(std::find(ring.begin(), ring.end(), met.front()) - ring.begin());
  auto size = static_cast<std::uint32_t>(ring.size());
  std::uint32_t at_yarn = forward ? first : (first + 1) % size;
  std::uint32_t behind = forward ? (first + 1) % size : first;
  auto is_spot = [&](std::uint32_t k) {
    return std::find(spots.begin(), spots.end(), k % size) != spots.end();
  };
  std::uint32_t marker = is_spot(at_yarn) ? at_yarn : behind;
  if (!is_spot(marker)) not_yet(s, "takes sts from elsewhere where the yarn cannot reach them");
  std::rotate(ring.begin(), ring.begin() + marker % size, ring.end());
  n.ring = std::move(ring);
  index_ring(n);
  std::sort(blocks.begin(), blocks.end(),
            [&](const auto& a, const auto& b) { return pos_[a.second[0]] < pos_[b.second[0]]; });
  for (auto& [source, block] : blocks) {
    place(s, source, block, pos_[block[0]]);
    places_.set(block, {Place::needle, current_});
  }
  n.gap = 0;
  n.live = hand_stitch_count(g_, n.ring);
}

std::vector<std::uint32_t> ProgramPatternBuilder::whole_source(LoopAt source,
                                                               std::span<const std::uint32_t> run,
                                                               bool run_first) const {
  if (source.place != Place::holder && source.place != Place::spare && source.place != Place::chain)
    return {};
  std::vector<std::uint32_t> all = places_.loops_of(source);
  std::erase_if(all, [&](std::uint32_t l) { return places_.at(l) != source; });
  // Round from the run (a tube's sts wait in a ring), going on the way the run goes, or (one
  // st) towards the st taken next.
  auto at = std::find(all.begin(), all.end(), run_first ? run.front() : run.back());
  if (at == all.end() || run.size() > all.size()) return {};
  std::rotate(all.begin(), at, all.end());
  std::size_t n = all.size();
  auto taken_sooner = [&](std::uint32_t a, std::uint32_t b) {
    return taker_step_[a] < taker_step_[b];
  };
  bool down = run.size() > 1 ? all[1] != run[run_first ? 1 : run.size() - 2]
                             : n > 1 && taken_sooner(all[n - 1], all[1]);
  if (down) std::reverse(all.begin() + 1, all.end());
  if (!run_first) std::reverse(all.begin(), all.end());
  auto from = run_first ? all.begin() : all.end() - static_cast<std::ptrdiff_t>(run.size());
  if (!std::equal(run.begin(), run.end(), from)) return {};
  return all;
}

bool ProgramPatternBuilder::goes_round(const Step& s, std::size_t ring) const {
  std::size_t loops = 0;
  for (std::size_t k = step_; k < p_.steps.size() && loops < ring; ++k) {
    const Step& next = p_.steps[k];
    if (next.kind != StepKind::course || next.yarn != s.yarn || next.direction != s.direction)
      break;
    for (std::uint32_t i = next.stitches.begin; i < next.stitches.end; ++i)
      loops += taken_by(i).size();
  }
  return loops >= ring;
}

void ProgramPatternBuilder::begin_rnd_at_yarn(const Step& s, Needle& n) {
  // The row before passed the marker: it removes it, and this rnd places it anew here.
  if (n.gap != 0 && !n.marker_off && n.marker_slipped_at != kNone) {
    out_.ops[n.marker_slipped_at] = HandOp::rm;
    n.marker_off = true;
  }
  if (!n.marker_off) return;
  if (row_open_) {  // the row going this way ends where the rnd begins, without turning
    out_.ops.push_back(HandOp::no_turn);
    close_ring_row(s, n, true);
  }
  if (!n.ring.empty())
    std::rotate(n.ring.begin(), n.ring.begin() + n.gap % n.ring.size(), n.ring.end());
  n.gap = 0;
  n.marker_off = false;
  pm_next_ = true;
  index_ring(n);
}

std::vector<std::uint32_t> ProgramPatternBuilder::join_flat_piece_in_the_rnd(
    const Step& s, const std::vector<std::uint32_t>& met) {
  Needle& n = needle();
  PatternSection& sec = section();
  auto row_of = [&](std::uint32_t l) {
    StitchId maker = g_.loops[l].maker;
    return maker == kNoStitch ? kNone : row_of_[maker];
  };
  // The row that made the needle's sts; or, where a short row left only cast-on sts there, the
  // last row written.
  std::uint32_t last_row = kNone;
  for (std::uint32_t l : n.ring) last_row = last_row == kNone ? row_of(l) : last_row;
  if (last_row == kNone && out_.rows.size() > sec.first_row)
    last_row = static_cast<std::uint32_t>(out_.rows.size() - 1);
  bool worked_since = last_row < sec.first_row && out_.rows.size() > sec.first_row;
  if (row_open_ || last_row == kNone || worked_since || sec.joined_in_rnd_at)
    not_yet(s, "joins a flat piece in the rnd after rows of its own that are not its last");
  std::size_t kept = 0;
  bool older = false;
  for (std::uint32_t l : n.ring) {
    kept += in_met_[l];
    older = older || row_of(l) != last_row;
  }
  // The rnd takes all the needle's sts where they are (the sts a short row left, between a
  // strip's edges), or none: they go to a holder, to be placed.
  bool keeps_all = kept == n.ring.size();
  if ((kept > 0 && !keeps_all) || (!keeps_all && older))
    not_yet(s,
            "joins a flat piece in the rnd with some sts of its own, or of rows before its last");
  // The rnd goes on the way the last row went: that row ends without turning.
  PatternRow& last = out_.rows[last_row];
  Side rnd_side = s.direction == CourseDirection::right_to_left ? Side::rs : Side::ws;
  if (last.side == rnd_side) {
    if (last.end_op != out_.ops.size())
      not_yet(s, "joins a flat piece in the rnd the way its last row went, after other work");
    if (out_.ops.back() == HandOp::turn) {  // a short row goes on round the corner instead
      out_.ops.pop_back();
      last.short_row = false;
    }
    out_.ops.push_back(HandOp::no_turn);
    last.end_op = static_cast<std::uint32_t>(out_.ops.size());
  }
  sec.in_round = true;
  sec.joined_in_rnd_at = static_cast<std::uint32_t>(out_.rows.size());
  if (keeps_all) {
    std::vector<std::uint32_t> host;
    for (std::uint32_t l : met)
      if (places_.at(l) == LoopAt{Place::needle, current_}) host.push_back(l);
    return host;
  }
  std::vector<std::uint32_t> row = counted_on_spare_needle(n);  // as the last row worked them
  // Taken up again: the sts are slipped as it is taken up, naming the row.
  bool taken_up = last_row < sec.first_row;
  PatternSection::Holding h{taken_up ? sec.first_row - 1 : last_row, 1, hand_stitch_count(g_, row),
                            places_.hold(row, n.section)};
  h.flat_row = true;
  h.of_number = taken_up ? out_.rows[last_row].number : 0;
  sec.holdings.push_back(h);
  n.ring.clear();
  n.live = n.ahead = n.behind = 0;
  return {};
}

std::vector<std::uint32_t> ProgramPatternBuilder::row_ahead(const Step& s) {
  Needle& n = needle();
  if (row_open_ || s.direction == n.last || n.live != hand_stitch_count(g_, n.ring))
    not_yet(s, "places sts into a row that does not turn from a whole row");
  for (std::uint32_t l : n.ring)
    if (!in_met_[l]) not_yet(s, "places sts into a row that leaves some of its own");
  std::vector<std::uint32_t> own = n.ring;
  if (s.direction == CourseDirection::right_to_left) std::reverse(own.begin(), own.end());
  return own;
}

void ProgramPatternBuilder::lay_row_ahead(const Step& s, const std::vector<std::uint32_t>& met,
                                          bool own) {
  Needle& n = needle();
  n.ring = met;
  if (s.direction == CourseDirection::right_to_left) std::reverse(n.ring.begin(), n.ring.end());
  n.gap =
      s.direction == CourseDirection::right_to_left ? static_cast<std::uint32_t>(met.size()) : 0;
  n.live = hand_stitch_count(g_, met);
  n.ahead = 0;
  n.behind = n.live;
  n.last = reversed(s.direction);
  n.worked = own;
  index_ring(n);
  places_.set(met, {Place::needle, current_});
}

LoopAt ProgramPatternBuilder::hold_parts_of_spare_needle(std::uint32_t section, std::uint32_t loop,
                                                         bool round_the_end_stays) {
  PatternSection& sec = out_.sections[section];
  const LoopAt spare_needle{Place::spare, section};
  std::vector<std::uint32_t> spare = places_.loops_of(spare_needle);
  std::optional<PatternSection::Holding> counted = counting_of_spare_needle(sec, spare);
  if (!counted) return spare_needle;
  // The sts keep the numbers they had when the piece was left, so each part is a run of
  // those numbers, and all parts go to holders in one sentence, in order, but the one that
  // goes round past the end, which stays on the spare needle for a rnd to place from its
  // middle (where `round_the_end_stays`).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> parts;  // [begin, end) in `spare`
  for (std::uint32_t i = 0, end = 0; i < spare.size(); i = end) {
    for (end = i + 1; end < spare.size() &&
                      (taken_together(spare[end - 1], spare[end]) ||
                       taken_by_rows_one_by_one(spare[end - 1], spare[end])) &&
                      places_.counted_at(spare[end]) == places_.counted_at(spare[end - 1]) + 1;
         ++end) {
    }
    parts.emplace_back(i, end);
  }
  bool round_the_end =
      round_the_end_stays && parts.size() > 1 && taken_together(spare.back(), spare.front());
  for (std::size_t k = round_the_end ? 1 : 0; k + (round_the_end ? 1 : 0) < parts.size(); ++k) {
    std::span<const std::uint32_t> part(spare.data() + parts[k].first,
                                        parts[k].second - parts[k].first);
    PatternSection::Holding h = *counted;
    h.first = places_.counted_at(part.front());
    h.count = static_cast<std::uint32_t>(part.size());
    places_.take_off_spare(section, part);
    h.holder = places_.hold(part, section);
    auto later = std::find_if(sec.holdings.begin(), sec.holdings.end(), [&](const auto& o) {
      return o.after_row == h.after_row && o.first > h.first;
    });
    sec.holdings.insert(later, h);
    sec.live_at_end -= hand_stitch_count(g_, part);
  }
  return places_.at(loop);
}

std::optional<Lie> ProgramPatternBuilder::lie_parting_spare_needle(
    LoopAt& source, std::span<const std::uint32_t> block) {
  std::optional<Lie> lie = places_.lie(source, block);
  if (lie || source.place != Place::spare) return lie;
  source = hold_parts_of_spare_needle(source.index, block.front());
  return places_.lie(source, block);
}

bool ProgramPatternBuilder::taken_by_rows_one_by_one(std::uint32_t a, std::uint32_t b) const {
  std::uint32_t at = taker_step_[a], bt = taker_step_[b];
  if (at == kNone || bt == kNone || at == bt) return false;
  const Step &sa = p_.steps[at], &sb = p_.steps[bt];
  auto later_row = [&](const Step& s, std::uint32_t step) {
    return s.shape != RowShape::closed && !starts_its_yarn(step);
  };
  // Taken from one end of the needle: by rows one or two apart (every row, or every other row
  // where the rows take sts at both their ends).
  std::uint32_t apart = std::max(course_number_[at], course_number_[bt]) -
                        std::min(course_number_[at], course_number_[bt]);
  return sa.yarn == sb.yarn && later_row(sa, at) && later_row(sb, bt) && apart <= 2;
}

bool ProgramPatternBuilder::taken_together(std::uint32_t a, std::uint32_t b) const {
  if (taker_step_[a] != taker_step_[b]) return false;
  return taker_step_[a] == kNone || met_at_[a] + 1 == met_at_[b] || met_at_[b] + 1 == met_at_[a];
}

std::optional<PatternSection::Holding> ProgramPatternBuilder::counting_of_spare_needle(
    const PatternSection& sec, const std::vector<std::uint32_t>& spare) const {
  PatternSection::Holding h{};
  if (sec.first_row == sec.end_row) {  // its cast-on only
    if (sec.resumed || sec.starts_from || sec.picks_up || sec.in_round) return std::nullopt;
    h.after_row = sec.first_row - 1;
    h.of_cast_on = true;
    return h;
  }
  h.after_row = sec.end_row - 1;
  const PatternRow& last = out_.rows[h.after_row];
  // A row in the rnd numbers the sts in the order it worked them: only where it made them all.
  if (sec.in_round != last.round && !std::all_of(spare.begin(), spare.end(), [&](std::uint32_t l) {
        return row_of_[g_.loops[l].maker] == h.after_row;
      }))
    return std::nullopt;
  h.of_row = !last.round;
  return h;
}

std::vector<std::uint32_t> ProgramPatternBuilder::hold_what_it_leaves(const Step& s) {
  Needle& n = needle();
  // After rows that ended away from the marker (a set-in sweater's front, whose yarn goes on
  // to a sleeve) the yarn is at the marker once the sts between them are slipped.
  auto kept = [&](std::uint32_t l) { return in_met_[l] != 0; };
  auto gap = static_cast<std::ptrdiff_t>(n.gap);
  bool at_marker = std::none_of(n.ring.begin(), n.ring.begin() + gap, kept) ||
                   std::none_of(n.ring.begin() + gap, n.ring.end(), kept);
  if (!n.in_round || row_open_ || !at_marker)
    not_yet(s, "gathers sts onto a flat piece, or a tube not at the end of a rnd");
  n.gap = 0;
  if (out_.rows.empty()) not_yet(s, "gathers sts before any row is worked");
  return hold_blocks(n.ring, kept, false);
}

std::vector<std::uint32_t> ProgramPatternBuilder::hold_blocks(
    const std::vector<std::uint32_t>& order, const std::function<bool(std::uint32_t)>& stays,
    bool of_row) {
  Needle& n = needle();
  PatternSection& sec = section();
  auto after_row = static_cast<std::uint32_t>(out_.rows.size()) - 1;
  std::vector<std::uint32_t> stay;
  for (std::uint32_t i = 0; i < order.size();) {
    if (stays(order[i])) {
      stay.push_back(order[i++]);
      continue;
    }
    // A block for each yarn that takes them (a gusset's sts, and a join's beside them).
    std::uint32_t end = i + 1;
    while (end < order.size() && !stays(order[end]) && held_together(order[end - 1], order[end]))
      ++end;
    std::span<const std::uint32_t> block(order.data() + i, end - i);
    std::uint32_t holder = holder_met_before(block, n.section), onto = 0;
    if (holder != 0) {
      onto = static_cast<std::uint32_t>(places_.loops_of({Place::holder, holder}).size());
      places_.hold_onto(holder, block);
    } else {
      holder = places_.hold(block, n.section);
    }
    PatternSection::Holding h{after_row, i + 1, end - i, holder, onto};
    h.of_row = of_row;
    sec.holdings.push_back(h);
    i = end;
  }
  return stay;
}

std::uint32_t ProgramPatternBuilder::holder_met_before(std::span<const std::uint32_t> block,
                                                       std::uint32_t section) const {
  for (std::uint32_t h = places_.holders(); h > 0; --h) {
    if (places_.holder_section(h) != section) continue;
    std::vector<std::uint32_t> all = places_.loops_of({Place::holder, h});
    all.insert(all.end(), block.begin(), block.end());
    return met_one_after_another(all) ? h : 0;
  }
  return 0;
}

bool ProgramPatternBuilder::met_one_after_another(const std::vector<std::uint32_t>& loops) const {
  if (loops.size() < 2 || taker_step_[loops[0]] == kNone) return false;
  int by = static_cast<int>(met_at_[loops[1]]) - static_cast<int>(met_at_[loops[0]]);
  for (std::size_t k = 1; k < loops.size(); ++k)
    if (taker_step_[loops[k]] != taker_step_[loops[0]] ||
        static_cast<int>(met_at_[loops[k]]) - static_cast<int>(met_at_[loops[k - 1]]) != by ||
        (by != 1 && by != -1) || places_.at(loops[k - 1]).place == Place::none)
      return false;
  return true;
}

bool ProgramPatternBuilder::held_together(std::uint32_t a, std::uint32_t b) const {
  if (holder_for(a) != holder_for(b)) return false;
  std::uint32_t at = taker_step_[a], bt = taker_step_[b];
  return at == bt || (!starts_its_yarn(at) && !starts_its_yarn(bt));
}

void ProgramPatternBuilder::index_loops_met() {
  std::vector<std::uint32_t> courses_of_yarn(needle_of_yarn_.size(), 0);  // so far
  for (std::uint32_t i = 0; i < p_.steps.size(); ++i) {
    const Step& s = p_.steps[i];
    bool picks_up = s.kind == StepKind::cast_on && s.picked_up > 0;
    if (s.kind != StepKind::course && s.kind != StepKind::bind_off &&
        s.kind != StepKind::three_needle_bind_off && !picks_up)
      continue;
    course_number_[i] = courses_of_yarn[s.yarn]++;
    std::vector<std::uint32_t> met = loops_met(s);
    for (std::uint32_t k = 0; k < met.size(); ++k) {
      taker_step_[met[k]] = i;
      met_at_[met[k]] = k;
    }
    // A three-needle bind-off's sts held behind are taken too, pair by pair.
    auto k = static_cast<std::uint32_t>(met.size());
    for (std::uint32_t w = s.stitches.begin; w < s.stitches.end; ++w)
      if (binds_off_together(w)) {
        std::uint32_t behind = all_taken_by(w)[1];
        taker_step_[behind] = i;
        met_at_[behind] = k++;
      }
  }
}

std::vector<std::uint32_t> ProgramPatternBuilder::join_to_first_source(
    const Step& s, const std::vector<std::uint32_t>& met, bool round) {
  if (needle_of_yarn_[s.yarn] == kNone) end_section();  // the piece worked before waits
  LoopAt source = places_.at(met.front());
  std::vector<std::uint32_t> host;
  for (std::uint32_t l : met)
    if (places_.at(l) == source) host.push_back(l);
  if (source.place == Place::edge) return start_from_pick_up(s, host, round);
  std::optional<Lie> lie = lie_parting_spare_needle(source, host);
  if (source.place == Place::none || source.place == Place::needle || !lie)
    not_yet(s, "begins on sts that wait nowhere the pattern can name, or out of their order");
  auto count = static_cast<std::uint32_t>(host.size());
  std::uint32_t own = needle_of_yarn_[s.yarn];
  if (own != kNone) {  // carried on from a bind-off
    if (!round || source.place != Place::holder || lie->at != 0 || needle().live != 0)
      not_yet(s, "carries its yarn on to sts other than a holder's, from their end");
    section().carries.push_back(
        {static_cast<std::uint32_t>(out_.rows.size()), source.index, count, lie->from_last});
    return host;
  }
  bool holder = source.place == Place::holder;
  if ((!holder || !round) && lie->at != 0)
    not_yet(s, "joins a yarn to a spare needle, or to a row's sts, in the middle of its sts");
  start_section(s.yarn, kNone);
  section().in_round = round;
  section().starts_from =
      PatternSection::Start{holder ? places_.holder_section(source.index) : source.index,
                            source.place == Place::chain,
                            lie->from_last,
                            count,
                            holder ? source.index : 0,
                            lie->at};
  return host;
}

void ProgramPatternBuilder::place_the_others(const Step& s, const std::vector<std::uint32_t>& met,
                                             const std::vector<std::uint32_t>& host) {
  std::vector<std::uint32_t> rest;
  // A flat piece joined in the rnd here keeps none of its sts: every run is placed.
  LoopAt hosted = host.empty() && !section().joined_in_rnd_at ? places_.at(met.front())
                  : host.empty()                              ? LoopAt{}
                                                              : places_.at(host.front());
  for (std::uint32_t i = 0; i < met.size();) {
    LoopAt source = places_.at(met[i]);
    if (source == hosted) {
      rest.push_back(met[i++]);
      continue;
    }
    std::uint32_t end = i;
    while (end < met.size() && places_.at(met[end]) == source) ++end;
    place(s, source, std::span<const std::uint32_t>(met.data() + i, end - i), i);
    i = end;
  }
  if (rest != host) not_yet(s, "meets the sts it keeps out of their order on the needle");
}

void ProgramPatternBuilder::place(const Step& s, LoopAt source,
                                  std::span<const std::uint32_t> block, std::uint32_t after) {
  if (source.place == Place::edge) return pick_up_into_rnd(s, source, block, after);
  std::optional<Lie> lie = lie_parting_spare_needle(source, block);
  bool nameable =
      source.place == Place::holder || source.place == Place::spare || source.place == Place::chain;
  if (!nameable || !lie || (lie->from_last && lie->at != 0))
    not_yet(s, fmt::format("takes {} sts it cannot place from where they wait (all of a "
                           "holder, spare needle or chain, in their order)",
                           block.size()));
  bool holder = source.place == Place::holder;
  PatternSection::Placement p{holder ? places_.holder_section(source.index) : source.index,
                              static_cast<std::uint32_t>(block.size()), after, lie->from_last};
  p.chain = source.place == Place::chain;
  p.before_row = static_cast<std::uint32_t>(out_.rows.size());
  p.holder = holder ? source.index : 0;
  p.start = lie->at;
  section().placements.push_back(p);
}

void ProgramPatternBuilder::note_row_end(StitchId st, const PatternRow& r) {
  auto row = static_cast<std::uint32_t>(out_.rows.size());  // the row being written
  if (row_ends_.size() <= row) row_ends_.resize(row + 1);
  RowEnds& ends = row_ends_[row];
  if (ends.first == kNoStitch) ends.first = st;
  ends.last = st;
  ends.side = r.side;
  row_of_[st] = row;
  number_of_[st] = r.number;
}

void ProgramPatternBuilder::note_cast_on_end(StitchId st, CourseDirection direction) {
  RowEnds& ends = cast_on_ends_[st];
  ends.first = p_.stitches[p_.steps[step_].stitches.begin].stitch;
  ends.last = p_.stitches[p_.steps[step_].stitches.end - 1].stitch;
  ends.side = direction == CourseDirection::right_to_left ? Side::rs : Side::ws;
}

const ProgramPatternBuilder::RowEnds* ProgramPatternBuilder::ends_of_row_of(StitchId st) const {
  if (row_of_[st] != kNone) return &row_ends_[row_of_[st]];
  auto cast_on = cast_on_ends_.find(st);
  return cast_on == cast_on_ends_.end() ? nullptr : &cast_on->second;
}

std::optional<ProgramPatternBuilder::Edge> ProgramPatternBuilder::edge_of(
    StitchId maker, std::uint32_t loop, const RowEnds& ends) const {
  bool at_right = maker == (ends.side == Side::rs ? ends.first : ends.last);
  bool at_left = maker == (ends.side == Side::rs ? ends.last : ends.first);
  auto made = made_by(p_.worked_at[maker]);
  if (made.size() > 1) {  // the loop across the edge made after its wale's is on the right
    bool right = made.back().loop == loop;
    if (!(right ? at_right : at_left)) return std::nullopt;
    return right ? Edge::right : Edge::left;
  }
  if (at_right && at_left) return Edge::either;
  if (!at_right && !at_left) return std::nullopt;
  return at_right ? Edge::right : Edge::left;
}

std::optional<PatternSection::PickUp> ProgramPatternBuilder::pick_up_of(
    LoopAt source, std::span<const std::uint32_t> loops) const {
  auto [p, count] = longest_pick_up(source, loops);
  if (count == 0 || count != loops.size()) return std::nullopt;
  return p;
}

std::pair<PatternSection::PickUp, std::size_t> ProgramPatternBuilder::longest_pick_up(
    LoopAt source, std::span<const std::uint32_t> loops) const {
  PatternSection::PickUp p;
  p.section = source.index;
  std::optional<bool> right_edge;  // known once a st says which edge it is on
  std::size_t i = 0;
  for (; i < loops.size(); ++i) {
    StitchId maker = g_.loops[loops[i]].maker;
    const RowEnds* ends = maker == kNoStitch ? nullptr : ends_of_row_of(maker);
    if (places_.at(loops[i]) != source || !ends) break;
    std::optional<Edge> edge = edge_of(maker, loops[i], *ends);
    if (!edge) break;
    bool right = *edge == Edge::right;
    if (*edge != Edge::either && right != right_edge.value_or(right)) break;
    std::uint32_t row = number_of_[maker];  // 0: the cast-on
    bool up = row == p.to_row + 1 && (i == 1 || p.from_row < p.to_row);
    bool down = row + 1 == p.to_row && (i == 1 || p.from_row > p.to_row);
    if (i > 0 && !(up || down)) break;
    if (*edge != Edge::either) right_edge = right;
    if (i == 0) p.from_row = row;
    p.to_row = row;
  }
  p.right = right_edge.value_or(true);
  return {p, i};
}

std::vector<std::uint32_t> ProgramPatternBuilder::start_from_pick_up(
    const Step& s, const std::vector<std::uint32_t>& host, bool round) {
  // A row after the pick-up works the last loop picked up first; a rnd joined after it, the
  // first.
  std::vector<std::uint32_t> picked(host.rbegin(), host.rend());
  if (round) picked = host;
  std::optional<PatternSection::PickUp> p = pick_up_of(places_.at(host.front()), picked);
  if (!p) not_yet(s, "begins on loops along an edge that are not one in each row of an edge");
  start_section(s.yarn, kNone);
  section().in_round = round;
  section().picks_up = *p;
  section().cast_on = hand_stitch_count(g_, host);
  return host;
}

void ProgramPatternBuilder::pick_up_into_rnd(const Step& s, LoopAt source,
                                             std::span<const std::uint32_t> block,
                                             std::uint32_t after) {
  // One pick-up per edge (a rnd goes down one edge of a flap and up the other).
  while (!block.empty()) {
    auto [p, count] = longest_pick_up(source, block);
    if (count == 0 || !section().in_round)
      not_yet(s, fmt::format("picks up {} loops along an edge into a row, or not one in each "
                             "row of an edge",
                             block.size()));
    PatternSection::Placement placed{p.section, static_cast<std::uint32_t>(count), after, false};
    placed.before_row = static_cast<std::uint32_t>(out_.rows.size());
    placed.edge = p;
    section().placements.push_back(placed);
    block = block.subspan(count);
    after += static_cast<std::uint32_t>(count);
  }
}

}  // namespace skein::hand::from_program
