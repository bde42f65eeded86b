// The emitter fits the piece on the profile and lays each course out on the needles: where
// each stitch is knit, and the room a short row's shaping makes (emitter.hpp has the state).
#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "common/error.hpp"
#include "knitout/emitter.hpp"

namespace skein::knitout::emit {

Emitter::Footprint Emitter::measure(const Course& c) const {
  Footprint f;
  each_in_layout_order(c, [&](StitchId s) { f.total += footprint(g_.type[s]); });
  if (!l_.tube) return f;
  // The back takes what is left once the front holds at least half.
  each_in_layout_order(c, [&](StitchId s) {
    if (2 * f.front < f.total) {
      f.front += footprint(g_.type[s]);
      ++f.split;
    }
  });
  return f;
}
std::uint32_t Emitter::needles_needed(const Footprint& f) const {
  return l_.tube ? 2 * std::max(f.front, f.total - f.front) : f.total;
}

// Checks that the piece fits the profile, and centres a tube's widest course on the bed.
void Emitter::check_fit() {
  check_width();
  check_needle_loads();
  if (reach_ < pitch_)
    throw UnsupportedError(
        fmt::format("{} allows no sideways transfer (racking.max_transfer_stretch {})", p_.name,
                    p_.max_transfer_stretch));
}

void Emitter::check_width() {
  std::uint32_t widest = 0;
  const Course* at_course = nullptr;
  for (const Course& c : l_.courses) {
    std::uint32_t n = needles_needed(measure(c));
    if (n > widest) widest = n, at_course = &c;
  }
  std::int32_t span = static_cast<std::int32_t>(p_.needles / 2),
               half = static_cast<std::int32_t>(widest / 2);
  fold_ = (span + half) / 2 - 1;
  if (widest > p_.needles)
    throw UnsupportedError(fmt::format("{} needs {} needles{} (row {}, from {}), {} has {}",
                                       c_.input, widest, l_.tube ? " in half gauge" : "",
                                       at_course->row + 1, g_.describe(l_.order[at_course->begin]),
                                       p_.name, p_.needles));
  check_side_by_side();
}

// Sheets cast on beside the first (flaps a later row joins): the needles they take at their
// cast-on, one empty needle apart, left and right of the first, so that the first is placed
// where all of them fit.
void Emitter::check_side_by_side() {
  for (const Course& c : l_.courses) {
    if (c.beside == Beside::none) continue;
    auto width = static_cast<std::int32_t>(needles_needed(measure(c))) + pitch_;
    (c.beside == Beside::left ? beside_left_ : beside_right_) += width;
  }
  const Course& first = l_.courses.front();
  std::uint32_t own = needles_needed(measure(first)),
                needed = static_cast<std::uint32_t>(beside_left_ + beside_right_) + own;
  if (needed > p_.needles)
    throw UnsupportedError(
        fmt::format("{} needs {} needles for its pieces cast on side by side (from {}), {} has {}",
                    c_.input, needed, g_.describe(l_.order[first.begin]), p_.name, p_.needles));
  // A tube with tubes beside it: the first is centred with them (its right fold halved).
  if (l_.tube && beside_left_ + beside_right_ > 0) {
    std::int32_t low = (static_cast<std::int32_t>(p_.needles - needed) / 2 + beside_left_) & ~1;
    fold_ = (low + static_cast<std::int32_t>(own)) / 2 - 1;
  }
}

// The loops each stitch gathers on one needle, and the transfers a double decrease needs.
void Emitter::check_needle_loads() {
  std::vector<std::uint32_t> held = held_loops(), wraps = keep_wraps_within_limit(held);
  for (StitchId s : l_.order) {
    std::uint32_t in = info(g_.type[s]).loops_in;
    if (needle_load(s, held) + wraps[s] > std::max(p_.max_loops_per_needle, in))
      throw UnsupportedError(
          fmt::format("{} would gather {} loops on one needle ({}), {} allows {}", g_.describe(s),
                      needle_load(s, held) + wraps[s], what_the_needle_holds(s, held, wraps[s]),
                      p_.name, p_.max_loops_per_needle));
    if (in > p_.max_loops_per_needle)
      throw UnsupportedError(
          fmt::format("a {}-to-1 decrease exceeds the {} loop{} per needle {} allows, at {}", in,
                      p_.max_loops_per_needle, p_.max_loops_per_needle == 1 ? "" : "s", p_.name,
                      g_.describe(s)));
    if (in == 3 && reach_ < 2 * pitch_)
      throw UnsupportedError(
          fmt::format("a 3-to-1 decrease needs transfers across {} needles, {} allows {}, at {}",
                      2 * pitch_, p_.name, p_.max_transfer_stretch, g_.describe(s)));
  }
}

// How many loops a needle holds for each knit graph loop: a tuck keeps the loops it takes
// under its own, a slip passes them on.
std::vector<std::uint32_t> Emitter::held_loops() const {
  std::vector<std::uint32_t> held(g_.loops.size(), 1);
  for (StitchId s : l_.order)
    if (keeps_loop_below(g_.type[s]))
      held[g_.loops_made_by(s)[0]] = held[taken(s)[0]] + (g_.type[s] == StitchType::tuck ? 1 : 0);
  return held;
}

// The loops a stitch gathers on its needle, short-row wraps aside: those it takes with the
// tucked loops they hold, and a bind-off's chain loop.
std::uint32_t Emitter::needle_load(StitchId s, const std::vector<std::uint32_t>& held) const {
  std::uint32_t load = chained_off(g_.type[s]) ? 1 : 0;
  for (std::uint32_t loop : taken(s)) load += held[loop];
  return load;
}

// For a refusal: what the stitch's needle would hold, "2 loops taken, 1 tucked loop under
// them, 1 short-row wrap, the bind-off chain's loop".
std::string Emitter::what_the_needle_holds(StitchId s, const std::vector<std::uint32_t>& held,
                                           std::uint32_t wraps) const {
  std::size_t loops = taken(s).size();
  std::uint32_t tucked =
      needle_load(s, held) - static_cast<std::uint32_t>(loops) - (chained_off(g_.type[s]) ? 1 : 0);
  auto count = [](std::size_t n, const char* one, const char* many) {
    return fmt::format("{} {}", n, n == 1 ? one : many);
  };
  std::string out = count(loops, "loop taken", "loops taken");
  if (tucked) out += ", " + count(tucked, "tucked loop under them", "tucked loops under them");
  if (wraps) out += ", " + count(wraps, "short-row wrap", "short-row wraps");
  if (chained_off(g_.type[s])) out += ", the bind-off chain's loop";
  return out;
}

// How many short-row turns wrap each stitch's loop (their tucks are knit with it). A turn
// whose wrap the needle could not hold with the loops it gathers is left bare (the model's
// fabric: the wrap only closes the hole a turn leaves), the first turns keeping theirs.
std::vector<std::uint32_t> Emitter::keep_wraps_within_limit(
    const std::vector<std::uint32_t>& held) {
  std::vector<std::uint32_t> wraps(g_.size(), 0);
  bare_turn_.assign(l_.courses.size(), 0);
  for (std::size_t i = 0; i < l_.courses.size(); ++i) {
    if (l_.courses[i].wrap == kNoWrap) continue;
    StitchId taker = g_.loops[l_.courses[i].wrap].taker;
    std::uint32_t limit =
        std::max<std::uint32_t>(p_.max_loops_per_needle, info(g_.type[taker]).loops_in);
    if (needle_load(taker, held) + wraps[taker] < limit)
      ++wraps[taker];
    else
      bare_turn_[i] = 1;
  }
  return wraps;
}

// ---- laying a course out on the needles ----
// A tube keeps its folds where they are while the halves stay within two loops of each other,
// so that loops cross from one bed to the other only to rebalance the tube.
bool Emitter::keep_folds(const Course& c, Footprint& f) const {
  Footprint kept;
  bool on_front = true;
  each_in_layout_order(c, [&](StitchId s) {
    on_front = on_front && live_[taken(s)[stacking_order(g_.type[s])[0]]].home.bed == Bed::f;
    if (!on_front) return;
    kept.front += footprint(g_.type[s]);
    ++kept.split;
  });
  kept.total = f.total;
  std::uint32_t back = f.total - kept.front;
  bool balanced = kept.front <= back + 2 && back <= kept.front + 2;
  if (kept.split == 0 || !balanced) return false;
  f = kept;
  return true;
}

// Where a stitch knits and which way its pass goes, once its home bed and needle are known.
void Emitter::aim(StitchId s, StitchPlan& sp, bool on_back) const {
  sp.step = on_back ? -pitch_ : pitch_;
  sp.knit = is_purl(g_.type[s]) ? other(sp.home) : sp.home;
  bool rightward = (sp.step > 0) == l_.left_to_right[s];
  sp.travel = rightward ? Direction::plus : Direction::minus;
}

// An sr5's turn loop, which waits on the facing needle of the sr5's own loop.
bool Emitter::is_turn_loop(std::uint32_t loop) const {
  StitchId maker = g_.loops[loop].maker;
  return g_.type[maker] == StitchType::sr5 &&
         g_.loops[loop].maker_slot != knit_slot(StitchType::sr5, l_.left_to_right[maker]);
}

// The taken loop that rests where the fabric's loops rest: not an sr5's turn loop.
std::uint32_t Emitter::resting_loop(StitchId s) const {
  for (std::uint32_t loop : taken(s))
    if (!is_turn_loop(loop)) return loop;
  return taken(s)[0];
}

// Tubes side by side (legs) are one tube to the round that joins them only where it goes
// round the bed one way: along the fronts left to right, the backs right to left (or all the
// other way). Where the model takes a leg's outer arc round the fold that faces the other leg,
// the round would cross between the beds: the leg needs laying out turned round, which the
// target does not do yet.
void Emitter::check_round_order(const Course& c) const {
  auto needles = static_cast<std::int32_t>(p_.needles);
  std::vector<std::int32_t> keys;  // places round the bed, front left to right, back after
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    if (taken(l_.order[i]).empty()) continue;
    const Place& h = live_[resting_loop(l_.order[i])].home;
    keys.push_back(h.bed == Bed::f ? h.needle : 2 * needles - h.needle);
  }
  std::size_t up = 0, down = 0;  // steps round the bed each way, closing the course on itself
  for (std::size_t k = 0; k < keys.size(); ++k) {
    std::int32_t a = keys[k], b = keys[(k + 1) % keys.size()];
    up += b > a ? 1 : 0;
    down += b < a ? 1 : 0;
  }
  if (up > 1 && down > 1)
    unsupported_split(c,
                      "tubes side by side joined by a round that goes round one of them the other "
                      "way (a leg whose outer arc is at the fold facing the other leg)");
}

// A short row takes the loops of one needle per stitch and leaves one: each stitch knits
// where its loop waits, so the loops beside the short row stay where they are.
void Emitter::plan_in_place(const Course& c) {
  if (l_.tube && beside_left_ + beside_right_ > 0) check_round_order(c);
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    StitchId s = l_.order[i];
    StitchPlan& sp = plan_[s];
    const Place& h = live_[resting_loop(s)].home;
    sp.home = h.bed;
    sp.needle = h.needle;
    sp.knit_slot = knit_slot(g_.type[s], l_.left_to_right[s]);
    aim(s, sp, l_.tube && h.bed == Bed::b);
  }
  // A bind-off leaves one loop where each st's loops were: the chain's, taken at once.
  if (c.partial && !chained_off(g_.type[l_.order[c.begin]])) make_room(c);
}

// ---- shaping inside a short row ----
// A short row is knit where its loops wait. Where its stitches make more loops than they
// take (or fewer), the loops on lower needles of that bed, waiting ones included, first move
// down (or up) by the difference: room for the new loops (or the gap closed) on the side of
// a tube's left fold and a sheet's left edge, so that a tube's right fold stays put.

// The bed of the fabric a loop lies in: an sr5's turn loop waits on the facing bed.
Bed Emitter::fabric_bed(std::uint32_t loop) const {
  return is_turn_loop(loop) ? other(live_[loop].home.bed) : live_[loop].home.bed;
}

Emitter::Occupied Emitter::occupied(StitchId s) const {
  Occupied o;
  for (std::uint32_t loop : taken(s)) {
    if (is_turn_loop(loop)) continue;
    const Place& h = live_[loop].home;
    std::size_t b = bed_index(h.bed);
    o.top[b] = o.count[b]++ ? std::max(o.top[b], h.needle) : h.needle;
  }
  return o;
}

// Where the room puts a loop now at `p` (in the fabric): down by the pitch times the
// shaping on higher needles of its bed.
Place Emitter::after_room(Place p) const {
  const std::vector<Shaping>& bed = shaping_[bed_index(p.bed)];
  auto above = std::upper_bound(bed.begin(), bed.end(), p.needle,
                                [](std::int32_t n, const Shaping& sh) { return n < sh.top; });
  return {p.bed, p.needle - (above == bed.end() ? 0 : above->upward * pitch_)};
}

void Emitter::make_room(const Course& c) {
  std::vector<Occupied> occupancy;
  for (std::uint32_t i = c.begin; i < c.end; ++i) {
    StitchId s = l_.order[i];
    StitchPlan& sp = plan_[s];
    sp.home = fabric_bed(taken(s)[stacking_order(g_.type[s])[0]]);  // a decrease's bottom
    occupancy.push_back(occupied(s));
    for (std::size_t b = 0; b < 2; ++b) {
      std::int32_t delta =
          (b == bed_index(sp.home) ? needles_after(g_.type[s]) : 0) - occupancy.back().count[b];
      if (delta) shaping_[b].push_back({occupancy.back().top[b], delta});
    }
  }
  if (!shaped()) return;
  for (auto& bed : shaping_) {
    std::sort(bed.begin(), bed.end(),
              [](const Shaping& a, const Shaping& b) { return a.top < b.top; });
    for (std::size_t k = bed.size(); k-- > 0;)
      bed[k].upward = bed[k].delta + (k + 1 < bed.size() ? bed[k + 1].upward : 0);
  }
  for (std::uint32_t i = c.begin; i < c.end; ++i)
    place_in_room(l_.order[i], occupancy[i - c.begin]);
  move_waiting_loops(c);
}

// A stitch's needles below its (moved) top, as many as it occupies once knit.
void Emitter::place_in_room(StitchId s, const Occupied& o) {
  StitchPlan& sp = plan_[s];
  std::size_t b = bed_index(sp.home);
  std::int32_t top = after_room({sp.home, o.top[b]}).needle;
  std::int32_t low = top - (needles_after(g_.type[s]) - 1) * pitch_;
  aim(s, sp, l_.tube && sp.home == Bed::b);
  std::int32_t knit_at =
      g_.type[s] == StitchType::sr5 ? 0 : sp.knit_slot;  // its turn loop faces it
  sp.needle = (sp.step > 0 ? low : top) + knit_at * sp.step;
  if (low < 0) off_the_bed(s);
}

// The waiting loops the room moves, and those away from their needle (a purl, a kfb's second
// loop), which go home first so that the moving stacks find the facing needles empty.
void Emitter::move_waiting_loops(const Course& c) {
  for (std::uint32_t i = c.begin; i < c.end; ++i)
    for (std::uint32_t loop : taken(l_.order[i])) in_course_[loop] = 1;
  for (std::uint32_t loop : on_needles_) {
    const LoopPlace& lp = live_[loop];
    Place fabric{fabric_bed(loop), lp.home.needle}, to = after_room(fabric);
    if (in_course_[loop] || (to == fabric && lp.now == lp.home)) continue;
    if (is_turn_loop(loop) && to != fabric)
      throw UnsupportedError(fmt::format(
          "not yet supported by the knitout target: shaping in a short row that moves an "
          "sr5's waiting turn loop, at {}",
          g_.describe(g_.loops[loop].maker)));
    if (to.needle < 0) off_the_bed(g_.loops[loop].maker);
    room_.push_back({loop, {lp.home.bed, to.needle}});
  }
  for (std::uint32_t i = c.begin; i < c.end; ++i)
    for (std::uint32_t loop : taken(l_.order[i])) in_course_[loop] = 0;
  std::sort(room_.begin(), room_.end(), [](const RoomMove& a, const RoomMove& b) {
    return std::pair(a.to.bed, a.to.needle) < std::pair(b.to.bed, b.to.needle);
  });
}

void Emitter::off_the_bed(StitchId s) const {
  throw UnsupportedError(fmt::format(
      "{}: making room for a short row's shaping moves the loop of {} off the bed's left end "
      "({} has needles 0..{})",
      c_.input, g_.describe(s), p_.name, p_.needles - 1));
}

// Once a tube has rolled round its needles, its round starts elsewhere than at the front's
// left end: a whole round is laid out from the stitch whose loop lies there, so that its loops
// need not move round the tube back again.
std::uint32_t Emitter::stitch_at_front_left(const Course& c) const {
  std::uint32_t n = c.end - c.begin, best = 0;
  std::int32_t fold = ring_fold(c), leftmost = std::numeric_limits<std::int32_t>::max();
  for (std::uint32_t k = 0; k < n; ++k) {
    StitchId s = l_.order[c.left_to_right ? c.begin + k : c.end - 1 - k];
    auto in = taken(s);
    if (in.empty()) continue;
    std::int32_t u = ring(live_[in[stacking_order(g_.type[s])[0]]].home, fold);
    if (u < leftmost) leftmost = u, best = k;
  }
  return best;
}

void Emitter::plan_course(const Course& course, bool first) {
  room_.clear();
  for (auto& bed : shaping_) bed.clear();
  // A bind-off, like a short row, is knit where its loops wait (wherever its round starts).
  if (course.partial || chained_off(g_.type[l_.order[course.begin]])) return plan_in_place(course);
  Course c = course;
  // So is a round over tubes side by side (their loops lie round the bed in the round's order
  // from the front's left end, whichever piece the round's start came from).
  bool beside = l_.tube && beside_left_ + beside_right_ > 0;
  if ((rolled_ || beside) && !first) c.layout_start = stitch_at_front_left(c);
  Footprint f = measure(c);
  // A tube whose halves keep their folds moves no loop between the beds: its right fold may
  // then follow the loops; while loops cross a fold it stays where it is.
  bool fold_may_move = l_.tube && !first && keep_folds(c, f);
  std::uint32_t back = f.total - f.front;
  // Where the stitches' bottom loops are, as offsets that would leave them in place.
  std::vector<std::int32_t> wants;
  if (!first) lay_out(c, f, 0, &wants);
  std::int32_t span = static_cast<std::int32_t>(l_.tube ? p_.needles / 2 : p_.needles);
  std::int32_t used = static_cast<std::int32_t>(l_.tube ? std::max(f.front, back) : f.total);
  std::int32_t low = l_.tube ? used - 1 : 0, high = l_.tube ? span - 1 : span - used;
  std::int32_t offset = (span - used - beside_left_ - beside_right_) / 2 + low + beside_left_;
  if (!wants.empty()) {
    auto mid = wants.begin() + static_cast<std::ptrdiff_t>(wants.size() / 2);
    std::nth_element(wants.begin(), mid, wants.end());
    offset = std::clamp(*mid, low, high);
  }
  if (l_.tube && !fold_may_move) offset = fold_;
  if (l_.tube) fold_ = offset;
  lay_out(c, f, offset, nullptr);
}

// Each stitch's needle with the course laid out from `offset`: a sheet's left end, a tube's
// right fold (in half gauge: front loops on even needles, back loops on odd ones).
void Emitter::lay_out(const Course& c, const Footprint& f, std::int32_t offset,
                      std::vector<std::int32_t>* wants) {
  std::uint32_t q = 0, index = 0;
  each_in_layout_order(c, [&](StitchId s) {
    StitchPlan& sp = plan_[s];
    sp.knit_slot = knit_slot(g_.type[s], l_.left_to_right[s]);
    std::uint32_t qk = q + sp.knit_slot;
    bool on_back = l_.tube && index >= f.split;
    sp.home = on_back ? Bed::b : Bed::f;
    // A sheet counts from its left end; a tube from its right fold, where the two beds meet.
    std::int32_t rank = static_cast<std::int32_t>(!l_.tube  ? qk
                                                  : on_back ? qk - f.front
                                                            : f.front - 1 - qk);
    std::int32_t sign = l_.tube ? -1 : 1;
    sp.needle = l_.tube ? 2 * (offset - rank) + (on_back ? 1 : 0) : offset + rank;
    aim(s, sp, on_back);
    if (wants && !g_.loops_taken_by(s).empty()) {
      std::uint32_t bottom = g_.loops_taken_by(s)[stacking_order(g_.type[s])[0]];
      const Place& h = live_[bottom].home;
      if (h.bed == sp.home) {
        std::int32_t have = l_.tube ? (h.needle - (on_back ? 1 : 0)) / 2 : h.needle;
        wants->push_back(have - sign * rank);
      }
    }
    q += footprint(g_.type[s]);
    ++index;
  });
}

// A piece cast on while another piece's loops wait on the bed: on the needles beside theirs,
// on the side from which the course joining them takes it, with one empty needle between (two
// for a tube, which keeps its front loops on even needles).
void Emitter::plan_beside(const Course& c) {
  std::int32_t low = std::numeric_limits<std::int32_t>::max(), high = -1;
  for (std::uint32_t loop : on_needles_) {
    for (const Place& p : {live_[loop].now, live_[loop].home}) {
      low = std::min(low, p.needle);
      high = std::max(high, p.needle);
    }
  }
  Footprint f = measure(c);
  auto total = static_cast<std::int32_t>(needles_needed(f));
  std::int32_t gap = pitch_, first = c.beside == Beside::right ? high + 1 + gap : low - gap - total;
  if (l_.tube) first += first & 1;  // even: the tube's first front needle
  if (first < 0 || first + total > static_cast<std::int32_t>(p_.needles))
    throw UnsupportedError(fmt::format(
        "{}: {} is cast on beside the loops on needles {}..{}, which leaves it no room on "
        "{}'s {} needles",
        c_.input, g_.describe(l_.order[c.begin]), low, high, p_.name, p_.needles));
  // A tube's right fold is its last front needle (halved): the back's loops face the front's.
  lay_out(c, f, l_.tube ? (first + total) / 2 - 1 : first, nullptr);
}

}  // namespace skein::knitout::emit
