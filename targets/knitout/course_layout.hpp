// Courses (rows of a sheet, rounds of a tube) in knitting order, as the live-loop program
// (src/lowering) gives them: each course step's stitches in working order, its direction from
// the input, whether it is a short row (it takes part of its run). What the emitter adds: where a
// tube's round is laid out from, and which waiting loop a short row's turn wraps.
#pragma once

#include <cstdint>
#include <vector>

#include "driver/pipeline.hpp"

namespace skein::knitout {

inline constexpr std::uint32_t kNoWrap = 0xffffffffu;

// Where a piece cast on while another piece's loops wait on the bed goes (a sheet beside sheets,
// a tube beside tubes): beside them, on the side from which the course that later joins the
// pieces takes it (a flap left of the other, a leg right of the other).
enum class Beside : std::uint8_t { none, left, right };

struct Course {
  std::uint32_t row = 0;             // the knit graph's row number
  std::uint32_t begin = 0, end = 0;  // its stitches: CourseLayout::order[begin, end)
  std::uint32_t yarn = 0;            // the yarn piece that knits it (its carrier's)
  bool first_of_yarn = false;        // its yarn's first course: the carrier comes in
  bool last_of_yarn = false;         // its yarn's last course: the carrier goes out after it
  bool left_to_right = true;         // the yarn runs left to right in its stitches' frames
  bool partial = false;              // a short row (or a flap's row): loops beside it wait
  bool cast_on = false;              // a cast-on: its yarn comes in with a border of its own
  Beside beside = Beside::none;      // a cast-on beside loops on the bed: which side
  bool rotated = false;              // a tube's round that starts elsewhere than the round below it
  // Its stitch (counted left to right from the first) that takes the round's start: laid out
  // first, at the tube's front left end, so that its loops need not move round the tube.
  std::uint32_t layout_start = 0;
  // Where a short row turns beside a waiting loop, the yarn tucks over that loop's needle so
  // the turn leaves no hole; the tuck is knit with the loop. The loop (knit graph index); when
  // another turn wrapped it already, the turning stitch's own loop instead (wrap_back).
  std::uint32_t wrap = kNoWrap;
  bool wrap_back = false;  // the wrap is over the turning stitch's own loop, made going back
  // A cast-on along a split (sco sts, a crotch): a tube parts into two branches and each st
  // makes a loop for each, cast on between them where they part. The loops of the first
  // branch's ring (the one that takes the sts' first loops) just before and just after its sts.
  bool along_split = false;
  bool alone = false;  // the tube it parts is all that is on the bed (no branch waits beside it)
  std::uint32_t arc_end = kNoWrap, arc_start = kNoWrap;
};

// A cast-on along a split lays the loops of its first sts (in the first branch's order) on the
// bed where the first branch's arc ends, the others on the other bed: the first ones half.
inline std::uint32_t crotch_sts_on_end_bed(std::uint32_t sts) {
  return (sts + 1) / 2;
}

struct CourseLayout {
  bool tube = false;            // closed rounds (a helix) rather than open rows
  std::vector<StitchId> order;  // the piece's stitches, in yarn order
  std::vector<Course> courses;
  std::vector<std::uint8_t> left_to_right;  // per stitch of the model (the piece's are set)
};

// One layout per piece cast on, in the order the program starts them, each knit on its own from
// cast-on to bind-off; a yarn that starts on another's loops (a leg after a leg) is knit in the
// layout of the yarn that made them, with its own carrier. Sheets that a course later joins
// (flaps knit from their tops into one sheet) share a layout: each is cast on beside the loops
// already on the bed, on the side the join takes it, and knit in place until the join. Throws
// UnsupportedError "not yet supported by the knitout target: <what>, at <stitch>" for inputs the
// target does not handle yet (tubes joined on the bed, splits, mismatches, stitch types without a
// machine recipe).
std::vector<CourseLayout> lay_out_pieces(const Compilation& compilation);

}  // namespace skein::knitout
