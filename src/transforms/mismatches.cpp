#include "transforms/mismatches.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <unordered_map>

#include "common/error.hpp"

namespace skein {
namespace {

// Position of every stitch along the yarn (pieces one after another): orders the edges of a
// group the way its neighbours are knit.
std::vector<std::uint32_t> yarn_order(const KnitGraph& g) {
  std::vector<std::uint8_t> has_prev(g.size(), 0);
  for (StitchId s = 0; s < g.size(); ++s)
    if (g.yarn_next[s] != kNoStitch) has_prev[g.yarn_next[s]] = 1;
  std::vector<std::uint32_t> order(g.size(), kNoStitch);
  std::uint32_t next = 0;
  for (StitchId head = 0; head < g.size(); ++head)
    if (!has_prev[head])
      for (StitchId s = head; s != kNoStitch && order[s] == kNoStitch; s = g.yarn_next[s])
        order[s] = next++;
  for (StitchId s = 0; s < g.size(); ++s)  // yarn that closes on itself: left as it is
    if (order[s] == kNoStitch) order[s] = next++;
  return order;
}

class MismatchTransform {
 public:
  explicit MismatchTransform(KnitGraph& g)
      : g_(g), order_(yarn_order(g)), removed_(g.loops.size(), 0) {}

  void run() && {
    g_.first_extruded = g_.size();
    std::vector<std::vector<std::uint32_t>> edges_of(g_.groups.size());
    for (std::uint32_t e = 0; e < g_.mismatch_edges.size(); ++e)
      edges_of[g_.mismatch_edges[e].group].push_back(e);
    for (std::uint32_t grp = 0; grp < g_.groups.size(); ++grp) transform(grp, edges_of[grp]);
    drop_removed_loops();
    g_.index_loops();
  }

 private:
  void transform(std::uint32_t grp, std::vector<std::uint32_t>& edges) {
    const MismatchGroup& group = g_.groups[grp];
    sort_along_yarn(edges);
    order_along_chain(edges);
    bool extra = group.yarn == MismatchYarnUse::extra;
    switch (group.kind) {
      case MismatchKind::join:
        return extra ? extrude(edges, StitchType::tnbo) : with_own_yarn(group, edges);
      case MismatchKind::split:
        return extra ? extrude(edges, StitchType::sco) : with_own_yarn(group, edges);
      case MismatchKind::contracting:
        for (std::uint32_t e : edges) become_decrease(g_.loops[loop_of(e)].taker);
        return;
      case MismatchKind::expanding:  // picked up and knit through the other side's edge
        return;
    }
  }

  std::uint32_t loop_of(std::uint32_t edge) const { return g_.mismatch_edges[edge].loop[0]; }

  // A stitch beside the edge: the maker of a joined loop or the taker of a split loop.
  StitchId side_stitch(std::uint32_t loop) const {
    const Loop& l = g_.loops[loop];
    return l.kind == LoopKind::joined ? l.maker : l.taker;
  }

  void sort_along_yarn(std::vector<std::uint32_t>& edges) const {
    std::sort(edges.begin(), edges.end(), [&](std::uint32_t a, std::uint32_t b) {
      return order_[side_stitch(loop_of(a))] < order_[side_stitch(loop_of(b))];
    });
  }

  // The edges as a knitter meets them along the group's chain of touching edges, walked from
  // the end where it goes on with the yarn (from the lowest along the yarn, for a ring). A
  // chain across a shift-path (a join whose rnd starts in its middle) stays one run this way,
  // where the yarn's order alone would part it in two. A group whose edges are not one chain
  // or ring keeps the yarn's order.
  void order_along_chain(std::vector<std::uint32_t>& edges) const {
    std::vector<std::array<std::uint32_t, 2>> next = touching(edges);
    if (next.empty()) return;
    auto ends = [&](std::uint32_t i) { return next[i][1] == kNoGroup; };
    std::uint32_t start = 0;
    for (std::uint32_t i = edges.size(); i-- > 0;)  // the lowest end that goes on upwards
      if (ends(i) && (next[i][0] == kNoGroup || next[i][0] > i)) start = i;
    std::vector<std::uint32_t> chain;
    for (std::uint32_t at = start, from = kNoGroup;
         at != kNoGroup && chain.size() < edges.size();) {
      chain.push_back(edges[at]);
      std::uint32_t to = next[at][0] == from ? next[at][1] : next[at][0];
      if (from == kNoGroup && !ends(at)) to = std::min(next[at][0], next[at][1]);  // a ring
      from = at, at = to;
    }
    if (chain.size() == edges.size()) edges = std::move(chain);
  }

  // Per edge (by index into `edges`), the edges that share a vertex with it, the missing one
  // last; empty when a vertex has three edges or an edge touches none.
  std::vector<std::array<std::uint32_t, 2>> touching(
      const std::vector<std::uint32_t>& edges) const {
    std::unordered_map<std::uint32_t, std::array<std::uint32_t, 2>> at_vertex;
    for (std::uint32_t i = 0; i < edges.size(); ++i)
      for (std::uint32_t v : g_.mismatch_edges[edges[i]].vertex) {
        auto [it, fresh] = at_vertex.try_emplace(v, std::array{i, kNoGroup});
        if (fresh) continue;
        if (it->second[1] != kNoGroup) return {};
        it->second[1] = i;
      }
    std::vector<std::array<std::uint32_t, 2>> next(edges.size(), {kNoGroup, kNoGroup});
    for (const auto& [v, pair] : at_vertex) {
      if (pair[1] == kNoGroup) continue;
      for (int k : {0, 1}) {
        auto& n = next[pair[k]];
        (n[0] == kNoGroup ? n[0] : n[1]) = pair[1 - k];
      }
    }
    if (edges.size() > 1 &&
        std::any_of(next.begin(), next.end(), [](const auto& n) { return n[0] == kNoGroup; }))
      return {};
    return next;
  }

  // Which edges of a chain run against its first one: their loops are recorded from the other
  // side of the edge, and the extruded stitch must take them the other way round so that every
  // stitch of the row has the same side first (one needle in front of a three-needle bind-off).
  std::vector<std::uint8_t> flipped_along_chain(const std::vector<std::uint32_t>& edges) const {
    std::vector<std::uint8_t> flipped(edges.size(), 0);
    auto vertex = [&](std::size_t i, int k) { return g_.mismatch_edges[edges[i]].vertex[k]; };
    auto tail_shared = [&](std::size_t i, std::size_t j) {  // edge i's tail is on edge j
      return vertex(i, 0) == vertex(j, 0) || vertex(i, 0) == vertex(j, 1);
    };
    auto touch = [&](std::size_t i, std::size_t j) {
      return tail_shared(i, j) || vertex(i, 1) == vertex(j, 0) || vertex(i, 1) == vertex(j, 1);
    };
    for (std::size_t i = 1; i < edges.size(); ++i)
      if (!touch(i, i - 1)) return std::vector<std::uint8_t>(edges.size(), 0);
    if (edges.size() < 2) return flipped;
    bool first_forward = !tail_shared(0, 1);
    for (std::size_t i = 1; i < edges.size(); ++i)
      flipped[i] = tail_shared(i, i - 1) != first_forward;
    return flipped;
  }

  // One extruded stitch per edge, on a new row and a new yarn piece along the group.
  void extrude(const std::vector<std::uint32_t>& edges, StitchType type) {
    std::uint32_t row = static_cast<std::uint32_t>(g_.row_shape.size());
    g_.row_shape.push_back(RowShape::open);
    StitchId previous = kNoStitch;
    std::vector<std::uint8_t> flipped = flipped_along_chain(edges);
    for (std::size_t i = 0; i < edges.size(); ++i) {
      std::uint32_t e = edges[i];
      StitchId t = g_.add_stitch(type, row, e, kExtruded | kBesideMismatch,
                                 CourseDirection::along_its_loops);
      g_.extruded_at.push_back(e);
      for (std::uint8_t side = 0; side < 2; ++side) {
        Loop& l = g_.loops[g_.mismatch_edges[e].loop[side ^ flipped[i]]];
        if (type == StitchType::tnbo)
          l.taker = t, l.taker_slot = side;
        else
          l.maker = t, l.maker_slot = side;
      }
      if (previous != kNoStitch)
        g_.yarn_next[previous] = t, g_.yarn_link[previous] = YarnLink::course;
      previous = t;
    }
  }

  void with_own_yarn(const MismatchGroup& group, const std::vector<std::uint32_t>& edges) {
    std::uint32_t own_row = g_.row[group.own_side];
    for (std::uint32_t e : edges) {
      const MismatchEdge& me = g_.mismatch_edges[e];
      bool first_is_own = g_.row[side_stitch(me.loop[0])] == own_row;
      work_with_own_yarn(group.kind, me.loop[first_is_own ? 0 : 1], me.loop[first_is_own ? 1 : 0]);
    }
  }

  // The own side's stitch does the work of the extruded row: on a join it takes the other
  // side's loop too and binds off (Fig. 6d); on a split it casts on the loop the other side is
  // pulled through (Fig. 7d).
  void work_with_own_yarn(MismatchKind kind, std::uint32_t own_loop, std::uint32_t other_loop) {
    bool join = kind == MismatchKind::join;
    StitchId f = side_stitch(own_loop);
    require_plain(f, join ? "work a three-needle bind-off with its own yarn"
                          : "cast on along a split with its own yarn");
    g_.type[f] = join ? StitchType::tnbo : StitchType::sco;
    removed_[own_loop] = 1;
    Loop& other = g_.loops[other_loop];
    (join ? other.taker : other.maker) = f;
    (join ? other.taker_slot : other.maker_slot) = 1;
  }

  void require_plain(StitchId s, const char* what) const {
    if (g_.type[s] != StitchType::k && g_.type[s] != StitchType::p)
      throw Error(
          fmt::format("{} cannot {}: only plain knit or purl stitches can; knit this "
                      "group with an extra yarn piece instead",
                      g_.describe(s), what));
  }

  void become_decrease(StitchId s) {
    StitchType& t = g_.type[s];
    switch (t) {
      case StitchType::k:
        t = StitchType::k2tog;
        return;
      case StitchType::p:
        t = StitchType::p2tog;
        return;
      case StitchType::k2tog:
      case StitchType::ssk:
        t = StitchType::s2kp;
        return;
      case StitchType::bo:
        t = StitchType::k2tog_bo;
        return;
      case StitchType::co:  // it has no loop of its own to knit: it knits the one beside it
        t = StitchType::k;
        return;
      default:
        throw Error(
            fmt::format("{} treats a contracting perpendicular edge as a course edge, so "
                        "it must become a decrease; a {} has no decrease form",
                        g_.describe(s), info(t).name));
    }
  }

  void drop_removed_loops() {
    std::vector<std::uint32_t> new_index(g_.loops.size(), kNoGroup);
    std::uint32_t kept = 0;
    for (std::uint32_t l = 0; l < g_.loops.size(); ++l)
      if (!removed_[l]) g_.loops[new_index[l] = kept++] = g_.loops[l];
    g_.loops.resize(kept);
    for (MismatchEdge& e : g_.mismatch_edges)
      for (std::uint32_t& l : e.loop)
        if (l != kNoGroup) l = new_index[l];
  }

  KnitGraph& g_;
  std::vector<std::uint32_t> order_;
  std::vector<std::uint8_t> removed_;
};

}  // namespace

void make_mismatches_knittable(KnitGraph& graph) {
  MismatchTransform(graph).run();
}

}  // namespace skein
