// Yarn curves from per-stitch templates (Yuksel et al. 2012 §4; Knittable Stitch Meshes §5).
// Each stitch lays one lobe per loop it makes (one for a bind-off) in its cell: the yarn comes
// in low, rises through the loops the stitch consumes, makes its loop's head above the cell
// and comes down again. A lobe's head bends over to where the stitch that consumes the loop
// grips it, so heads and the legs through them meet whatever the two cells' shapes. Lobes
// follow each other in yarn order, one polyline per yarn piece, built from the knit graph
// (so a stitch graph without a mesh gets yarn too).
#pragma once

#include <cstdint>
#include <vector>

#include "knitgraph/knit_graph.hpp"
#include "knitgraph/yarn_pieces.hpp"
#include "yarn/layout.hpp"

namespace skein {

// Points per lobe of a stitch's template.
inline constexpr std::uint32_t kLobeSamples = 24;
inline constexpr std::uint32_t kNoPoint = 0xffffffffu;

// How a stitch's yarn goes through its cell.
enum class LobeKind : std::uint8_t {
  pulled_through,  // knit, purl, increases, decreases, short-row faces: through the old loops
  cast_on,         // makes loops out of nothing (co, sco)
  bound_off,       // through the old loops, makes no loop: a low lobe (bo, 3nbo, k2tog-bo)
  slipped,         // the old loop passes up unworked; the yarn floats behind it (sl)
  tucked,          // a loop held behind the old one, not pulled through it (tuck)
};

struct StitchTemplate {
  LobeKind kind;
  float side;          // +1: the loop is pulled towards the right side (knit), -1 purl
  std::uint8_t lobes;  // one per loop made, at least one
};
StitchTemplate stitch_template(StitchType type);

// The lobe (counted in slot order, left to right in the maker's frame) that makes `loop`, or
// kPickedUp for a loop picked up through the side of its maker: across an expanding
// perpendicular edge an edge stitch makes a loop besides its own (paper §3.2), and the yarn
// does not lay it as a lobe of its own.
inline constexpr std::uint32_t kPickedUp = 0xffffffffu;
std::uint32_t lobe_making(const KnitGraph& graph, std::uint32_t loop);

struct YarnModel {
  float radius = 0;                        // model units
  std::vector<Point3> point;               // every piece's points, piece after piece
  std::vector<std::uint32_t> piece_first;  // CSR over point, size pieces + 1
  // Per stitch: its first point; its lobes' points follow (kLobeSamples each). kNoPoint for a
  // stitch on no yarn piece.
  std::vector<std::uint32_t> stitch_first;
  // Per stitch: its yarn travels right to left (its lobes run against its slots' order).
  std::vector<std::uint8_t> right_to_left;
  std::uint32_t pieces() const { return static_cast<std::uint32_t>(piece_first.size()) - 1; }
};

struct CurveOptions {
  float diameter = 0.25f;  // yarn diameter, in stitch widths
  unsigned threads = 0;    // 0: all cores
};

YarnModel generate_yarn(const KnitGraph& graph, const YarnPieces& pieces,
                        const StitchLayout& layout, const CurveOptions& options = {});

// The stitches in yarn order, piece after piece (a ring from its first stitch round).
std::vector<StitchId> yarn_order(const KnitGraph& graph, const YarnPieces& pieces);

}  // namespace skein
