// One row's instructions written the way designers write them: runs ("k12"), repeats
// ("*K2, p2; rep from * to last 2 sts, k2", "[K6, k2tog] 8 times") and counts a knitter need
// not keep ("k to last 3 sts", "k to m"). Linear in the row's length: repeats are found
// greedily over runs ("k126" is one token), up to a couple of dozen tokens a unit.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "hand/hand_ops.hpp"

namespace skein::hand {

enum class Dialect : std::uint8_t {
  standard,   // "*K2, p2; rep from * to end"
  knitspeak,  // Stitch-Maps' KnitSpeak: "*K2, p2, repeat from *"
};

// "*K2, p2; rep from * to end": no label, no final period, first letter capitalised.
std::string row_instructions(std::span<const HandOp> ops, Dialect dialect = Dialect::standard);

}  // namespace skein::hand
