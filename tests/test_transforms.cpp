// The knittable transforms (paper §3.2): one small mesh per mismatched direction and option,
// each compiled, checked, scheduled and proven by the schedule simulator.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <sstream>

#include "builtin_targets.hpp"
#include "common/error.hpp"
#include "fixtures.hpp"
#include "labeling/labeling.hpp"
#include "labeling/project.hpp"
#include "labeling/shapes.hpp"
#include "labeling/stitch_generation.hpp"
#include "mesh/generate.hpp"

namespace skein {
namespace {

using Kind = MismatchYarn::Kind;
using T = StitchType;

Compilation proven(StitchMesh mesh, const std::string& name) {
  Compilation c = compile_stitch_mesh(std::move(mesh), name);
  EXPECT_TRUE(c.knittability.knittable) << check_report(c);
  if (!c.knittability.knittable) return c;
  Registry registry;
  register_builtin_targets(registry);
  std::ostringstream out;
  registry.target("schedule")->emit(c, {}, out);
  VerifyReport report = registry.simulator_for("schedule")->verify(out.str(), name, &c, {});
  EXPECT_TRUE(report.proven) << report.summary;
  return c;
}

// Compiling `mesh` must fail with a MeshError whose message contains `expected`.
void expect_mesh_error(StitchMesh mesh, const std::string& name, const std::string& expected) {
  try {
    compile_stitch_mesh(std::move(mesh), name);
    FAIL() << "expected a MeshError";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

std::size_t count_type(const KnitGraph& g, StitchType t) {
  return static_cast<std::size_t>(std::count(g.type.begin(), g.type.end(), t));
}

TEST(Join, ExtraYarnExtrudesAThreeNeedleBindOffRow) {
  Compilation c = proven(testing::join_mesh(), "join");
  const KnitGraph& g = c.knit;
  ASSERT_EQ(g.groups.size(), 1u);
  EXPECT_EQ(g.groups[0].kind, MismatchKind::join);
  EXPECT_EQ(g.groups[0].edges, 3u);
  EXPECT_EQ(g.size(), 15u);
  EXPECT_EQ(count_type(g, T::tnbo), 3u);
  EXPECT_EQ(c.yarns.size(), 3u);  // lower piece, upper piece, the extra yarn
  for (StitchId s = g.first_extruded; s < g.size(); ++s) {
    auto taken = g.loops_taken_by(s);
    ASSERT_EQ(taken.size(), 2u);
    EXPECT_LT(g.row[g.loops[taken[0]].maker], g.row[g.loops[taken[1]].maker] + 10);
    EXPECT_NE(g.row[g.loops[taken[0]].maker], g.row[g.loops[taken[1]].maker]);
  }
  EXPECT_EQ(g.describe(12), "extruded 3nbo on edge 12-11 (row 5)");
}

TEST(Join, OwnYarnOfEitherSideNeedsNoExtraRow) {
  for (bool upper : {false, true}) {
    Compilation c = proven(testing::join_mesh(Kind::own, upper), "join-own");
    EXPECT_EQ(c.knit.size(), 12u);
    EXPECT_EQ(count_type(c.knit, T::tnbo), 3u);
    EXPECT_EQ(c.yarns.size(), 2u);
    // The side whose yarn joins is the one whose row became three-needle bind-offs.
    std::uint32_t own_row = c.knit.row[upper ? 6 : 3];
    for (StitchId s = 0; s < c.knit.size(); ++s)
      EXPECT_EQ(c.knit.type[s] == T::tnbo, c.knit.row[s] == own_row) << c.knit.describe(s);
  }
}

// An extruded row runs along its group's edges as a knitter meets them: each stitch's edge
// touches the next one's, also where the rnd beside a join starts in its middle (letter H),
// and every stitch has the same side first.
TEST(Join, TheExtrudedRowFollowsTheChainOfEdges) {
  for (const char* sample : {"letter-h", "three-bars", "two-bars", "teapot"}) {
    std::string file = fmt::format("{}/samples/{}/{}.yaml", SKEIN_SOURCE_DIR, sample, sample);
    Compilation c = compile_model(file);
    const KnitGraph& g = c.knit;
    std::uint32_t steps = 0;
    for (StitchId s = g.first_extruded; s < g.size(); ++s) {
      StitchId next = g.yarn_next[s];
      if (next == kNoStitch) continue;
      const MismatchEdge& a = g.mismatch_edges[g.extruded_at[s - g.first_extruded]];
      const MismatchEdge& b = g.mismatch_edges[g.extruded_at[next - g.first_extruded]];
      bool touch = std::ranges::find_first_of(a.vertex, b.vertex) != std::end(a.vertex);
      EXPECT_TRUE(touch) << sample << ": " << g.describe(s) << " then " << g.describe(next);
      auto side_rows = [&](StitchId t) {  // the rows of its slot 0 and 1 loops' other stitch
        bool join = g.type[t] == StitchType::tnbo;
        auto loops = join ? g.loops_taken_by(t) : g.loops_made_by(t);
        auto row = [&](std::uint32_t l) {
          StitchId other = join ? g.loops[l].maker : g.loops[l].taker;
          return other == kNoStitch ? ~0u : g.row[other];
        };
        return std::pair{row(loops[0]), row(loops[1])};
      };
      auto [a0, a1] = side_rows(s);
      auto [b0, b1] = side_rows(next);
      if (a0 != a1 && b0 != b1) {
        EXPECT_EQ(a0, b0) << sample << ": " << g.describe(next)
                          << " takes the other side first (one needle in front for all)";
      }
      ++steps;
    }
    EXPECT_GT(steps, 5u) << sample;
  }
}

TEST(Split, ExtraYarnExtrudesACastOnBothSidesArePulledThrough) {
  Compilation c = proven(testing::split_mesh(), "split");
  const KnitGraph& g = c.knit;
  ASSERT_EQ(g.groups.size(), 1u);
  EXPECT_EQ(g.groups[0].kind, MismatchKind::split);
  EXPECT_EQ(count_type(g, T::sco), 3u);
  EXPECT_EQ(c.yarns.size(), 3u);
  for (StitchId s = g.first_extruded; s < g.size(); ++s) {
    auto made = g.loops_made_by(s);
    ASSERT_EQ(made.size(), 2u);
    EXPECT_NE(g.row[g.loops[made[0]].taker], g.row[g.loops[made[1]].taker]);
  }
  // Knitting starts with the cast-on: both sides wait for it.
  EXPECT_EQ(g.type[c.schedule.events.front().stitch], T::sco);
}

TEST(Split, OwnYarnReplacesOneSidesStitchesByTheCastOn) {
  for (bool upper : {false, true}) {
    Compilation c = proven(testing::split_mesh(Kind::own, upper), "split-own");
    EXPECT_EQ(c.knit.size(), 12u);
    EXPECT_EQ(count_type(c.knit, T::sco), 3u);
    EXPECT_EQ(count_type(c.knit, T::k), 3u);
    EXPECT_EQ(c.yarns.size(), 2u);
  }
}

TEST(Perpendicular, ContractingMakesTheWaleSideADecrease) {
  Compilation c = proven(testing::contracting_mesh(), "contracting");
  const KnitGraph& g = c.knit;
  ASSERT_EQ(g.groups.size(), 1u);
  EXPECT_EQ(g.groups[0].kind, MismatchKind::contracting);
  EXPECT_EQ(g.type[1], T::k2tog);
  EXPECT_EQ(g.type[2], T::k2tog);
  EXPECT_EQ(g.loops_taken_by(1).size(), 2u);
  EXPECT_EQ(c.yarns.size(), 2u);
}

TEST(Perpendicular, ABindOffBesideAContractingEdgeKnitsTwoTogetherThenBindsOff) {
  using testing::Square;
  Compilation c = proven(testing::grid_mesh(2, 4,
                                            {{0, 0, T::co, "boti"},
                                             {0, 1, T::k, "bito"},
                                             {0, 2, T::k, "boti"},
                                             {0, 3, T::bo, "bito"},
                                             {1, 2, T::co, "ibot"},
                                             {1, 3, T::co, "ibot"}}),
                         "contracting at the bind-off");
  EXPECT_EQ(c.knit.type[3], T::k2tog_bo);
  EXPECT_EQ(c.knit.loops_taken_by(3).size(), 2u);
}

TEST(Perpendicular, ACastOnBesideAContractingEdgeKnitsTheLoopBesideIt) {
  // Column 1 runs sideways (wales to the left): its tops are column 0's wale edges. The
  // cast-on at the foot of column 0 takes the loop beside it, so it becomes a knit stitch.
  Compilation c = proven(testing::grid_mesh(2, 2,
                                            {{0, 0, T::co, "boti"},
                                             {0, 1, T::bo, "bito"},
                                             {1, 0, T::co, "ibot"},
                                             {1, 1, T::co, "ibot"}}),
                         "contracting at the cast-on");
  EXPECT_EQ(c.knit.type[0], T::k);
  EXPECT_EQ(c.knit.loops_taken_by(0).size(), 1u);
  EXPECT_EQ(c.knit.type[1], T::k2tog_bo);
}

TEST(Perpendicular, ExpandingIsPickedUpThroughTheEdgeAndAnOddCountLeavesATiedEnd) {
  Compilation c = proven(testing::expanding_mesh(), "expanding");
  const KnitGraph& g = c.knit;
  ASSERT_EQ(g.groups.size(), 1u);
  EXPECT_EQ(g.groups[0].kind, MismatchKind::expanding);
  EXPECT_EQ(g.type[1], T::k);  // the column is unchanged
  for (StitchId s = 3; s < 6; ++s) {
    ASSERT_EQ(g.loops_taken_by(s).size(), 1u);
    EXPECT_EQ(g.loops[g.loops_taken_by(s)[0]].maker, s - 3);
  }
  EXPECT_NE(check_report(c).find(
                "expanding perpendicular, 3 edges between rows 1 and 4, odd: one tied end"),
            std::string::npos)
      << check_report(c);
}

TEST(YarnChoice, OneGroupAskingForTwoYarnsIsRejected) {
  StitchMesh mesh = testing::join_mesh(Kind::extra);
  Halfedge h = mesh.halfedge(mesh.find_edge(Vertex(9), Vertex(10)));
  mesh.mismatch_yarn[mesh.edge(h)] = {Kind::own, mesh.face(h)};
  expect_mesh_error(std::move(mesh), "conflict",
                    "belong to one joining mismatch group but ask for different yarns");
}

}  // namespace
}  // namespace skein

namespace skein {
namespace {

// A tube whose shift-path marks are all removed, then `marked` rounds marked again.
StitchMesh tube_marked_at(const RowPlan& plan, const std::vector<std::uint32_t>& marked,
                          ShiftOption option = kShiftUpRight) {
  StitchMesh mesh = build_from_rows(plan, Layout::tube);
  std::vector<Edge> seam;
  for (Edge e : mesh.edges())
    if (mesh.shift_path[e]) seam.push_back(e), mesh.shift_path[e] = kNotShifted;
  for (std::uint32_t row : marked) mesh.shift_path[seam[row]] = option;
  return mesh;
}

std::uint32_t marks(const StitchMesh& mesh) {
  std::uint32_t n = 0;
  for (Edge e : mesh.edges()) n += mesh.shift_path[e] != kNotShifted;
  return n;
}

TEST(ShiftPath, PlacedAutomaticallyOnATubeWithNone) {
  Compilation c = proven(tube_marked_at(ribbed_rows(10, 4, {T::k}), {}), "auto");
  EXPECT_EQ(c.shift_paths.paths, 1u);
  EXPECT_EQ(c.shift_paths.placed, 1u);
  EXPECT_EQ(marks(*c.mesh), 6u);
  EXPECT_EQ(c.yarns.size(), 1u);
  // skein chooses up-left: the rnds run right to left seen from the RS, as hands knit them.
  for (Edge e : c.mesh->edges())
    EXPECT_TRUE(c.mesh->shift_path[e] == kNotShifted || c.mesh->shift_path[e] == kShiftUpLeft);
  EXPECT_FALSE(c.mesh->runs_left_to_right(Face(7)));
}

TEST(ShiftPath, OneMarkedEdgeIdentifiesTheWholePath) {
  StitchMesh mesh = tube_marked_at(ribbed_rows(10, 4, {T::k}), {3});
  Edge given;
  for (Edge e : mesh.edges())
    if (mesh.shift_path[e]) given = e;
  Compilation c = proven(std::move(mesh), "one-mark");
  EXPECT_EQ(c.shift_paths.paths, 1u);
  EXPECT_EQ(c.shift_paths.placed, 0u);
  EXPECT_EQ(marks(*c.mesh), 6u);
  EXPECT_TRUE(c.mesh->shift_path[given]);
  EXPECT_EQ(c.yarns.size(), 1u);
}

// Fig. 3f: a path that runs into the middle of a decrease ends there; the rounds above need a
// path of their own, and so a yarn piece of their own.
TEST(ShiftPath, PathEndingInsideADecreaseNeedsAnotherPath) {
  RowPlan plan = {std::vector<StitchType>(8, T::co), std::vector<StitchType>(8, T::k),
                  std::vector<StitchType>(4, T::k2tog), std::vector<StitchType>(4, T::k),
                  std::vector<StitchType>(4, T::bo)};
  StitchMesh mesh = build_from_rows(plan, Layout::tube);
  for (Edge e : mesh.edges()) mesh.shift_path[e] = kNotShifted;
  // Mark the wale edge between the first two knit stitches of round 2: its top corner lies in
  // the middle of the first k2tog above.
  Face k1(8);
  Halfedge right = mesh.wale_out(k1);
  mesh.shift_path[mesh.edge(right)] = kShiftUpRight;
  Compilation c = proven(std::move(mesh), "fig3f");
  EXPECT_EQ(c.shift_paths.paths, 2u);
  EXPECT_EQ(c.shift_paths.placed, 1u);
  EXPECT_EQ(c.yarns.size(), 2u);
}

TEST(ShiftPath, OptionsThatRunTheOtherWayTurnTheRounds) {
  for (ShiftOption option : {kShiftUpRight, kShiftUpLeft, kShiftDownRight, kShiftDownLeft}) {
    Compilation c = proven(tube_marked_at(ribbed_rows(6, 3, {T::k}), {0}, option), "options");
    bool turned = !runs_left_to_right(option);
    EXPECT_EQ(c.shift_paths.reversed_rows, turned ? 5u : 0u) << shift_option_name(option);
    EXPECT_EQ(c.mesh->runs_left_to_right(Face(7)), !turned) << shift_option_name(option);
    EXPECT_EQ(c.yarns.size(), 1u);
    // The second round starts right of the path either way; it is worked the way the option says.
    std::vector<StitchId> order;
    for (const Event& e : c.schedule.events)
      if (e.kind == EventKind::stitch && c.knit.row[e.stitch] == 1) order.push_back(e.stitch);
    EXPECT_EQ(order.front(), turned ? 11u : 6u) << shift_option_name(option);
  }
}

TEST(ShiftPath, MarkOnAnOpenRowIsRejected) {
  StitchMesh mesh = build_from_rows(ribbed_rows(4, 2, {T::k}), Layout::sheet);
  mesh.shift_path[mesh.edge(mesh.wale_out(Face(5)))] = kShiftUpRight;  // inside row 2
  expect_mesh_error(std::move(mesh), "open", "is marked as a shift-path, but row 2 is an open row");
}

TEST(ShiftPath, TwoMarksOnOneRoundAreRejected) {
  StitchMesh mesh = tube_marked_at(ribbed_rows(6, 2, {T::k}), {1});
  mesh.shift_path[mesh.edge(mesh.wale_out(Face(8)))] = kShiftUpRight;
  expect_mesh_error(std::move(mesh), "two", "row 2 is cut by two shift-path edges");
}

// An edited mesh: the second round's mark moved one stitch over, away from where the path
// coming up from the first round goes on.
TEST(ShiftPath, AMarkThatBreaksAPathIsRejected) {
  StitchMesh mesh = tube_marked_at(ribbed_rows(6, 3, {T::k}), {0});
  mesh.shift_path[mesh.edge(mesh.wale_out(Face(8)))] = kShiftUpRight;  // row 2, not on the path
  expect_mesh_error(std::move(mesh), "moved",
                    "is marked as the shift-path of row 2, but the path coming up from row 1");
}

}  // namespace
}  // namespace skein

namespace skein {
namespace {

TEST(ShortRows, PairTurnsAtAShortRowFaceOnOneYarn) {
  for (StitchType turn : {StitchType::sr4, StitchType::sr5, StitchType::srn}) {
    Compilation c = proven(testing::short_row_mesh(turn), "short rows");
    const KnitGraph& g = c.knit;
    EXPECT_EQ(c.yarns.size(), 1u);
    // Rows: cast-on, first short row (ending at the turn face), second short row, full row, bo.
    EXPECT_EQ(g.row_shape,
              (std::vector<RowShape>{RowShape::open, RowShape::short_row, RowShape::short_row,
                                     RowShape::open, RowShape::open}))
        << abbreviation(turn);
    EXPECT_EQ(g.yarn_link[6], YarnLink::turn);
    std::vector<StitchId> order;
    for (const Event& e : c.schedule.events)
      if (e.kind == EventKind::stitch) order.push_back(e.stitch);
    EXPECT_EQ(order,
              (std::vector<StitchId>{0, 1, 2, 3, 5, 4, 6, 7, 8, 12, 11, 10, 9, 13, 14, 15, 16}))
        << abbreviation(turn);
    // The short-row face consumes the loop of the stitch below it and feeds the full row.
    ASSERT_EQ(g.loops_taken_by(6).size(), 1u);
    EXPECT_EQ(g.loops[g.loops_taken_by(6)[0]].maker, 1u);
    // One loop per top edge: sr5 and srn make more stitches at the turn (no hole).
    EXPECT_EQ(g.loops_made_by(6).size(), turn == StitchType::sr4   ? 1u
                                         : turn == StitchType::sr5 ? 2u
                                                                   : 3u);
    EXPECT_NE(check_report(c).find("rows: 5 (closed 0, open 3, short 2)"), std::string::npos)
        << check_report(c);
  }
}

// A heel round stops, turns twice and comes back to where it began: its short rows close on
// themselves, so without a mark they would be a ring of yarn with no end. Socks generated with
// their marks erased must get a path through the heel from skein, still on one yarn (§3.3).
TEST(ShortRows, HeelRingsInATubeAreJoinedToTheHelixWithoutMarks) {
  for (double size : {12.0, 19.0, 27.0, 41.0}) {
    SCOPED_TRACE(size);
    Shape s = make_shape("sock", {size, size * 0.8, size * 0.7}, "sock");
    Project p = parse_project(s.project, "sock.yaml");
    StitchMesh mesh = generate_stitch_mesh(s.mesh, label_coarse_mesh(s.mesh, p), p).mesh;
    for (Edge e : mesh.edges()) mesh.shift_path[e] = kNotShifted;
    Compilation c = proven(std::move(mesh), "sock without marks");
    EXPECT_EQ(c.yarns.size(), 1u) << check_report(c);
    EXPECT_GT(std::count(c.knit.row_shape.begin(), c.knit.row_shape.end(), RowShape::short_row), 0);
  }
}

TEST(ShortRows, MarkersWrapTheTurn) {
  Compilation c = proven(testing::short_row_mesh(), "short rows");
  std::size_t begin = 0, end = 0;
  for (const Event& e : c.schedule.events) {
    begin += e.kind == EventKind::marker && e.marker == MarkerKind::short_row_begin;
    end += e.kind == EventKind::marker && e.marker == MarkerKind::short_row_end;
  }
  EXPECT_EQ(begin, 1u);
  EXPECT_EQ(end, 1u);
}

}  // namespace
}  // namespace skein

namespace skein {
namespace {

// The simulator is the judge: many generated meshes with short rows, joins and splits, each
// compiled with a random yarn option, must schedule and prove.
TEST(Randomized, ShortRowSheetsScheduleAndProve) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 60; ++trial) {
    std::uint32_t width = 3 + static_cast<std::uint32_t>(rng() % 12);
    StitchMesh mesh = short_row_sheet(width, 1 + static_cast<std::uint32_t>(rng() % 12), rng());
    std::uint32_t turns = 0;
    for (Face f : mesh.faces()) turns += info(mesh.stitch[f]).wales_adjacent;
    Compilation c = proven(std::move(mesh), "short-row sheet");
    EXPECT_EQ(c.yarns.size(), 1u);
    std::uint32_t short_rows = static_cast<std::uint32_t>(
        std::count(c.knit.row_shape.begin(), c.knit.row_shape.end(), RowShape::short_row));
    EXPECT_EQ(short_rows, 2 * turns);  // each turn ends one short row and starts the next
  }
}

TEST(Randomized, JoinedAndSplitSheetsScheduleAndProveWithEveryYarnOption) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 80; ++trial) {
    Meeting meeting = trial % 2 ? Meeting::join : Meeting::split;
    auto yarn = static_cast<Kind>(rng() % 3);
    bool own_lower = rng() % 2;
    std::uint32_t width = 1 + static_cast<std::uint32_t>(rng() % 10);
    std::uint32_t lower = 2 + static_cast<std::uint32_t>(rng() % 5),
                  upper = 2 + static_cast<std::uint32_t>(rng() % 5);
    Compilation c =
        proven(meeting_sheets(meeting, width, lower, upper, yarn, own_lower, rng()), "meeting");
    bool extra = yarn != Kind::own;
    EXPECT_EQ(c.yarns.size(), extra ? 3u : 2u);
    EXPECT_EQ(c.knit.size(), width * (lower + upper) + (extra ? width : 0));
    StitchType made = meeting == Meeting::join ? T::tnbo : T::sco;
    EXPECT_EQ(count_type(c.knit, made), width);
  }
}

// Corner links: a rnd going on into a flap's rows back over the sts just made turns the work
// in the schedule, and the flap's last row going on down its edge into the rnd shifts, flagged
// as a corner (letter R's flap in small; the model has them the other way round).
TEST(CornerLinks, TheScheduleTurnsWhereTheYarnGoesBackAndShiftsRoundACorner) {
  Compilation c = compile_knit_graph(testing::reversed_gusset_leg_graph(), "flap");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  const StitchId last_of_rnd = 17, first_of_flap = 18, flap_corner = 23, plain_rnd_end = 11;
  EXPECT_EQ(c.knit.yarn_link[last_of_rnd], YarnLink::turn);
  EXPECT_EQ(c.knit.yarn_link[flap_corner], YarnLink::shift);
  EXPECT_TRUE(c.knit.flags[flap_corner] & kRoundsACorner);
  EXPECT_EQ(c.knit.yarn_link[plain_rnd_end], YarnLink::shift);
  EXPECT_FALSE(c.knit.flags[plain_rnd_end] & kRoundsACorner);
  auto event_before = [&](StitchId s, EventKind kind) {
    return std::any_of(c.schedule.events.begin(), c.schedule.events.end(),
                       [&](const Event& e) { return e.kind == kind && e.stitch == s; });
  };
  EXPECT_TRUE(event_before(first_of_flap, EventKind::turn));
  EXPECT_FALSE(event_before(flap_corner + 1, EventKind::turn));
}

}  // namespace
}  // namespace skein
