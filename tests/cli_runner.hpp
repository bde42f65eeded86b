// Runs the skein binary as a user would, each test in a fresh folder of its own, from the
// repository root so that sample paths read as in the README.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace skein::testing {

struct CliRun {
  int exit_code;
  std::string out, err;
};

class SkeinCliTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  // Runs `skein ARGS`; stdout and stderr are kept in the folder as "stdout" and "stderr".
  CliRun skein(const std::string& args) const;
  std::string in_dir(const std::string& name) const { return (dir_ / name).string(); }
  std::string read(const std::string& name) const;  // a file in the folder
  // The files in the folder besides the captured streams.
  std::vector<std::string> outputs() const;

  std::filesystem::path dir_;
};

}  // namespace skein::testing
