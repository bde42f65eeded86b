#include <gtest/gtest.h>

#include "common/error.hpp"
#include "fixtures.hpp"
#include "mesh/generate.hpp"

namespace skein {
namespace {

using testing::grid_mesh;
using testing::Square;
using T = StitchType;

TEST(StitchCatalogue, AbbreviationsRoundTripAndCountsAreConsistent) {
  for (const StitchTypeInfo& t : stitch_catalogue()) {
    EXPECT_EQ(stitch_type_from_abbreviation(t.abbreviation), t.type) << t.abbreviation;
    EXPECT_LE(t.loops_in, t.bottom_edges) << t.abbreviation;
    EXPECT_LE(t.loops_out, t.top_edges) << t.abbreviation;
  }
  EXPECT_EQ(info(T::k2tog).bottom_edges, 2);
  EXPECT_EQ(info(T::s2kp).bottom_edges, 3);
  EXPECT_EQ(info(T::kfb).top_edges, 2);
  EXPECT_EQ(info(T::co).loops_in, 0);
  EXPECT_EQ(info(T::bo).loops_out, 0);
  EXPECT_TRUE(info(T::sr4).wales_adjacent);
  EXPECT_FALSE(stitch_type_from_abbreviation("knit").has_value());
}

// A decrease's loops lie on one another as the stitch says, seen from the right side: k2tog
// (and p2tog) leans right, its left loop in front; ssk leans left; s2kp's centre loop lies in
// front, the right one behind it, the left one at the back.
TEST(StitchCatalogue, DecreasesStackTheirLoopsAsTheyLean) {
  EXPECT_GT(stack_position(StitchType::k2tog, 0, 2), stack_position(StitchType::k2tog, 1, 2));
  EXPECT_GT(stack_position(StitchType::p2tog, 0, 2), stack_position(StitchType::p2tog, 1, 2));
  EXPECT_LT(stack_position(StitchType::ssk, 0, 2), stack_position(StitchType::ssk, 1, 2));
  EXPECT_EQ(stack_position(StitchType::s2kp, 1, 3), 1.0f);
  EXPECT_EQ(stack_position(StitchType::s2kp, 2, 3), 0.0f);
  EXPECT_EQ(stack_position(StitchType::s2kp, 0, 3), -1.0f);
  EXPECT_EQ(stack_position(StitchType::k, 0, 1), 0.0f);
  for (const StitchTypeInfo& i : stitch_catalogue())
    EXPECT_EQ(i.stack == LoopStack::single, i.loops_in < 2) << i.abbreviation;
}

TEST(StitchMesh, GeneratedSheetHasRowsInKnittingOrderAndValidates) {
  StitchMesh mesh = build_from_rows(ribbed_rows(6, 4, {T::k, T::p}), Layout::sheet);
  EXPECT_EQ(mesh.num_faces(), 36u);
  EXPECT_NO_THROW(validate(mesh));
  for (Face f : mesh.faces()) EXPECT_EQ(mesh.row[f], f.index() / 6) << f.index();
  // Odd rows run right to left: the rightmost stitch's right edge is where its yarn enters.
  Face row1_right(11);
  EXPECT_EQ(mesh.role[mesh.wale_in(row1_right)], EdgeRole::wale_in);
  EXPECT_FALSE(mesh.twin(mesh.wale_in(row1_right)).valid());
}

TEST(StitchMesh, TubeSharesSeamEdgesAndMarksTheShiftPath) {
  StitchMesh mesh = build_from_rows(ribbed_rows(8, 3, {T::k}), Layout::tube);
  validate(mesh);
  int marked = 0, border = 0;
  for (Edge e : mesh.edges()) {
    marked += mesh.shift_path[e];
    border += mesh.is_border(e);
    if (mesh.shift_path[e]) {
      EXPECT_EQ(mesh.kind(e), EdgeKind::wale);
    }
  }
  EXPECT_EQ(marked, 5);   // one per round, cast-on and bind-off rounds included
  EXPECT_EQ(border, 16);  // the cast-on and bind-off edges
  EXPECT_EQ(mesh.num_edges(), 5u * 8 + 6u * 8);
}

TEST(StitchMesh, HatCrownDecreasesDownToOneStitchPerSection) {
  RowPlan plan = hat_rows(48, 10, 8);
  EXPECT_EQ(plan.back().size(), 8u);
  StitchMesh mesh = build_from_rows(plan, Layout::tube);
  EXPECT_NO_THROW(validate(mesh));
  int k2tog = 0;
  for (Face f : mesh.faces()) k2tog += mesh.stitch[f] == T::k2tog;
  EXPECT_EQ(k2tog, 48 - 8);
}

TEST(StitchMesh, RowPlanThatDoesNotConsumeTheRowBelowIsRejected) {
  RowPlan plan = {{T::co, T::co, T::co}, {T::k, T::k2tog}, {T::bo, T::bo, T::bo}};
  EXPECT_THROW(
      {
        try {
          build_from_rows(plan, Layout::sheet);
        } catch (const Error& e) {
          EXPECT_STREQ(e.what(), "row 3 of the plan consumes 3 loops, but row 2 makes 2");
          throw;
        }
      },
      Error);
}

// Validation failures: each names the face or edge and what was expected.
std::string validation_error(const StitchMesh& mesh) {
  try {
    validate(mesh);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "no error";
}

std::vector<Square> two_rows(std::string upper_roles, T upper = T::bo) {
  return {{0, 0, T::co, "boti"}, {0, 1, upper, std::move(upper_roles)}};
}

TEST(Validate, TwoWaleInEdgesAreRejected) {
  EXPECT_EQ(validation_error(grid_mesh(1, 2, two_rows("biti"))),
            "face 2 (bo, row 2) with edges 'biti': expected exactly one wale edge where the yarn "
            "enters (i) and one where it leaves (o), found 2 and 0");
}

TEST(Validate, WrongCourseEdgeCountForTheStitchTypeIsRejected) {
  EXPECT_EQ(validation_error(grid_mesh(1, 2, two_rows("boti", T::k2tog))),
            "face 2 (k2tog, row 2) with edges 'boti': a knit 2 together has 2 bottom and 1 top "
            "course edges, found 1 and 1");
}

TEST(Validate, KnitStitchWithNothingBelowIsRejected) {
  std::string error = validation_error(grid_mesh(1, 1, {{0, 0, T::k, "boti"}}));
  EXPECT_NE(error.find("face 1 (k, row 1): edge 1-2 on the border: a knit consumes a loop"),
            std::string::npos)
      << error;
}

TEST(Validate, LiveLoopAtTheTopIsRejected) {
  std::string error = validation_error(grid_mesh(1, 2, two_rows("boti", T::k)));
  EXPECT_NE(error.find("the loop this knit makes is never consumed or bound off; expected a "
                       "bind-off (bo)"),
            std::string::npos)
      << error;
}

TEST(Validate, CourseDirectionsThatDisagreeAreRejected) {
  StitchMesh mesh = grid_mesh(2, 1, {{0, 0, T::co, "boti"}, {1, 0, T::co, "bito"}});
  std::string error = validation_error(mesh);
  EXPECT_NE(error.find("edge 2-5 between face 1 (co, row 1) and face 2 (co, row 2): both faces' "
                       "yarn leaves here"),
            std::string::npos)
      << error;
}

TEST(Validate, ShiftPathOnACourseEdgeIsRejected) {
  StitchMesh mesh = grid_mesh(1, 2, two_rows("boti"));
  mesh.shift_path[mesh.find_edge(Vertex(2), Vertex(3))] = 1;
  std::string error = validation_error(mesh);
  EXPECT_NE(error.find("a shift-path runs along wale edges only; this is a course edge"),
            std::string::npos)
      << error;
}

TEST(Validate, ShiftPathOnTheBorderIsRejected) {
  StitchMesh mesh = grid_mesh(1, 2, two_rows("boti"));
  mesh.shift_path[mesh.find_edge(Vertex(0), Vertex(2))] = 1;
  EXPECT_NE(validation_error(mesh).find("edge 3-1: a shift-path edge must join two stitches of a "
                                        "closed row"),
            std::string::npos);
}

TEST(Validate, YarnChoiceOnAPlainCourseEdgeIsRejected) {
  StitchMesh mesh = grid_mesh(1, 2, two_rows("boti"));
  mesh.mismatch_yarn[mesh.find_edge(Vertex(2), Vertex(3))] = {MismatchYarn::Kind::extra, Face()};
  EXPECT_NE(validation_error(mesh).find("a yarn choice applies to joining or splitting edges only"),
            std::string::npos);
}

TEST(Validate, ShortRowFaceNeedsItsWaleEdgesSideBySide) {
  std::string error = validation_error(grid_mesh(1, 2, two_rows("boti", T::sr4)));
  EXPECT_NE(error.find("a short-row face has its two wale edges side by side"), std::string::npos)
      << error;
}

TEST(Build, FacesRunningTheSameWayAlongAnEdgeAreRejected) {
  StitchMeshBuilder builder("flipped.obj");
  for (int i = 0; i < 6; ++i)
    builder.add_vertex({static_cast<float>(i % 3), static_cast<float>(i / 3), 0});
  EdgeRole roles[] = {EdgeRole::bottom, EdgeRole::wale_out, EdgeRole::top, EdgeRole::wale_in};
  Vertex a[] = {Vertex(0), Vertex(1), Vertex(4), Vertex(3)};
  Vertex flipped[] = {Vertex(4), Vertex(5), Vertex(2), Vertex(1)};
  builder.add_face(a, roles, T::co);
  builder.add_face(flipped, roles, T::co);
  try {
    std::move(builder).build();
    FAIL() << "expected a MeshError";
  } catch (const MeshError& e) {
    EXPECT_STREQ(e.what(),
                 "flipped.obj: the edge between vertices 2 and 5 is used twice in the same "
                 "direction, by faces 1 and 2; expected neighbouring faces listed with the same "
                 "orientation (counter-clockwise)");
  }
}

}  // namespace
}  // namespace skein
