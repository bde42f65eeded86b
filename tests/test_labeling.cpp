// Labeling (paper §3.4) and stitch-mesh generation at a gauge: every face gets its directions,
// every failure names the faces left over and why, and generated stitch meshes are valid and
// knittable (randomized grids and cylinders of varying radius, compiled and scheduled).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>

#include "driver/pipeline.hpp"
#include "labeling/labeling.hpp"
#include "labeling/shapes.hpp"
#include "labeling/stitch_generation.hpp"

namespace skein {
namespace {

using Faces = std::vector<std::vector<std::uint32_t>>;

Project project_with_stitch(double width, double height) {
  Project p;
  p.file = "test.yaml";
  p.stitch_width = width;
  p.stitch_height = height;
  return p;
}

// A sheet of cols x rows quads in the xy plane, column widths and row heights jittered.
CoarseMesh grid(std::uint32_t cols, std::uint32_t rows, std::mt19937& rng) {
  std::uniform_real_distribution<double> size(3, 9);
  std::vector<double> xs{0}, ys{0};
  for (std::uint32_t c = 0; c < cols; ++c) xs.push_back(xs.back() + size(rng));
  for (std::uint32_t r = 0; r < rows; ++r) ys.push_back(ys.back() + size(rng));
  std::vector<Vec3> v;
  for (double y : ys)
    for (double x : xs) v.push_back({static_cast<float>(x), static_cast<float>(y), 0});
  Faces faces;
  for (std::uint32_t r = 0; r < rows; ++r)
    for (std::uint32_t c = 0; c < cols; ++c) {
      std::uint32_t a = r * (cols + 1) + c;
      faces.push_back({a, a + 1, a + cols + 2, a + cols + 1});
    }
  return build_coarse_mesh("<grid>", v, faces);
}

// A tube up the y axis: `sides` faces round, one ring per radius (varying: shaping).
CoarseMesh cylinder(std::uint32_t sides, const std::vector<double>& radii, double ring_height) {
  std::vector<Vec3> v;
  for (std::size_t r = 0; r < radii.size(); ++r)
    for (std::uint32_t j = 0; j < sides; ++j) {
      double a = 2 * std::numbers::pi * j / sides;
      v.push_back({static_cast<float>(radii[r] * std::cos(a)), static_cast<float>(r * ring_height),
                   static_cast<float>(-radii[r] * std::sin(a))});
    }
  Faces faces;
  for (std::uint32_t r = 0; r + 1 < radii.size(); ++r)
    for (std::uint32_t j = 0; j < sides; ++j) {
      std::uint32_t k = (j + 1) % sides;
      faces.push_back({r * sides + j, r * sides + k, (r + 1) * sides + k, (r + 1) * sides + j});
    }
  return build_coarse_mesh("<cylinder>", v, faces);
}

// Square bars of unit cubes (the paper's Figs. 18 and 19): the cube faces no other cube
// covers, outwards; a face towards a cell in `open_ends` is left out (an open end of a bar).
// `starts` gets, per open end, the edge from its first corner to its second.
struct Cell {
  int x, y, z;
  auto operator<=>(const Cell&) const = default;
};
CoarseMesh cube_bars(const std::vector<Cell>& cubes, const std::vector<Cell>& open_ends,
                     std::vector<CoarseEdgeRef>* starts = nullptr) {
  std::set<Cell> filled(cubes.begin(), cubes.end()), open(open_ends.begin(), open_ends.end());
  std::map<Cell, std::uint32_t> index;
  std::vector<Vec3> v;
  auto vertex = [&](Cell c) {
    auto [it, added] = index.try_emplace(c, static_cast<std::uint32_t>(v.size()));
    if (added) v.push_back({float(c.x), float(c.y), float(c.z)});
    return it->second;
  };
  Faces faces;
  for (Cell c : cubes)
    for (int axis = 0; axis < 3; ++axis)
      for (int sign : {1, -1}) {
        int p[3] = {c.x, c.y, c.z};
        p[axis] += sign;
        Cell beyond{p[0], p[1], p[2]};
        if (filled.count(beyond)) continue;
        // Corners counter-clockwise seen from outside: along the next two axes in turn.
        int b = (axis + 1) % 3, d = (axis + 2) % 3;
        std::vector<std::uint32_t> face;
        for (auto [db, dd] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
          int q[3] = {c.x, c.y, c.z};
          q[axis] += sign > 0;
          q[b] += db;
          q[d] += dd;
          face.push_back(vertex({q[0], q[1], q[2]}));
        }
        if (sign < 0) std::reverse(face.begin(), face.end());
        if (!open.count(beyond)) {
          faces.push_back(face);
        } else if (starts) {
          starts->push_back({face[1], face[0], 0});  // the border runs against the missing face
        }
      }
  return build_coarse_mesh("<bars>", v, faces);
}

std::string labeling_error(const CoarseMesh& mesh, const Project& project) {
  try {
    label_coarse_mesh(mesh, project);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

// Every edge of the coarse mesh carries the same number of stitch segments on both sides, and
// the compiled model is knittable with the expected yarn pieces.
void expect_generated_knittable(const CoarseMesh& coarse, const Project& project,
                                std::uint32_t yarn_pieces) {
  Labeling labeling = label_coarse_mesh(coarse, project);
  GeneratedStitchMesh g = generate_stitch_mesh(coarse, labeling, project);
  ASSERT_NO_THROW(validate(g.mesh));
  EXPECT_EQ(g.coarse_face.size(), g.mesh.num_faces());
  Compilation c = compile_stitch_mesh(std::move(g.mesh), coarse.source);
  EXPECT_TRUE(c.knittability.knittable) << check_report(c);
  EXPECT_EQ(c.yarns.size(), yarn_pieces) << check_report(c);
}

TEST(Labeling, SheetRowsRunAcrossFromTheLowestEdge) {
  std::mt19937 rng(1);
  CoarseMesh m = grid(3, 2, rng);
  Labeling l = label_coarse_mesh(m, project_with_stitch(1, 1));
  for (CoarseFace f : m.faces()) {
    CoarseHalfedge b = l.find(m, f, CoarseRole::bottom);
    EXPECT_EQ(m.at(m.tail(b)).y, m.at(m.head(b)).y);  // horizontal bottoms
    EXPECT_LT(m.at(m.tail(b)).x, m.at(m.head(b)).x);  // running left to right
  }
  // The first row is labelled first, across: faces 1-3, then 4-6.
  EXPECT_LT(l.order[2], l.order[3]);
}

TEST(Labeling, TubeRowsCloseIntoRings) {
  CoarseMesh m = cylinder(6, {5, 5, 5}, 4);
  Labeling l = label_coarse_mesh(m, project_with_stitch(1, 1));
  for (CoarseFace f : m.faces()) {
    CoarseHalfedge r = l.find(m, f, CoarseRole::right);
    EXPECT_EQ(l[m.twin(r)], CoarseRole::left);  // every neighbour in the ring agrees
  }
}

TEST(Labeling, TriangleReachedSidewaysEndsShortRows) {
  Project p;
  p.file = "test.yaml";
  p.mesh = std::string(SKEIN_SOURCE_DIR) + "/samples/short-row-wedge/short-row-wedge.obj";
  CoarseMesh m = read_coarse_mesh(p.mesh);
  Labeling l = label_coarse_mesh(m, p);
  EXPECT_TRUE(l.short_row[2]);
  EXPECT_EQ(l.wide_side[2], CoarseRole::right);
  CoarseHalfedge wale = l.find(m, CoarseFace(2), CoarseRole::right);
  EXPECT_EQ(m.describe(wale), "edge 5-7");
}

TEST(Labeling, TriangleDetectedWhenItsNeighboursAreLabelled) {
  // The triangle (face 3) is reached from below first; once the quad beside it is labelled,
  // the side that quad gives it decides its wale edge (paper §3.4).
  std::vector<Vec3> v{{0, 0, 0}, {2, 0, 0}, {4, 0, 0}, {0, 2, 0},
                      {2, 2, 0}, {4, 2, 0}, {2, 4, 0}, {4, 4, 0}};
  Faces faces{{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 6}, {4, 5, 7, 6}};
  CoarseMesh m = build_coarse_mesh("<t>", v, faces);
  Labeling l = label_coarse_mesh(m, project_with_stitch(0.5, 0.5));
  EXPECT_TRUE(l.short_row[2]);
  EXPECT_EQ(l.wide_side[2], CoarseRole::right);
}

TEST(Labeling, ClosedSurfaceHasNoStart) {
  // A cube: every edge is shared.
  std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  Faces faces{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  EXPECT_EQ(labeling_error(build_coarse_mesh("cube.obj", v, faces), project_with_stitch(1, 1)),
            "cube.obj: the mesh has no open boundary to start from; name an interior edge to cast "
            "on along in the project file (start: [{edge: [a, b]}])");
}

TEST(Labeling, SeparatePieceNeedsItsOwnStart) {
  std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                      {3, 5, 0}, {4, 5, 0}, {4, 6, 0}, {3, 6, 0}};
  Faces faces{{0, 1, 2, 3}, {4, 5, 6, 7}};
  EXPECT_EQ(labeling_error(build_coarse_mesh("two.obj", v, faces), project_with_stitch(1, 1)),
            "two.obj: 1 of 2 faces could not be labelled:\n  face 2 (around (3.5, 5.5, 0)): they "
            "are not connected to any start; add one at their boundary, e.g. start: [{edge: [5, "
            "6]}]");
}

TEST(Labeling, FacesReachedOnlyFromAboveAreNamed) {
  // Face 3 hangs under face 2 without touching face 1: rows come down into it head-on.
  std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},    {1, 2, 0},
                      {0, 2, 0}, {2, 1, 0}, {2, 2, 0}, {1.2f, 0, 0}, {2, 0, 0}};
  Faces faces{{0, 1, 2, 3}, {3, 2, 4, 5}, {8, 9, 6, 2}, {2, 6, 7, 4}};
  std::string e =
      labeling_error(build_coarse_mesh("hang.obj", v, faces), project_with_stitch(1, 1));
  EXPECT_NE(
      e.find("face 3 (around (1.55, 0.5, 0)): they are reached only from above (edge 7-3), so "
             "rows would run into them head-on; add a start at their own boundary, e.g. "
             "start: [{edge: [9, 10]}]"),
      std::string::npos)
      << e;
}

TEST(Labeling, RowsStopAtMarkedMismatchEdges) {
  std::mt19937 rng(2);
  CoarseMesh m = grid(2, 1, rng);
  Project p = project_with_stitch(1, 1);
  p.mismatch_edges.push_back({1, 4, 7});  // the edge between the two faces
  std::string e = labeling_error(m, p);
  EXPECT_NE(e.find("face 2 (around"), std::string::npos) << e;
  EXPECT_NE(e.find("they are reached only across edge 5-2, where rows stop"), std::string::npos)
      << e;
}

TEST(Labeling, MarkedTopsAreNotHandedOn) {
  // A 2x2 sheet knit up from the bottom, with a second start on the left edge of the upper
  // left face; the mark on that face's bottom keeps the row below from handing it on, so it
  // is knit sideways from its own start: perpendicular mismatches with both faces beside it.
  std::mt19937 rng(4);
  CoarseMesh m = grid(2, 2, rng);
  Project p = project_with_stitch(1, 1);
  p.start = {{StartSeed::Kind::lowest, {}}, {StartSeed::Kind::edge, {6, 3, 5}}};
  p.mismatch_edges.push_back({3, 4, 6});
  Labeling l = label_coarse_mesh(m, p);
  CoarseFace upper_left(2);
  EXPECT_EQ(m.describe(l.find(m, upper_left, CoarseRole::bottom)), "edge 7-4");
  EXPECT_TRUE(is_side(l[m.find_halfedge(CoarseVertex(3), CoarseVertex(4))]));
  EXPECT_EQ(l[m.find_halfedge(CoarseVertex(4), CoarseVertex(3))], CoarseRole::top);
  EXPECT_EQ(l[m.find_halfedge(CoarseVertex(4), CoarseVertex(7))], CoarseRole::top);
  EXPECT_TRUE(is_side(l[m.find_halfedge(CoarseVertex(7), CoarseVertex(4))]));
  expect_generated_knittable(m, p, 1);  // the sideways rows start where the yarn stopped
}

TEST(Labeling, PolygonsAndUnlabelledTrianglesAreExplained) {
  std::vector<Vec3> v{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1.5f, 0}, {0, 1, 0}, {1, 3, 0}};
  Faces faces{{0, 1, 2, 3, 4}};
  EXPECT_NE(labeling_error(build_coarse_mesh("penta.obj", v, faces), project_with_stitch(1, 1))
                .find("face 1 has 5 sides; labeling knows quads and triangles"),
            std::string::npos);
  // A lone triangle on a quad: which side carries its short rows is unknown.
  std::vector<Vec3> w{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 3, 0}};
  Faces g{{0, 1, 2, 3}, {3, 2, 4}};
  EXPECT_NE(labeling_error(build_coarse_mesh("roof.obj", w, g), project_with_stitch(1, 1))
                .find("triangle 2 is reached only from below (edge 4-3), so which side carries "
                      "its short rows is unknown"),
            std::string::npos);
}

TEST(Labeling, ProjectEdgesMustExist) {
  std::mt19937 rng(3);
  Project p = project_with_stitch(1, 1);
  p.start.push_back({StartSeed::Kind::edge, {0, 7, 4}});
  EXPECT_EQ(labeling_error(grid(1, 1, rng), p),
            "test.yaml:4: vertices 1 and 8 share no edge in <grid>; expected the two ends of an "
            "edge of the coarse mesh");
}

TEST(Generation, CountsAreSharedAndShapingIsSpread) {
  // A cone: the bottom 40 stitches round, the top 20; decreases spread, never stacked here.
  CoarseMesh m = cylinder(4, {40 / (2 * std::numbers::pi), 20 / (2 * std::numbers::pi)}, 20);
  Project p = project_with_stitch(1.0, 1.0);
  Labeling l = label_coarse_mesh(m, p);
  GeneratedStitchMesh g = generate_stitch_mesh(m, l, p);
  validate(g.mesh);
  std::uint32_t decreases = 0, stacked = 0;
  for (Face f : g.mesh.faces()) {
    if (g.mesh.stitch[f] != StitchType::k2tog) continue;
    ++decreases;
    for (Halfedge h : g.mesh.halfedges(f)) {
      Face above = g.mesh.neighbour(h);
      if (g.mesh.role[h] == EdgeRole::top && above.valid() &&
          g.mesh.stitch[above] == StitchType::k2tog)
        ++stacked;
    }
  }
  EXPECT_GT(decreases, 0u);
  EXPECT_EQ(stacked, 0u);
  for (CoarseHalfedge h : m.halfedges())
    if (!m.is_border(h)) {
      EXPECT_EQ(g.segments[h.index()], g.segments[m.twin(h).index()]);
    }
}

TEST(Generation, RandomGridsAreKnittable) {
  for (std::uint32_t seed = 0; seed < 12; ++seed) {
    std::mt19937 rng(seed);
    CoarseMesh m = grid(1 + seed % 4, 1 + seed % 3, rng);
    SCOPED_TRACE(seed);
    expect_generated_knittable(m, project_with_stitch(0.5 + 0.1 * (seed % 3), 0.4), 1);
  }
}

TEST(Generation, RandomCylindersOfVaryingRadiusAreKnittable) {
  for (std::uint32_t seed = 0; seed < 12; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> radius(2, 8);
    std::vector<double> radii;
    for (std::uint32_t r = 0; r < 2 + seed % 4; ++r) radii.push_back(radius(rng));
    SCOPED_TRACE(seed);
    expect_generated_knittable(cylinder(3 + seed % 6, radii, 3), project_with_stitch(0.5, 0.4), 1);
  }
}

TEST(Generation, ShortRowWedgeTurnsInItsTriangle) {
  Project p;
  p.file = "test.yaml";
  p.mesh = std::string(SKEIN_SOURCE_DIR) + "/samples/short-row-wedge/short-row-wedge.obj";
  CoarseMesh m = read_coarse_mesh(p.mesh);
  for (ShortRowMethod method : {ShortRowMethod::sr4, ShortRowMethod::sr5}) {
    p.short_row_method = method;
    GeneratedStitchMesh g = generate_stitch_mesh(m, label_coarse_mesh(m, p), p);
    validate(g.mesh);
    std::uint32_t turns = 0;
    for (Face f : g.mesh.faces()) turns += info(g.mesh.stitch[f]).wales_adjacent;
    EXPECT_EQ(
        turns,
        g.segments[label_coarse_mesh(m, p).find(m, CoarseFace(2), CoarseRole::right).index()] / 2);
    Compilation c = compile_stitch_mesh(std::move(g.mesh), "wedge");
    EXPECT_TRUE(c.knittability.knittable) << check_report(c);
  }
}

TEST(Generation, ShiftPathsFollowTheProjectOrContinueFromBelow) {
  CoarseMesh m = cylinder(4, {5, 5, 5}, 4);
  Project p = project_with_stitch(1, 1);
  p.shift_paths.push_back({{2, 6, 9}, 3});  // the side edge from vertex 3 up to vertex 7
  GeneratedStitchMesh g = generate_stitch_mesh(m, label_coarse_mesh(m, p), p);
  EXPECT_EQ(g.shift_paths, 1u);  // the upper ring continues the path of the lower one
  std::uint32_t marked = 0;
  for (Edge e : g.mesh.edges()) {
    marked += g.mesh.shift_path[e] != kNotShifted;
    if (g.mesh.shift_path[e]) {
      EXPECT_EQ(g.mesh.shift_path[e], kShiftDownRight);  // the ring above inherits the option
    }
  }
  EXPECT_EQ(marked, g.segments[m.find_halfedge(CoarseVertex(2), CoarseVertex(6)).index()] * 2);
  p.shift_paths = {{{0, 1, 9}, 1}};  // a course edge: no round starts there
  EXPECT_THROW(generate_stitch_mesh(m, label_coarse_mesh(m, p), p), Error);
}

// Three bars crossing in one cube (Fig. 19), knit from the ends of -x, +x and -y towards it: -y
// joins both x arms, +y splits from both z arms, and each incoming tube's path goes on into an
// outgoing tube of its own: 3 yarns, and one extra per join or split (the paper's 7), or
// none when each is worked with a side's own yarn (the paper's 3).
TEST(Generation, TubesMeetingAtAJunctionEachGoOnIntoTheirOwnTube) {
  std::vector<Cell> cubes{{0, 0, 0}}, ends;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1}) {
      for (int k = 1; k <= 2; ++k) {
        int p[3] = {0, 0, 0};
        p[axis] = sign * k;
        cubes.push_back({p[0], p[1], p[2]});
      }
      int p[3] = {0, 0, 0};
      p[axis] = sign * 3;
      ends.push_back({p[0], p[1], p[2]});
    }
  std::vector<CoarseEdgeRef> end_edges;
  CoarseMesh m = cube_bars(cubes, ends, &end_edges);  // ends: -x, +x, -y, +y, -z, +z
  Project p = project_with_stitch(0.25, 0.25);
  for (std::size_t e : {0, 1, 2}) p.start.push_back({StartSeed::Kind::edge, end_edges[e]});
  p.default_yarn = YarnHandling::extra;
  expect_generated_knittable(m, p, 3 + 4);
  p.default_yarn = YarnHandling::own;
  expect_generated_knittable(m, p, 3);
}

// Two bars crossing in a plane (Fig. 18), knit from the ends of -y and -x: the centre
// cube's flat faces are open rows between the tubes (marks make their sides perpendicular
// mismatches), one knit on from each incoming tube and on into an outgoing one: 2 yarns, and
// one extra each for the join and the split (the paper's 4).
TEST(Generation, OpenRowsBetweenTubesCarryTheYarnOn) {
  std::vector<Cell> cubes{{0, 0, 0},  {-1, 0, 0}, {-2, 0, 0}, {1, 0, 0}, {2, 0, 0},
                          {0, -1, 0}, {0, -2, 0}, {0, 1, 0},  {0, 2, 0}};
  std::vector<CoarseEdgeRef> end_edges;
  CoarseMesh m = cube_bars(cubes, {{-3, 0, 0}, {3, 0, 0}, {0, -3, 0}, {0, 3, 0}}, &end_edges);
  auto at = [&](float x, float y, float z) {
    auto v = std::find_if(m.position.begin(), m.position.end(),
                          [&](Vec3 p) { return p.x == x && p.y == y && p.z == z; });
    return static_cast<std::uint32_t>(v - m.position.begin());
  };
  Project p = project_with_stitch(0.25, 0.25);
  p.start = {{StartSeed::Kind::edge, end_edges[2]}, {StartSeed::Kind::edge, end_edges[0]}};
  p.mismatch_edges = {{at(0, 0, 1), at(0, 1, 1), 0},  // the front face: rows from -y
                      {at(1, 0, 1), at(1, 1, 1), 0},
                      {at(0, 0, 0), at(1, 0, 0), 0},  // the back face: rows from -x
                      {at(0, 1, 0), at(1, 1, 0), 0}};
  p.default_yarn = YarnHandling::extra;
  expect_generated_knittable(m, p, 2 + 2);
}

// The letter H of unit cubes (the H sample at a third of its size, without short rows): leg
// ends knit towards the bar, the bar split off the left legs; the left junction's outer walls
// are open rows between the lower leg's yarn and the bar's first round, and the right
// junction's take the bar's yarn round to its join with both right legs. 4 + 1 + 1 yarns.
TEST(Generation, LegsAndABarMeetInOpenRowsOfTheirJunctions) {
  std::vector<Cell> cubes{{1, 2, 0}};
  for (int x : {0, 2})
    for (int y = 0; y < 5; ++y) cubes.push_back({x, y, 0});
  std::vector<CoarseEdgeRef> end_edges;
  CoarseMesh m = cube_bars(cubes, {{0, -1, 0}, {0, 5, 0}, {2, -1, 0}, {2, 5, 0}}, &end_edges);
  auto at = [&](int x, int y, int z) {
    auto v = std::find_if(m.position.begin(), m.position.end(), [&](Vec3 p) {
      return p.x == float(x) && p.y == float(y) && p.z == float(z);
    });
    return static_cast<std::uint32_t>(v - m.position.begin());
  };
  auto edge = [&](std::array<int, 3> a, std::array<int, 3> b) {
    return CoarseEdgeRef{at(a[0], a[1], a[2]), at(b[0], b[1], b[2]), 0};
  };
  Project p = project_with_stitch(0.25, 0.25);
  for (const CoarseEdgeRef& e : end_edges) p.start.push_back({StartSeed::Kind::edge, e});
  p.start.push_back({StartSeed::Kind::edge, edge({1, 2, 1}, {1, 3, 1})});  // the bar's split
  for (int y : {2, 3})  // the junctions' outer walls end where the legs meet them
    for (int x : {0, 3}) {
      int inner = x == 0 ? 1 : 2;
      p.mismatch_edges.push_back(edge({x, y, 0}, {x, y, 1}));
      p.mismatch_edges.push_back(edge({x, y, 0}, {inner, y, 0}));
      p.mismatch_edges.push_back(edge({x, y, 1}, {inner, y, 1}));
    }
  p.mismatch_edges.push_back(edge({2, 2, 1}, {2, 3, 1}));  // the bar goes round the right walls
  p.default_yarn = YarnHandling::extra;
  expect_generated_knittable(m, p, 4 + 2);
}

// A square bar turned a right angle by one bevelled ring (the R's and the teapot's corners):
// a sloped outer wall, a short inner wall and short-row front and back walls, tall on the
// outside. The tube bends in the round, so its path goes on through the turn: one yarn.
TEST(Generation, ABarBentByABevelledShortRowRingStaysOneYarn) {
  std::vector<Vec3> v{{0, 0, 3}, {0, 0, 0}, {3, 0, 3}, {3, 0, 0},               // cast on
                      {0, 3, 3}, {0, 3, 0}, {3, 3, 3}, {3, 3, 0},               // the turn's bottom
                      {3, 4, 0}, {3, 4, 3}, {3, 7, 3}, {3, 7, 0},               // its top, upright
                      {6, 4, 3}, {6, 4, 0}, {6, 7, 3}, {6, 7, 0}};              // bound off
  Faces faces{{3, 7, 6, 2},     {0, 4, 5, 1},   {0, 2, 6, 4},    {5, 7, 3, 1},  // a ring
              {6, 7, 8, 9},     {5, 4, 10, 11},                                 // inner, slope
              {4, 6, 9, 10},    {7, 5, 11, 8},                                  // front, back
              {11, 10, 14, 15}, {13, 12, 9, 8}, {9, 12, 14, 10}, {11, 15, 13, 8}};  // the bar
  CoarseMesh m = build_coarse_mesh("<bent bar>", v, faces);
  Project p = project_with_stitch(0.25, 0.25);
  p.short_row_faces = {{6, std::nullopt, 0}, {7, std::nullopt, 0}};
  expect_generated_knittable(m, p, 1);
}

TEST(Generation, SkeinNewShapesAreKnittableAtSeveralSizes) {
  // Sheets, tubes, hats and socks (short rows inside rounds) on one yarn; sweaters on three
  // (body and sleeves, as the paper's).
  for (double size : {12.0, 19.0, 27.0, 41.0})
    for (const char* kind : {"sheet", "tube", "hat", "sock", "sweater"}) {
      SCOPED_TRACE(std::string(kind) + " " + std::to_string(size));
      bool sweater = std::string(kind) == "sweater";
      if (sweater && size < 27) continue;  // the sleeves need room at the armpits
      Shape s = make_shape(kind, {sweater ? size * 3 : size, size * 0.8, size * 0.7}, "shape");
      expect_generated_knittable(s.mesh, parse_project(s.project, "shape.yaml"), sweater ? 3 : 1);
    }
}

// Garments that part or join at a fork: the mitten (the tube parts into hand and thumb, the sts
// between them cast on along the crotch with an extra yarn), shorts (the body parts into the
// legs) and trousers (the legs join into the body with a three-needle bind-off along the
// crotch): two pieces and the extra yarn of the cast-on or the bind-off.
TEST(Generation, ForkedGarmentsAreKnittableAtSeveralSizes) {
  for (double size : {12.0, 19.0, 27.0, 41.0})
    for (const char* kind : {"mitten", "shorts", "trousers"}) {
      SCOPED_TRACE(std::string(kind) + " " + std::to_string(size));
      double round = std::string(kind) == "mitten" ? size : size * 3;
      Shape s = make_shape(kind, {round, 0, size}, "shape");
      expect_generated_knittable(s.mesh, parse_project(s.project, "shape.yaml"), 3);
    }
}

// The set-in sweater at random sizes and gauges: knittable at every one. Its sleeves are
// picked up round the armholes and knit down to the cuffs, so no sleeve row meets the body's
// rows head-on: the rows picked up along each armhole's two sides are expanding perpendicular
// mismatches, the cast-on across its top a split (one extra yarn each), and nothing joins.
TEST(Generation, SetInSweaterIsKnittableAtRandomSizesAndGauges) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 30; ++trial) {
    ShapeSize size{20 + static_cast<double>(rng() % 180), 0, 4 + static_cast<double>(rng() % 116)};
    Shape s = make_shape("set-in-sweater", size, "sweater");
    Project p = parse_project(s.project, "sweater.yaml");
    double stitches = 8 + static_cast<double>(rng() % 33),
           rows = 10 + static_cast<double>(rng() % 41);
    p.stitches_per_10cm = stitches;
    p.rows_per_10cm = rows;
    SCOPED_TRACE(fmt::format("{} cm round, {} cm long, {} sts and {} rows per 10 cm",
                             size.circumference, size.length, stitches, rows));
    Labeling labeling = label_coarse_mesh(s.mesh, p);
    GeneratedStitchMesh g = generate_stitch_mesh(s.mesh, labeling, p);
    Compilation c = compile_stitch_mesh(std::move(g.mesh), "sweater.obj");
    std::string report = check_report(c);
    ASSERT_TRUE(c.knittability.knittable) << report;
    EXPECT_EQ(c.yarns.size(), 5u) << report;  // body, back, yoke, and the two armholes' cast-ons
    auto count = [&](const std::string& what) {
      std::size_t n = 0;
      for (std::size_t at = report.find(what); at != std::string::npos;
           at = report.find(what, at + 1))
        ++n;
      return n;
    };
    EXPECT_EQ(count(": expanding perpendicular,"), 4u) << report;
    EXPECT_EQ(count(": splitting,"), 2u) << report;
    EXPECT_EQ(count(": joining,"), 0u) << report;
  }
}

TEST(Generation, EveryShapeOfSkeinNewGeneratesAValidStitchMesh) {
  for (const std::string& kind : shape_kinds()) {
    SCOPED_TRACE(kind);
    Shape s = make_shape(kind, {}, kind);
    Project p = parse_project(s.project, kind + ".yaml");
    GeneratedStitchMesh g = generate_stitch_mesh(s.mesh, label_coarse_mesh(s.mesh, p), p);
    EXPECT_NO_THROW(validate(g.mesh));
  }
}

}  // namespace
}  // namespace skein
