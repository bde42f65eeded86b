// Courses (rows of a sheet, rounds of a tube) in knitting order, and which way the yarn runs
// through each stitch in the stitch's own frame (right side facing, wale up). The knit graph
// orders loops left to right in each stitch's frame but does not record which way its yarn
// goes; this derives it by laying each course's loops out left to right and checking that the
// next course consumes them in order. A course takes a run of the loops on the needles (all
// of them, or part for a short row) in order. Shared by the emitter and the fabric proof.
#pragma once

#include <cstdint>
#include <vector>

#include "driver/pipeline.hpp"

namespace skein::knitout {

inline constexpr std::uint32_t kNoWrap = 0xffffffffu;

struct Course {
  std::uint32_t row = 0;             // the knit graph's row number
  std::uint32_t begin = 0, end = 0;  // its stitches: CourseLayout::order[begin, end)
  bool left_to_right = true;         // the yarn runs left to right in its stitches' frames
  bool partial = false;              // a short row: loops beside it wait on their needles
  bool rotated = false;              // a tube's round that starts elsewhere than the round below it
  // Its stitch (counted left to right from the first) that takes the round's start: laid out
  // first, at the tube's front left end, so that its loops need not move round the tube.
  std::uint32_t layout_start = 0;
  // Where a short row turns beside a waiting loop, the yarn tucks over that loop's needle so
  // the turn leaves no hole; the tuck is knit with the loop. The loop (knit graph index); when
  // another turn wrapped it already, the turning stitch's own loop instead (wrap_back).
  std::uint32_t wrap = kNoWrap;
  bool wrap_back = false;  // the wrap is over the turning stitch's own loop, made going back
};

struct CourseLayout {
  bool tube = false;            // closed rounds (a helix) rather than open rows
  std::vector<StitchId> order;  // the piece's stitches, in yarn order
  std::vector<Course> courses;
  std::vector<std::uint8_t> left_to_right;  // per stitch of the model (the piece's are set)
};

// One layout per yarn piece, in the order the schedule knits them (each piece is knit on its
// own, cast-on to bind-off). Throws Error "not yet supported by the knitout target: <what>, at
// <stitch>" for inputs the target does not handle yet (pieces joined on the bed, shaping in a
// short row, mismatches, stitch graphs that turn, stitch types without a machine recipe).
std::vector<CourseLayout> lay_out_pieces(const Compilation& compilation);

}  // namespace skein::knitout
