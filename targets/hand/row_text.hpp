// One row's instructions written the way designers write them: runs ("k12"), repeats
// ("*K2, p2; rep from * to last 2 sts, k2", "[K6, k2tog] 8 times") and counts a knitter need
// not keep ("k to last 3 sts", "k to m"). Linear in the row's length: repeats are found
// greedily over runs ("k126" is one token), up to a couple of dozen tokens a unit.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "hand/hand_ops.hpp"

namespace skein::hand {

enum class Dialect : std::uint8_t {
  standard,   // "*K2, p2; rep from * to end"
  knitspeak,  // Stitch-Maps' KnitSpeak: "*K2, p2, repeat from *"
};

// "*K2, p2; rep from * to end": no label, no final period, first letter capitalised. With
// `end_is_marker` (a round with a beginning-of-round marker) the end of the row counts as a
// marker, so that "*K to 2 sts before m, ssk, sm; rep from * to end" covers every section.
std::string row_instructions(std::span<const HandOp> ops, Dialect dialect = Dialect::standard,
                             bool end_is_marker = false);

// When the whole row is one unit of operations worked `count` times (count >= 2), the
// shortest such unit: its length in operations.
struct RowRepeat {
  std::uint32_t unit_ops;
  std::uint32_t count;
};
std::optional<RowRepeat> whole_row_repeat(std::span<const HandOp> ops);

}  // namespace skein::hand
