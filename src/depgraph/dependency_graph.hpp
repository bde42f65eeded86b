// The dependency graph (paper §4.1) as a Boost.Graph compressed sparse row graph: an arc
// u -> v means stitch v waits for stitch u. The model is knittable exactly when it has no
// cycle; when it has one, we show the shortest cycle through a stitch on it, arrow by arrow.
#pragma once

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "knitgraph/knit_graph.hpp"

namespace skein {

struct DependencyArc {
  DependencyReason reason = DependencyReason::yarn;
};

using DependencyGraph =
    boost::compressed_sparse_row_graph<boost::bidirectionalS, boost::no_property, DependencyArc,
                                       boost::no_property, std::uint32_t, std::uint32_t>;

// Yarn order, loops (maker before taker) and the knit graph's extra dependencies.
DependencyGraph build_dependency_graph(const KnitGraph& graph);

// One arrow of a cycle: `waiter` waits for `waited_for` because of `reason`.
struct CycleStep {
  StitchId waiter, waited_for;
  DependencyReason reason;
};

struct Knittability {
  bool knittable = true;
  std::vector<CycleStep> cycle;  // empty when knittable
  std::string hint;              // how to fix the cycle, in a user's words
};

Knittability check_knittability(const KnitGraph& graph, const DependencyGraph& deps);

// "face 12 (k, row 7) waits for face 40 (k, row 6): it consumes its loop"
std::string describe(const KnitGraph& graph, const CycleStep& step);

}  // namespace skein
