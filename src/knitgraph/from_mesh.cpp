#include "knitgraph/from_mesh.hpp"

#include <algorithm>
#include <numeric>

#include <fmt/format.h>

#include "common/error.hpp"

namespace skein {
namespace {

bool is_short_row_face(StitchType t) {
  return info(t).wales_adjacent;
}

// True when the yarn leaving through `out` goes straight on into the next stitch of its row.
bool continues_row(const StitchMesh& m, Halfedge out) {
  Halfedge t = m.twin(out);
  return t.valid() && m.role[t] == EdgeRole::wale_in && !m.shift_path[m.edge(out)];
}

// True when the yarn comes into `in` from somewhere other than the previous stitch of a row.
bool row_starts_at(const StitchMesh& m, Halfedge in) {
  Halfedge t = m.twin(in);
  return m.role[in] == EdgeRole::wale_in &&
         !(t.valid() && m.role[t] == EdgeRole::wale_out && !m.shift_path[m.edge(in)]);
}

// Where a row that ends at `out` continues: the first stitch of the next row whose yarn
// enters at the top end of `out` (a shift-path in a tube, a turn at a border or at a
// perpendicular mismatch). Lowest row wins; a stitch already reached by another yarn is skipped.
Face next_row_start(const StitchMesh& m, Halfedge out, const std::vector<std::uint8_t>& reached) {
  Vertex v = m.wale_top(out);
  Face best;
  if (!v.valid()) return best;
  std::uint32_t row = m.row[m.face(out)];
  auto consider = [&](Halfedge c) {
    if (!row_starts_at(m, c)) return;
    Face g = m.face(c);
    if (m.row[g] == row || reached[g.index()] || m.wale_bottom(c) != v) return;
    if (!best.valid() || m.row[g] < m.row[best]) best = g;
  };
  for (Halfedge h : m.outgoing(v)) {
    consider(h);
    consider(m.prev(h));
  }
  return best;
}

void link_yarn(const StitchMesh& m, KnitGraph& g) {
  std::vector<std::uint8_t> reached(m.num_faces(), 0);
  for (Face f : m.faces()) {
    Halfedge out = m.wale_out(f);
    if (continues_row(m, out)) {
      Face next = m.face(m.twin(out));
      g.yarn_next[f.index()] = next.index();
      g.yarn_link[f.index()] = is_short_row_face(m.stitch[f]) ? YarnLink::turn : YarnLink::course;
      reached[next.index()] = 1;
    }
  }
  for (Face f : m.faces()) {
    Halfedge out = m.wale_out(f);
    if (continues_row(m, out)) continue;
    Face next = next_row_start(m, out, reached);
    if (!next.valid()) continue;
    g.yarn_next[f.index()] = next.index();
    g.yarn_link[f.index()] = m.shift_path[m.edge(out)] ? YarnLink::shift : YarnLink::turn;
    reached[next.index()] = 1;
  }
}

// The first halfedge of a face after the run of edges with role `after` (the face's corner
// where a left-to-right walk of the other course run begins).
Halfedge first_after(const StitchMesh& m, Face f, EdgeRole after) {
  for (Halfedge h : m.halfedges(f))
    if (m.role[m.prev(h)] == after && m.role[h] != after) return h;
  return *m.halfedges(f).begin();
}

// Does the stitch on this side of h make a loop that crosses h?
bool makes_loop_across(const StitchMesh& m, Halfedge h) {
  Halfedge t = m.twin(h);
  if (!t.valid()) return false;  // a bind-off's top, or an open wale edge
  return m.role[h] == EdgeRole::top || (is_wale(m.role[h]) && m.role[t] == EdgeRole::bottom);
}

// Per halfedge where a stitch makes a loop: its slot, left to right in the stitch's frame.
// Counter-clockwise the top run goes right to left, so the ranks are reversed.
std::vector<std::uint8_t> maker_slots(const StitchMesh& m) {
  std::vector<std::uint8_t> slot(m.num_halfedges(), 0);
  std::vector<Halfedge> making;
  for (Face f : m.faces()) {
    making.clear();
    Halfedge h = first_after(m, f, EdgeRole::bottom);
    for (std::uint32_t i = 0; i < m.degree(f); ++i, h = m.next(h))
      if (makes_loop_across(m, h)) making.push_back(h);
    for (std::size_t k = 0; k < making.size(); ++k)
      slot[making[k].index()] = static_cast<std::uint8_t>(making.size() - 1 - k);
  }
  return slot;
}

// Loops are listed from the consuming stitch's side, walking its edges left to right (from
// the corner after its top run), so taker slots count up; loops nobody consumes are listed
// from the maker.
std::vector<std::uint32_t> add_loops(const StitchMesh& m, KnitGraph& g) {
  std::vector<std::uint8_t> made_slot = maker_slots(m);
  std::vector<std::uint32_t> loop_at(m.num_halfedges(), kNoGroup);  // loop listed from h's side
  for (Face f : m.faces()) {
    std::uint8_t taker_slot = 0;
    Halfedge h = first_after(m, f, EdgeRole::top);
    for (std::uint32_t i = 0; i < m.degree(f); ++i, h = m.next(h)) {
      Halfedge t = m.twin(h);
      if (!t.valid()) continue;
      EdgeRole mine = m.role[h], theirs = m.role[t];
      StitchId self = f.index(), other = m.face(t).index();
      auto take = [&](StitchId maker, LoopKind kind, std::uint8_t slot) {
        loop_at[h.index()] = static_cast<std::uint32_t>(g.loops.size());
        g.loops.push_back({maker, self, kind, slot, taker_slot++});
      };
      if (mine == EdgeRole::bottom && theirs == EdgeRole::top)
        take(other, LoopKind::wale, made_slot[t.index()]);
      else if (mine == EdgeRole::bottom && is_wale(theirs))
        take(other, LoopKind::perpendicular, made_slot[t.index()]);
      else if (is_wale(mine) && theirs == EdgeRole::top)
        take(other, LoopKind::perpendicular, made_slot[t.index()]);
      else if (mine == EdgeRole::bottom && theirs == EdgeRole::bottom)
        take(kNoStitch, LoopKind::split, 0);
      else if (mine == EdgeRole::top && theirs == EdgeRole::top) {
        loop_at[h.index()] = static_cast<std::uint32_t>(g.loops.size());
        g.loops.push_back({self, kNoStitch, LoopKind::joined, made_slot[h.index()], 0});
      }
    }
  }
  g.index_loops();
  return loop_at;
}

// Union-find over edges: mismatched edges of one kind that share a vertex form a group.
std::vector<std::uint32_t> group_mismatches(const StitchMesh& m, std::uint32_t& groups) {
  constexpr std::uint32_t kNone = Handle<EdgeTag>::kInvalid;
  std::vector<std::uint32_t> parent(m.num_edges());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (Vertex v : m.vertices()) {
    std::uint32_t first[8];
    std::fill(std::begin(first), std::end(first), kNone);
    for (Halfedge h : m.outgoing(v))
      for (Halfedge c : {h, m.prev(h)}) {
        Edge e = m.edge(c);
        EdgeKind k = m.kind(e);
        if (!is_mismatch(k)) continue;
        auto& root = first[static_cast<int>(k)];
        if (root == kNone)
          root = e.index();
        else
          parent[find(e.index())] = find(root);
      }
  }
  std::vector<std::uint32_t> group(m.num_edges(), kNone);
  std::vector<std::uint32_t> numbering(m.num_edges(), kNone);
  groups = 0;
  for (Edge e : m.edges()) {
    if (!is_mismatch(m.kind(e))) continue;
    std::uint32_t r = find(e.index());
    if (numbering[r] == kNone) numbering[r] = groups++;
    group[e.index()] = numbering[r];
  }
  return group;
}

MismatchKind mismatch_kind(EdgeKind k) {
  switch (k) {
    case EdgeKind::join:
      return MismatchKind::join;
    case EdgeKind::split:
      return MismatchKind::split;
    case EdgeKind::contracting_perpendicular:
      return MismatchKind::contracting;
    default:
      return MismatchKind::expanding;
  }
}

// The yarn a join or split edge asks for; every edge of a group must agree.
void apply_yarn_choice(const StitchMesh& m, Edge e, MismatchGroup& group, Edge& chosen_by) {
  const MismatchYarn& y = m.mismatch_yarn[e];
  if (y.kind == MismatchYarn::Kind::by_default) return;
  MismatchYarnUse use =
      y.kind == MismatchYarn::Kind::own ? MismatchYarnUse::own : MismatchYarnUse::extra;
  StitchId side = use == MismatchYarnUse::own ? y.side.index() : kNoStitch;
  if (chosen_by.valid() && (group.yarn != use || (use == MismatchYarnUse::own &&
                                                  m.row[Face(group.own_side)] != m.row[y.side])))
    throw MeshError(
        fmt::format("{} and {} belong to one {} group but ask for different yarns; "
                    "expected one choice per group",
                    describe(m, chosen_by), describe(m, e), edge_kind_name(m.kind(e))));
  group.yarn = use;
  group.own_side = side;
  chosen_by = e;
}

// Records every mismatched edge with the loops that meet on it, grouped (paper §3.2). Groups
// without a yarn choice default to an extra yarn piece, so separate groups on one row never
// deadlock (§4.1) unless a user asks for it.
void record_mismatches(const StitchMesh& m, KnitGraph& g,
                       const std::vector<std::uint32_t>& loop_at) {
  std::uint32_t count = 0;
  std::vector<std::uint32_t> group = group_mismatches(m, count);
  g.groups.assign(count, MismatchGroup{});
  std::vector<Edge> chosen_by(count);
  for (Edge e : m.edges()) {
    EdgeKind k = m.kind(e);
    if (!is_mismatch(k)) continue;
    MismatchGroup& grp = g.groups[group[e.index()]];
    grp.kind = mismatch_kind(k);
    Halfedge h = m.halfedge(e), t = m.twin(h);
    if (grp.edges++ == 0)
      grp.rows[0] = std::min(m.row[m.face(h)], m.row[m.face(t)]),
      grp.rows[1] = std::max(m.row[m.face(h)], m.row[m.face(t)]);
    apply_yarn_choice(m, e, grp, chosen_by[group[e.index()]]);
    MismatchEdge me{group[e.index()],
                    {loop_at[h.index()], loop_at[t.index()]},
                    {m.tail(h).index(), m.head(h).index()}};
    if (me.loop[0] == kNoGroup) std::swap(me.loop[0], me.loop[1]);
    g.mismatch_edges.push_back(me);
  }
}

void flag_stitches(const StitchMesh& m, KnitGraph& g) {
  for (Face f : m.faces()) {
    std::uint8_t flags = is_short_row_face(m.stitch[f]) ? kShortRowEnd : 0;
    for (Halfedge h : m.halfedges(f)) {
      Edge e = m.edge(h);
      if (is_mismatch(m.kind(e))) flags |= kBesideMismatch;
      if (m.role[h] == EdgeRole::wale_in && m.shift_path[e]) flags |= kShiftPathStart;
    }
    g.flags[f.index()] = flags;
  }
}

// Which way the course runs as its yarn enters the face: from the wale edge on its left (the
// side after its top course edges, counter-clockwise) left to right. For every face but a
// short-row face this is StitchMesh::runs_left_to_right; a short-row face's yarn turns inside
// it and leaves the other way, so it runs as the course it ends.
CourseDirection entering_direction(const StitchMesh& m, Face f) {
  Halfedge h = m.wale_in(f);
  while (is_wale(m.role[h])) h = m.prev(h);
  return m.role[h] == EdgeRole::top ? CourseDirection::left_to_right
                                    : CourseDirection::right_to_left;
}

void shape_rows(const StitchMesh& m, KnitGraph& g) {
  for (RowKind kind : row_kinds(m))
    g.row_shape.push_back(kind == RowKind::closed      ? RowShape::closed
                          : kind == RowKind::short_row ? RowShape::short_row
                                                       : RowShape::open);
}

}  // namespace

KnitGraph build_knit_graph(const StitchMesh& mesh, const std::string& source_name) {
  const std::uint32_t n = mesh.num_faces();
  KnitGraph g;
  g.source_name = source_name;
  g.element = "face";
  g.type = mesh.stitch.raw();
  g.row = mesh.row.raw();
  g.source.resize(n);
  std::iota(g.source.begin(), g.source.end(), 0u);
  g.yarn_next.assign(n, kNoStitch);
  g.yarn_link.assign(n, YarnLink::none);
  g.flags.assign(n, 0);
  g.direction.resize(n);
  for (Face f : mesh.faces()) g.direction[f.index()] = entering_direction(mesh, f);
  g.part_names = mesh.part_names;
  if (!mesh.part_names.empty()) g.part = mesh.part.raw();
  link_yarn(mesh, g);
  record_mismatches(mesh, g, add_loops(mesh, g));
  flag_stitches(mesh, g);
  shape_rows(mesh, g);
  return g;
}

}  // namespace skein
