// The emitter rolls a tube round on its needles (emitter.hpp has the state): every loop moves
// the same number of places along the ring of the tube's loops, over the folds where it must,
// the needles the loops occupy staying the same. A cast-on along a split needs it where one
// branch (a thumb) lies on one bed: rolled so that a fold runs through the middle of that
// branch, each branch goes round one fold and the crotch closes both as tubes.
//
// A roll goes in stages of at most the transfer reach: loops moving along their bed go out to
// the facing needle at rack 0 (empty in half gauge) and land at the stage's racking; loops that
// go over a fold go straight across, once the loops on their new needles have left.
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "common/error.hpp"
#include "knitout/emitter.hpp"

namespace skein::knitout::emit {

// The places the tube's loops occupy, in ring order (front left to right, back right to left):
// one loop a needle, and no loop facing another (a half-gauge tube), else none.
std::vector<std::uint32_t> Emitter::loops_round_the_tube() const {
  std::vector<std::uint32_t> loops(on_needles_);
  std::sort(loops.begin(), loops.end(), [&](std::uint32_t a, std::uint32_t b) {
    return ring(live_[a].home) < ring(live_[b].home);
  });
  std::vector<std::uint8_t> used(p_.needles, 0);
  for (std::uint32_t loop : loops) {
    std::uint8_t& u = used[static_cast<std::size_t>(live_[loop].home.needle)];
    if (u++ || is_turn_loop(loop)) return {};
  }
  return loops;
}

// The roll (in places along the ring) that puts a fold between ring places lo and hi (an arc
// on one bed), through its middle, the shortest way round; `front`: the loops on the front.
std::int32_t Emitter::roll_onto_fold(std::int32_t lo, std::int32_t hi, std::int32_t front,
                                     std::int32_t n) {
  std::int32_t best = n;
  // A fold lies between places f - 1 and f: f = front (the right fold), 0 or n (the left).
  for (std::int32_t f : {front, 0, n}) {
    std::int32_t r = f - lo - (hi - lo + 1) / 2;
    if (std::abs(r) < std::abs(best)) best = r;
  }
  return best;
}

// Where a branch's arc ends on the bed where it starts, rolls the tube so that a fold runs
// between the two ends: the branch on one bed (or the other, round both folds) then goes
// round one fold. Only a tube alone on the bed rolls (no branch of it waiting beside it).
void Emitter::roll_branch_onto_fold(const Course& c) {
  std::vector<Move> home;
  for (std::uint32_t loop : on_needles_) {
    LoopPlace& lp = live_[loop];
    if (lp.now != lp.home) home.push_back({lp.now, lp.home});
    lp.now = lp.home;
  }
  queue_moves(home);
  flush_moves();
  std::vector<std::uint32_t> loops =
      c.alone ? loops_round_the_tube() : std::vector<std::uint32_t>{};
  auto index = [&](std::uint32_t loop) {
    return static_cast<std::int32_t>(std::find(loops.begin(), loops.end(), loop) - loops.begin());
  };
  auto n = static_cast<std::int32_t>(loops.size());
  std::int32_t e = index(c.arc_end), s = index(c.arc_start);
  if (e == n || s == n || e == s)
    unsupported_split(c,
                      "a cast-on along a split whose branch lies on one bed of a tube that cannot "
                      "roll (a branch waits beside it, or its loops are stacked)");
  auto front = static_cast<std::int32_t>(std::count_if(
      loops.begin(), loops.end(), [&](std::uint32_t l) { return live_[l].home.bed == Bed::f; }));
  std::int32_t by = roll_onto_fold(std::min(e, s), std::max(e, s), front, n);
  std::vector<Place> slots;
  for (std::uint32_t loop : loops) slots.push_back(live_[loop].home);
  // A stage moves each loop at most the reach, and no further than half the shorter half, so
  // that the loops on a fold's new needles are ones that move along their bed.
  std::int32_t most = std::min({reach_ / pitch_, front / 2, (n - front) / 2});
  rolled_ = true;
  w_.line(fmt::format(";!source: row {} transfers: the tube rolled {} places round its needles",
                      c.row + 1, by));
  for (std::int32_t rolled = 0; rolled != by;) {
    std::int32_t step = std::clamp(by - rolled, -most, most);
    if (step == 0 || !roll_stage(loops, slots, step))
      unsupported_split(c,
                        fmt::format("a cast-on along a split whose branch lies on one bed, where "
                                    "the tube cannot roll a fold into the branch within {}'s "
                                    "transfer stretch of {}",
                                    p_.name, p_.max_transfer_stretch));
    rolled += step;
  }
  flush_moves();
}

// One stage of a roll: each loop to the place `step` further round the ring. False (nothing
// written) where a transfer would stretch further than the profile allows.
bool Emitter::roll_stage(std::vector<std::uint32_t>& loops, const std::vector<Place>& slots,
                         std::int32_t step) {
  auto n = static_cast<std::int32_t>(loops.size());
  std::vector<Move> out, over, landing;
  for (std::int32_t i = 0; i < n; ++i) {
    Place from = slots[static_cast<std::size_t>(i)],
          to = slots[static_cast<std::size_t>(((i + step) % n + n) % n)];
    bool along = from.bed == to.bed;
    Move m = along ? Move{facing(from), to} : Move{from, to};
    if (std::abs(rack_of(m)) > p_.max_transfer_stretch) return false;
    if (along) out.push_back({from, facing(from)});
    (along ? landing : over).push_back(m);
  }
  queue_moves(out);
  queue_moves(over);
  queue_moves(landing);
  std::vector<std::uint32_t> rolled(loops.size());
  for (std::int32_t i = 0; i < n; ++i) {
    auto to = static_cast<std::size_t>(((i + step) % n + n) % n);
    rolled[to] = loops[static_cast<std::size_t>(i)];
    live_[rolled[to]] = {slots[to], slots[to]};
  }
  loops = std::move(rolled);
  return true;
}

}  // namespace skein::knitout::emit
