// Project files: the smallest is one line; every mistake names its line, the field and the
// nearest valid name.
#include <gtest/gtest.h>

#include <fstream>

#include "common/error.hpp"
#include "common/yaml_source.hpp"
#include "labeling/project.hpp"

namespace skein {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_project(text, "dir/p.yaml");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Project, OneLineProjectTakesEveryDefault) {
  Project p = parse_project("mesh: hat.obj\n", "dir/p.yaml");
  EXPECT_EQ(p.mesh, "dir/hat.obj");  // resolved beside the project file
  EXPECT_EQ(p.unit, "cm");
  EXPECT_DOUBLE_EQ(p.stitch_width_in_units(), 10.0 / 22);
  EXPECT_DOUBLE_EQ(p.stitch_height_in_units(), 10.0 / 30);
  EXPECT_TRUE(p.start.empty());
  EXPECT_EQ(p.pattern, StitchPattern::knit);
  EXPECT_EQ(p.short_row_method, ShortRowMethod::sr4);
  EXPECT_EQ(p.default_yarn, YarnHandling::by_default);
  EXPECT_TRUE(p.shift_paths.empty() && p.mismatch_edges.empty() && p.target.empty());
}

TEST(Project, EveryFieldIsRead) {
  Project p = parse_project(R"(mesh: /abs/m.obj
unit: mm
gauge: {stitches: 20, rows: 28}
start:
  - edge: [1, 2]
  - vertex: 7
pattern: k1p1
patterns: {cuff: k2p2}
short_rows:
  method: sr5
  faces: [3, {face: 4, wide_edge: [5, 6]}]
mismatches: [[8, 9]]
yarn:
  default: extra
  edges:
    - {edge: [10, 11], use: own, face: 2}
shift_paths: [[12, 13], {edge: [14, 15], option: down-left}]
shift_option: up-left
target: {machine: kniterate}
)",
                            "p.yaml");
  EXPECT_EQ(p.mesh, "/abs/m.obj");
  EXPECT_DOUBLE_EQ(p.stitch_width_in_units(), 100.0 / 20);  // 10 cm in mm over 20 stitches
  ASSERT_EQ(p.start.size(), 2u);
  EXPECT_EQ(p.start[0].edge.a, 0u);
  EXPECT_EQ(p.start[0].edge.b, 1u);
  EXPECT_EQ(p.start[1].kind, StartSeed::Kind::vertex);
  EXPECT_EQ(p.start[1].edge.a, 6u);
  EXPECT_EQ(p.pattern, StitchPattern::k1p1);
  EXPECT_EQ(p.group_patterns.at("cuff").pattern, StitchPattern::k2p2);
  EXPECT_EQ(p.short_row_method, ShortRowMethod::sr5);
  ASSERT_EQ(p.short_row_faces.size(), 2u);
  EXPECT_EQ(p.short_row_faces[1].face, 3u);
  EXPECT_EQ(p.short_row_faces[1].wide_edge->a, 4u);
  EXPECT_EQ(p.mismatch_edges.at(0).line, 12);
  EXPECT_EQ(p.default_yarn, YarnHandling::extra);
  EXPECT_EQ(p.yarn_marks.at(0).use, YarnHandling::own);
  EXPECT_EQ(*p.yarn_marks.at(0).face, 1u);
  EXPECT_EQ(p.shift_paths.at(0).edge.b, 12u);
  EXPECT_EQ(p.shift_paths.at(0).option, 2);  // shift_option, though written after the list
  EXPECT_EQ(p.shift_paths.at(1).option, 4);
  EXPECT_EQ(p.target.at("machine"), "kniterate");
}

TEST(Project, StitchSizeOverridesTheGauge) {
  Project p = parse_project("mesh: m.obj\nstitch_size: {width: 0.5, height: 0.25}\n", "p.yaml");
  EXPECT_DOUBLE_EQ(p.stitch_width_in_units(), 0.5);
  EXPECT_DOUBLE_EQ(p.stitch_height_in_units(), 0.25);
}

TEST(Project, MisspelledFieldNamesLineAndNearestName) {
  EXPECT_EQ(error_of("mesh: m.obj\nguage: {stitches: 20}\n"),
            "dir/p.yaml:2: unknown field 'guage' in the project; did you mean 'gauge'? (known: "
            "mesh, unit, gauge, stitch_size, start, pattern, patterns, short_rows, mismatches, "
            "yarn, shift_paths, shift_option, target)\n      2 | guage: {stitches: 20}");
  EXPECT_NE(error_of("mesh: m.obj\ngauge:\n  stiches: 20\n")
                .find(":3: unknown field 'stiches' in gauge; did you mean 'stitches'?"),
            std::string::npos);
  EXPECT_NE(error_of("mesh: m.obj\nshort_rows: {methd: sr5}\n").find("did you mean 'method'?"),
            std::string::npos);
}

TEST(Project, BadValuesNameWhatWasExpected) {
  EXPECT_NE(error_of("mesh: m.obj\npattern: k2p3\n")
                .find(":2: unknown stitch pattern 'k2p3'; did you mean 'k2p2'?"),
            std::string::npos);
  EXPECT_NE(error_of("mesh: m.obj\ngauge: {stitches: -3}\n")
                .find("expected stitches per 10 cm (a number from 1 to 100), found '-3'"),
            std::string::npos);
  EXPECT_NE(error_of("mesh: m.obj\nstart: [{edge: [1]}]\n")
                .find("expected an edge as its two vertex numbers"),
            std::string::npos);
  EXPECT_NE(error_of("mesh: m.obj\nstart: [{vertex: 0}]\n").find("a number from 1"),
            std::string::npos);
  EXPECT_NE(error_of("mesh: m.obj\nunit: furlong\n").find("unknown unit 'furlong'"),
            std::string::npos);
  EXPECT_NE(error_of("mesh: m.obj\nyarn: {default: spare}\n").find("unknown yarn handling 'spare'"),
            std::string::npos);
  EXPECT_NE(error_of("unit: cm\n").find("expected 'mesh: FILE.obj'"), std::string::npos);
  EXPECT_NE(error_of("mesh: [a\n").find("not valid YAML"), std::string::npos);
  EXPECT_NE(error_of("- just a list\n").find("expected a project"), std::string::npos);
}

TEST(Project, TargetOptionsComeFromTheProjectFile) {
  std::string dir = ::testing::TempDir();
  std::ofstream(dir + "/t.yaml") << "mesh: m.obj\ntarget: {machine: kniterate}\n";
  EXPECT_EQ(project_target_option(dir + "/t.yaml", "machine"), "kniterate");
  EXPECT_EQ(project_target_option(dir + "/t.yaml", "carriers"), "");
  EXPECT_EQ(project_target_option("samples/hat/hat.obj", "machine"), "");  // not a project
}

TEST(Project, NearestNameIgnoresCase) {
  EXPECT_EQ(nearest_name("Gauge", {"mesh", "gauge", "unit"}), "gauge");
  EXPECT_EQ(nearest_name("shiftpaths", {"short_rows", "shift_paths"}), "shift_paths");
}

}  // namespace
}  // namespace skein
