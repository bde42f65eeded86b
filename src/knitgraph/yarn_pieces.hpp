// Separate yarn pieces (paper §4.2): each maximal chain of stitches joined by the yarn is one
// piece; its first stitch is where knitting with that yarn starts.
#pragma once

#include <cstdint>
#include <vector>

#include "knitgraph/knit_graph.hpp"

namespace skein {

struct YarnPieces {
  std::vector<StitchId> first;          // per piece, in order of first stitch id
  std::vector<std::uint32_t> length;    // stitches per piece
  std::vector<std::uint8_t> ring;       // 1 when the yarn closes on itself (no start)
  std::vector<std::uint32_t> piece_of;  // per stitch
  std::uint32_t size() const { return static_cast<std::uint32_t>(first.size()); }
};

YarnPieces find_yarn_pieces(const KnitGraph& graph);

}  // namespace skein
