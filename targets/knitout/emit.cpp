#include "knitout/emit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <limits>
#include <ostream>

#include "common/error.hpp"
#include "knitout/course_layout.hpp"
#include "knitout/knitout_writer.hpp"
#include "knitout/stitch_recipes.hpp"

namespace skein::knitout {
namespace {

struct Place {
  Bed bed = Bed::f;
  std::int32_t needle = 0;
  friend bool operator==(const Place&, const Place&) = default;
};
Needle at(Place p) {
  return {p.bed, p.needle};
}
Bed other(Bed b) {
  return b == Bed::f ? Bed::b : Bed::f;
}
Place facing(Place p) {
  return {other(p.bed), p.needle};
}

// Where a stitch is knit in its course.
struct StitchPlan {
  Bed home = Bed::f;        // the bed its made loops live on
  Bed knit = Bed::f;        // home, or the other bed for a purl
  std::int32_t needle = 0;  // its knit slot's needle: where its taken loops are stacked
  std::int32_t step = 1;    // needles from one of its made slots to the next, left to right
  std::uint8_t knit_slot = 0;
  Direction travel = Direction::plus;
  Place home_of(std::uint32_t slot) const {
    return {home, needle + (static_cast<std::int32_t>(slot) - knit_slot) * step};
  }
};

struct LoopPlace {
  Place now, home;  // where the loop is, and where it rests between courses
};

struct Move {
  Place from, to;
};
std::int32_t rack_of(const Move& m) {
  return m.from.bed == Bed::f ? m.from.needle - m.to.needle : m.to.needle - m.from.needle;
}

// Needles a course occupies: per stitch max(made, 1), laid out left to right.
std::uint32_t footprint(StitchType t) {
  return std::max<std::uint32_t>(info(t).loops_out, 1);
}

class Emitter {
 public:
  // Checks that the piece fits the profile (throws Error in the user's words otherwise).
  // `carriers`: per yarn piece, its carrier.
  Emitter(const Compilation& c, const MachineProfile& p, const CourseLayout& l, KnitoutWriter& w,
          const std::vector<std::string>& carriers)
      : c_(c), g_(c.knit), p_(p), l_(l), w_(w), carriers_(carriers) {
    pitch_ = l_.tube ? 2 : 1;
    reach_ = p_.max_transfer_stretch / pitch_ * pitch_;
    plan_.resize(g_.size());
    live_.resize(g_.loops.size());
    index_on_needles_.resize(g_.loops.size());
    in_course_.resize(g_.loops.size());
    check_fit();
  }

  void run() {
    const Course& first = l_.courses.front();
    carrier_ = carriers_[first.yarn];
    plan_course(first, true);
    cast_on(first);
    for (std::size_t i = 1; i < l_.courses.size(); ++i) {
      const Course& course = l_.courses[i];
      carrier_ = carriers_[course.yarn];
      if (course.cast_on) {  // a sheet beside the loops on the bed, its yarn and border its own
        plan_beside(course);
        cast_on(course);
        continue;
      }
      plan_course(course, false);
      transition(course);
      // A yarn that starts on loops on the bed comes in for its first course: the hook (if
      // any) lets go once that course holds it.
      if (course.first_of_yarn) bring_in(course);
      if (g_.type[l_.order[course.begin]] == StitchType::bo) {
        bind_off(course, course.last_of_yarn);
      } else {
        knit_course(course);
        wrap_turn(course);
        if (course.last_of_yarn) leave_loops(course);
      }
      if (course.first_of_yarn) release(carrier_);
    }
  }

 private:
  // ---- fitting the model on the profile ----
  struct Footprint {
    std::uint32_t total = 0, front = 0,
                  split = 0;  // split: first stitch (left to right) on the back
  };
  // The course's stitches left to right along the fabric, from the one laid out first (at a
  // tube's front left end): a round that starts elsewhere than the round below it is laid out
  // from the stitch that takes the round's start, so that its loops need not move round.
  template <typename F>
  void each_in_layout_order(const Course& c, F f) const {
    std::uint32_t n = c.end - c.begin;
    for (std::uint32_t k = 0; k < n; ++k) {
      std::uint32_t j = (k + c.layout_start) % n;
      f(l_.order[c.left_to_right ? c.begin + j : c.end - 1 - j]);
    }
  }
  Footprint measure(const Course& c) const {
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
  std::uint32_t needles_needed(const Footprint& f) const {
    return l_.tube ? 2 * std::max(f.front, f.total - f.front) : f.total;
  }

  // Checks that the piece fits the profile, and centres a tube's widest course on the bed.
  void check_fit() {
    check_width();
    check_needle_loads();
    if (reach_ < pitch_)
      throw UnsupportedError(
          fmt::format("{} allows no sideways transfer (racking.max_transfer_stretch {})", p_.name,
                      p_.max_transfer_stretch));
  }

  void check_width() {
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
      throw UnsupportedError(
          fmt::format("{} needs {} needles{} (row {}, from {}), {} has {}", c_.input, widest,
                      l_.tube ? " in half gauge" : "", at_course->row + 1,
                      g_.describe(l_.order[at_course->begin]), p_.name, p_.needles));
    check_side_by_side();
  }

  // Sheets cast on beside the first (flaps a later row joins): the needles they take at their
  // cast-on, one empty needle apart, left and right of the first, so that the first is placed
  // where all of them fit.
  void check_side_by_side() {
    for (const Course& c : l_.courses) {
      if (c.beside == Beside::none) continue;
      auto width = static_cast<std::int32_t>(measure(c).total) + 1;
      (c.beside == Beside::left ? beside_left_ : beside_right_) += width;
    }
    const Course& first = l_.courses.front();
    auto needed = static_cast<std::uint32_t>(beside_left_ + beside_right_) + measure(first).total;
    if (needed > p_.needles)
      throw UnsupportedError(fmt::format(
          "{} needs {} needles for its pieces cast on side by side (from {}), {} has {}", c_.input,
          needed, g_.describe(l_.order[first.begin]), p_.name, p_.needles));
  }

  // The loops each stitch gathers on one needle, and the transfers a double decrease needs.
  void check_needle_loads() const {
    std::vector<std::uint32_t> wraps = wraps_per_stitch(), held = held_loops();
    for (StitchId s : l_.order) {
      // A bind-off's needle also receives the chain's loop.
      std::uint32_t in = info(g_.type[s]).loops_in,
                    gathered = wraps[s] + (g_.type[s] == StitchType::bo ? 1 : 0);
      for (std::uint32_t loop : taken(s)) gathered += held[loop];
      if (gathered > p_.max_loops_per_needle && gathered > in)
        throw UnsupportedError(fmt::format(
            "{} would gather {} loops on one needle (with tucked loops, short-row wraps or the "
            "bind-off chain), {} allows {}",
            g_.describe(s), gathered, p_.name, p_.max_loops_per_needle));
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
  std::vector<std::uint32_t> held_loops() const {
    std::vector<std::uint32_t> held(g_.loops.size(), 1);
    for (StitchId s : l_.order)
      if (keeps_loop_below(g_.type[s]))
        held[g_.loops_made_by(s)[0]] = held[taken(s)[0]] + (g_.type[s] == StitchType::tuck ? 1 : 0);
    return held;
  }

  // How many short-row turns wrap each stitch's loop (their tucks are knit with it).
  std::vector<std::uint32_t> wraps_per_stitch() const {
    std::vector<std::uint32_t> wraps(g_.size(), 0);
    for (const Course& c : l_.courses)
      if (c.wrap != kNoWrap) ++wraps[g_.loops[c.wrap].taker];
    return wraps;
  }

  // ---- laying a course out on the needles ----
  // A tube keeps its folds where they are while the halves stay within two loops of each other,
  // so that loops cross from one bed to the other only to rebalance the tube.
  bool keep_folds(const Course& c, Footprint& f) const {
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
  void aim(StitchId s, StitchPlan& sp, bool on_back) const {
    sp.step = on_back ? -pitch_ : pitch_;
    sp.knit = is_purl(g_.type[s]) ? other(sp.home) : sp.home;
    bool rightward = (sp.step > 0) == l_.left_to_right[s];
    sp.travel = rightward ? Direction::plus : Direction::minus;
  }

  // An sr5's turn loop, which waits on the facing needle of the sr5's own loop.
  bool is_turn_loop(std::uint32_t loop) const {
    StitchId maker = g_.loops[loop].maker;
    return g_.type[maker] == StitchType::sr5 &&
           g_.loops[loop].maker_slot != knit_slot(StitchType::sr5, l_.left_to_right[maker]);
  }

  // The taken loop that rests where the fabric's loops rest: not an sr5's turn loop.
  std::uint32_t resting_loop(StitchId s) const {
    for (std::uint32_t loop : taken(s))
      if (!is_turn_loop(loop)) return loop;
    return taken(s)[0];
  }

  // A short row takes the loops of one needle per stitch and leaves one: each stitch knits
  // where its loop waits, so the loops beside the short row stay where they are.
  void plan_in_place(const Course& c) {
    for (std::uint32_t i = c.begin; i < c.end; ++i) {
      StitchId s = l_.order[i];
      StitchPlan& sp = plan_[s];
      const Place& h = live_[resting_loop(s)].home;
      sp.home = h.bed;
      sp.needle = h.needle;
      sp.knit_slot = knit_slot(g_.type[s], l_.left_to_right[s]);
      aim(s, sp, l_.tube && h.bed == Bed::b);
    }
    if (c.partial) make_room(c);
  }

  // ---- shaping inside a short row ----
  // A short row is knit where its loops wait. Where its stitches make more loops than they
  // take (or fewer), the loops on lower needles of that bed, waiting ones included, first move
  // down (or up) by the difference: room for the new loops (or the gap closed) on the side of
  // a tube's left fold and a sheet's left edge, so that a tube's right fold stays put.
  struct Shaping {
    std::int32_t top = 0;     // a shaped stitch's highest needle on the bed
    std::int32_t delta = 0;   // the needles it occupies there after, less before
    std::int32_t upward = 0;  // the deltas of this stitch and those above it on the bed
  };
  struct Occupied {  // a stitch's taken loops per bed (front, back)
    std::array<std::int32_t, 2> count{0, 0}, top{0, 0};
  };
  struct RoomMove {
    std::uint32_t loop;  // a waiting loop
    Place to;
  };
  static std::size_t bed_index(Bed b) { return b == Bed::f ? 0 : 1; }

  // The bed of the fabric a loop lies in: an sr5's turn loop waits on the facing bed.
  Bed fabric_bed(std::uint32_t loop) const {
    return is_turn_loop(loop) ? other(live_[loop].home.bed) : live_[loop].home.bed;
  }

  // Needles a stitch occupies once knit: an sr5's turn loop waits on the facing needle.
  static std::int32_t needles_after(StitchType t) {
    return t == StitchType::sr5 ? 1 : static_cast<std::int32_t>(footprint(t));
  }

  Occupied occupied(StitchId s) const {
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
  Place after_room(Place p) const {
    const std::vector<Shaping>& bed = shaping_[bed_index(p.bed)];
    auto above = std::upper_bound(bed.begin(), bed.end(), p.needle,
                                  [](std::int32_t n, const Shaping& sh) { return n < sh.top; });
    return {p.bed, p.needle - (above == bed.end() ? 0 : above->upward * pitch_)};
  }

  void make_room(const Course& c) {
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
  void place_in_room(StitchId s, const Occupied& o) {
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
  void move_waiting_loops(const Course& c) {
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

  [[noreturn]] void off_the_bed(StitchId s) const {
    throw UnsupportedError(fmt::format(
        "{}: making room for a short row's shaping moves the loop of {} off the bed's left end "
        "({} has needles 0..{})",
        c_.input, g_.describe(s), p_.name, p_.needles - 1));
  }

  bool shaped() const { return !shaping_[0].empty() || !shaping_[1].empty(); }

  void plan_course(const Course& c, bool first) {
    room_.clear();
    for (auto& bed : shaping_) bed.clear();
    // A bind-off, like a short row, is knit where its loops wait (wherever its round starts).
    if (c.partial || g_.type[l_.order[c.begin]] == StitchType::bo) return plan_in_place(c);
    Footprint f = measure(c);
    // A tube whose halves keep their folds moves no loop between the beds: its right fold may
    // then follow the loops; while loops cross a fold it stays where it is.
    bool fold_may_move = l_.tube && !first && keep_folds(c, f);
    std::uint32_t back = f.total - f.front;
    std::vector<std::int32_t> wants;
    std::uint32_t q = 0, index = 0;
    auto place = [&](StitchId s, std::int32_t offset, bool record) {
      StitchPlan& sp = plan_[s];
      bool ltr = l_.left_to_right[s];
      sp.knit_slot = knit_slot(g_.type[s], ltr);
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
      if (record && !g_.loops_taken_by(s).empty()) {
        std::uint32_t bottom = g_.loops_taken_by(s)[stacking_order(g_.type[s])[0]];
        const Place& h = live_[bottom].home;
        if (h.bed == sp.home) {
          std::int32_t have = l_.tube ? (h.needle - (on_back ? 1 : 0)) / 2 : h.needle;
          wants.push_back(have - sign * rank);
        }
      }
      q += footprint(g_.type[s]);
      ++index;
    };
    each_in_layout_order(c, [&](StitchId s) { place(s, 0, !first); });
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
    q = index = 0;
    each_in_layout_order(c, [&](StitchId s) { place(s, offset, false); });
  }

  // A sheet cast on while another piece's loops wait on the bed: on the needles beside theirs,
  // with one empty needle between, on the side from which the course joining them takes it.
  void plan_beside(const Course& c) {
    std::int32_t low = std::numeric_limits<std::int32_t>::max(), high = -1;
    for (std::uint32_t loop : on_needles_) {
      for (const Place& p : {live_[loop].now, live_[loop].home}) {
        low = std::min(low, p.needle);
        high = std::max(high, p.needle);
      }
    }
    auto total = static_cast<std::int32_t>(measure(c).total);
    std::int32_t first = c.beside == Beside::right ? high + 2 : low - 1 - total;
    if (first < 0 || first + total > static_cast<std::int32_t>(p_.needles))
      throw UnsupportedError(fmt::format(
          "{}: {} is cast on beside the loops on needles {}..{}, which leaves it no room on "
          "{}'s {} needles",
          c_.input, g_.describe(l_.order[c.begin]), low, high, p_.name, p_.needles));
    std::uint32_t q = 0;
    each_in_layout_order(c, [&](StitchId s) {
      StitchPlan& sp = plan_[s];
      sp.knit_slot = knit_slot(g_.type[s], l_.left_to_right[s]);
      sp.home = Bed::f;
      sp.needle = first + static_cast<std::int32_t>(q + sp.knit_slot);
      aim(s, sp, false);
      q += footprint(g_.type[s]);
    });
  }

  // ---- output helpers ----
  void source(const Course& c, const char* what) {
    StitchId a = l_.order[c.begin], b = l_.order[c.end - 1];
    w_.note(fmt::format(";!source: row {} {}: {}s {}..{} ({})", c.row + 1, what, g_.element,
                        g_.source[a] + 1, g_.source[b] + 1,
                        c.left_to_right ? "left to right" : "right to left"));
  }

  void emit_moves(std::vector<Move>& moves) {
    std::stable_sort(moves.begin(), moves.end(),
                     [](const Move& a, const Move& b) { return rack_of(a) < rack_of(b); });
    for (const Move& m : moves) w_.xfer(at(m.from), at(m.to));
    moves.clear();
  }

  std::span<const std::uint32_t> taken(StitchId s) const { return g_.loops_taken_by(s); }

  // ---- the transfers between two courses ----
  void transition(const Course& c) {
    source(c, "transfers");
    std::vector<std::uint8_t> ready(c.end - c.begin, 0);  // already on its knit needle
    go_home(c, ready, !fits_one_stage(c) || shaped());
    merge_decreases(c);
    shift_stacks(c, ready);
    send_purls(c, ready);
  }

  // True when every loop reaches its new needle in one transfer: then a loop already where its
  // next stitch is knit may stay there, as no stack passes through its needle on the way.
  bool fits_one_stage(const Course& c) const {
    for (std::uint32_t i = c.begin; i < c.end; ++i) {
      Place target{plan_[l_.order[i]].home, plan_[l_.order[i]].needle};
      for (std::uint32_t loop : taken(l_.order[i]))
        if (next_stop(live_[loop].home, target, live_[loop].home.bed != target.bed) != target)
          return false;
    }
    return true;
  }

  // Loops knit on the other bed (purls, kfb's second loop) go back to their home needle,
  // unless (when not `staged`) the next stitch takes that loop alone right where it is.
  // A waiting loop the room moves, or that the course's turn wraps, goes home too (a kfb's
  // second loop waits on the facing needle until then), so that the wrap lies where it rests.
  void go_home(const Course& c, std::vector<std::uint8_t>& ready, bool staged) {
    std::vector<Move> moves;
    auto send_home = [&](std::uint32_t loop) {
      LoopPlace& lp = live_[loop];
      if (lp.now != lp.home) moves.push_back({lp.now, lp.home});
      lp.now = lp.home;
    };
    for (const RoomMove& r : room_) send_home(r.loop);
    if (c.wrap != kNoWrap && !c.wrap_back) send_home(c.wrap);
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
    emit_moves(moves);
  }

  // Each decrease's loops land on its bottom loop's needle in stacking order (the lean).
  void merge_decreases(const Course& c) {
    for (std::size_t stage = 1; stage < 3; ++stage) {
      std::vector<Move> to_transit, landing;
      for (std::uint32_t i = c.begin; i < c.end; ++i) {
        StitchId s = l_.order[i];
        auto order = stacking_order(g_.type[s]);
        if (stage >= order.size()) continue;
        Place bottom = live_[taken(s)[order[0]]].now;
        LoopPlace& lp = live_[taken(s)[order[stage]]];
        if (lp.now.bed == bottom.bed) {
          to_transit.push_back({lp.now, facing(lp.now)});
          landing.push_back({facing(lp.now), bottom});
        } else if (std::abs(rack_of({lp.now, bottom})) <= p_.max_transfer_stretch) {
          landing.push_back({lp.now, bottom});
        } else {
          move_across_beds(lp.now, bottom);
        }
        lp.now = lp.home = bottom;
      }
      emit_moves(to_transit);
      emit_moves(landing);
    }
  }

  // A loop moved straight to the other bed. Between a tube's two left ends (a k2tog across the
  // round's start, the bind-off chain) it may have further to go than one transfer stretches:
  // it then hops from bed to bed, as far as the profile allows each time, over needles strictly
  // between the two ends with the parity of the one further right. Those are empty: on that
  // end's bed they lie beyond its loops, on the other bed they face them and hold none.
  void move_across_beds(Place from, Place to) {
    std::int32_t stretch = p_.max_transfer_stretch, parity = std::max(from.needle, to.needle) & 1;
    Place now = from;
    while (now.bed == to.bed || std::abs(to.needle - now.needle) > stretch) {
      std::int32_t dir = to.needle > now.needle ? 1 : -1;
      std::int32_t n = now.needle + dir * std::min(stretch, std::abs(to.needle - now.needle));
      if ((n & 1) != parity) n -= dir;
      Place next{other(now.bed), n};
      w_.xfer(at(now), at(next));
      now = next;
    }
    w_.xfer(at(now), at(to));
  }

  // A loop's place along the fabric, left to right in the stitches' frames: the needle on a
  // sheet; on a tube, counted from the right fold (front f2R is 0, back b2R+1 is 1), so that
  // the front reads ..., -1, 0 and the back 1, 2, ... and a fold is crossed between 0 and 1.
  std::int32_t ring(Place p) const {
    if (!l_.tube) return p.needle;
    return p.bed == Bed::f ? p.needle / 2 - fold_ : fold_ - (p.needle - 1) / 2 + 1;
  }
  Place place_at(std::int32_t u) const {
    if (!l_.tube) return {Bed::f, u};
    return u <= 0 ? Place{Bed::f, 2 * (fold_ + u)} : Place{Bed::b, 2 * (fold_ - u + 1) + 1};
  }

  // Re-spaces the stacks onto the course's needles in stages: in each, every stack moves at
  // most the transfer reach toward its needle (along its bed, or along the fabric across a
  // tube's fold). Moving every stack the same clamped way keeps their order, so no two ever
  // meet. Stacks moving along a bed pass through the facing needle; stacks crossing the fold
  // go straight over once the others have left for the facing needles.
  void shift_stacks(const Course& c, const std::vector<std::uint8_t>& ready) {
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
    for (bool moved = true; moved;) {
      moved = false;
      std::vector<Move> to_transit, over, landing;
      for (Stack& st : stacks) {
        if (st.now == st.target) continue;
        moved = true;
        Place stop = next_stop(st.now, st.target, crossing);
        if (stop.bed == st.now.bed) {
          to_transit.push_back({st.now, facing(st.now)});
          landing.push_back({facing(st.now), stop});
        } else {
          over.push_back({st.now, stop});
        }
        st.now = stop;
      }
      emit_moves(to_transit);
      emit_moves(over);
      emit_moves(landing);
    }
    for (const Stack& st : stacks) {
      if (st.stitch == kNoStitch) {
        live_[st.waiting] = {st.target, st.target};
        continue;
      }
      for (std::uint32_t loop : taken(st.stitch)) live_[loop].now = live_[loop].home = st.target;
    }
  }

  // One stage's stop toward `target`: along the bed by at most the reach, or, when some loops
  // cross a tube's fold (which then stays put), along the fabric across the fold.
  Place next_stop(Place now, Place target, bool crossing) const {
    if (now == facing(target)) return target;  // an sr5's stack, gathered on its turn loop
    if (!crossing)
      return {now.bed, std::clamp(target.needle, now.needle - reach_, now.needle + reach_)};
    std::int32_t u = ring(now), step = reach_ / pitch_;
    return place_at(std::clamp(ring(target), u - step, u + step));
  }

  void send_purls(const Course& c, const std::vector<std::uint8_t>& ready) {
    std::vector<Move> moves;
    for (std::uint32_t i = c.begin; i < c.end; ++i) {
      StitchId s = l_.order[i];
      const StitchPlan& sp = plan_[s];
      if (ready[i - c.begin] || sp.knit == sp.home || taken(s).empty()) continue;
      moves.push_back({{sp.home, sp.needle}, {sp.knit, sp.needle}});
      for (std::uint32_t loop : taken(s)) live_[loop].now = {sp.knit, sp.needle};
    }
    emit_moves(moves);
  }

  // ---- knitting ----
  void made(StitchId s, std::uint32_t slot, Place now) {
    auto loops = g_.loops_made_by(s);
    if (slot < loops.size()) live_[loops[slot]] = {now, plan_[s].home_of(slot)};
  }

  // The loops on the needles (made and not yet taken), for a short row's shaping to move.
  void track_loops(StitchId s) {
    for (std::uint32_t loop : taken(s)) {
      std::uint32_t last = on_needles_.back();
      on_needles_[index_on_needles_[loop]] = last;
      index_on_needles_[last] = index_on_needles_[loop];
      on_needles_.pop_back();
    }
    for (std::uint32_t loop : g_.loops_made_by(s)) {
      index_on_needles_[loop] = static_cast<std::uint32_t>(on_needles_.size());
      on_needles_.push_back(loop);
    }
  }

  void knit_stitch(StitchId s) {
    track_loops(s);
    const StitchPlan& sp = plan_[s];
    Needle n{sp.knit, sp.needle};
    StitchType t = g_.type[s];
    if (keeps_loop_below(t)) {  // the needle keeps its loops: a tuck adds one, a slip nothing
      if (t == StitchType::tuck) w_.tuck(sp.travel, n, carrier_);
      made(s, 0, {sp.knit, sp.needle});
      return;
    }
    if (info(t).loops_out < 2) {
      w_.knit(sp.travel, n, carrier_);
      made(s, 0, {sp.knit, sp.needle});
      return;
    }
    std::uint32_t extra = 1u - sp.knit_slot;
    if (t == StitchType::sr5) {  // the turn's loop: a tuck on the facing needle on the way back
      Place turn = facing({sp.knit, sp.needle});
      w_.knit(sp.travel, n, carrier_);
      w_.tuck(opposite(sp.travel), at(turn), carrier_);
      made(s, sp.knit_slot, {sp.knit, sp.needle});
      live_[g_.loops_made_by(s)[extra]] = {turn, turn};  // it waits there for its decrease
      return;
    }
    Place extra_home = sp.home_of(extra);
    if (t ==
        StitchType::kfb) {  // split: the old loop waits on the facing needle, then is knit there
      Needle behind{other(sp.knit), sp.needle};
      w_.split(sp.travel, n, behind, carrier_);
      w_.knit(sp.travel, behind, carrier_);
      made(s, sp.knit_slot, {sp.knit, sp.needle});
      made(s, extra, {behind.bed, behind.index});
      return;
    }
    // yo, m1l, m1r: a tuck on the empty needle beside the knit, in the order the yarn passes.
    bool tuck_first = (extra_home.needle < sp.needle) == (sp.travel == Direction::plus);
    if (tuck_first) w_.tuck(sp.travel, at(extra_home), carrier_);
    w_.knit(sp.travel, n, carrier_);
    if (!tuck_first) w_.tuck(sp.travel, at(extra_home), carrier_);
    made(s, sp.knit_slot, {sp.knit, sp.needle});
    made(s, extra, extra_home);
  }

  void knit_course(const Course& c) {
    source(c, c.partial ? "knit (short row)" : "knit");
    w_.rack(0);
    for (std::uint32_t i = c.begin; i < c.end; ++i) knit_stitch(l_.order[i]);
  }

  // Before turning beside a waiting loop, the yarn tucks over its needle, going on the way it
  // went: the waiting stitch is later knit through the tuck too, which closes the turn's hole.
  // A wrap over the turning stitch's own loop is made on the way back.
  void wrap_turn(const Course& c) {
    if (c.wrap == kNoWrap) return;
    const LoopPlace& waiting = live_[c.wrap];
    bool on_back = l_.tube && waiting.home.bed == Bed::b;
    bool rightward = (!on_back == c.left_to_right) != c.wrap_back;
    w_.tuck(rightward ? Direction::plus : Direction::minus, at(waiting.now), carrier_);
  }

  // ---- cast-on and bind-off ----
  // The course's needles on the bed a pass in direction d works, in the order it meets them.
  std::vector<Needle> pass_needles(const Course& c, Direction d) const {
    std::vector<Needle> needles;
    for (std::uint32_t i = c.begin; i < c.end; ++i) {
      const StitchPlan& sp = plan_[l_.order[i]];
      if (sp.travel == d || !l_.tube) needles.push_back({sp.knit, sp.needle});
    }
    std::sort(needles.begin(), needles.end(), [d](const Needle& a, const Needle& b) {
      return d == Direction::plus ? a.index < b.index : a.index > b.index;
    });
    return needles;
  }

  // Alternating tucks over the cast-on needles (two passes per bed), starting in the profile's
  // first direction; returns the direction of the next pass. Each bed's first pass tucks the
  // first needle it meets, so a yarn-inserting hook beside the first stitch is beyond them all.
  Direction tuck_border(const Course& c, const std::string& carrier) {
    Direction d = p_.first_pass;
    std::int32_t beds = l_.tube ? 2 : 1, start[2] = {0, 0};
    for (std::int32_t pass = 0; pass < 2 * beds; ++pass, d = opposite(d)) {
      std::vector<Needle> needles = pass_needles(c, d);
      if (needles.empty()) continue;
      std::int32_t& first = start[pass % beds];
      if (pass < beds) first = needles.front().index;
      for (const Needle& n : needles)
        if (std::abs(n.index - first) / pitch_ % 2 == pass / beds) w_.tuck(d, n, carrier);
    }
    return d;
  }
  void knit_pass(const Course& c, Direction d, const std::string& carrier) {
    for (const Needle& n : pass_needles(c, d)) w_.knit(d, n, carrier);
  }
  void yarn_in(const std::string& carrier) {
    w_.carriers(p_.hook == YarnHook::inhook ? "inhook" : "in", carrier);
  }
  // A yarn that starts on loops on the bed: its carrier comes in and first moves the profile's
  // way (a miss) to the course's needle furthest that way, so that a hook holding its end
  // blocks none of the course's needles.
  void bring_in(const Course& c) {
    w_.line(fmt::format(";!source: carrier {} comes in for yarn piece {}", carrier_, c.yarn + 1));
    yarn_in(carrier_);
    bool plus = p_.first_pass == Direction::plus;
    Needle edge = {Bed::f, plus ? std::numeric_limits<std::int32_t>::max() : -1};
    for (std::uint32_t i = c.begin; i < c.end; ++i) {
      const StitchPlan& sp = plan_[l_.order[i]];
      if (plus ? sp.needle < edge.index : sp.needle > edge.index) edge = {sp.knit, sp.needle};
    }
    w_.miss(p_.first_pass, edge, carrier_);
  }
  // A yarn whose last course leaves its loops to another yarn (a flap's, which a course of the
  // other flap's yarn later joins) goes out after it; its loops wait on their needles.
  void leave_loops(const Course& c) {
    w_.line(
        fmt::format(";!source: carrier {} goes out: yarn piece {}'s loops wait for another yarn",
                    carrier_, c.yarn + 1));
    yarn_out(carrier_);
  }
  void release(const std::string& carrier) {
    if (p_.hook == YarnHook::inhook) w_.carriers("releasehook", carrier);
  }
  void yarn_out(const std::string& carrier) {
    w_.carriers(p_.hook == YarnHook::inhook ? "outhook" : "out", carrier);
  }

  void cast_on(const Course& c) {
    Direction next = p_.first_pass;
    if (p_.waste_rows > 0) {
      w_.line(fmt::format(";!source: waste section: {} {} of waste yarn (carrier {})",
                          p_.waste_rows, l_.tube ? "rounds" : "rows", p_.waste_carrier));
      yarn_in(p_.waste_carrier);
      Direction d = tuck_border(c, p_.waste_carrier);
      release(p_.waste_carrier);
      for (std::uint32_t row = 0; row < p_.waste_rows * (l_.tube ? 2 : 1); ++row, d = opposite(d))
        knit_pass(c, d, p_.waste_carrier);
      yarn_out(p_.waste_carrier);
      if (!p_.draw_carrier.empty()) draw_thread(c);
      yarn_in(carrier_);
    } else {
      w_.line(";!source: cast-on border: alternating tucks");
      yarn_in(carrier_);
      next = tuck_border(c, carrier_);
      release(carrier_);
    }
    Direction first = plan_[l_.order[c.begin]].travel;
    if (first != next) {
      w_.line(";!source: cast-on border: a pass to bring the yarn to where the first row starts");
      knit_pass(c, next, carrier_);
      if (p_.waste_rows > 0) release(carrier_);
    } else if (p_.waste_rows > 0) {
      // The main yarn's first pass is the cast-on row itself; the hook lets go after it.
      knit_course(c);
      release(carrier_);
      return;
    }
    knit_course(c);
  }

  // One row (a round on a tube) of the draw thread over the waste loops: pulling it out later
  // frees the piece from the waste section.
  void draw_thread(const Course& c) {
    w_.line(fmt::format(";!source: draw thread (carrier {})", p_.draw_carrier));
    yarn_in(p_.draw_carrier);
    Direction d = p_.first_pass;
    for (int pass = 0; pass < (l_.tube ? 2 : 1); ++pass, d = opposite(d))
      knit_pass(c, d, p_.draw_carrier);
    release(p_.draw_carrier);
    yarn_out(p_.draw_carrier);
  }

  // Chain bind-off: knit a loop, move it onto the next stitch's needle, knit both, and so on;
  // then a tag knit back and forth on the last needle, the yarn out, and the tag dropped. A
  // bind-off of part of the work (the rest knit on after it) drops its last loop instead: the
  // yarn goes on through it to the next course, as a knitter's does, and its needles are free.
  void bind_off(const Course& c, bool last_course) {
    source(c, last_course ? "bind-off" : "bind-off (part of the work; the rest goes on)");
    for (std::uint32_t i = c.begin; i < c.end; ++i) {
      track_loops(l_.order[i]);
      const StitchPlan& sp = plan_[l_.order[i]];
      Place here{sp.knit, sp.needle};
      w_.rack(0);
      w_.knit(sp.travel, at(here), carrier_);
      if (i + 1 == c.end) break;
      const StitchPlan& next = plan_[l_.order[i + 1]];
      Place there{next.knit, next.needle};
      if (here.bed == there.bed) {
        w_.xfer(at(here), at(facing(here)));
        here = facing(here);
      }
      move_across_beds(here, there);
    }
    const StitchPlan& last = plan_[l_.order[c.end - 1]];
    Needle tag{last.knit, last.needle};
    if (!last_course) return w_.drop(tag);
    if (p_.tag_rows) w_.line(fmt::format(";!source: tag: {} rows on the last loop", p_.tag_rows));
    Direction d = last.travel;
    for (std::uint32_t row = 0; row < p_.tag_rows; ++row) {
      d = opposite(d);
      w_.knit(d, tag, carrier_);
    }
    yarn_out(carrier_);
    w_.drop(tag);
  }

  const Compilation& c_;
  const KnitGraph& g_;
  const MachineProfile& p_;
  const CourseLayout& l_;
  KnitoutWriter& w_;
  std::int32_t pitch_ = 1, reach_ = 1;
  std::int32_t fold_ = 0;  // a tube's right fold: front f2R faces back b2R+1 beside it
  std::int32_t beside_left_ = 0, beside_right_ = 0;  // needles for the sheets cast on beside
  std::vector<StitchPlan> plan_;                     // per stitch, for the course being knit
  std::vector<LoopPlace> live_;                      // per loop of the knit graph
  std::vector<std::uint32_t> on_needles_, index_on_needles_;  // the loops made, not yet taken
  std::array<std::vector<Shaping>, 2> shaping_;  // a short row's shaped stitches, per bed
  std::vector<RoomMove> room_;                   // the waiting loops the shaping moves
  std::vector<std::uint8_t> in_course_;          // per loop: taken by the course being planned
  const std::vector<std::string>& carriers_;
  std::string carrier_;  // the carrier of the course being knit
};

// "46 rows: a sheet", "107 rounds and 20 short rows: a tube in half gauge".
std::string describe(const CourseLayout& l) {
  auto partial = static_cast<std::size_t>(
      std::count_if(l.courses.begin(), l.courses.end(), [](const Course& c) { return c.partial; }));
  return fmt::format("{} {}{}: {}", l.courses.size() - partial, l.tube ? "rounds" : "rows",
                     partial ? fmt::format(" and {} short rows", partial) : "",
                     l.tube ? "a tube in half gauge" : "a sheet");
}

void write_header(KnitoutWriter& w, const Compilation& c, const MachineProfile& p,
                  const std::vector<CourseLayout>& pieces) {
  w.line(";!knitout-2");
  w.line(fmt::format(";;Machine: {}", p.machine));
  w.line(fmt::format(";;Gauge: {}", p.gauge));
  if (p.width_header) w.line(fmt::format(";;Width: {}", p.needles));
  w.line(fmt::format(";;Carriers: {}", p.carriers_line()));
  w.line(fmt::format(";;Position: {}", p.position));
  std::string what = pieces.size() == 1
                         ? describe(pieces[0])
                         : fmt::format("{} yarn pieces knit one after another", pieces.size());
  w.line(fmt::format(";!source: {} ({} stitches, {}), knit by skein for {}", c.input, c.knit.size(),
                     what, p.name));
  if (p.stitch_number) w.line(fmt::format("x-stitch-number {}", p.stitch_number));
  if (p.speed_number) w.line(fmt::format("x-speed-number {}", p.speed_number));
}

// One carrier per yarn piece: the profile's yarn carrier, then the others in the header's
// order, never the waste yarn's or the draw thread's.
std::vector<std::string> piece_carriers(const Compilation& c, const MachineProfile& p,
                                        std::size_t pieces) {
  std::vector<std::string> carriers{p.yarn_carrier};
  for (const std::string& name : p.carriers)
    if (carriers.size() < pieces && name != p.yarn_carrier && name != p.waste_carrier &&
        name != p.draw_carrier)
      carriers.push_back(name);
  if (carriers.size() < pieces)
    throw UnsupportedError(
        fmt::format("{} has {} yarn pieces, one carrier each, and {} has only {} carriers "
                    "for them{}",
                    c.input, pieces, p.name, carriers.size(),
                    p.waste_carrier.empty()  ? ""
                    : p.draw_carrier.empty() ? " besides the waste yarn's"
                                             : " besides the waste yarn's and the draw "
                                               "thread's"));
  return carriers;
}

}  // namespace

// Per yarn piece its carrier, in the order the layouts bring the yarns in.
std::vector<std::string> yarn_carriers(const Compilation& c, const MachineProfile& p,
                                       const std::vector<CourseLayout>& pieces) {
  std::vector<std::string> names = piece_carriers(c, p, c.yarns.size()), carriers(c.yarns.size());
  std::size_t next = 0;
  for (const CourseLayout& l : pieces)
    for (const Course& course : l.courses)
      if (course.first_of_yarn) carriers[course.yarn] = names[next++];
  return carriers;
}

// "carrier 3", "carriers 3, 4".
std::string carriers_of(const CourseLayout& l, const std::vector<std::string>& carriers) {
  std::vector<std::string> used;
  for (const Course& course : l.courses)
    if (course.first_of_yarn) used.push_back(carriers[course.yarn]);
  return fmt::format("carrier{} {}", used.size() > 1 ? "s" : "", fmt::join(used, ", "));
}

void emit_knitout(const Compilation& c, const MachineProfile& p, std::ostream& out) {
  std::vector<CourseLayout> pieces = lay_out_pieces(c);
  std::vector<std::string> carriers = yarn_carriers(c, p, pieces);
  KnitoutWriter w(out);
  write_header(w, c, p, pieces);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (pieces.size() > 1)
      w.line(fmt::format(";!source: yarn piece {} ({}): {}", i + 1,
                         carriers_of(pieces[i], carriers), describe(pieces[i])));
    Emitter(c, p, pieces[i], w, carriers).run();  // one piece's state at a time
  }
}

}  // namespace skein::knitout
