// `skein new`, `skein render`, `skein generate` and project files through `skein check`, as a
// user meets them: exit codes, the files written, and nothing half-written on an error.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_runner.hpp"

namespace skein {
namespace {

namespace fs = std::filesystem;

// Exit codes alone; what was printed stays in the folder's "stdout" and "stderr".
class LabelingCli : public testing::SkeinCliTest {
 protected:
  int run(const std::string& args) const { return skein(args).exit_code; }
};

TEST_F(LabelingCli, NewWritesMeshAndProjectThatCheck) {
  ASSERT_EQ(run("new tube --circumference 40cm --length 20cm -o " + in_dir("tube")), 0)
      << read("stderr");
  EXPECT_TRUE(fs::exists(in_dir("tube.obj")));
  EXPECT_NE(read("tube.yaml").find("mesh: tube.obj"), std::string::npos);
  EXPECT_EQ(run("check " + in_dir("tube.yaml")), 0) << read("stderr");
  EXPECT_NE(read("stdout").find("knittable"), std::string::npos);
  EXPECT_NE(read("stdout").find("yarn pieces: 1"), std::string::npos);
}

TEST_F(LabelingCli, BadLengthOrKindIsAUsageError) {
  EXPECT_EQ(run("new tube --length twenty -o " + in_dir("t")), 2);
  EXPECT_NE(read("stderr").find("'twenty' is not a length"), std::string::npos);
  EXPECT_EQ(run("new scarf -o " + in_dir("t")), 2);
  EXPECT_NE(read("stderr").find("unknown shape 'scarf'"), std::string::npos);
  EXPECT_FALSE(fs::exists(in_dir("t.obj")));
}

TEST_F(LabelingCli, RenderAndGenerateWriteWholeFiles) {
  ASSERT_EQ(run("render samples/swatch/swatch.yaml -o " + in_dir("s.svg")), 0) << read("stderr");
  EXPECT_NE(read("s.svg").find("</svg>"), std::string::npos);
  ASSERT_EQ(run("render samples/swatch/swatch.yaml --coarse -o " + in_dir("c.svg")), 0);
  ASSERT_EQ(run("render samples/swatch/swatch.obj -o " + in_dir("plain.svg")), 0) << read("stderr");
  ASSERT_EQ(run("generate samples/swatch/swatch.yaml -o " + in_dir("s.obj")), 0) << read("stderr");
  EXPECT_EQ(run("check " + in_dir("s.obj")), 0);  // the written stitch mesh reads back
  EXPECT_NE(read("stdout").find("stitches: 2024"), std::string::npos) << read("stdout");
}

TEST_F(LabelingCli, ProjectErrorsNameTheLineAndLeaveNothing) {
  std::ofstream(in_dir("p.yaml")) << "mesh: ../nowhere.obj\ngauge: {stiches: 20}\n";
  EXPECT_EQ(run("render " + in_dir("p.yaml") + " -o " + in_dir("p.svg")), 2);
  EXPECT_NE(
      read("stderr").find("p.yaml:2: unknown field 'stiches' in gauge; did you mean 'stitches'?"),
      std::string::npos)
      << read("stderr");
  EXPECT_FALSE(fs::exists(in_dir("p.svg")));
}

}  // namespace
}  // namespace skein
