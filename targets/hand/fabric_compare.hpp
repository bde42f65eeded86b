// Compares the fabric a pattern knits with the model's knit graph, stitch for stitch: each
// yarn in the order the model's schedule starts them, each stitch along it with the same link
// (along the row, turn, or on around), the same type as seen from the RS, and the same loops
// taken, each from the same maker and slot, left to right. A mirror image (left and right
// swapped) is compared with slots reversed and leaning stitches swapped.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "hand/needle_sim.hpp"

namespace skein {
struct Compilation;
}

namespace skein::hand {

struct Difference {
  std::uint32_t stitch;  // the first fabric stitch that differs (in the order worked)
  std::string what;
  bool type = false;  // its stitch type differs (not only its loops or yarn)
};

// Where the next st along the yarn takes a loop across the edge of `s` itself (a rnd that starts
// by picking up along the edge of the row just worked, as the teapot's tube after its strip),
// the yarn goes round a corner into the course beside: whether the model calls that a turn or
// a shift, it does not reverse the direction along the needle, and a knitter goes on without
// turning.
bool turns_a_corner(const KnitGraph& g, StitchId s);

std::optional<Difference> first_difference(const Fabric& fabric, const Compilation& model,
                                           bool mirror);

}  // namespace skein::hand
