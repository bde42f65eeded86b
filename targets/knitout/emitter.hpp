// The knitout emitter's state while it knits one yarn piece (emit.hpp says what it writes).
// Its work is split by job: emit.cpp runs the courses in order and writes the header and the
// carriers; emit_layout.cpp checks that the piece fits the profile and lays each course out on
// the needles (with a short row's shaping); emit_transfers.cpp moves the loops between two
// courses within the racking limit; emit_courses.cpp knits the courses, the cast-on border,
// waste section and draw thread, the bind-off, and brings the yarns in and out.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "driver/pipeline.hpp"
#include "knitout/course_layout.hpp"
#include "knitout/knitout_writer.hpp"
#include "knitout/machine_profile.hpp"
#include "knitout/stitch_recipes.hpp"

namespace skein::knitout::emit {

struct Place {
  Bed bed = Bed::f;
  std::int32_t needle = 0;
  friend bool operator==(const Place&, const Place&) = default;
};
inline Needle at(Place p) {
  return {p.bed, p.needle};
}
inline Bed other(Bed b) {
  return b == Bed::f ? Bed::b : Bed::f;
}
inline Place facing(Place p) {
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
inline std::int32_t rack_of(const Move& m) {
  return m.from.bed == Bed::f ? m.from.needle - m.to.needle : m.to.needle - m.from.needle;
}

// Needles a course occupies: per stitch max(made, 1), laid out left to right.
inline std::uint32_t footprint(StitchType t) {
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

  void run();

 private:
  // ---- fitting the model on the profile (emit_layout.cpp) ----
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
  Footprint measure(const Course& c) const;
  std::uint32_t needles_needed(const Footprint& f) const;
  void check_fit();
  void check_width();
  void check_side_by_side();
  void check_needle_loads();
  std::vector<std::uint32_t> held_loops() const;
  std::uint32_t needle_load(StitchId s, const std::vector<std::uint32_t>& held) const;
  std::string what_the_needle_holds(StitchId s, const std::vector<std::uint32_t>& held,
                                    std::uint32_t wraps) const;
  std::vector<std::uint32_t> keep_wraps_within_limit(const std::vector<std::uint32_t>& held);

  // ---- laying a course out on the needles (emit_layout.cpp) ----
  bool keep_folds(const Course& c, Footprint& f) const;
  void aim(StitchId s, StitchPlan& sp, bool on_back) const;
  bool is_turn_loop(std::uint32_t loop) const;
  std::uint32_t resting_loop(StitchId s) const;
  void check_round_order(const Course& c) const;
  void plan_in_place(const Course& c);
  std::uint32_t stitch_at_front_left(const Course& c) const;
  void plan_course(const Course& course, bool first);
  void lay_out(const Course& c, const Footprint& f, std::int32_t offset,
               std::vector<std::int32_t>* wants);
  void plan_beside(const Course& c);

  // ---- shaping inside a short row (emit_layout.cpp) ----
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
  // Needles a stitch occupies once knit: an sr5's turn loop waits on the facing needle.
  static std::int32_t needles_after(StitchType t) {
    return t == StitchType::sr5 ? 1 : static_cast<std::int32_t>(footprint(t));
  }
  Bed fabric_bed(std::uint32_t loop) const;
  Occupied occupied(StitchId s) const;
  Place after_room(Place p) const;
  void make_room(const Course& c);
  void place_in_room(StitchId s, const Occupied& o);
  void move_waiting_loops(const Course& c);
  [[noreturn]] void off_the_bed(StitchId s) const;
  bool shaped() const { return !shaping_[0].empty() || !shaping_[1].empty(); }

  // ---- the order transfers are written in (emit_transfer_order.cpp) ----
  struct TransferOrder {
    std::vector<std::uint32_t> moves;  // the queue's moves in the order written
    std::uint32_t changes = 0;         // the rack changes they take (and one to 0 if wanted)
    std::int32_t end = 0;              // the racking they leave
    // Fewer changes, or as many and ending nearer 0, where the next course's transfers mostly
    // begin (loops going home to the facing needle).
    bool better_than(const TransferOrder& o) const {
      return std::pair(changes, std::abs(end)) < std::pair(o.changes, std::abs(o.end));
    }
  };
  void queue_moves(std::vector<Move>& moves);  // after the moves queued before, emptying `moves`
  TransferOrder order_moves(bool zero_after) const;     // fewest rack changes first
  TransferOrder order_by_batch(bool zero_after) const;  // as the moves were queued
  TransferOrder best_order(bool zero_after) const;      // the better of the two
  void write_moves(const TransferOrder& order);         // and empties the queue
  void flush_moves() { write_moves(best_order(false)); }

  // ---- the transfers between two courses (emit_transfers.cpp) ----
  void transition(const Course& c);
  void plan_transfers(const Course& c);
  bool fits_one_stage(const Course& c) const;
  void go_home(const Course& c, std::vector<std::uint8_t>& ready, bool staged);
  void merge_decreases(const Course& c);
  void move_across_beds(Place from, Place to, const std::vector<std::uint8_t>* busy = nullptr);
  std::vector<Place> hops_between(Place from, Place to,
                                  const std::vector<std::uint8_t>* busy) const;
  std::vector<Place> hops_across(Place from, Place to, bool tube_free) const;
  std::int32_t ring(Place p) const { return ring(p, fold_); }
  std::int32_t ring(Place p, std::int32_t fold) const;
  Place place_at(std::int32_t u, std::int32_t fold) const;
  std::int32_t ring_fold(const Course& c) const;
  void shift_stacks(const Course& c, const std::vector<std::uint8_t>& ready);
  void route_through_other_bed(const std::vector<Move>& along,
                               const std::vector<std::uint8_t>* busy, std::vector<Move>& to_transit,
                               std::vector<Move>& landing);
  Place next_stop(Place now, Place target, bool crossing, std::int32_t fold) const;
  void send_purls(const Course& c, const std::vector<std::uint8_t>& ready);

  // ---- knitting, cast-on and bind-off (emit_courses.cpp) ----
  void made(StitchId s, std::uint32_t slot, Place now);
  void track_loops(StitchId s);
  void knit_stitch(StitchId s);
  void knit_course(const Course& c);
  bool needs_rack_zero(const Course& c) const;
  void wrap_turn(const Course& c);
  std::vector<Needle> pass_needles(const Course& c, Direction d) const;
  Direction tuck_border(const Course& c, const std::string& carrier, Direction then);
  void knit_pass(const Course& c, Direction d, const std::string& carrier);
  void yarn_in(const std::string& carrier);
  void bring_in(const Course& c);
  Needle outermost_against_first_pass(const Course& c) const;
  void leave_loops(const Course& c);
  void release(const std::string& carrier);
  void yarn_out(const std::string& carrier);
  void cast_on(const Course& c);
  void draw_thread(const Course& c);
  void bind_off(const Course& c, bool last_course);
  std::vector<std::uint8_t> busy_needles() const;
  std::size_t needle_slot(Place p) const;
  void chain_link(Place here, Place there, const std::vector<std::uint8_t>& busy);

  // ---- a cast-on along a split (emit_split.cpp) ----
  struct Crotch {
    bool first_right = false;      // the first branch lies right of the cuts
    Bed end_bed = Bed::f;          // the bed where the first branch's arc ends
    std::uint32_t on_end_bed = 0;  // the sts whose loops lie on that bed (the first ones)
    // Per bed (front, back): the first needle right of the cut, the gap's lowest needle once
    // the room is made, and the gap's width in loops.
    std::array<std::int32_t, 2> cut{0, 0}, bottom{0, 0}, gap{0, 0};
  };
  [[noreturn]] void unsupported_split(const Course& c, const std::string& what) const;
  Place fabric_place(std::uint32_t loop) const;
  bool on_the_bed(std::uint32_t loop) const;
  Crotch plan_crotch(const Course& c);
  void make_crotch_room(const Course& c, Crotch& k);
  std::array<Place, 2> crotch_places(const Crotch& k, std::uint32_t i, std::uint32_t sts) const;
  void cast_on_along_split(const Course& c);

  // ---- rolling a tube round its needles (emit_roll.cpp) ----
  std::vector<std::uint32_t> loops_round_the_tube() const;
  static std::int32_t roll_onto_fold(std::int32_t lo, std::int32_t hi, std::int32_t front,
                                     std::int32_t n);
  void roll_branch_onto_fold(const Course& c);
  bool roll_stage(std::vector<std::uint32_t>& loops, const std::vector<Place>& slots,
                  std::int32_t step);

  // ---- output helpers ----
  void source(const Course& c, const char* what);  // emit.cpp
  std::span<const std::uint32_t> taken(StitchId s) const { return g_.loops_taken_by(s); }

  const Compilation& c_;
  const KnitGraph& g_;
  const MachineProfile& p_;
  const CourseLayout& l_;
  KnitoutWriter& w_;
  std::int32_t pitch_ = 1, reach_ = 1;
  std::int32_t fold_ = 0;  // a tube's right fold: front f2R faces back b2R+1 beside it
  std::int32_t beside_left_ = 0, beside_right_ = 0;  // needles for the pieces cast on beside
  std::vector<StitchPlan> plan_;                     // per stitch, for the course being knit
  std::vector<LoopPlace> live_;                      // per loop of the knit graph
  std::vector<std::uint32_t> on_needles_, index_on_needles_;  // the loops made, not yet taken
  std::array<std::vector<Shaping>, 2> shaping_;        // a short row's shaped stitches, per bed
  std::vector<RoomMove> room_;                         // the waiting loops the shaping moves
  std::vector<Move> pending_;                          // the transfers queued, not yet written
  std::vector<std::uint32_t> batch_ends_;              // where each batch queued ends in pending_
  mutable std::vector<std::uint32_t> last_on_needle_;  // per needle slot: order_moves' scratch
  enum class Route : std::uint8_t { as_racked, out_first, over_first };
  Route route_ = Route::as_racked;       // how loops along a bed go through the other bed
  bool could_go_over_first_ = false;     // some could, in the course being planned
  std::int32_t batch_rack_ = 0;          // the racking the batches queued leave, written by batch
  std::vector<std::uint8_t> in_course_;  // per loop: taken by the course being planned
  std::vector<std::uint8_t> bare_turn_;  // per course: its turn's wrap left out (no room for it)
  const std::vector<std::string>& carriers_;
  std::string carrier_;  // the carrier of the course being knit
  bool rolled_ = false;  // the tube has rolled round its needles: its rounds start elsewhere
};

}  // namespace skein::knitout::emit
