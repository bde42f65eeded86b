// Checks of a yarn model that can fail: yarn never passes through yarn, every loop is held by
// the loops the knit graph says, and the yarn's length per stitch.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "knitgraph/knit_graph.hpp"
#include "yarn/curves.hpp"

namespace skein {

struct Clearance {
  float closest = 1;          // closest approach of two yarns, in yarn diameters (capped at 1)
  std::uint64_t closer = 0;   // segment pairs closer than `allowed` diameters
  std::uint64_t checked = 0;  // segment pairs within a diameter
};
// Over every pair of segments that are not neighbours along a piece.
Clearance yarn_clearance(const YarnModel& model, float allowed, unsigned threads = 0);

// Does the yarn hold the loops the knit graph says? For every loop whose taker pulls yarn
// through it, the taker's yarn must pierce the loop's eye (the maker's lobe from one leg's
// middle over the head to the other's, closed by a chord) at least once; the stitch one row
// above the taker and the maker's neighbour in its row must not.
struct TopologyProblem {
  std::uint32_t loop;  // in the knit graph
  // The stitch whose yarn goes through the loop's eye though it should not, or kNoStitch when
  // the loop's taker misses it.
  StitchId stranger = kNoStitch;
};
struct TopologyReport {
  std::uint32_t loops = 0;         // loops checked
  std::uint32_t not_held = 0;      // the taker's yarn misses the eye
  std::uint32_t wrongly_held = 0;  // an unrelated stitch's yarn goes through the eye
  // Loops picked up through the side of an edge stitch (an expanding perpendicular edge): no
  // lobe of their own, so no eye to check; counted apart from `loops`.
  std::uint32_t picked_up = 0;
  std::string first_problem;              // describes the first one, for messages
  std::vector<TopologyProblem> problems;  // every one, in loop order
};
TopologyReport check_yarn_topology(const KnitGraph& graph, const YarnModel& model);

// Mean yarn length per stitch of `types`, in model units (lobes only, not the ways between).
double yarn_length_per_stitch(const KnitGraph& graph, const YarnModel& model, StitchType type);

// Total length of every piece, in model units.
double total_yarn_length(const YarnModel& model);

}  // namespace skein
