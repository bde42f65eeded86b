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
  std::stringstream expected_text;
  expected_text << in.rdbuf();
  if (expected_text.str() == actual) return;
  // Name the first line that differs rather than printing both files whole.
  std::istringstream expected(expected_text.str()), got(actual);
  std::string want, have;
  for (std::size_t line = 1;; ++line) {
    bool more_want = static_cast<bool>(std::getline(expected, want));
    bool more_have = static_cast<bool>(std::getline(got, have));
    if (more_want && more_have && want == have) continue;
    ADD_FAILURE() << "golden file " << relative << " differs at line " << line
                  << "\n  expected: " << (more_want ? want : "<end of file>")
                  << "\n  actual:   " << (more_have ? have : "<end of file>")
                  << "\n(rerun with SKEIN_UPDATE_GOLDEN=1 and read the diff)";
    return;
  }
}

}  // namespace skein::testing
