// The emitter's cast-on along a split (a crotch, sco sts): a tube parts into two branches, each
// knit where its loops wait, and the crotch's sts close each branch into a tube of its own
// (emitter.hpp has the state).
//
// The branches are the tube's two arcs between the places where it parts, one round each fold
// (as trousers' legs): on each bed one lies left of the cut, the other right of it. The loops
// left of the cuts move left to open a gap on each bed; each crotch st makes one loop for each
// branch in the gap, the first branch's beside its arc, the second's beside the other arc, the
// sts next to where the first branch's arc ends on that end's bed, the others on the other bed,
// so both branches close as tubes. Every loop is made on the front bed (on the needle facing its
// place when that is on the back, then moved there): the yarn lays them in the order of the
// sts, each st's first branch's loop left of its second's in the st's own frame.
#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "common/error.hpp"
#include "knitout/emitter.hpp"

namespace skein::knitout::emit {

void Emitter::unsupported_split(const Course& c, const std::string& what) const {
  throw UnsupportedError(fmt::format("not yet supported by the knitout target: {}, at {}", what,
                                     g_.describe(l_.order[c.begin])));
}

// The loop's place in the fabric (an sr5's turn loop waits on the facing bed).
Place Emitter::fabric_place(std::uint32_t loop) const {
  return {fabric_bed(loop), live_[loop].home.needle};
}

bool Emitter::on_the_bed(std::uint32_t loop) const {
  return loop < index_on_needles_.size() && index_on_needles_[loop] < on_needles_.size() &&
         on_needles_[index_on_needles_[loop]] == loop;
}

Emitter::Crotch Emitter::plan_crotch(const Course& c) {
  if (!l_.tube || !on_the_bed(c.arc_end) || !on_the_bed(c.arc_start))
    unsupported_split(c, "a cast-on along a split that does not close a branch of a tube");
  if (fabric_place(c.arc_end).bed == fabric_place(c.arc_start).bed) roll_branch_onto_fold(c);
  Place end = fabric_place(c.arc_end), start = fabric_place(c.arc_start);
  Crotch k;
  // The first branch is right of the cuts when its arc reaches the crotch from the back (it
  // goes round the tube's right fold), left of them otherwise.
  k.first_right = end.bed == Bed::b;
  auto sts = c.end - c.begin;
  std::array<std::uint32_t, 2> count{};
  count[bed_index(end.bed)] = crotch_sts_on_end_bed(sts);
  count[bed_index(start.bed)] = sts - count[bed_index(end.bed)];
  for (Bed b : {Bed::f, Bed::b}) {
    std::size_t i = bed_index(b);
    k.gap[i] = 2 * static_cast<std::int32_t>(count[i]);
    k.cut[i] = (end.bed == b ? end : start).needle + (k.first_right ? 0 : 1);
  }
  k.on_end_bed = count[bed_index(end.bed)];
  k.end_bed = end.bed;
  make_crotch_room(c, k);
  return k;
}

// The loops on one side of the cut on each bed (every piece's) move away by the gap: left
// where the bed has room for them, else right.
void Emitter::make_crotch_room(const Course& c, Crotch& k) {
  auto needles = static_cast<std::int32_t>(p_.needles);
  std::int32_t short_by = std::numeric_limits<std::int32_t>::max();  // on the better side
  for (bool right : {false, true}) {
    room_.clear();
    std::int32_t over = 0;
    for (std::uint32_t loop : on_needles_) {
      std::size_t i = bed_index(fabric_place(loop).bed);
      if (k.gap[i] == 0 || (fabric_place(loop).needle >= k.cut[i]) != right) continue;
      std::int32_t to = live_[loop].home.needle + (right ? 1 : -1) * k.gap[i] * pitch_;
      over = std::max(over, right ? to - (needles - 1) : -to);
      room_.push_back({loop, {live_[loop].home.bed, to}});
    }
    short_by = std::min(short_by, over);
    if (over > 0) continue;
    for (std::size_t i = 0; i < 2; ++i) {  // the tube's loops: front on even needles, back odd
      auto parity = static_cast<std::int32_t>(i);
      std::int32_t first_right = k.cut[i] + ((k.cut[i] & 1) != parity ? 1 : 0);
      k.bottom[i] = right ? first_right : first_right - k.gap[i] * pitch_;
    }
    std::sort(room_.begin(), room_.end(), [](const RoomMove& a, const RoomMove& b) {
      return std::pair(a.to.bed, a.to.needle) < std::pair(b.to.bed, b.to.needle);
    });
    return;
  }
  throw UnsupportedError(fmt::format(
      "{}: the cast-on along a split at {} needs {} more needles on one side of the tube, for "
      "the crotch's loops between the branches ({} has needles 0..{})",
      c_.input, g_.describe(l_.order[c.begin]), short_by, p_.name, needles - 1));
}

// The needles of a crotch st's loops: {first branch's, second's}.
std::array<Place, 2> Emitter::crotch_places(const Crotch& k, std::uint32_t i,
                                            std::uint32_t sts) const {
  bool near_end = i < k.on_end_bed;
  Bed b = near_end ? k.end_bed : other(k.end_bed);
  std::size_t bi = bed_index(b);
  auto d = static_cast<std::int32_t>(near_end ? i : sts - 1 - i);  // from the arc it closes
  std::int32_t g = k.gap[bi];
  auto needle = [&](std::int32_t slot) { return Place{b, k.bottom[bi] + slot * pitch_}; };
  Place left = needle(d), right = needle(g - 1 - d);
  return k.first_right ? std::array{right, left} : std::array{left, right};
}

void Emitter::cast_on_along_split(const Course& c) {
  source(c, "transfers (room for a cast-on along a split)");
  Crotch k = plan_crotch(c);
  std::vector<std::uint8_t> ready(c.end - c.begin, 1);  // its sts take no loops
  go_home(c, ready, true);
  shift_stacks(c, ready);
  flush_moves();
  room_.clear();
  auto sts = c.end - c.begin;
  // A carrier brought in moves to the crotch's needle furthest the profile's way first, so
  // that a hook holding its end there blocks none of them.
  for (std::uint32_t j = 0; j < sts; ++j) {
    std::array<Place, 2> places = crotch_places(k, j, sts);
    StitchPlan& sp = plan_[l_.order[c.begin + j]];
    sp = {};
    sp.needle = p_.first_pass == Direction::plus ? std::min(places[0].needle, places[1].needle)
                                                 : std::max(places[0].needle, places[1].needle);
  }
  if (c.first_of_yarn) bring_in(c);
  source(c, "cast-on along a split");
  Direction d = p_.first_pass;
  std::vector<Move> to_back;
  for (std::uint32_t j = 0; j < sts; ++j, d = opposite(d)) {
    StitchId s = l_.order[c.begin + j];
    std::array<Place, 2> places = crotch_places(k, c.left_to_right ? j : sts - 1 - j, sts);
    // Made on the front, seen from the right side: the yarn makes the st's slots in its
    // direction (along its loops: whichever way this pass goes).
    bool ltr = g_.direction[s] == CourseDirection::along_its_loops ? d == Direction::plus
                                                                   : l_.left_to_right[s] != 0;
    d = ltr ? Direction::plus : Direction::minus;
    track_loops(s);
    auto made = g_.loops_made_by(s);
    for (std::uint8_t i = 0; i < 2; ++i) {
      std::uint8_t slot = made_slot_along_yarn(StitchType::sco, ltr, i, 2);
      Place home = places[slot], made_at{Bed::f, home.needle};
      w_.tuck(d, at(made_at), carrier_);
      live_[made[slot]] = {home, home};  // moved there next
      if (home != made_at) to_back.push_back({made_at, home});
    }
  }
  if (c.first_of_yarn) release(carrier_);
  queue_moves(to_back);
  flush_moves();
  if (c.last_of_yarn) leave_loops(c);
}

}  // namespace skein::knitout::emit
