// The knittable transforms (paper §3.2): one small mesh per mismatched direction and option,
// each compiled, checked, scheduled and proven by the schedule simulator.
#include <gtest/gtest.h>

#include <sstream>

#include "builtin_targets.hpp"
#include "common/error.hpp"
#include "fixtures.hpp"

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
  EXPECT_NE(check_report(c).find("expanding perpendicular, 3 edges between rows 1 and 4, odd: one tied end"),
            std::string::npos)
      << check_report(c);
}

TEST(YarnChoice, OneGroupAskingForTwoYarnsIsRejected) {
  StitchMesh mesh = testing::join_mesh(Kind::extra);
  Halfedge h = mesh.halfedge(mesh.find_edge(Vertex(9), Vertex(10)));
  mesh.mismatch_yarn[mesh.edge(h)] = {Kind::own, mesh.face(h)};
  try {
    compile_stitch_mesh(std::move(mesh), "conflict");
    FAIL() << "expected a MeshError";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("belong to one joining mismatch group but ask for different yarns"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace skein
