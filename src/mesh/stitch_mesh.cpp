#include "mesh/stitch_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <queue>

#include "common/error.hpp"

namespace skein {

char role_letter(EdgeRole r) {
  switch (r) {
    case EdgeRole::bottom:
      return 'b';
    case EdgeRole::top:
      return 't';
    case EdgeRole::wale_in:
      return 'i';
    case EdgeRole::wale_out:
      return 'o';
  }
  return '?';
}

std::optional<EdgeRole> role_from_letter(char letter) {
  for (EdgeRole r : {EdgeRole::bottom, EdgeRole::top, EdgeRole::wale_in, EdgeRole::wale_out})
    if (role_letter(r) == letter) return r;
  return std::nullopt;
}

const char* edge_kind_name(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::border:
      return "border";
    case EdgeKind::course:
      return "course";
    case EdgeKind::wale:
      return "wale";
    case EdgeKind::join:
      return "joining mismatch";
    case EdgeKind::split:
      return "splitting mismatch";
    case EdgeKind::contracting_perpendicular:
      return "contracting perpendicular mismatch";
    case EdgeKind::expanding_perpendicular:
      return "expanding perpendicular mismatch";
    case EdgeKind::conflicting_wale:
      return "conflicting wale edge";
  }
  return "?";
}

const char* shift_option_name(ShiftOption option) {
  switch (option) {
    case kNotShifted:
      return "none";
    case kShiftUpRight:
      return "up-right";
    case kShiftUpLeft:
      return "up-left";
    case kShiftDownRight:
      return "down-right";
    case kShiftDownLeft:
      return "down-left";
  }
  return "?";
}

// ---------------------------------------------------------------- navigation

Halfedge StitchMesh::next(Halfedge h) const {
  Face f = face(h);
  std::uint32_t n = h.index() + 1;
  return Halfedge(n == face_first_[f.index() + 1] ? face_first_[f.index()] : n);
}

Halfedge StitchMesh::prev(Halfedge h) const {
  Face f = face(h);
  std::uint32_t first = face_first_[f.index()];
  return Halfedge(h.index() == first ? face_first_[f.index() + 1] - 1 : h.index() - 1);
}

std::span<const Halfedge> StitchMesh::outgoing(Vertex v) const {
  return {vertex_out_.data() + vertex_first_[v.index()],
          vertex_out_.data() + vertex_first_[v.index() + 1]};
}

Edge StitchMesh::find_edge(Vertex a, Vertex b) const {
  for (Halfedge h : outgoing(a))
    if (head(h) == b) return edge(h);
  for (Halfedge h : outgoing(b))
    if (head(h) == a) return edge(h);
  return {};
}

Face StitchMesh::neighbour(Halfedge h) const {
  Halfedge t = twin(h);
  return t.valid() ? face(t) : Face();
}

Vertex StitchMesh::wale_top(Halfedge h) const {
  if (role[next(h)] == EdgeRole::top) return head(h);
  if (role[prev(h)] == EdgeRole::top) return tail(h);
  return {};
}

Vertex StitchMesh::wale_bottom(Halfedge h) const {
  if (role[prev(h)] == EdgeRole::bottom) return tail(h);
  if (role[next(h)] == EdgeRole::bottom) return head(h);
  return {};
}

// Counter-clockwise, the right-hand wale edge comes straight after the bottom course edges.
bool StitchMesh::runs_left_to_right(Face f) const {
  Halfedge out = wale_out(f);
  return role[prev(out)] == EdgeRole::bottom;
}

Halfedge StitchMesh::wale_in(Face f) const {
  for (Halfedge h : halfedges(f))
    if (role[h] == EdgeRole::wale_in) return h;
  return {};
}

Halfedge StitchMesh::wale_out(Face f) const {
  for (Halfedge h : halfedges(f))
    if (role[h] == EdgeRole::wale_out) return h;
  return {};
}

EdgeKind StitchMesh::kind(Edge e) const {
  Halfedge h = halfedge(e), t = twin(h);
  if (!t.valid()) return EdgeKind::border;
  EdgeRole a = role[h], b = role[t];
  if (is_course(a) && is_course(b)) {
    if (a != b) return EdgeKind::course;
    return a == EdgeRole::top ? EdgeKind::join : EdgeKind::split;
  }
  if (is_wale(a) && is_wale(b)) return a != b ? EdgeKind::wale : EdgeKind::conflicting_wale;
  EdgeRole course = is_course(a) ? a : b;
  return course == EdgeRole::top ? EdgeKind::contracting_perpendicular
                                 : EdgeKind::expanding_perpendicular;
}

// ---------------------------------------------------------------- building

StitchMeshBuilder::StitchMeshBuilder(std::string source_name) : source_(std::move(source_name)) {
  mesh_.face_first_.push_back(0);
}

void StitchMeshBuilder::reserve(std::size_t vertices, std::size_t faces, std::size_t halfedges) {
  mesh_.position.reserve(vertices);
  mesh_.face_first_.reserve(faces + 1);
  mesh_.stitch.reserve(faces);
  mesh_.he_tail_.reserve(halfedges);
  mesh_.he_face_.reserve(halfedges);
  mesh_.role.reserve(halfedges);
}

Vertex StitchMeshBuilder::add_vertex(Vec3 p) {
  mesh_.position.push_back(p);
  return Vertex(mesh_.num_vertices() - 1);
}

Face StitchMeshBuilder::add_face(std::span<const Vertex> vertices, std::span<const EdgeRole> roles,
                                 StitchType type) {
  SKEIN_ASSERT(vertices.size() == roles.size(), "one role per face edge");
  SKEIN_ASSERT(vertices.size() >= 3, "a face has at least three corners (callers check input)");
  Face f(mesh_.num_faces());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    mesh_.he_tail_.push_back(vertices[i]);
    mesh_.he_face_.push_back(f);
    mesh_.role.push_back(roles[i]);
  }
  mesh_.face_first_.push_back(mesh_.num_halfedges());
  mesh_.stitch.push_back(type);
  return f;
}

namespace {

std::string vertex_pair(Vertex a, Vertex b) {
  return fmt::format("vertices {} and {}", a.index() + 1, b.index() + 1);
}

}  // namespace

StitchMesh StitchMeshBuilder::build() && {
  StitchMesh& m = mesh_;
  const std::uint32_t nv = m.num_vertices(), nh = m.num_halfedges();
  for (std::uint32_t i = 0; i < nh; ++i)
    if (m.he_tail_[Halfedge(i)].index() >= nv)
      throw MeshError(fmt::format("{}: face {} uses vertex {}, but there are only {} vertices",
                                  source_, m.he_face_[Halfedge(i)].index() + 1,
                                  m.he_tail_[Halfedge(i)].index() + 1, nv));

  // Outgoing halfedges per vertex, by counting sort: linear, and small per vertex.
  m.vertex_first_.assign(nv + 1, 0);
  for (std::uint32_t i = 0; i < nh; ++i) ++m.vertex_first_[m.he_tail_[Halfedge(i)].index() + 1];
  std::partial_sum(m.vertex_first_.begin(), m.vertex_first_.end(), m.vertex_first_.begin());
  m.vertex_out_.resize(nh);
  {
    std::vector<std::uint32_t> fill(m.vertex_first_.begin(), m.vertex_first_.end() - 1);
    for (std::uint32_t i = 0; i < nh; ++i)
      m.vertex_out_[fill[m.he_tail_[Halfedge(i)].index()]++] = Halfedge(i);
  }

  m.he_twin_ = HalfedgeData<Halfedge>(nh);
  m.he_edge_ = HalfedgeData<Edge>(nh);
  for (std::uint32_t i = 0; i < nh; ++i) {
    Halfedge h(i);
    Vertex a = m.tail(h), b = m.head(h);
    if (a == b)
      throw MeshError(fmt::format("{}: face {} repeats vertex {} on consecutive corners", source_,
                                  m.face(h).index() + 1, a.index() + 1));
    for (Halfedge o : m.outgoing(a))
      if (o != h && m.head(o) == b)
        throw MeshError(fmt::format(
            "{}: the edge between {} is used twice in the same direction, by faces {} and {}; "
            "expected neighbouring faces listed with the same orientation (counter-clockwise)",
            source_, vertex_pair(a, b), m.face(h).index() + 1, m.face(o).index() + 1));
    for (Halfedge o : m.outgoing(b)) {
      if (m.head(o) != a) continue;
      m.he_twin_[h] = o;
    }
  }
  for (std::uint32_t i = 0; i < nh; ++i) {
    Halfedge h(i), t = m.he_twin_[h];
    if (t.valid() && t < h) {
      m.he_edge_[h] = m.he_edge_[t];
      continue;
    }
    m.he_edge_[h] = Edge(m.num_edges());
    m.edge_halfedge_.push_back(h);
  }
  m.shift_path = EdgeData<std::uint8_t>(m.num_edges(), 0);
  m.mismatch_yarn = EdgeData<MismatchYarn>(m.num_edges());
  assign_rows(m);
  return std::move(m);
}

// ---------------------------------------------------------------- rows

namespace {

// Union-find over faces, with path halving.
struct Components {
  std::vector<std::uint32_t> parent;
  explicit Components(std::uint32_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // root is the lowest face
  }
};

}  // namespace

void assign_rows(StitchMesh& mesh) {
  const std::uint32_t nf = mesh.num_faces();
  Components rows(nf);
  for (Face f : mesh.faces()) {
    Halfedge out = mesh.wale_out(f);
    if (!out.valid()) continue;
    Halfedge t = mesh.twin(out);
    // A short-row face is where the work turns: the next row starts after it.
    if (t.valid() && mesh.role[t] == EdgeRole::wale_in && !info(mesh.stitch[f]).wales_adjacent)
      rows.unite(f.index(), mesh.face(t).index());
  }
  // Row graph: row A -> row B when B consumes a loop made in A (course edge, top to bottom).
  std::vector<std::uint32_t> root(nf);
  for (std::uint32_t f = 0; f < nf; ++f) root[f] = rows.find(f);
  std::vector<std::uint32_t> indegree(nf, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> arcs;
  for (Edge e : mesh.edges()) {
    if (mesh.kind(e) != EdgeKind::course) continue;
    Halfedge h = mesh.halfedge(e), t = mesh.twin(h);
    if (mesh.role[h] == EdgeRole::bottom) std::swap(h, t);
    std::uint32_t from = root[mesh.face(h).index()], to = root[mesh.face(t).index()];
    if (from != to) arcs.emplace_back(from, to);
  }
  // Counting sort by the row they leave, each target kept once: linear, unlike a sort.
  std::vector<std::uint32_t> first(nf + 1, 0);
  for (auto [from, to] : arcs) ++first[from + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<std::uint32_t> targets(arcs.size()), fill(first.begin(), first.end() - 1);
  for (auto [from, to] : arcs) targets[fill[from]++] = to;
  std::vector<std::uint32_t> seen_from(nf, Handle<FaceTag>::kInvalid);
  std::uint32_t kept = 0;
  for (std::uint32_t from = 0; from < nf; ++from) {
    std::uint32_t begin = first[from];
    first[from] = kept;
    for (std::uint32_t i = begin; i < fill[from]; ++i) {
      std::uint32_t to = targets[i];
      if (seen_from[to] == from) continue;
      seen_from[to] = from;
      targets[kept++] = to;
      ++indegree[to];
    }
  }
  first[nf] = kept;

  // Kahn's order, lowest root face first; rows in a cycle (unknittable) follow in face order.
  constexpr std::uint32_t kUnset = Handle<FaceTag>::kInvalid;
  std::vector<std::uint32_t> number(nf, kUnset);
  std::priority_queue<std::uint32_t, std::vector<std::uint32_t>, std::greater<>> ready;
  for (std::uint32_t r = 0; r < nf; ++r)
    if (root[r] == r && indegree[r] == 0) ready.push(r);
  std::uint32_t next_number = 0;
  auto take = [&](std::uint32_t r) {
    number[r] = next_number++;
    for (std::uint32_t i = first[r]; i < first[r + 1]; ++i)
      if (number[targets[i]] == kUnset && --indegree[targets[i]] == 0) ready.push(targets[i]);
  };
  for (std::uint32_t scan = 0;;) {
    while (!ready.empty()) {
      std::uint32_t r = ready.top();
      ready.pop();
      take(r);
    }
    while (scan < nf && (root[scan] != scan || number[scan] != kUnset)) ++scan;
    if (scan == nf) break;
    indegree[scan] = 0;
    ready.push(scan);
  }
  mesh.row = FaceData<std::uint32_t>(nf);
  for (Face f : mesh.faces()) mesh.row[f] = number[root[f.index()]];
}

std::vector<RowKind> row_kinds(const StitchMesh& mesh) {
  std::uint32_t rows = 0;
  for (Face f : mesh.faces()) rows = std::max(rows, mesh.row[f] + 1);
  std::vector<RowKind> kinds(rows, RowKind::closed);
  for (Face f : mesh.faces()) {
    Halfedge t = mesh.twin(mesh.wale_out(f));
    bool ring_link =
        t.valid() && mesh.role[t] == EdgeRole::wale_in && mesh.row[mesh.face(t)] == mesh.row[f];
    if (!ring_link && kinds[mesh.row[f]] == RowKind::closed) kinds[mesh.row[f]] = RowKind::open;
  }
  // Both rows meeting in a short-row face are short: the one that turns there and the next.
  for (Face f : mesh.faces()) {
    if (!info(mesh.stitch[f]).wales_adjacent) continue;
    kinds[mesh.row[f]] = RowKind::short_row;
    Face next = mesh.neighbour(mesh.wale_out(f));
    if (next.valid()) kinds[mesh.row[next]] = RowKind::short_row;
  }
  return kinds;
}

// ---------------------------------------------------------------- validation

std::string describe(const StitchMesh& mesh, Face f) {
  return fmt::format("face {} ({}, row {})", f.index() + 1, abbreviation(mesh.stitch[f]),
                     mesh.row[f] + 1);
}

std::string describe(const StitchMesh& mesh, Edge e) {
  Halfedge h = mesh.halfedge(e);
  return fmt::format("edge {}-{}", mesh.tail(h).index() + 1, mesh.head(h).index() + 1);
}

namespace {

std::string role_string(const StitchMesh& mesh, Face f) {
  std::string s;
  for (Halfedge h : mesh.halfedges(f)) s += role_letter(mesh.role[h]);
  return s;
}

// Counts maximal runs of equal "is course" flags around the face, cyclically.
int course_runs(const StitchMesh& mesh, Face f) {
  int runs = 0;
  for (Halfedge h : mesh.halfedges(f)) {
    Halfedge p = mesh.prev(h);
    bool here = is_course(mesh.role[h]), before = is_course(mesh.role[p]);
    if (here && !before) ++runs;
    if (here && before && mesh.role[h] != mesh.role[p]) ++runs;  // bottom run meets top run
  }
  return runs;
}

void validate_face(const StitchMesh& mesh, Face f) {
  const StitchTypeInfo& t = info(mesh.stitch[f]);
  int bottoms = 0, tops = 0, ins = 0, outs = 0;
  for (Halfedge h : mesh.halfedges(f)) {
    switch (mesh.role[h]) {
      case EdgeRole::bottom:
        ++bottoms;
        break;
      case EdgeRole::top:
        ++tops;
        break;
      case EdgeRole::wale_in:
        ++ins;
        break;
      case EdgeRole::wale_out:
        ++outs;
        break;
    }
  }
  auto fail = [&](const std::string& what) {
    throw MeshError(
        fmt::format("{} with edges '{}': {}", describe(mesh, f), role_string(mesh, f), what));
  };
  if (ins != 1 || outs != 1)
    fail(
        fmt::format("expected exactly one wale edge where the yarn enters (i) and one where it "
                    "leaves (o), found {} and {}",
                    ins, outs));
  bool tops_ok = t.variable_course_edges ? tops >= t.top_edges : tops == t.top_edges;
  if (bottoms != t.bottom_edges || !tops_ok)
    fail(fmt::format("a {} has {} bottom and {}{} top course edges, found {} and {}", t.name,
                     t.bottom_edges, t.variable_course_edges ? "at least " : "", t.top_edges,
                     bottoms, tops));
  bool adjacent = mesh.role[mesh.next(mesh.wale_in(f))] == EdgeRole::wale_out ||
                  mesh.role[mesh.next(mesh.wale_out(f))] == EdgeRole::wale_in;
  if (adjacent != t.wales_adjacent)
    fail(t.wales_adjacent ? "a short-row face has its two wale edges side by side"
                          : "the two wale edges must separate the bottom from the top edges");
  if (course_runs(mesh, f) != 2)
    fail("the bottom course edges and the top course edges must each be contiguous");
}

void validate_border(const StitchMesh& mesh, Halfedge h) {
  Face f = mesh.face(h);
  const StitchTypeInfo& t = info(mesh.stitch[f]);
  EdgeRole r = mesh.role[h];
  auto fail = [&](const std::string& what) {
    throw MeshError(fmt::format("{}: {} on the border: {}", describe(mesh, f),
                                describe(mesh, mesh.edge(h)), what));
  };
  if (r == EdgeRole::bottom && t.loops_in > 0)
    fail(
        fmt::format("a {} consumes a loop, but no stitch below makes one; expected a cast-on "
                    "(co) or a neighbour below",
                    t.name));
  if (r == EdgeRole::top && t.loops_out > 0)
    fail(
        fmt::format("the loop this {} makes is never consumed or bound off; expected a "
                    "bind-off (bo) or a neighbour above",
                    t.name));
}

void validate_interior(const StitchMesh& mesh, Edge e) {
  Halfedge h = mesh.halfedge(e), t = mesh.twin(h);
  auto fail = [&](const std::string& what) {
    throw MeshError(fmt::format("{} between {} and {}: {}", describe(mesh, e),
                                describe(mesh, mesh.face(h)), describe(mesh, mesh.face(t)), what));
  };
  EdgeKind k = mesh.kind(e);
  if (k == EdgeKind::conflicting_wale)
    fail(
        fmt::format("both faces' yarn {} here; expected the yarn to leave one face and enter "
                    "the other (course directions disagree)",
                    mesh.role[h] == EdgeRole::wale_out ? "leaves" : "enters"));
  for (Halfedge side : {h, t}) {
    const StitchTypeInfo& ti = info(mesh.stitch[mesh.face(side)]);
    if (mesh.role[side] == EdgeRole::bottom && ti.loops_in == 0)
      fail(fmt::format("a {} consumes no loop, so its bottom edge must be on the border", ti.name));
    if (mesh.role[side] == EdgeRole::top && ti.loops_out == 0)
      fail(fmt::format("a {} makes no loop, so its top edge must be on the border", ti.name));
  }
  if (mesh.shift_path[e] && k != EdgeKind::wale)
    fail(fmt::format("a shift-path runs along wale edges only; this is a {} edge",
                     edge_kind_name(k)));
  const MismatchYarn& y = mesh.mismatch_yarn[e];
  if (y.kind != MismatchYarn::Kind::by_default && k != EdgeKind::join && k != EdgeKind::split)
    fail(fmt::format("a yarn choice applies to joining or splitting edges only; this is a {} edge",
                     edge_kind_name(k)));
  if (y.kind == MismatchYarn::Kind::own && y.side != mesh.face(h) && y.side != mesh.face(t))
    fail(fmt::format("the yarn choice names face {}, which is not beside this edge",
                     y.side.index() + 1));
}

}  // namespace

void validate(const StitchMesh& mesh) {
  if (mesh.num_faces() == 0) throw MeshError("the stitch mesh has no faces");
  for (Face f : mesh.faces()) validate_face(mesh, f);
  for (Edge e : mesh.edges()) {
    if (mesh.is_border(e)) {
      if (mesh.shift_path[e])
        throw MeshError(
            fmt::format("{}: a shift-path edge must join two stitches of a closed "
                        "row, but this edge is on the border",
                        describe(mesh, e)));
      if (mesh.mismatch_yarn[e].kind != MismatchYarn::Kind::by_default)
        throw MeshError(
            fmt::format("{}: a yarn choice applies to joining or splitting edges "
                        "only, but this edge is on the border",
                        describe(mesh, e)));
      validate_border(mesh, mesh.halfedge(e));
    } else {
      validate_interior(mesh, e);
    }
  }
}

}  // namespace skein
