// Golden files: expected output kept beside its sample. Run the tests with
// SKEIN_UPDATE_GOLDEN=1 to rewrite them, then read every diff before committing it.
#pragma once

#include <string>

namespace skein::testing {

// The repository root (tests run from anywhere).
std::string source_path(const std::string& relative);

// Compares `actual` with the golden file at `relative` (from the repository root).
void expect_golden(const std::string& relative, const std::string& actual);

}  // namespace skein::testing
