#include "depgraph/dependency_graph.hpp"

#include <fmt/format.h>

#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <set>

#include "common/error.hpp"

namespace skein {
namespace {

using Vertex = std::uint32_t;
using ArcList = std::vector<std::pair<Vertex, Vertex>>;

DependencyReason reason_for(LoopKind kind) {
  switch (kind) {
    case LoopKind::wale:
      return DependencyReason::loop;
    case LoopKind::perpendicular:
      return DependencyReason::perpendicular_loop;
    case LoopKind::joined:
      return DependencyReason::joined_loop;
    case LoopKind::split:
      return DependencyReason::split_loop;
  }
  return DependencyReason::loop;
}

void collect_arcs(const KnitGraph& g, ArcList& arcs, std::vector<DependencyArc>& props) {
  auto add = [&](StitchId before, StitchId after, DependencyReason reason) {
    arcs.emplace_back(before, after);
    props.push_back({reason});
  };
  for (StitchId s = 0; s < g.size(); ++s)
    if (g.yarn_next[s] != kNoStitch) add(s, g.yarn_next[s], DependencyReason::yarn);
  for (const Loop& l : g.loops)
    if (l.maker != kNoStitch && l.taker != kNoStitch) add(l.maker, l.taker, reason_for(l.kind));
}

// Kahn's algorithm: removes every stitch that can be ordered; what stays lies on or behind a
// cycle. Returns the stitches left (each has a remaining predecessor).
std::vector<std::uint8_t> stitches_on_or_behind_cycles(const DependencyGraph& deps,
                                                       bool& any_left) {
  const Vertex n = static_cast<Vertex>(num_vertices(deps));
  std::vector<std::uint32_t> waiting(n);
  std::vector<Vertex> ready;
  for (Vertex v = 0; v < n; ++v) {
    waiting[v] = static_cast<std::uint32_t>(in_degree(v, deps));
    if (waiting[v] == 0) ready.push_back(v);
  }
  std::vector<std::uint8_t> left(n, 1);
  while (!ready.empty()) {
    Vertex v = ready.back();
    ready.pop_back();
    left[v] = 0;
    for (auto e : boost::make_iterator_range(out_edges(v, deps)))
      if (--waiting[target(e, deps)] == 0) ready.push_back(target(e, deps));
  }
  any_left = std::find(left.begin(), left.end(), 1) != left.end();
  return left;
}

// Walks backwards through remaining predecessors until a stitch repeats: it lies on a cycle.
Vertex stitch_on_cycle(const DependencyGraph& deps, const std::vector<std::uint8_t>& left) {
  Vertex v = static_cast<Vertex>(std::find(left.begin(), left.end(), 1) - left.begin());
  std::vector<std::uint8_t> seen(left.size(), 0);
  while (!seen[v]) {
    seen[v] = 1;
    for (auto e : boost::make_iterator_range(in_edges(v, deps)))
      if (left[source(e, deps)]) {
        v = static_cast<Vertex>(source(e, deps));
        break;
      }
  }
  return v;
}

// Breadth-first from `start` along remaining arcs back to `start`: the shortest cycle through it.
std::vector<CycleStep> shortest_cycle_through(const DependencyGraph& deps, Vertex start,
                                              const std::vector<std::uint8_t>& left) {
  using Edge = boost::graph_traits<DependencyGraph>::edge_descriptor;
  std::vector<Edge> reached_by(left.size());
  std::vector<std::uint8_t> seen(left.size(), 0);
  std::vector<Vertex> frontier{start}, next;
  Edge closing{};
  bool closed = false;
  while (!frontier.empty() && !closed) {
    next.clear();
    for (Vertex v : frontier) {
      for (auto e : boost::make_iterator_range(out_edges(v, deps))) {
        Vertex w = static_cast<Vertex>(target(e, deps));
        if (!left[w]) continue;
        if (w == start) {
          closing = e;
          closed = true;
          break;
        }
        if (seen[w]) continue;
        seen[w] = 1;
        reached_by[w] = e;
        next.push_back(w);
      }
      if (closed) break;
    }
    frontier.swap(next);
  }
  SKEIN_ASSERT(closed, "a stitch found on a cycle reaches itself");
  std::vector<CycleStep> steps;
  for (Edge e = closing;;) {
    steps.push_back({static_cast<StitchId>(target(e, deps)), static_cast<StitchId>(source(e, deps)),
                     deps[e].reason});
    Vertex from = static_cast<Vertex>(source(e, deps));
    if (from == start) break;
    e = reached_by[from];
  }
  std::reverse(steps.begin(), steps.end());
  return steps;
}

bool crosses_join_or_split(DependencyReason r) {
  return r == DependencyReason::joined_loop || r == DependencyReason::split_loop;
}

// The mismatch group whose loop an arrow of a cycle follows.
std::uint32_t group_of(const KnitGraph& g, const CycleStep& step) {
  for (const MismatchEdge& e : g.mismatch_edges)
    for (std::uint32_t l : e.loop)
      if (l != kNoGroup && g.loops[l].maker == step.waited_for && g.loops[l].taker == step.waiter)
        return e.group;
  return kNoGroup;
}

// Paper §4.1's special case: two or more separate join/split groups between the same rows,
// knit with the yarn of different sides.
bool is_special_deadlock(const KnitGraph& g, const std::vector<CycleStep>& cycle) {
  for (const CycleStep& step : cycle) {
    std::uint32_t in_cycle = crosses_join_or_split(step.reason) ? group_of(g, step) : kNoGroup;
    if (in_cycle == kNoGroup) continue;
    const MismatchGroup& a = g.groups[in_cycle];
    std::set<std::uint32_t> groups, sides;
    for (std::uint32_t i = 0; i < g.groups.size(); ++i) {
      const MismatchGroup& b = g.groups[i];
      if (b.yarn != MismatchYarnUse::own || b.rows[0] != a.rows[0] || b.rows[1] != a.rows[1])
        continue;
      groups.insert(i);
      sides.insert(g.row[b.own_side]);
    }
    if (groups.size() >= 2 && sides.size() >= 2) return true;
  }
  return false;
}

std::string hint_for(const KnitGraph& g, const std::vector<CycleStep>& cycle) {
  bool only_yarn = std::all_of(cycle.begin(), cycle.end(), [](const CycleStep& s) {
    return s.reason == DependencyReason::yarn;
  });
  bool own_yarn = std::any_of(cycle.begin(), cycle.end(),
                              [](const CycleStep& s) { return crosses_join_or_split(s.reason); });
  if (only_yarn)
    return fmt::format(
        "row {} is a closed round whose yarn never ends: mark one of its wale edges as a "
        "shift-path (a '#~shift' line) so the rounds become one helix",
        g.row[cycle.front().waiter] + 1);
  if (own_yarn && is_special_deadlock(g, cycle))
    return "this is the special deadlock of paper §4.1: separate groups of joining or splitting "
           "edges between the same rows are knit with different sides' yarn. Knit every group "
           "there with an extra yarn piece ('#~yarn A B extra'), or all of them with the yarn of "
           "the same side";
  if (own_yarn)
    return "a join or split knit with one side's yarn closes this cycle: knit it with an extra "
           "yarn piece ('#~yarn A B extra') or with the other side's yarn";
  auto across = std::find_if(cycle.begin(), cycle.end(), [](const CycleStep& s) {
    return s.reason == DependencyReason::perpendicular_loop;
  });
  if (across != cycle.end())
    return fmt::format(
        "a perpendicular mismatched edge makes {} wait for {}, while the rest of the cycle makes "
        "the second wait for the first: label one of the two regions from its other end (its "
        "wale direction reversed), so the stitches across the edge wait one way only",
        g.describe(across->waiter), g.describe(across->waited_for));
  return "every stitch in the cycle waits for the next one; change the knitting direction "
         "(edge labels) of one of these faces so that the cycle is broken";
}

}  // namespace

DependencyGraph build_dependency_graph(const KnitGraph& g) {
  ArcList arcs;
  std::vector<DependencyArc> props;
  arcs.reserve(g.size() + g.loops.size());
  props.reserve(arcs.capacity());
  collect_arcs(g, arcs, props);
  return DependencyGraph(boost::edges_are_unsorted_multi_pass, arcs.begin(), arcs.end(),
                         props.begin(), g.size());
}

Knittability check_knittability(const KnitGraph& g, const DependencyGraph& deps) {
  bool any_left = false;
  std::vector<std::uint8_t> left = stitches_on_or_behind_cycles(deps, any_left);
  Knittability result;
  if (!any_left) return result;
  result.knittable = false;
  result.cycle = shortest_cycle_through(deps, stitch_on_cycle(deps, left), left);
  result.hint = hint_for(g, result.cycle);
  return result;
}

std::string describe(const KnitGraph& g, const CycleStep& step) {
  return fmt::format("{} waits for {}: {}", g.describe(step.waiter), g.describe(step.waited_for),
                     explain(step.reason));
}

}  // namespace skein
