// The hand pattern built on the live-loop program (program_pattern.cpp): each course is worked
// as a row or in the rnd, with the side facing that its direction gives, its stitches in the
// course's working order; the needle's loops, the yarn's place and the rows written follow it.
// The members' why-comments: program_builder.hpp.
#include <algorithm>

#include "hand/program_builder.hpp"
#include "hand/stitch_working.hpp"

namespace skein::hand::from_program {

void ProgramPatternBuilder::course(const Step& s) {
  Needle& n = needle_for(s, loops_met(s));
  if (n.in_round) return ring_course(s, n);
  PatternRow r = open_row(s, n);
  r.bind_off = std::all_of(stitches_of(s).begin(), stitches_of(s).end(),
                           [&](const WorkedStitch& w) { return g_.type[w.stitch] == T::bo; });
  begin_row(s, n);
  check_met_along_the_row(s, n);
  std::uint32_t takes = 0;
  for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
    note_region_mark(p_.stitches[i].stitch, r);  // before the sts it slips from spare needles
    std::uint32_t slipped = slip_from_spare_needles(i, n);
    takes += work(s, i, n, r) - slipped;  // the needle's sts the row works
  }
  end_row(s, n, r, takes);
  replace_in_line(s, n);
  let_go_of_used_spare_needles();
  r.end_op = static_cast<std::uint32_t>(out_.ops.size());
  r.sts_after = n.live;
  out_.rows.push_back(r);
  note_course(s, n);
}

PatternRow ProgramPatternBuilder::open_row(const Step& s, const Needle& n) const {
  PatternRow r;
  r.side = s.direction == CourseDirection::right_to_left ? Side::rs : Side::ws;
  r.number =
      static_cast<std::uint32_t>(out_.rows.size()) - section().first_row + section().first_number;
  r.first_op = static_cast<std::uint32_t>(out_.ops.size());
  r.sts_before = n.live;
  return r;
}

std::uint32_t ProgramPatternBuilder::work(const Step& s, std::uint32_t i, Needle& n,
                                          PatternRow& r) {
  StitchId st = p_.stitches[i].stitch;
  note_row_end(st, r);
  if (g_.type[st] == T::sco || g_.type[st] == T::co) return cast_on_in_row(i, n);
  if (g_.type[st] == T::tnbo) return bind_off_with_held_st(i, n);
  append_stitch_ops(g_, st, r.side, out_.mirror, out_.turns, out_.ops, r.wraps_again);
  return move_loops(st, n, s);
}

std::uint32_t ProgramPatternBuilder::bind_off_with_held_st(std::uint32_t i, Needle& n) {
  const Step& s = p_.steps[step_];
  if (held_behind_left_ == 0) {
    // The sts held behind on one needle (or holder); others are held after them. Those that
    // go round past the end of a spare needle are parted there, each part held in turn.
    std::vector<std::uint32_t> behind = held_behind_from(i);
    LoopAt source = places_.at(behind.front());
    std::optional<Lie> lie = places_.lie(source, behind);
    if (!lie && source.place == Place::spare) {
      hold_parts_of_spare_needle(source.index, behind.front(), false);
      behind = held_behind_from(i);
      source = places_.at(behind.front());
      lie = places_.lie(source, behind);
    }
    bool nameable = source.place == Place::holder || source.place == Place::spare;
    if (!nameable || !lie || lie->at != 0)
      not_yet(s,
              "binds off sts held behind that do not wait on one spare needle or holder, "
              "from an end");
    bool holder = source.place == Place::holder;
    PatternSection::Hold h;
    h.section = holder ? places_.holder_section(source.index) : source.index;
    h.count = static_cast<std::uint32_t>(behind.size());
    h.from_last = lie->from_last;
    h.first = p_.stitches[i].stitch;
    h.holder = holder ? source.index : 0;
    h.before_row = static_cast<std::uint32_t>(out_.rows.size());
    section().holds.push_back(h);
    held_behind_left_ = h.count;
  }
  --held_behind_left_;
  out_.ops.push_back(HandOp::tnbo);
  --n.live;
  if (!n.in_round) --n.ahead;
  return 1;
}

std::vector<std::uint32_t> ProgramPatternBuilder::held_behind_from(std::uint32_t i) const {
  const Step& s = p_.steps[step_];
  std::vector<std::uint32_t> behind;
  for (std::uint32_t k = i; k < s.stitches.end; ++k) {
    if (!binds_off_together(k)) continue;
    std::uint32_t held = all_taken_by(k)[1];
    if (!behind.empty() && places_.at(held) != places_.at(behind.front())) break;
    behind.push_back(held);
  }
  return behind;
}

std::uint32_t ProgramPatternBuilder::cast_on_in_row(std::uint32_t i, Needle& n) {
  StitchId st = p_.stitches[i].stitch;
  if (g_.type[st] == T::co) {
    out_.ops.push_back(HandOp::co);
  } else {
    out_.ops.push_back(HandOp::provisional_co);
    PatternSection& sec = section();
    if (sec.row_chain++ == 0) sec.row_chain_ends[0] = st;
    sec.row_chain_ends[1] = st;
    for (const PlacedLoop& m : made_by(i))
      if (m.place == LoopPlace::other_side) places_.add(n.section, Place::chain, m.loop);
  }
  ++n.live;
  if (!n.in_round) ++n.behind;
  return 0;
}

void ProgramPatternBuilder::note_course(const Step& s, Needle& n) {
  StitchId last = p_.stitches[s.stitches.end - 1].stitch;
  for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
    for (std::uint32_t l : all_taken_by(i)) places_.take(l);
    for (const PlacedLoop& m : made_by(i)) {
      if (m.place == LoopPlace::in_run) places_.set({&m.loop, 1}, {Place::needle, current_});
      if (m.place == LoopPlace::along_edge) places_.set({&m.loop, 1}, {Place::edge, n.section});
    }
  }
  n.turn_loops = worked_by_hand(g_, last) == T::sr4 ? made_by(s.stitches.end - 1).size() : 0;
  n.last = s.direction;
  n.worked = true;
  section().stitches += s.stitches.size();
  section().last_row_ends[0] = p_.stitches[s.stitches.begin].stitch;
  section().last_row_ends[1] = last;
}

void ProgramPatternBuilder::ring_course(const Step& s, Needle& n) {
  // Rows on one line of a rnd bound off in places (a bag's flaps between its handles): the
  // lines other yarns work go to holders first.
  if (s.shape != RowShape::closed) hold_what_others_take(s);
  n.opened = n.opened && s.shape != RowShape::closed;
  if (s.run_shape != RunShape::ring && s.run_shape != RunShape::line)
    not_yet(s, "leaves its sts in no known order");
  if (!n.worked && s.direction != n.rnds) {  // the first rnd goes against the cast-on
    std::reverse(n.ring.begin() + 1, n.ring.end());
    n.rnds = s.direction;
    index_ring(n);
  }
  turn_in_ring(s, n);
  std::vector<std::uint32_t> met = on_the_needle(loops_met(s));
  bool forward = s.direction == n.rnds;
  if (forward && !row_open_ && goes_round(s, n.ring.size())) begin_rnd_at_yarn(s, n);
  bool back = check_met_at_the_yarn(s, n, met, forward);
  if (back && row_open_) not_yet(s, "slips a st back in the middle of a row");
  const auto size = static_cast<std::uint32_t>(n.ring.size());
  bool back_across_marker = back && n.gap == 0 && !n.marker_off;
  if (back) n.gap = forward ? (n.gap + size - 1) % size : (n.gap + 1) % size;
  std::uint32_t first = forward ? n.gap : (n.gap + size - 1) % size;
  std::uint32_t taken_so_far = 0;
  for (std::uint32_t i = s.stitches.begin; i < s.stitches.end; ++i) {
    std::uint32_t on_needle = 0, first_loop = kNone;
    for_each_met(taken_by(i), s.direction, [&](std::uint32_t l) {
      if (spare_slot(l) != kNone) return;
      if (on_needle++ == 0) first_loop = l;
    });
    std::uint32_t at = first_loop == kNone ? kNone : pos_[first_loop];
    bool marker = !n.marker_off && row_open_ && pending_takes_ > 0;
    bool at_marker = marker && at == (forward ? 0 : size - 1);
    if (at_marker && i > s.stitches.begin && binds_off_together(i - 1) && binds_off_together(i))
      not_yet(s, "binds off with a three-needle bind-off across the beginning-of-round marker");
    // A row going the rnds' way ends a rnd at the marker (or the rest of one, begun where the
    // yarn was); a row that turns before the marker comes round again slips it.
    bool rnd_ends = row_from_marker_ || met.size() - taken_so_far >= size;
    if (at_marker && forward && rnd_ends) close_ring_row(s, n, false);
    if (at_marker && (!forward || !rnd_ends)) {
      n.marker_slipped_at = static_cast<std::uint32_t>(out_.ops.size());
      n.row_began_at_marker = kNone;
      out_.ops.push_back(HandOp::sm);
    }
    if (!row_open_) {
      row_from_marker_ = forward && (at == 0 || (at == kNone && n.gap == 0));
      open_ring_row(s, n, forward);
      if (back) slip_back_across_gap(n, back_across_marker);
    }
    if (row_from_marker_ && pending_takes_ == 0) n.row_began_at_marker = pending_.first_op;
    if (s.shape != RowShape::closed && decreases_across_marker(i, n)) take_marker_off(s, n);
    note_region_mark(p_.stitches[i].stitch, pending_);
    std::uint32_t slipped = slip_from_spare_needles(i, n);
    pending_takes_ += work(s, i, n, pending_) - slipped;
    taken_so_far += on_needle;
  }
  replace_in_ring(s, n, forward, first, static_cast<std::uint32_t>(met.size()));
  let_go_of_used_spare_needles();
  note_course(s, n);
  if (forward && !n.marker_off && (n.gap == 0 || n.ring.empty())) close_ring_row(s, n, false);
  // Bound off in one or two places (underarms), the rest stays on the circular needle in
  // its order, for a rnd that takes it up again with others (a yoke).
  auto binds_off = [&](const WorkedStitch& w) { return g_.type[w.stitch] == T::bo; };
  if (s.run_shape == RunShape::line && !n.ring.empty() &&
      std::any_of(stitches_of(s).begin(), stitches_of(s).end(), binds_off))
    n.opened = true;
}

bool ProgramPatternBuilder::decreases_across_marker(std::uint32_t worked, const Needle& n) const {
  if (n.marker_off || n.ring.size() < 3) return false;
  const auto last = static_cast<std::uint32_t>(n.ring.size() - 1);
  bool first_st = false, last_st = false;
  for (std::uint32_t l : taken_by(worked)) {
    if (spare_slot(l) != kNone) continue;
    first_st = first_st || pos_[l] == 0;
    last_st = last_st || pos_[l] == last;
  }
  return first_st && last_st;
}

void ProgramPatternBuilder::take_marker_off(const Step& s, Needle& n) {
  // Where the marker was at the tip of the needle last: slipped there, or a row began there.
  if (n.marker_slipped_at != kNone) {
    out_.ops[n.marker_slipped_at] = HandOp::rm;
  } else if (n.row_began_at_marker != kNone) {
    insert_op(n.row_began_at_marker, HandOp::rm);
  } else {
    not_yet(s, "decreases across the beginning-of-round marker");
  }
  n.marker_off = true;
}

void ProgramPatternBuilder::insert_op(std::uint32_t at, HandOp op) {
  out_.ops.insert(out_.ops.begin() + at, op);
  auto shift = [&](std::uint32_t& index, bool at_too) {
    if (index != kNone && (index > at || (at_too && index == at))) ++index;
  };
  for (PatternRow& r : out_.rows) {
    shift(r.first_op, false);  // a row that begins there begins with it
    shift(r.end_op, false);
  }
  if (row_open_) shift(pending_.first_op, false);
  for (Needle& other : needles_) {
    shift(other.marker_slipped_at, true);
    shift(other.row_began_at_marker, false);
  }
}

void ProgramPatternBuilder::turn_in_ring(const Step& s, Needle& n) {
  if (!n.worked || s.direction == n.last) return;
  if (!row_open_) turn_after_last_rnd();
  close_ring_row(s, n, true);
  if (n.turn_loops) step_over_turn(n, s.direction == n.rnds);
  n.last = s.direction;
}

void ProgramPatternBuilder::turn_after_last_rnd() {
  if (out_.rows.size() <= section().first_row) return;  // the last rnd was another piece's
  PatternRow& r = out_.rows.back();
  if (r.end_op != out_.ops.size() || out_.ops.back() == HandOp::wt) return;
  out_.ops.push_back(HandOp::turn);
  ++r.end_op;
  // A rnd that turns at the marker is a row in the rnd that ends there (rows on a rnd bound
  // off in part): a short row, labelled as the rows before and after it.
  r.round = false;
  r.short_row = true;
}

void ProgramPatternBuilder::step_over_turn(Needle& n, bool forward) {
  if (n.ring.empty()) return;
  auto size = static_cast<std::uint32_t>(n.ring.size());
  auto by = static_cast<std::uint32_t>(n.turn_loops % size);
  n.gap = forward ? (n.gap + by) % size : (n.gap + size - by) % size;
  if (out_.turns == TurnMethod::german) ds_next_ = true;
}

bool ProgramPatternBuilder::check_met_at_the_yarn(const Step& s, const Needle& n,
                                                  const std::vector<std::uint32_t>& met,
                                                  bool forward) const {
  const auto size = static_cast<std::uint32_t>(n.ring.size());
  if (met.empty() || met.size() > size) not_yet(s, "takes no loop of the rnd, or too many");
  std::uint32_t first = forward ? n.gap : (n.gap + size - 1) % size;
  std::uint32_t behind = forward ? (first + size - 1) % size : (first + 1) % size;
  // A row may begin with the st behind the yarn (slipped back across the gap), also one that
  // takes every st left (a band's last row, the teapot's top at 14/20).
  bool back = n.ring[first] != met[0] && n.ring[behind] == met[0];
  if (back) first = behind;
  for (std::uint32_t i = 0; i < met.size(); ++i) {
    std::uint32_t want = forward ? (first + i) % size : (first + size - i) % size;
    if (pos_[met[i]] != want || n.ring[want] != met[i])
      not_yet(s, i == 0 ? "begins away from where the yarn is on the needle"
                        : "does not meet its loops side by side on the needle");
  }
  return back;
}

void ProgramPatternBuilder::slip_back_across_gap(Needle& n, bool across_marker) {
  if (across_marker) {
    out_.ops.push_back(HandOp::rm);
    n.marker_off = true;
  }
  out_.ops.push_back(HandOp::slip_back);
}

void ProgramPatternBuilder::open_ring_row(const Step& s, Needle& n, bool forward) {
  pending_ = open_row(s, n);
  pending_takes_ = 0;
  row_open_ = true;
  row_forward_ = forward;
  // The row before ended slipping the marker, then turned: the marker is first now.
  bool slipped_last = n.marker_slipped_at != kNone && n.marker_slipped_at + 2 == out_.ops.size();
  row_at_marker_after_turn_ =
      forward && n.gap == 0 && !n.marker_off && n.worked && s.direction != row_dir_ && slipped_last;
  row_dir_ = s.direction;
  if (pm_next_) out_.ops.push_back(HandOp::pm);
  pm_next_ = false;
  if (ds_next_) out_.ops.push_back(HandOp::ds);
  ds_next_ = false;
}

void ProgramPatternBuilder::close_ring_row(const Step& s, Needle& n, bool turn) {
  if (!row_open_) return;
  PatternRow& r = pending_;
  if (!turn && !row_forward_)
    not_yet(s, "leaves a row in the rnd that neither turns nor ends at the marker");
  r.round = !turn;
  r.short_row = turn;
  if (turn && out_.ops.back() != HandOp::wt && out_.ops.back() != HandOp::no_turn)
    out_.ops.push_back(HandOp::turn);
  if (turn && row_at_marker_after_turn_) {
    out_.ops.insert(out_.ops.begin() + r.first_op, HandOp::sm);
    n.marker_slipped_at = r.first_op;
  }
  if (!turn) n.marker_slipped_at = n.row_began_at_marker = kNone;
  r.end_op = static_cast<std::uint32_t>(out_.ops.size());
  r.sts_after = n.live;
  r.bind_off = n.live == 0 && std::all_of(out_.ops.begin() + r.first_op, out_.ops.end(),
                                          [](HandOp op) { return op == HandOp::bo; });
  r.partial = r.short_row || (!r.bind_off && pending_takes_ != r.sts_before);
  out_.short_rows = out_.short_rows || r.short_row;
  out_.ws_rounds = out_.ws_rounds || (r.round && r.side == Side::ws);
  out_.rows.push_back(r);
  row_open_ = false;
}

void ProgramPatternBuilder::replace_in_ring(const Step& s, Needle& n, bool forward,
                                            std::uint32_t first, std::uint32_t count) {
  const auto size = static_cast<std::uint32_t>(n.ring.size());
  std::uint32_t begin = forward ? first : (first + size + 1 - count) % size;  // in ring order
  std::vector<std::uint32_t> made;
  std::uint32_t bor = n.ring[0], new_bor = kNone;
  for (std::uint32_t k = 0; k < s.stitches.size(); ++k) {
    std::uint32_t i = forward ? s.stitches.begin + k : s.stitches.end - 1 - k;
    auto m = made_by(i);
    auto taken = taken_by(i);
    bool takes_bor = std::find(taken.begin(), taken.end(), bor) != taken.end();
    std::size_t before = made.size();
    bool reversed = (s.direction == CourseDirection::right_to_left) == forward;
    for (std::size_t j = 0; j < m.size(); ++j) {
      const PlacedLoop& pl = m[reversed ? m.size() - 1 - j : j];
      if (pl.place == LoopPlace::in_run) made.push_back(pl.loop);
    }
    if (takes_bor && made.size() > before) new_bor = made[before];
  }
  // A rnd (or a row) that begins at the marker leaves all its loops after it.
  if (forward && first == 0 && !made.empty()) new_bor = made.front();
  std::vector<std::uint32_t> ring = made;
  for (std::uint32_t k = count; k < size; ++k) ring.push_back(n.ring[(begin + k) % size]);
  // `ring` starts at the block; the marker goes before the loop that takes its place.
  std::uint32_t start = static_cast<std::uint32_t>(made.size());
  bool block_has_bor = begin == 0 || begin + count > size;
  if (block_has_bor) {
    if (new_bor == kNone && !made.empty())
      not_yet(s, "binds off the st the beginning-of-round marker sits before");
    start = new_bor == kNone ? 0
                             : static_cast<std::uint32_t>(
                                   std::find(ring.begin(), ring.end(), new_bor) - ring.begin());
  } else {
    start = static_cast<std::uint32_t>(std::find(ring.begin(), ring.end(), bor) - ring.begin());
  }
  if (!ring.empty()) std::rotate(ring.begin(), ring.begin() + start % ring.size(), ring.end());
  n.ring = std::move(ring);
  index_ring(n);
  // The yarn: after the made loops going the rnds' way, before them going back.
  std::uint32_t edge_loop = made.empty() ? kNone : (forward ? made.back() : made.front());
  if (n.ring.empty()) {
    n.gap = 0;
  } else if (edge_loop == kNone) {
    n.gap = 0;
    not_yet(s, "leaves no loop where the yarn is");
  } else {
    auto sz = static_cast<std::uint32_t>(n.ring.size());
    n.gap = forward ? (pos_[edge_loop] + 1) % sz : pos_[edge_loop];
  }
}

void ProgramPatternBuilder::begin_row(const Step& s, Needle& n) {
  if (s.direction == n.last)
    not_yet(s, "is a row that goes on the way the row before went, without turning");
  std::swap(n.ahead, n.behind);
  auto by = static_cast<std::uint32_t>(n.turn_loops);  // past the st it turned at
  n.gap = s.direction == CourseDirection::left_to_right ? n.gap + by : n.gap - std::min(by, n.gap);
  if (!n.double_stitch_next) return;
  out_.ops.push_back(HandOp::ds);
  n.double_stitch_next = false;
  --n.ahead;
  ++n.behind;
}

std::uint32_t ProgramPatternBuilder::move_loops(StitchId st, Needle& n, const Step& s) const {
  const StitchTypeInfo& t = info(worked_by_hand(g_, st));
  n.live = n.live + t.loops_out - t.loops_in;
  if (n.in_round || (t.type == T::sr4 && out_.turns == TurnMethod::wrap_and_turn))
    return t.loops_in;
  if (n.ahead < t.loops_in)
    not_yet(s, fmt::format("works past the end of the needle at {}", g_.describe(st)));
  n.ahead -= t.loops_in;
  n.behind += t.loops_out;
  return t.loops_in;
}

void ProgramPatternBuilder::hold_what_others_work(const Step& s, Needle& n) {
  auto others_take = [&](std::uint32_t l) {
    StitchId taker = g_.loops[l].taker;
    return taker != kNoStitch && yarn_of_[taker] != s.yarn;
  };
  if (std::none_of(n.ring.begin(), n.ring.end(), others_take)) return;
  // Where none stay, the piece is left whole (or joined in the rnd) as it is.
  if (std::all_of(n.ring.begin(), n.ring.end(), others_take)) return;
  if (!n.worked) not_yet(s, "leaves sts to another yarn before its first row");
  // Taken up again, the sts are slipped as it is taken up, naming the row that made them.
  bool taken_up = out_.rows.size() == section().first_row;
  std::uint32_t last_row = taken_up ? kNone : static_cast<std::uint32_t>(out_.rows.size() - 1);
  for (std::uint32_t l : n.ring) {
    StitchId maker = g_.loops[l].maker;
    std::uint32_t row = maker == kNoStitch ? kNone : row_of_[maker];
    if (taken_up && row != kNone) last_row = last_row == kNone ? row : std::max(last_row, row);
  }
  if (last_row == kNone) not_yet(s, "leaves sts to another yarn before its first row");
  // The sts counted are the last row's: all of the needle's, or after a short row (a strip
  // going round a corner), those it worked, the others staying where they wait.
  auto [lo, hi] = n.ahead == 0 ? std::pair<std::uint32_t, std::uint32_t>{0, n.ring.size()}
                               : last_rows_sts(n, last_row);
  for (std::uint32_t i = 0; i < n.ring.size(); ++i)
    if ((i < lo || i >= hi) && others_take(n.ring[i]))
      not_yet(s, "leaves sts to another yarn that its last row did not work");
  std::vector<std::uint32_t> order(n.ring.begin() + lo, n.ring.begin() + hi);
  bool right_to_left = n.last == CourseDirection::right_to_left;
  if (right_to_left) std::reverse(order.begin(), order.end());  // as the last row worked them
  std::size_t held_before = section().holdings.size();
  std::vector<std::uint32_t> stay = hold_blocks(
      order, [&](std::uint32_t l) { return !others_take(l); }, true);
  for (std::size_t k = held_before; taken_up && k < section().holdings.size(); ++k)
    section().holdings[k].of_number = out_.rows[last_row].number;
  if (right_to_left) std::reverse(stay.begin(), stay.end());
  std::uint32_t before_gap = 0, held = 0;
  for (std::uint32_t i = lo; i < hi; ++i) {
    bool leaves = others_take(n.ring[i]);
    before_gap += leaves && i < n.gap;
    if (leaves) held += hand_stitch_count(g_, {n.ring.data() + i, 1});
  }
  stay.insert(stay.begin(), n.ring.begin(), n.ring.begin() + lo);
  stay.insert(stay.end(), n.ring.begin() + hi, n.ring.end());
  n.ring = std::move(stay);
  n.gap -= before_gap;
  n.live -= held;
  n.behind -= held;
  index_ring(n);
}

std::pair<std::uint32_t, std::uint32_t> ProgramPatternBuilder::last_rows_sts(
    const Needle& n, std::uint32_t last_row) const {
  auto of_last_row = [&](std::uint32_t l) {
    StitchId maker = g_.loops[l].maker;
    return maker != kNoStitch && row_of_[maker] == last_row;
  };
  // They lie side by side, ending at the yarn.
  std::uint32_t lo = n.gap, hi = n.gap;
  if (n.last == CourseDirection::right_to_left) {
    while (hi < n.ring.size() && of_last_row(n.ring[hi])) ++hi;
  } else {
    while (lo > 0 && of_last_row(n.ring[lo - 1])) --lo;
  }
  return {lo, hi};
}

void ProgramPatternBuilder::check_met_along_the_row(const Step& s, const Needle& n) const {
  std::vector<std::uint32_t> met = on_the_needle(loops_met(s));
  bool right = s.direction == CourseDirection::left_to_right;
  if (met.size() > (right ? n.ring.size() - std::min<std::size_t>(n.gap, n.ring.size()) : n.gap))
    not_yet(s, "works past the end of the needle");
  for (std::uint32_t i = 0; i < met.size(); ++i)
    if (n.ring[right ? n.gap + i : n.gap - 1 - i] != met[i])
      not_yet(s, i == 0 ? "begins away from where the yarn is on the needle"
                        : "does not meet its loops side by side on the needle");
}

void ProgramPatternBuilder::replace_in_line(const Step& s, Needle& n) {
  bool right = s.direction == CourseDirection::left_to_right;
  std::vector<std::uint32_t> made;
  std::uint32_t taken = 0;
  for (std::uint32_t k = 0; k < s.stitches.size(); ++k) {
    std::uint32_t i = right ? s.stitches.begin + k : s.stitches.end - 1 - k;
    for (std::uint32_t l : taken_by(i)) taken += spare_slot(l) == kNone;
    for (const PlacedLoop& m : made_by(i))
      if (m.place == LoopPlace::in_run) made.push_back(m.loop);
  }
  std::uint32_t lo = right ? n.gap : n.gap - taken;
  n.ring.erase(n.ring.begin() + lo, n.ring.begin() + lo + taken);
  n.ring.insert(n.ring.begin() + lo, made.begin(), made.end());
  n.gap = right ? lo + static_cast<std::uint32_t>(made.size()) : lo;
  index_ring(n);
}

void ProgramPatternBuilder::end_row(const Step& s, Needle& n, PatternRow& r, std::uint32_t takes) {
  StitchId last = p_.stitches[s.stitches.end - 1].stitch;
  r.short_row = !r.round && n.ahead > 0;
  if (r.short_row && out_.ops.back() != HandOp::wt) out_.ops.push_back(HandOp::turn);
  n.double_stitch_next = out_.turns == TurnMethod::german && worked_by_hand(g_, last) == T::sr4;
  if (r.round && takes != r.sts_before)
    not_yet(s, fmt::format("is a rnd that works {} of the {} live stitches", takes, r.sts_before));
  r.partial = r.short_row || (!r.bind_off && takes != r.sts_before);
  out_.short_rows = out_.short_rows || r.short_row;
  if (!r.round) check_make_one_has_a_strand(g_, last);
}

void ProgramPatternBuilder::note_region_mark(StitchId st, const PatternRow& r) {
  auto at = marked_.find(st);
  if (at == marked_.end()) return;
  out_.region_marks.push_back({static_cast<std::uint32_t>(out_.rows.size()),
                               static_cast<std::uint32_t>(out_.ops.size()) - r.first_op,
                               at->second});
}

}  // namespace skein::hand::from_program
