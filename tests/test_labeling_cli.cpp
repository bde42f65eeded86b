// `skein new`, `skein render`, `skein generate` and project files through `skein check`, as a
// user meets them: exit codes, the files written, and nothing half-written on an error.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace skein {
namespace {

namespace fs = std::filesystem;

class LabelingCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("skein-label-cli-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    fs::current_path(SKEIN_SOURCE_DIR);
  }
  void TearDown() override { fs::remove_all(dir_); }

  int skein(const std::string& args) {
    std::string command = std::string(SKEIN_BINARY) + " " + args + " >" + (dir_ / "out").string() +
                          " 2>" + (dir_ / "err").string();
    return WEXITSTATUS(std::system(command.c_str()));
  }
  std::string read(const std::string& name) const {
    std::ifstream in(dir_ / name);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string at(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

TEST_F(LabelingCli, NewWritesMeshAndProjectThatCheck) {
  ASSERT_EQ(skein("new tube --circumference 40cm --length 20cm -o " + at("tube")), 0)
      << read("err");
  EXPECT_TRUE(fs::exists(at("tube.obj")));
  EXPECT_NE(read("tube.yaml").find("mesh: tube.obj"), std::string::npos);
  EXPECT_EQ(skein("check " + at("tube.yaml")), 0) << read("err");
  EXPECT_NE(read("out").find("knittable"), std::string::npos);
  EXPECT_NE(read("out").find("yarn pieces: 1"), std::string::npos);
}

TEST_F(LabelingCli, BadLengthOrKindIsAUsageError) {
  EXPECT_EQ(skein("new tube --length twenty -o " + at("t")), 2);
  EXPECT_NE(read("err").find("'twenty' is not a length"), std::string::npos);
  EXPECT_EQ(skein("new scarf -o " + at("t")), 2);
  EXPECT_NE(read("err").find("unknown shape 'scarf'"), std::string::npos);
  EXPECT_FALSE(fs::exists(at("t.obj")));
}

TEST_F(LabelingCli, RenderAndGenerateWriteWholeFiles) {
  ASSERT_EQ(skein("render samples/swatch/swatch.yaml -o " + at("s.svg")), 0) << read("err");
  EXPECT_NE(read("s.svg").find("</svg>"), std::string::npos);
  ASSERT_EQ(skein("render samples/swatch/swatch.yaml --coarse -o " + at("c.svg")), 0);
  ASSERT_EQ(skein("render samples/swatch/swatch.obj -o " + at("plain.svg")), 0) << read("err");
  ASSERT_EQ(skein("generate samples/swatch/swatch.yaml -o " + at("s.obj")), 0) << read("err");
  EXPECT_EQ(skein("check " + at("s.obj")), 0);  // the written stitch mesh reads back
  EXPECT_NE(read("out").find("stitches: 2024"), std::string::npos) << read("out");
}

TEST_F(LabelingCli, ProjectErrorsNameTheLineAndLeaveNothing) {
  std::ofstream(at("p.yaml")) << "mesh: ../nowhere.obj\ngauge: {stiches: 20}\n";
  EXPECT_EQ(skein("render " + at("p.yaml") + " -o " + at("p.svg")), 2);
  EXPECT_NE(
      read("err").find("p.yaml:2: unknown field 'stiches' in gauge; did you mean 'stitches'?"),
      std::string::npos)
      << read("err");
  EXPECT_FALSE(fs::exists(at("p.svg")));
}

}  // namespace
}  // namespace skein
