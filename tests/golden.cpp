#include "golden.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace skein::testing {

std::string source_path(const std::string& relative) {
  return std::string(SKEIN_SOURCE_DIR) + "/" + relative;
}

void expect_golden(const std::string& relative, const std::string& actual) {
  std::string path = source_path(relative);
  if (const char* update = std::getenv("SKEIN_UPDATE_GOLDEN"); update && *update == '1') {
    std::ofstream(path, std::ios::binary) << actual;
    return;
  }
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << "missing golden file " << relative << " (run with SKEIN_UPDATE_GOLDEN=1)";
  std::stringstream expected;
  expected << in.rdbuf();
  EXPECT_EQ(expected.str(), actual) << "golden file " << relative << " differs";
}

}  // namespace skein::testing
