// Row plans for the hand target's tests: random shaping a hand knitter can work, and wedges
// shaped alike (crowns, yokes) that get section markers.
#pragma once

#include <cstdint>

#include "hand/pattern_model.hpp"
#include "hand/program_pattern.hpp"
#include "hand/region_markers.hpp"
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

// The hand pattern of a crown (a tube of wedge_plan, with section markers) whose first two rnds
// the schedule would mark beside a mismatch group before their 5th and 9th sts: region markers
// among section markers (the 9th st's mark falls on a section marker and gives none).
inline hand::HandPattern with_region_marks_in_a_crown(const Compilation& crown) {
  hand::HandPattern p = hand::build_hand_pattern(crown);
  for (std::uint32_t row : {0u, 1u})
    for (std::uint32_t op : {4u, 8u})
      p.region_marks.push_back({row, op, MarkerKind::mismatch_begin});
  hand::place_region_markers(p);
  return p;
}

}  // namespace skein::testing
