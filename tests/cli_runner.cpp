#include "cli_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace skein::testing {

namespace fs = std::filesystem;

void SkeinCliTest::SetUp() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  dir_ = fs::temp_directory_path() / ("skein-cli-" + std::to_string(::getpid()) + "-" +
                                      test->test_suite_name() + "-" + test->name());
  fs::create_directories(dir_);
  fs::current_path(SKEIN_SOURCE_DIR);
}

void SkeinCliTest::TearDown() {
  fs::remove_all(dir_);
}

CliRun SkeinCliTest::skein(const std::string& args) const {
  std::string command =
      std::string(SKEIN_BINARY) + " " + args + " >" + in_dir("stdout") + " 2>" + in_dir("stderr");
  int status = std::system(command.c_str());
  return {WEXITSTATUS(status), read("stdout"), read("stderr")};
}

std::string SkeinCliTest::read(const std::string& name) const {
  std::ifstream in(dir_ / name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> SkeinCliTest::outputs() const {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir_)) {
    std::string name = entry.path().filename().string();
    if (name != "stdout" && name != "stderr") names.push_back(name);
  }
  return names;
}

}  // namespace skein::testing
