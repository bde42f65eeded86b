// Knit graph, dependency graph, knittability and Algorithm 1 on generated and hand-built meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/range/iterator_range.hpp>
#include <random>
#include <sstream>

#include "builtin_targets.hpp"
#include "common/error.hpp"
#include "fixtures.hpp"
#include "knitgraph/from_mesh.hpp"
#include "mesh/generate.hpp"

namespace skein {
namespace {

using T = StitchType;

// The schedule's stitches in order, checked to hold each stitch exactly once and each after
// everything it depends on; returns the order.
std::vector<StitchId> checked_order(const Compilation& c) {
  std::vector<StitchId> order;
  std::vector<std::uint8_t> done(c.knit.size(), 0);
  for (const Event& e : c.schedule.events) {
    if (e.kind != EventKind::stitch) continue;
    EXPECT_FALSE(done[e.stitch]) << c.knit.describe(e.stitch) << " scheduled twice";
    for (auto arc : boost::make_iterator_range(in_edges(e.stitch, c.deps)))
      EXPECT_TRUE(done[source(arc, c.deps)])
          << c.knit.describe(e.stitch) << " before " << c.knit.describe(source(arc, c.deps));
    done[e.stitch] = 1;
    order.push_back(e.stitch);
  }
  EXPECT_EQ(order.size(), c.knit.size());
  return order;
}

std::size_t count(const Schedule& s, EventKind kind, MarkerKind marker = MarkerKind::none) {
  std::size_t n = 0;
  for (const Event& e : s.events) n += e.kind == kind && e.marker == marker;
  return n;
}

TEST(KnitGraph, SheetIsOneYarnKnitRowByRowWithTurns) {
  Compilation c =
      compile_stitch_mesh(build_from_rows(ribbed_rows(5, 3, {T::k, T::p}), Layout::sheet), "sheet");
  ASSERT_TRUE(c.knittability.knittable);
  EXPECT_EQ(c.yarns.size(), 1u);
  EXPECT_EQ(c.yarns.first[0], 0u);  // the leftmost cast-on stitch
  EXPECT_EQ(c.knit.loops.size(), 20u);
  for (RowShape s : c.knit.row_shape) EXPECT_EQ(s, RowShape::open);
  std::vector<StitchId> order = checked_order(c);
  // Row 2 is worked right to left: faces 9, 8, ..., 5.
  EXPECT_EQ(std::vector<StitchId>(order.begin() + 5, order.begin() + 10),
            (std::vector<StitchId>{9, 8, 7, 6, 5}));
  EXPECT_EQ(count(c.schedule, EventKind::turn), 4u);
  EXPECT_EQ(count(c.schedule, EventKind::row_start), 5u);
}

// Loop slots count left to right in each stitch's own frame, on both ends of the loop.
TEST(KnitGraph, LoopSlotsRunLeftToRightOnBothEnds) {
  RowPlan plan = {
      {T::co, T::co, T::co}, {T::k, T::kfb, T::k}, {T::k2tog, T::k, T::k}, {T::bo, T::bo, T::bo}};
  for (Layout layout : {Layout::sheet, Layout::tube}) {
    Compilation c = compile_stitch_mesh(build_from_rows(plan, layout), "slots");
    const KnitGraph& g = c.knit;
    auto made = g.loops_made_by(4);  // the kfb
    ASSERT_EQ(made.size(), 2u);
    EXPECT_EQ(g.loops[made[0]].taker, 6u);  // left half of the k2tog above
    EXPECT_EQ(g.loops[made[1]].taker, 7u);
    auto taken = g.loops_taken_by(6);  // the k2tog: the k's loop, then the kfb's left loop
    ASSERT_EQ(taken.size(), 2u);
    EXPECT_EQ(g.loops[taken[0]].maker, 3u);
    EXPECT_EQ(g.loops[taken[1]].maker, 4u);
    EXPECT_EQ(g.loops[taken[1]].maker_slot, 0);
    EXPECT_EQ(g.loops[taken[1]].taker_slot, 1);
  }
}

TEST(KnitGraph, TubeWithShiftPathIsOneHelix) {
  Compilation c = compile_stitch_mesh(build_from_rows(hat_rows(24, 6, 6), Layout::tube), "hat");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  EXPECT_EQ(c.yarns.size(), 1u);
  for (RowShape s : c.knit.row_shape) EXPECT_EQ(s, RowShape::closed);
  checked_order(c);
  std::size_t rounds = c.knit.row_shape.size();
  EXPECT_EQ(count(c.schedule, EventKind::marker, MarkerKind::beginning_of_round), rounds - 1);
  EXPECT_EQ(count(c.schedule, EventKind::turn), 0u);
  EXPECT_EQ(c.schedule.holds, 0u);
}

// Without the shift-path transform, a round is a ring of stitches each waiting for the last.
TEST(Knittability, RoundWithoutShiftPathIsACycleInTheRawKnitGraph) {
  StitchMesh mesh = build_from_rows(ribbed_rows(12, 2, {T::k}), Layout::tube);
  for (Edge e : mesh.edges()) mesh.shift_path[e] = 0;
  Compilation c = compile_knit_graph(build_knit_graph(mesh, "tube"), "tube");
  ASSERT_FALSE(c.knittability.knittable);
  EXPECT_EQ(c.knittability.cycle.size(), 12u);
  for (const CycleStep& step : c.knittability.cycle) EXPECT_EQ(step.reason, DependencyReason::yarn);
  EXPECT_NE(c.knittability.hint.find("closed round whose yarn never ends: mark one of its wale "
                                     "edges as a shift-path"),
            std::string::npos);
  std::string report = check_report(c);
  EXPECT_NE(report.find("NOT knittable"), std::string::npos);
  EXPECT_NE(
      report.find("face 2 (co, row 1) waits for face 1 (co, row 1): it comes next along the yarn"),
      std::string::npos)
      << report;
}

TEST(Knittability, Fig13DeadlockIsFoundAndExplained) {
  Compilation c = compile_stitch_mesh(testing::fig13_deadlock_mesh(), "fig13");
  ASSERT_EQ(c.knit.groups.size(), 2u);
  for (const MismatchGroup& g : c.knit.groups) EXPECT_EQ(g.yarn, MismatchYarnUse::own);
  ASSERT_FALSE(c.knittability.knittable);
  int own_yarn_arrows = 0;
  for (const CycleStep& step : c.knittability.cycle)
    own_yarn_arrows += step.reason == DependencyReason::joined_loop;
  EXPECT_GE(own_yarn_arrows, 1);
  EXPECT_NE(c.knittability.hint.find("special deadlock of paper §4.1: separate groups"),
            std::string::npos)
      << c.knittability.hint;
}

TEST(Knittability, Fig13WithExtraYarnForBothGroupsIsKnittable) {
  StitchMesh mesh = testing::fig13_deadlock_mesh();
  for (Edge e : mesh.edges())
    if (mesh.kind(e) == EdgeKind::join) mesh.mismatch_yarn[e] = {MismatchYarn::Kind::extra, Face()};
  Compilation c = compile_stitch_mesh(std::move(mesh), "fig13-extra");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  EXPECT_EQ(c.yarns.size(), 6u);  // lower piece, two single cast-ons, row B, two extra yarns
  EXPECT_EQ(c.knit.size(), 16u);  // two extruded three-needle bind-off stitches
  checked_order(c);
}

// Algorithm 1 with six yarn pieces: row B must wait for the single cast-on T3 (face 14),
// so its piece is held, T3's piece moves to the top of the stack, and row B resumes after it;
// the two extruded three-needle bind-offs (extra yarn) come last, when both sides are done.
TEST(Schedule, HeldPieceResumesAfterThePieceItWaitsForIsMovedToTheTop) {
  StitchMesh mesh = testing::fig13_deadlock_mesh();
  for (Edge e : mesh.edges())
    if (mesh.kind(e) == EdgeKind::join) mesh.mismatch_yarn[e] = {MismatchYarn::Kind::extra, Face()};
  Compilation c = compile_stitch_mesh(std::move(mesh), "fig13-extra");
  EXPECT_EQ(checked_order(c),
            (std::vector<StitchId>{0, 1, 2, 3, 7, 6, 5, 4, 12, 8, 9, 10, 13, 11, 14, 15}));
  EXPECT_EQ(c.schedule.holds, 1u);
  auto hold = std::find_if(c.schedule.events.begin(), c.schedule.events.end(),
                           [](const Event& e) { return e.kind == EventKind::hold; });
  ASSERT_NE(hold, c.schedule.events.end());
  EXPECT_EQ(hold->stitch, 11u);
  EXPECT_EQ(hold->waits_for, 13u);
  EXPECT_EQ(count(c.schedule, EventKind::resume), 1u);
  EXPECT_EQ(count(c.schedule, EventKind::yarn_start), 6u);
  EXPECT_EQ(count(c.schedule, EventKind::yarn_end), 6u);
}

TEST(Knittability, Fig13WithTheSameSidesYarnForBothGroupsIsKnittable) {
  StitchMesh mesh = testing::fig13_deadlock_mesh();
  for (Edge e : mesh.edges())
    if (mesh.kind(e) == EdgeKind::join) {
      Halfedge h = mesh.halfedge(e);
      Face upper = mesh.row[mesh.face(h)] > mesh.row[mesh.face(mesh.twin(h))]
                       ? mesh.face(h)
                       : mesh.face(mesh.twin(h));
      mesh.mismatch_yarn[e] = {MismatchYarn::Kind::own, upper};
    }
  Compilation c = compile_stitch_mesh(std::move(mesh), "fig13-same-side");
  EXPECT_TRUE(c.knittability.knittable) << check_report(c);
}

// The schedule target's text, replayed by its own simulator.
VerifyReport emit_and_replay(const Compilation& c,
                             const std::function<void(std::string&)>& edit = {}) {
  Registry registry;
  register_builtin_targets(registry);
  std::ostringstream out;
  registry.target("schedule")->emit(c, {}, out);
  std::string text = out.str();
  if (edit) edit(text);
  return registry.simulator_for("schedule")->verify(text, "out.schedule", &c, {});
}

// Generates many sheets and tubes with random shaping; the simulator is the judge.
TEST(Randomized, SchedulesHoldEveryStitchOnceAfterItsDependencies) {
  std::mt19937_64 rng(2026);
  for (int trial = 0; trial < 150; ++trial) {
    Compilation c = compile_stitch_mesh(testing::random_sheet_or_tube(trial, rng), "random");
    ASSERT_TRUE(c.knittability.knittable) << check_report(c);
    ASSERT_EQ(c.yarns.size(), 1u);
    checked_order(c);
    VerifyReport report = emit_and_replay(c);
    EXPECT_TRUE(report.proven) << report.summary;
  }
}

TEST(ScheduleReplay, RejectsAStitchWorkedBeforeWhatItWaitsFor) {
  Compilation c =
      compile_stitch_mesh(build_from_rows(ribbed_rows(3, 2, {T::k}), Layout::sheet), "s");
  auto swap_lines = [](std::string& text) {
    std::size_t a = text.find("\n    4 k\n"), b = text.find("\n    3 co\n");
    ASSERT_NE(a, std::string::npos);
    ASSERT_NE(b, std::string::npos);
    text.replace(a, 9, "\n    3 co\n");
    text.replace(b, 10, "\n    4 k\n");
  };
  VerifyReport report = emit_and_replay(c, swap_lines);  // well formed, not the model's
  EXPECT_FALSE(report.proven);
  EXPECT_NE(report.summary.find("face 4 (k, row 2) is worked before face "), std::string::npos)
      << report.summary;
}

TEST(ScheduleReplay, RejectsAMissingStitch) {
  Compilation c =
      compile_stitch_mesh(build_from_rows(ribbed_rows(3, 2, {T::k}), Layout::sheet), "s");
  VerifyReport report = emit_and_replay(c, [](std::string& text) {
    std::size_t at = text.rfind("    10 bo\n");  // the last stitch: row 4 runs right to left
    text.erase(at, 10);
  });
  EXPECT_FALSE(report.proven);
  EXPECT_EQ(report.summary, "out.schedule: face 10 (bo, row 4) is never worked");
}

}  // namespace
}  // namespace skein
