// The hand simulator: a knitter with two needles, markers and a working yarn follows the
// steps a pattern reader produced. Every operation takes the loops it says off the left needle
// and puts the loops it makes on the right one, in order; the first impossible step stops it
// with the row and the reason ("Rnd 14: k2tog needs 2 sts before the marker, 1 left"). What it
// knits is rebuilt as a fabric: which loop went through which, and the order of the yarn.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hand/pattern_reader.hpp"
#include "knitgraph/knit_graph.hpp"

namespace skein::hand {

struct Fabric {
  struct RowWorked {
    std::size_t line = 0;         // the sentence that said to work it
    std::uint32_t number = 0;     // 0: the cast-on
    std::uint32_t repeat_of = 0;  // the row it repeats, or 0
    bool round = false;
    Side side = Side::rs;
    bool join = false;   // a three-needle bind-off
    bool aside = false;  // cast on onto a holder with the working yarn (not the piece's cast-on)
    std::uint32_t piece = 0;                            // 1-based
    std::uint32_t first = kNoStitch, last = kNoStitch;  // its stitches, in the order worked
  };

  // Per stitch, in the order worked.
  std::vector<StitchType> type;  // as seen from the RS
  std::vector<Side> facing;      // the side facing the knitter as it was worked
  std::vector<std::uint32_t> yarn_next;
  std::vector<YarnLink> yarn_link;
  std::vector<std::uint32_t> row;                       // into rows
  std::vector<std::uint32_t> position;                  // 1-based, in the order worked in its row
  std::vector<std::uint8_t> made;                       // loops it made
  std::vector<std::uint32_t> taken_first = {0}, taken;  // loops it took, in the order taken
  // Per loop: its maker and its index among the maker's loops, in the order made.
  std::vector<std::uint32_t> loop_maker;
  std::vector<std::uint8_t> loop_index;
  // Loops picked up along an edge: per stitch, which of its edges gave one (none, left or right
  // seen from the RS); per loop, whether it is that one. It is the stitch's first or last loop.
  enum Edge : std::uint8_t { kNoEdge, kLeftEdge, kRightEdge };
  std::vector<std::uint8_t> picked_from;
  std::vector<std::uint8_t> loop_picked;
  std::vector<std::uint32_t> piece_first;  // per piece (one yarn each): its first stitch
  std::vector<RowWorked> rows;

  std::uint32_t size() const { return static_cast<std::uint32_t>(type.size()); }
  // The loop's place among its maker's loops, left to right seen from the RS: a knitter
  // facing the RS puts each new loop to the left of the one before.
  std::uint8_t rs_slot(std::uint32_t loop) const;
  // The loops a stitch took, left to right seen from the RS.
  std::vector<std::uint32_t> rs_taken(std::uint32_t stitch) const;
  std::string row_label(std::uint32_t row) const;    // "Rnd 14", "Row 9 (RS), Row 3 again"
  std::string describe(std::uint32_t stitch) const;  // "Rnd 14, st 8 (k2tog)"
};

struct Replay {
  bool ok = true;
  std::string failure;  // "pattern.md:41: Rnd 14: k2tog needs 2 sts before the marker, 1 left"
  Fabric fabric;
  std::uint32_t rows = 0, rounds = 0;  // worked, repeats included
  std::uint32_t counts_checked = 0;    // printed stitch counts compared
};

// The simulator stops a pattern that works more sts and instructions than this (its failure
// names the line): twice what a pattern of the largest stitch mesh skein generates works (2M
// sts), and what keeps a hostile pattern under a second and the fabric it builds under 200 MB.
inline constexpr std::uint64_t kMaxPatternWork = 4'000'000;

// `max_work`: the fuzz harness lowers it, so that each run stays short under the sanitizers.
Replay replay(const Script& script, const std::string& file,
              std::uint64_t max_work = kMaxPatternWork);

}  // namespace skein::hand
