#include "yarn/mesh_relax.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "yarn/parallel.hpp"

namespace skein {
namespace {

Point3 point(const Vec3& v) {
  return {v.x, v.y, v.z};
}

// How much a wale edge of face f stretches because of a join or split beside the face.
float wale_scale_beside_mismatch(const StitchMesh& mesh, Face f) {
  for (Halfedge h : mesh.halfedges(f)) {
    EdgeKind kind = mesh.kind(mesh.edge(h));
    if (kind != EdgeKind::join && kind != EdgeKind::split) continue;
    return mesh.mismatch_yarn[mesh.edge(h)].kind == MismatchYarn::Kind::own ? 0.5f : 1.5f;
  }
  return 1;
}

// srn: the top course edges past the catalogue's count collapse.
bool extra_short_row_edge(const StitchMesh& mesh, Halfedge h, int top_index) {
  Face f = mesh.face(h);
  return mesh.stitch[f] == StitchType::srn && mesh.role[h] == EdgeRole::top &&
         top_index >= info(StitchType::srn).top_edges;
}

float rest_length(const StitchMesh& mesh, Edge e, const Gauge& g) {
  Halfedge h = mesh.halfedge(e);
  switch (mesh.kind(e)) {
    case EdgeKind::course:
    case EdgeKind::join:
    case EdgeKind::split:
      return g.stitch_width;
    case EdgeKind::wale:
    case EdgeKind::conflicting_wale:
      return g.row_height;
    case EdgeKind::contracting_perpendicular:
    case EdgeKind::expanding_perpendicular:
      return (g.stitch_width + g.row_height) / 2;
    case EdgeKind::border:
      break;
  }
  return is_course(mesh.role[h]) ? g.stitch_width : g.row_height;
}

std::vector<Spring> springs_of(const StitchMesh& mesh, const Gauge& g) {
  std::vector<Spring> springs;
  springs.reserve(mesh.num_edges() + 2 * mesh.num_faces());
  std::vector<float> rest(mesh.num_edges());
  for (Edge e : mesh.edges()) rest[e.index()] = rest_length(mesh, e, g);
  for (Face f : mesh.faces()) {
    float scale = wale_scale_beside_mismatch(mesh, f);
    int top_index = 0;
    for (Halfedge h : mesh.halfedges(f)) {
      float& r = rest[mesh.edge(h).index()];
      if (scale != 1 && is_wale(mesh.role[h]) && mesh.kind(mesh.edge(h)) == EdgeKind::wale)
        r = g.row_height * scale;
      if (extra_short_row_edge(mesh, h, top_index)) r = 0;
      top_index += mesh.role[h] == EdgeRole::top;
    }
    if (mesh.degree(f) != 4) continue;
    std::vector<std::uint32_t> corner;
    for (Halfedge h : mesh.halfedges(f)) corner.push_back(mesh.tail(h).index());
    float diagonal = std::hypot(g.stitch_width, g.row_height);
    springs.push_back({corner[0], corner[2], diagonal});
    springs.push_back({corner[1], corner[3], diagonal});
  }
  for (Edge e : mesh.edges()) {
    Halfedge h = mesh.halfedge(e);
    springs.push_back({mesh.tail(h).index(), mesh.head(h).index(), rest[e.index()]});
  }
  return springs;
}

}  // namespace

Gauge stitch_mesh_gauge(const StitchMesh& mesh) {
  std::vector<float> widths, heights;
  for (Edge e : mesh.edges()) {
    Halfedge h = mesh.halfedge(e);
    float length = (point(mesh.position[mesh.head(h)]) - point(mesh.position[mesh.tail(h)])).norm();
    EdgeKind kind = mesh.kind(e);
    bool border = kind == EdgeKind::border;
    if (kind == EdgeKind::course || (border && is_course(mesh.role[h]))) widths.push_back(length);
    if (kind == EdgeKind::wale || (border && is_wale(mesh.role[h]))) heights.push_back(length);
  }
  Gauge g;
  g.stitch_width = median(widths, 1);
  g.row_height = median(heights, g.stitch_width);
  return g;
}

std::vector<Point3> relax_springs(const std::vector<Point3>& start, std::span<const Spring> springs,
                                  const MeshRelaxOptions& options) {
  const auto n = static_cast<std::uint32_t>(start.size());
  std::vector<Point3> x = start, delta(n), lap(n), bilap(n);
  std::vector<float> valence(n, 0);
  for (const Spring& s : springs) valence[s.a] += 1, valence[s.b] += 1;
  // The umbrella operator: the mean of a point's spring neighbours minus the point.
  auto umbrella = [&](const std::vector<Point3>& f, std::vector<Point3>& out) {
    std::fill(out.begin(), out.end(), Point3::Zero());
    for (const Spring& s : springs) out[s.a] += f[s.b], out[s.b] += f[s.a];
    for (std::uint32_t v = 0; v < n; ++v)
      if (valence[v] > 0) out[v] = out[v] / valence[v] - f[v];
  };
  // Each spring moves its ends half way to its rest length, averaged over the springs at a
  // point, so that no step overshoots whatever the valence. Bending moves each point against
  // the umbrella of the umbrella (the discrete bi-Laplacian): a fold or an accordion of rows
  // is smoothed out, while a tube's even curvature, whose umbrella is the same everywhere, is
  // left alone (a plain umbrella step would shrink it).
  const bool bend = options.bend > 0;
  for (int it = 0; it < options.iterations; ++it) {
    std::fill(delta.begin(), delta.end(), Point3::Zero());
    if (bend) std::fill(lap.begin(), lap.end(), Point3::Zero());
    for (const Spring& s : springs) {
      Point3 d = x[s.b] - x[s.a];
      if (bend) lap[s.a] += d, lap[s.b] -= d;  // the umbrella of x, in the same pass
      float length = d.norm();
      if (length < 1e-12f) continue;
      Point3 c = d * ((length - s.rest) / length / 2);
      delta[s.a] += c;
      delta[s.b] -= c;
    }
    if (bend) {
      for (std::uint32_t v = 0; v < n; ++v)
        if (valence[v] > 0) lap[v] /= valence[v];
      umbrella(lap, bilap);
    }
    for (std::uint32_t v = 0; v < n; ++v) {
      if (valence[v] > 0) x[v] += delta[v] / valence[v];
      if (bend) x[v] -= options.bend * bilap[v];
      x[v] += options.anchor * (start[v] - x[v]);
    }
  }
  return x;
}

std::vector<Point3> relax_stitch_mesh(const StitchMesh& mesh, const Gauge& gauge,
                                      const MeshRelaxOptions& options) {
  std::vector<Point3> start(mesh.num_vertices());
  for (Vertex v : mesh.vertices()) start[v.index()] = point(mesh.position[v]);
  return relax_springs(start, springs_of(mesh, gauge), options);
}

std::uint32_t folded_faces(const StitchMesh& mesh, std::span<const Point3> positions) {
  std::vector<Point3> normal(mesh.num_faces(), Point3::Zero());
  for (Face f : mesh.faces())
    for (Halfedge h : mesh.halfedges(f))
      normal[f.index()] += positions[mesh.tail(h).index()].cross(positions[mesh.head(h).index()]);
  std::uint32_t folded = 0;
  for (Face f : mesh.faces())
    for (Halfedge h : mesh.halfedges(f)) {
      Halfedge twin = mesh.twin(h);
      if (!twin.valid() || normal[f.index()].dot(normal[mesh.face(twin).index()]) >= 0) continue;
      ++folded;
      break;
    }
  return folded;
}

}  // namespace skein
