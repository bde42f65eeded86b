// The emitter's transfers between two courses: loops home, decrease stacks in lean order,
// stacks re-spaced within the racking limit, purls to the other bed (emitter.hpp has the state).
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "common/error.hpp"
#include "knitout/emitter.hpp"

namespace skein::knitout::emit {

// The course's transfers are planned three ways: loops moving along a bed go over first where
// the machine is racked for one of them already, always out through the facing needle first,
// or over first wherever they can (route_through_other_bed). The plan written is the one that
// needs the fewest rack changes, counting the change to rack 0 that the course's knitting may
// need after (TransferOrder::better_than; of equals, the first).
void Emitter::transition(const Course& c) {
  source(c, "transfers");
  bool zero_after = needs_rack_zero(c);
  std::vector<LoopPlace> before(on_needles_.size()), best_live;
  for (std::size_t i = 0; i < on_needles_.size(); ++i) before[i] = live_[on_needles_[i]];
  std::vector<Move> best_moves;
  std::vector<std::uint32_t> best_batches;
  TransferOrder best;
  could_go_over_first_ = false;
  for (Route route : {Route::as_racked, Route::out_first, Route::over_first}) {
    if (route != Route::as_racked) {
      if (!could_go_over_first_) break;
      for (std::size_t i = 0; i < on_needles_.size(); ++i) live_[on_needles_[i]] = before[i];
    }
    route_ = route;
    plan_transfers(c);
    TransferOrder order = best_order(zero_after);
    if (route == Route::as_racked || order.better_than(best)) {
      best = std::move(order);
      best_moves = std::move(pending_);
      best_batches = std::move(batch_ends_);
      best_live.resize(on_needles_.size());
      for (std::size_t i = 0; i < on_needles_.size(); ++i) best_live[i] = live_[on_needles_[i]];
    }
    pending_.clear();
    batch_ends_.clear();
    batch_rack_ = w_.racking();
  }
  for (std::size_t i = 0; i < on_needles_.size(); ++i) live_[on_needles_[i]] = best_live[i];
  pending_ = std::move(best_moves);
  batch_ends_ = std::move(best_batches);
  route_ = Route::as_racked;
  write_moves(best);
}

void Emitter::plan_transfers(const Course& c) {
  std::vector<std::uint8_t> ready(c.end - c.begin, 0);  // already on its knit needle
  go_home(c, ready, !fits_one_stage(c) || shaped());
  merge_decreases(c);
  shift_stacks(c, ready);
  send_purls(c, ready);
}

// True when every loop reaches its new needle in one transfer: then a loop already where its
// next stitch is knit may stay there, as no stack passes through its needle on the way.
bool Emitter::fits_one_stage(const Course& c) const {
  std::int32_t fold = ring_fold(c);
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    Place target{plan_[l_.order[i]].home, plan_[l_.order[i]].needle};
    for (std::uint32_t loop : taken(l_.order[i]))
      if (next_stop(live_[loop].home, target, live_[loop].home.bed != target.bed, fold) != target)
        return false;
  }
  return true;
}

// Loops knit on the other bed (purls, kfb's second loop) go back to their home needle,
// unless (when not `staged`) the next stitch takes that loop alone right where it is.
// A waiting loop the room moves, or that the course's turn wraps, goes home too (a kfb's
// second loop waits on the facing needle until then), so that the wrap lies where it rests.
void Emitter::go_home(const Course& c, std::vector<std::uint8_t>& ready, bool staged) {
  std::vector<Move> moves;
  auto send_home = [&](std::uint32_t loop) {
    LoopPlace& lp = live_[loop];
    if (lp.now != lp.home) moves.push_back({lp.now, lp.home});
    lp.now = lp.home;
  };
  for (const RoomMove& r : room_) send_home(r.loop);
  if (c.wrap != kNoWrap && !c.wrap_back) send_home(c.wrap);
  // Beside pieces side by side, the loops that wait (a crotch between two legs) rest at home:
  // the transfers hop past them on the needles their tube leaves empty.
  if (l_.tube && beside_left_ + beside_right_ > 0) {
    for (std::uint32_t i = c.begin; i < c.end; ++i)
      for (std::uint32_t loop : taken(l_.order[i])) in_course_[loop] = 1;
    for (std::uint32_t loop : on_needles_)
      if (!in_course_[loop]) send_home(loop);
    for (std::uint32_t i = c.begin; i < c.end; ++i)
      for (std::uint32_t loop : taken(l_.order[i])) in_course_[loop] = 0;
  }
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    StitchId s = l_.order[i];
    const StitchPlan& sp = plan_[s];
    bool alone = taken(s).size() == 1 && !staged;
    for (std::uint32_t loop : taken(s)) {
      LoopPlace& lp = live_[loop];
      if (alone && lp.now == Place{sp.knit, sp.needle} && lp.now.needle == lp.home.needle) {
        ready[i - c.begin] = 1;
        continue;
      }
      if (lp.now == lp.home) continue;
      moves.push_back({lp.now, lp.home});
      lp.now = lp.home;
    }
  }
  queue_moves(moves);
}

// Each decrease's loops land on its bottom loop's needle in stacking order (the lean).
void Emitter::merge_decreases(const Course& c) {
  for (std::size_t stage = 1; stage < 3; ++stage) {
    std::vector<StitchId> stacking;  // the decreases with a loop to land in this stage
    for (std::uint32_t i = c.begin; i < c.end; ++i)
      if (stage < stacking_order(g_.type[l_.order[i]]).size()) stacking.push_back(l_.order[i]);
    if (stacking.empty()) return;
    std::vector<Move> along, to_transit, landing;
    std::vector<std::uint8_t> busy = busy_needles();
    for (StitchId s : stacking) {
      auto order = stacking_order(g_.type[s]);
      Place bottom = live_[taken(s)[order[0]]].now;
      LoopPlace& lp = live_[taken(s)[order[stage]]];
      bool along_bed = lp.now.bed == bottom.bed;
      bool near = std::abs(along_bed ? lp.now.needle - bottom.needle : rack_of({lp.now, bottom})) <=
                  p_.max_transfer_stretch;
      if (along_bed && !near && !l_.tube)  // a sheet's needles between hold its loops
        throw UnsupportedError(fmt::format(
            "not yet supported by the knitout target: a {} whose loops are {} needles apart, "
            "further than {} transfers a loop ({}), at {}",
            info(g_.type[s]).name, std::abs(lp.now.needle - bottom.needle), p_.name,
            p_.max_transfer_stretch, g_.describe(s)));
      if (along_bed && near) {
        along.push_back({lp.now, bottom});
      } else if (near) {
        landing.push_back({lp.now, bottom});
      } else {  // from bed to bed over a tube's empty needles (past loops that wait there)
        Place from = lp.now;
        for (Place hop : hops_between(lp.now, bottom, &busy)) {
          std::vector<Move> one{{from, hop}};  // each its own batch: they follow each other
          queue_moves(one);
          from = hop;
        }
      }
      lp.now = lp.home = bottom;
    }
    route_through_other_bed(along, &busy, to_transit, landing);
    queue_moves(to_transit);
    queue_moves(landing);
  }
}

// A loop moved straight to the other bed. Between a tube's two left ends (a k2tog across the
// round's start, the bind-off chain) it may have further to go than one transfer stretches:
// it then hops from bed to bed, as far as the profile allows each time, over needles strictly
// between the two ends with the parity of the one further right. Those are empty: on that
// end's bed they lie beyond its loops, on the other bed they face them and hold none. Where a
// fold is slanted (a branch's crotch, its ends far apart), loops lie between the two ends: with
// `busy` given, the hops then land on the needles a tube leaves empty (odd in front, even at
// the back), which face its loops.
void Emitter::move_across_beds(Place from, Place to, const std::vector<std::uint8_t>* busy) {
  for (Place hop : hops_between(from, to, busy)) {
    w_.xfer(at(from), at(hop));
    from = hop;
  }
}
std::vector<Place> Emitter::hops_between(Place from, Place to,
                                         const std::vector<std::uint8_t>* busy) const {
  std::vector<Place> hops = hops_across(from, to, false);
  if (busy && std::any_of(hops.begin(), hops.end() - 1,
                          [&](Place p) { return (*busy)[needle_slot(p)] != 0; }))
    hops = hops_across(from, to, true);
  return hops;
}
std::vector<Place> Emitter::hops_across(Place from, Place to, bool tube_free) const {
  std::int32_t stretch = p_.max_transfer_stretch, parity = std::max(from.needle, to.needle) & 1;
  std::vector<Place> hops;
  Place now = from;
  while (now.bed == to.bed || std::abs(to.needle - now.needle) > stretch) {
    std::int32_t dir = to.needle > now.needle ? 1 : -1;
    std::int32_t n = now.needle + dir * std::min(stretch, std::abs(to.needle - now.needle));
    Bed bed = other(now.bed);
    if ((n & 1) != (tube_free ? (bed == Bed::f ? 1 : 0) : parity)) n -= dir;
    now = {bed, n};
    hops.push_back(now);
  }
  hops.push_back(to);
  return hops;
}

// A loop's place along the fabric, left to right in the stitches' frames: the needle on a
// sheet; on a tube, counted from the right fold (front f2R is 0, back b2R+1 is 1), so that
// the front reads ..., -1, 0 and the back 1, 2, ... and a fold is crossed between 0 and 1.
std::int32_t Emitter::ring(Place p, std::int32_t fold) const {
  if (!l_.tube) return p.needle;
  return p.bed == Bed::f ? p.needle / 2 - fold : fold - (p.needle - 1) / 2 + 1;
}
Place Emitter::place_at(std::int32_t u, std::int32_t fold) const {
  if (!l_.tube) return {Bed::f, u};
  return u <= 0 ? Place{Bed::f, 2 * (fold + u)} : Place{Bed::b, 2 * (fold - u + 1) + 1};
}

// The fold a course's loops are counted round when they move along the fabric: the course's
// right fold, or further right where loops it takes lie beyond it (a tube cast on beside the
// others, right of them, whose loops a joining round takes): counted from there, every loop
// and every needle of the course lies in one order round the bed.
std::int32_t Emitter::ring_fold(const Course& c) const {
  std::int32_t fold = fold_;
  if (!l_.tube) return fold;
  for (std::uint32_t i = c.begin; i < c.end; ++i)
    for (std::uint32_t loop : taken(l_.order[i]))
      fold = std::max({fold, live_[loop].now.needle / 2, live_[loop].home.needle / 2});
  return fold;
}

// Re-spaces the stacks onto the course's needles in stages: in each, every stack moves at
// most the transfer reach toward its needle (along its bed, or along the fabric across a
// tube's fold). Moving every stack the same clamped way keeps their order, so no two ever
// meet. Stacks moving along a bed pass through the facing needle; stacks crossing the fold
// go straight over once the others have left for the facing needles.
void Emitter::shift_stacks(const Course& c, const std::vector<std::uint8_t>& ready) {
  struct Stack {
    StitchId stitch;  // kNoStitch for a waiting loop the room moves
    Place now, target;
    std::uint32_t waiting = kNoWrap;
  };
  std::vector<Stack> stacks;
  bool crossing = false;
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    StitchId s = l_.order[i];
    if (ready[i - c.begin]) continue;
    stacks.push_back({s, live_[taken(s)[0]].now, {plan_[s].home, plan_[s].needle}});
    crossing |= stacks.back().now.bed != stacks.back().target.bed;
  }
  for (const RoomMove& r : room_) stacks.push_back({kNoStitch, live_[r.loop].now, r.to, r.loop});
  if (stacks.empty()) return;
  std::vector<std::uint8_t> busy = busy_needles();
  std::int32_t fold = ring_fold(c);
  for (bool moved = true; moved;) {
    moved = false;
    std::vector<Move> along, to_transit, over, landing;
    for (Stack& st : stacks) {
      if (st.now == st.target) continue;
      moved = true;
      Place stop = next_stop(st.now, st.target, crossing, fold);
      if (stop.bed == st.now.bed)
        along.push_back({st.now, stop});
      else
        over.push_back({st.now, stop});
      st.now = stop;
    }
    // Stacks going over a fold land on the other bed between the two batches.
    route_through_other_bed(along, &busy, to_transit, landing);
    queue_moves(to_transit);
    queue_moves(over);
    queue_moves(landing);
  }
  for (const Stack& st : stacks) {
    if (st.stitch == kNoStitch) {
      live_[st.waiting] = {st.target, st.target};
      continue;
    }
    for (std::uint32_t loop : taken(st.stitch)) live_[loop].now = live_[loop].home = st.target;
  }
}

// Moves along one bed go through the other: out to the facing needle at rack 0 and over at
// the step's racking, or over first, to the needle facing where they land, and in at rack 0.
// The second is possible where the needles facing their landings are free (`busy`; none
// given: the first way); which is taken is the course's plan's route (transition). As racked,
// the second where it saves a rack change: the machine is racked for one of the moves already
// (the racking the batches queued so far leave).
void Emitter::route_through_other_bed(const std::vector<Move>& along,
                                      const std::vector<std::uint8_t>* busy,
                                      std::vector<Move>& to_transit, std::vector<Move>& landing) {
  bool free = busy && !along.empty(), saves = false;
  for (const Move& m : along) {
    free = free && !(*busy)[needle_slot(facing(m.to))];
    saves |= rack_of({m.from, facing(m.to)}) == batch_rack_;
  }
  could_go_over_first_ |= free;
  bool over_first = free && (route_ == Route::over_first ||
                             (route_ == Route::as_racked && batch_rack_ != 0 && saves));
  for (const Move& m : along) {
    Place via = over_first ? facing(m.to) : facing(m.from);
    to_transit.push_back({m.from, via});
    landing.push_back({via, m.to});
  }
}

// One stage's stop toward `target`: along the bed by at most the reach, or, when some loops
// cross a tube's fold (which then stays put), along the fabric across the fold.
Place Emitter::next_stop(Place now, Place target, bool crossing, std::int32_t fold) const {
  if (now == facing(target)) return target;  // an sr5's stack, gathered on its turn loop
  if (!crossing)
    return {now.bed, std::clamp(target.needle, now.needle - reach_, now.needle + reach_)};
  std::int32_t u = ring(now, fold), step = reach_ / pitch_;
  return place_at(std::clamp(ring(target, fold), u - step, u + step), fold);
}

void Emitter::send_purls(const Course& c, const std::vector<std::uint8_t>& ready) {
  std::vector<Move> moves;
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    StitchId s = l_.order[i];
    const StitchPlan& sp = plan_[s];
    if (ready[i - c.begin] || sp.knit == sp.home || taken(s).empty()) continue;
    moves.push_back({{sp.home, sp.needle}, {sp.knit, sp.needle}});
    for (std::uint32_t loop : taken(s)) live_[loop].now = {sp.knit, sp.needle};
  }
  queue_moves(moves);
}

}  // namespace skein::knitout::emit
