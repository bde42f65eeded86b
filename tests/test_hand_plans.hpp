// Row plans for the hand target's tests: random shaping a hand knitter can work, and wedges
// shaped alike (crowns, yokes) that get section markers.
#pragma once

#include <cstdint>

#include "mesh/generate.hpp"

namespace skein::testing {

// Make-ones need a strand on both sides: none may be the last stitch of a flat row (sheet
// rows alternate direction, the first worked row running right to left).
inline RowPlan without_edge_make_ones(RowPlan plan, Layout layout) {
  if (layout == Layout::tube) return plan;
  for (std::size_t r = 1; r < plan.size(); ++r) {
    StitchType& last = r % 2 == 0 ? plan[r].back() : plan[r].front();
    if (last == StitchType::m1l || last == StitchType::m1r) last = StitchType::kfb;
  }
  return plan;
}

// A plain row, then `shapings` rows that widen or narrow each of `sections` equal wedges by
// one stitch with `shaper` (at the end of each wedge), `plain` rows after each.
inline RowPlan wedge_plan(std::uint32_t sections, std::uint32_t wedge, std::uint32_t shapings,
                          std::uint32_t plain, StitchType shaper) {
  RowPlan plan = {std::vector<StitchType>(sections * wedge, StitchType::co),
                  std::vector<StitchType>(sections * wedge, StitchType::k)};
  for (std::uint32_t i = 0; i < shapings; ++i) {
    std::vector<StitchType>& row = plan.emplace_back();
    std::uint32_t takes = info(shaper).bottom_edges, makes = info(shaper).top_edges;
    for (std::uint32_t s = 0; s < sections; ++s) {
      row.insert(row.end(), wedge - takes, StitchType::k);
      row.push_back(shaper);
    }
    wedge = wedge - takes + makes;
    for (std::uint32_t k = 0; k < plain; ++k) plan.emplace_back(sections * wedge, StitchType::k);
  }
  plan.emplace_back(sections * wedge, StitchType::bo);
  return plan;
}

}  // namespace skein::testing
