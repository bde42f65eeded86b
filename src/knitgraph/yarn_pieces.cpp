#include "knitgraph/yarn_pieces.hpp"

namespace skein {
namespace {

constexpr std::uint32_t kNoPiece = kNoStitch;

void trace_piece(const KnitGraph& g, StitchId start, bool ring, YarnPieces& pieces) {
  std::uint32_t id = pieces.size();
  std::uint32_t length = 0;
  for (StitchId s = start; s != kNoStitch && pieces.piece_of[s] == kNoPiece; s = g.yarn_next[s]) {
    pieces.piece_of[s] = id;
    ++length;
  }
  pieces.first.push_back(start);
  pieces.length.push_back(length);
  pieces.ring.push_back(ring ? 1 : 0);
}

}  // namespace

YarnPieces find_yarn_pieces(const KnitGraph& g) {
  const std::uint32_t n = g.size();
  std::vector<std::uint8_t> has_prev(n, 0);
  for (StitchId s = 0; s < n; ++s)
    if (g.yarn_next[s] != kNoStitch) has_prev[g.yarn_next[s]] = 1;
  YarnPieces pieces;
  pieces.piece_of.assign(n, kNoPiece);
  for (StitchId s = 0; s < n; ++s)
    if (!has_prev[s]) trace_piece(g, s, false, pieces);
  // Whatever is left lies on yarn that closes on itself: a round with no shift-path.
  for (StitchId s = 0; s < n; ++s)
    if (pieces.piece_of[s] == kNoPiece) trace_piece(g, s, true, pieces);
  return pieces;
}

}  // namespace skein
