// Compares the fabric a pattern knits with the model's knit graph, stitch for stitch: each
// yarn in the order the model's schedule starts them, each stitch along it with the same link
// (along the row, turn, or on around), the same type as seen from the RS, and the same loops
// taken, each from the same maker and slot, left to right. A mirror image (left and right
// swapped) is compared with slots reversed and leaning stitches swapped. The model is read as
// a knitter's hands make it: an sr5 as the st of a DS or wrap, the decrease that knits its two
// loops together as the plain st of `k DS` / `kw`. The judge states that rule itself and calls
// none of the pattern builder's code (pattern_model), so a bug there cannot hide here.
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

std::optional<Difference> first_difference(const Fabric& fabric, const Compilation& model,
                                           bool mirror);

}  // namespace skein::hand
