// `skein compile --target knitout --machine P` and `skein verify FILE.k` as a user meets them.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>

#include "common/atomic_file.hpp"

namespace skein {
namespace {

namespace fs = std::filesystem;

struct CliResult {
  int exit_code;
  std::string out, err;
};

CliResult run_skein(const std::string& args, const fs::path& dir) {
  std::string command = std::string(SKEIN_BINARY) + " " + args + " >" + (dir / "out.txt").string() +
                        " 2>" + (dir / "err.txt").string();
  int status = std::system(command.c_str());
  return {WEXITSTATUS(status), read_file((dir / "out.txt").string()),
          read_file((dir / "err.txt").string())};
}

class KnitoutCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("skein-knitout-cli-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    fs::current_path(SKEIN_SOURCE_DIR);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(KnitoutCli, CompilesVerifiesAndProvesTheHat) {
  std::string k = (dir_ / "hat.k").string();
  CliResult compiled = run_skein(
      "compile samples/hat/hat.obj --target knitout --machine swg091n2 -o " + k + " --verify",
      dir_);
  EXPECT_EQ(compiled.exit_code, 0) << compiled.err;
  EXPECT_NE(compiled.out.find("proven against samples/hat/hat.obj: all 2048 stitches are there"),
            std::string::npos)
      << compiled.out;
  CliResult replayed = run_skein("verify " + k + " --machine swg091n2", dir_);
  EXPECT_EQ(replayed.exit_code, 1);  // valid, but nothing to prove it against
  EXPECT_NE(replayed.out.find("every operation is valid on swg091n2"), std::string::npos)
      << replayed.out;
  EXPECT_NE(replayed.out.find("estimated knitting time"), std::string::npos) << replayed.out;
  CliResult proven =
      run_skein("verify " + k + " --machine swg091n2 --against samples/hat/hat.obj", dir_);
  EXPECT_EQ(proven.exit_code, 0) << proven.out << proven.err;
}

TEST_F(KnitoutCli, ABadProfileOrFileExitsTwoAndWritesNothing) {
  std::string k = (dir_ / "swatch.k").string();
  CliResult unknown =
      run_skein("compile samples/rib-swatch/rib-swatch.obj -t knitout -m swg999 -o " + k, dir_);
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("no machine profile 'swg999'"), std::string::npos) << unknown.err;
  EXPECT_FALSE(fs::exists(k));
  CliResult on_generic =
      run_skein("compile samples/rib-swatch/rib-swatch.obj -t knitout -m generic -o " + k, dir_);
  ASSERT_EQ(on_generic.exit_code, 0) << on_generic.err;
  CliResult wrong_machine = run_skein("verify " + k + " --machine kniterate", dir_);
  EXPECT_EQ(wrong_machine.exit_code, 2);
  EXPECT_NE(wrong_machine.err.find("swatch.k:4: kniterate needs ';;Carriers: 1 2 3 4 5 6'"),
            std::string::npos)
      << wrong_machine.err;
}

}  // namespace
}  // namespace skein
