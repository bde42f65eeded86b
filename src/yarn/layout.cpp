#include "yarn/layout.hpp"

#include "yarn/mesh_relax.hpp"
#include "yarn/parallel.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <deque>

namespace skein {
namespace {

constexpr float kNarrowest = 0.5f;  // the narrowest cell, in stitch widths

std::vector<StitchId> yarn_predecessors(const KnitGraph& graph) {
  std::vector<StitchId> prev(graph.size(), kNoStitch);
  for (StitchId s = 0; s < graph.size(); ++s)
    if (graph.yarn_next[s] != kNoStitch) prev[graph.yarn_next[s]] = s;
  return prev;
}

// The yarn goes along the row (or round a helix) from s to its next stitch: they lie side
// by side. At a turn the next stitch is above, so it says nothing about the course direction.
bool beside(const KnitGraph& graph, StitchId s) {
  return graph.yarn_next[s] != kNoStitch &&
         (graph.yarn_link[s] == YarnLink::course || graph.yarn_link[s] == YarnLink::shift);
}

// A difference of centres across s: (after - before) / 2 with both, one-sided with one.
Point3 central_difference(const Point3& centre, const Point3* before, const Point3* after) {
  if (before && after) return (*after - *before) / 2;
  if (after) return *after - centre;
  if (before) return centre - *before;
  return Point3::Zero();
}

Point3 mean_of(const std::vector<Point3>& points) {
  Point3 sum = Point3::Zero();
  for (const Point3& p : points) sum += p;
  return sum / static_cast<float>(points.size());
}

// The course and wale axes of s from the centres of the stitches beside it along the yarn
// and of those whose loops it takes and that take its loops.
struct NeighbourAxes {
  Point3 course = Point3::Zero();
  Point3 wale = Point3::Zero();
};

NeighbourAxes neighbour_axes(const KnitGraph& graph, std::span<const Point3> centre,
                             std::span<const StitchId> prev, StitchId s) {
  NeighbourAxes axes;
  StitchId p = prev[s];
  const Point3* before = p != kNoStitch && beside(graph, p) ? &centre[p] : nullptr;
  const Point3* after = beside(graph, s) ? &centre[graph.yarn_next[s]] : nullptr;
  axes.course = central_difference(centre[s], before, after);
  std::vector<Point3> below, above;
  for (std::uint32_t l : graph.loops_taken_by(s))
    if (graph.loops[l].maker != kNoStitch) below.push_back(centre[graph.loops[l].maker]);
  for (std::uint32_t l : graph.loops_made_by(s))
    if (graph.loops[l].taker != kNoStitch) above.push_back(centre[graph.loops[l].taker]);
  Point3 b = below.empty() ? Point3::Zero() : mean_of(below);
  Point3 a = above.empty() ? Point3::Zero() : mean_of(above);
  axes.wale =
      central_difference(centre[s], below.empty() ? nullptr : &b, above.empty() ? nullptr : &a);
  return axes;
}

// Replaces missing or degenerate axes by ones of the gauge's size that are square to the
// normal, so that every frame spans a cell.
StitchFrame frame_at(const Point3& centre, Point3 course, Point3 wale, Point3 normal,
                     const Gauge& gauge) {
  if (!normal.allFinite() || normal.norm() < 1e-12f) normal = Point3::UnitZ();
  normal.normalize();
  if (!course.allFinite() || course.norm() < 1e-3f * gauge.stitch_width)
    course = normal.unitOrthogonal() * gauge.stitch_width;
  // A stitch on top of its neighbour (AutoKnit's miss beside the tuck that turns a short
  // row) still gets a cell its yarn fits in: half a stitch at least.
  course *= std::max(1.0f, kNarrowest * gauge.stitch_width / course.norm());
  if (!wale.allFinite() || wale.cross(course).norm() < 0.1f * wale.norm() * course.norm())
    wale = normal.cross(course).normalized() * gauge.row_height;
  StitchFrame f;
  f.course = course;
  f.wale = wale;
  f.normal = normal;
  f.origin = centre - course / 2 - wale / 2;
  return f;
}

// Flips normals to agree with a neighbour's, breadth first from each unvisited stitch.
void orient_normals(const KnitGraph& graph, std::span<const StitchId> prev,
                    std::vector<Point3>& normal) {
  std::vector<std::uint8_t> seen(graph.size(), 0);
  std::deque<StitchId> queue;
  auto visit = [&](StitchId from, StitchId to) {
    if (to == kNoStitch || seen[to]) return;
    seen[to] = 1;
    if (normal[to].dot(normal[from]) < 0) normal[to] = -normal[to];
    queue.push_back(to);
  };
  for (StitchId start = 0; start < graph.size(); ++start) {
    if (seen[start]) continue;
    seen[start] = 1;
    queue.push_back(start);
    while (!queue.empty()) {
      StitchId s = queue.front();
      queue.pop_front();
      visit(s, graph.yarn_next[s]);
      visit(s, prev[s]);
      for (std::uint32_t l : graph.loops_taken_by(s)) visit(s, graph.loops[l].maker);
      for (std::uint32_t l : graph.loops_made_by(s)) visit(s, graph.loops[l].taker);
    }
  }
}

// The wale axis without its part along the course. Where wales lean (beside AutoKnit's
// decreases a loop's taker sits more than a stitch aside) a sheared cell would put a
// stitch's lobe over its neighbour's; a square one keeps it over its own slot, and its head
// still bends to wherever the taker grips it.
void square_to_course(NeighbourAxes& axes) {
  float along = axes.course.squaredNorm();
  if (along > 0) axes.wale -= axes.course * (axes.wale.dot(axes.course) / along);
}

// AutoKnit places rows in close pairs (test-A: 0.10 apart, then 0.27), so cells centred on
// the stitches would overlap a row's neighbour and leave gaps at the next. Springs along the
// yarn (at their own lengths: the course keeps its shape) and along every loop (at the mean
// of the loops' lengths) space the rows evenly; a weak pull to the input keeps the shape.
std::vector<Point3> evenly_spaced_rows(const KnitGraph& graph, const std::vector<Point3>& centre) {
  std::vector<Spring> springs;
  double wale_sum = 0;
  for (const Loop& loop : graph.loops) {
    if (loop.maker == kNoStitch || loop.taker == kNoStitch) continue;
    wale_sum += (centre[loop.taker] - centre[loop.maker]).norm();
    springs.push_back({loop.maker, loop.taker, 0});
  }
  if (springs.empty()) return centre;
  const auto row_height = static_cast<float>(wale_sum / static_cast<double>(springs.size()));
  for (Spring& s : springs) s.rest = row_height;
  std::vector<float> widths;
  for (StitchId s = 0; s < graph.size(); ++s)
    if (beside(graph, s)) widths.push_back((centre[graph.yarn_next[s]] - centre[s]).norm());
  const float stitch_width = median(widths, row_height);
  for (StitchId s = 0; s < graph.size(); ++s)
    if (beside(graph, s)) springs.push_back({s, graph.yarn_next[s], stitch_width});
  // No bending: these springs join stitches, not a surface's vertices (with it test-A's yarn
  // no longer relaxed to tolerance).
  MeshRelaxOptions options;
  options.bend = 0;
  options.anchor = 0.05f;
  return relax_springs(centre, springs, options);
}

Gauge gauge_of(const std::vector<NeighbourAxes>& axes) {
  std::vector<float> widths, heights;
  for (const NeighbourAxes& a : axes) {
    if (a.course.norm() > 0) widths.push_back(a.course.norm());
    if (a.wale.norm() > 0) heights.push_back(a.wale.norm());
  }
  Gauge g;
  g.stitch_width = median(widths, 1);
  g.row_height = median(heights, g.stitch_width);
  return g;
}

// The frame of a face: course from its bottom and top course edges (bottom edges run left
// to right, top edges right to left, counter-clockwise from the right side), wale from the
// middle of its bottom edges to the middle of its top edges, normal by Newell's formula.
StitchFrame face_frame(const StitchMesh& mesh, std::span<const Point3> position, Face f,
                       const Gauge& gauge) {
  Point3 course = Point3::Zero(), bottom = Point3::Zero(), top = Point3::Zero();
  Point3 normal = Point3::Zero(), centre = Point3::Zero();
  int bottoms = 0, tops = 0;
  for (Halfedge h : mesh.halfedges(f)) {
    const Point3& a = position[mesh.tail(h).index()];
    const Point3& b = position[mesh.head(h).index()];
    centre += a;
    normal += a.cross(b);
    if (mesh.role[h] == EdgeRole::bottom) course += (b - a) / 2, bottom += (a + b) / 2, ++bottoms;
    if (mesh.role[h] == EdgeRole::top) course -= (b - a) / 2, top += (a + b) / 2, ++tops;
  }
  centre /= static_cast<float>(mesh.degree(f));
  Point3 wale = bottoms && tops ? Point3(top / tops - bottom / bottoms) : Point3::Zero();
  if (!mesh.runs_left_to_right(f)) course = -course;
  return frame_at(centre, course, wale, normal, gauge);
}

}  // namespace

StitchLayout layout_from_mesh(const StitchMesh& mesh, std::span<const Point3> position,
                              const KnitGraph& graph) {
  StitchLayout layout;
  layout.gauge = stitch_mesh_gauge(mesh);
  layout.frame.resize(graph.size());
  layout.right_to_left.assign(graph.size(), 0);
  std::vector<Point3> centre(graph.size(), Point3::Zero());
  const StitchId faces = std::min(graph.first_extruded, graph.size());
  for (StitchId s = 0; s < faces; ++s) {
    Face f(graph.source[s]);
    layout.frame[s] = face_frame(mesh, position, f, layout.gauge);
    layout.right_to_left[s] = !mesh.runs_left_to_right(f);
    centre[s] = layout.frame[s].at(0.5f, 0.5f, 0);
  }
  // Extruded stitches (a join's three-needle bind-off, a split's cast-on) sit on their
  // mismatched edge between two sides that meet there, their loops going to or coming from
  // both: they stand as a ridge on the wrong side, course along the edge the way their yarn
  // runs, wale out of the surface, so that each side's loops reach them from below (as the
  // two pieces held right sides together are bound off). A wale in the surface pointed away
  // from one side: its loops' heads were bent back across the cell (letter-h's seven loops
  // not held at its join).
  for (StitchId s = faces; s < graph.size(); ++s) {
    const MismatchEdge& e = graph.mismatch_edges[graph.extruded_at[s - faces]];
    centre[s] = (position[e.vertex[0]] + position[e.vertex[1]]) / 2;
  }
  std::vector<StitchId> prev = yarn_predecessors(graph);
  for (StitchId s = faces; s < graph.size(); ++s) {
    const MismatchEdge& e = graph.mismatch_edges[graph.extruded_at[s - faces]];
    NeighbourAxes axes = neighbour_axes(graph, centre, prev, s);
    Point3 surface = Point3::Zero();
    for (std::uint32_t l : graph.loops_taken_by(s))
      if (graph.loops[l].maker < faces) surface += layout.frame[graph.loops[l].maker].normal;
    for (std::uint32_t l : graph.loops_made_by(s))
      if (graph.loops[l].taker < faces) surface += layout.frame[graph.loops[l].taker].normal;
    if (surface.norm() < 1e-12f) surface = axes.course.cross(axes.wale);
    surface.normalize();
    Point3 course = position[e.vertex[1]] - position[e.vertex[0]];
    course -= surface * surface.dot(course);
    if (course.dot(axes.course) < 0) course = -course;
    Point3 wale = -surface * layout.gauge.row_height;
    layout.frame[s] =
        frame_at(centre[s] + wale / 2, course, wale, course.cross(wale), layout.gauge);
  }
  return layout;
}

StitchLayout layout_from_positions(const KnitGraph& graph,
                                   std::span<const std::array<double, 3>> positions) {
  const StitchId n = graph.size();
  std::vector<Point3> centre(n);
  Point3 middle = Point3::Zero();
  for (StitchId s = 0; s < n; ++s) {
    centre[s] = Eigen::Vector3d(positions[s][0], positions[s][1], positions[s][2]).cast<float>();
    if (!centre[s].allFinite()) centre[s] = Point3::Zero();
    middle += centre[s] / static_cast<float>(n);
  }
  centre = evenly_spaced_rows(graph, centre);
  std::vector<StitchId> prev = yarn_predecessors(graph);
  std::vector<NeighbourAxes> axes(n);
  std::vector<Point3> normal(n);
  for (StitchId s = 0; s < n; ++s) {
    axes[s] = neighbour_axes(graph, centre, prev, s);
    normal[s] = axes[s].course.cross(axes[s].wale).normalized();
    if (!normal[s].allFinite()) normal[s] = Point3::UnitZ();
    square_to_course(axes[s]);
  }
  orient_normals(graph, prev, normal);
  float outwards = 0;
  for (StitchId s = 0; s < n; ++s) outwards += normal[s].dot(centre[s] - middle);
  StitchLayout layout;
  layout.gauge = gauge_of(axes);
  layout.frame.resize(n);
  layout.right_to_left.assign(n, 0);
  for (StitchId s = 0; s < n; ++s) {
    if (outwards < 0) normal[s] = -normal[s];
    layout.frame[s] = frame_at(centre[s], axes[s].course, axes[s].wale, normal[s], layout.gauge);
    // A course axis that runs against the right side's left-to-right direction.
    layout.right_to_left[s] = axes[s].course.cross(axes[s].wale).dot(normal[s]) < 0;
  }
  return layout;
}

}  // namespace skein
