// The hand pattern built on the live-loop program (program_pattern.cpp): a course that takes
// loops from more than one place gathers them first. It slips what it leaves to holders, joins a
// yarn to a holder, a spare needle or a provisional cast-on's chain, places the others into the
// rnd, and picks up loops that wait along another piece's edge (paper section 3.2); then the needle
// holds its loops in the order the course meets them. Holders: program_holding.cpp; picking
// up: program_pick_up.cpp. The members' why-comments: program_builder.hpp.
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
  bool round = works_a_whole_rnd(s) || joins_a_tube(s);
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
  // The rnd goes on the way the last row went: that row ends without turning (taken up again,
  // the piece's last row written before it was set aside).
  bool taken_up_here = out_.rows.size() == sec.first_row;
  PatternRow& last = out_.rows[taken_up_here ? last_row_of_piece(sec.piece) : last_row];
  Side rnd_side = s.direction == CourseDirection::right_to_left ? Side::rs : Side::ws;
  if (last.side == rnd_side) {
    bool turns = last.end_op > last.first_op && out_.ops[last.end_op - 1] == HandOp::turn;
    if (last.end_op != out_.ops.size() && !turns)
      not_yet(s, "joins a flat piece in the rnd the way its last row went, after other work");
    if (turns) {  // a short row goes on round the corner instead
      out_.ops[last.end_op - 1] = HandOp::no_turn;
      last.short_row = false;
    } else {
      out_.ops.push_back(HandOp::no_turn);
      last.end_op = static_cast<std::uint32_t>(out_.ops.size());
    }
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

std::uint32_t ProgramPatternBuilder::last_row_of_piece(std::uint32_t piece) const {
  std::uint32_t last = kNone;
  for (const PatternSection& sec : out_.sections)
    if (sec.piece == piece && sec.end_row > sec.first_row) last = sec.end_row - 1;
  if (last == kNone) unsupported("a piece taken up again without a row written");
  return last;
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

}  // namespace skein::hand::from_program
