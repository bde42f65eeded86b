// Every input the fuzzers found that crashed, hung or broke a sanitizer (fuzz/README.md) is
// kept in tests/data/fuzz/READER/NAME with NAME.message beside it: the first line of the
// error it must now give, or "accepted". Each is replayed through the fuzz target's reader
// and must end in well under the fuzzers' 10 s.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../fuzz/fuzz_inputs.hpp"

namespace skein {
namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The first line of what the reader says: its error, or "accepted".
std::string outcome(fuzz::Reader read, const std::string& text) {
  try {
    read(text);
  } catch (const Error& e) {
    std::string what = e.what();
    return what.substr(0, what.find('\n'));
  }
  return "accepted";
}

TEST(FuzzFindings, EachGivesItsMessageQuickly) {
  int replayed = 0;
  for (auto [name, read] : fuzz::kReaders) {
    fs::path dir = fs::path(SKEIN_SOURCE_DIR) / "tests/data/fuzz" / name;
    if (!fs::exists(dir)) continue;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
      if (entry.path().extension() == ".message") continue;
      std::string expected = contents(entry.path().string() + ".message");
      while (!expected.empty() && expected.back() == '\n') expected.pop_back();
      auto start = std::chrono::steady_clock::now();
      EXPECT_EQ(outcome(read, contents(entry.path())), expected) << entry.path();
      EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2)) << entry.path();
      ++replayed;
    }
  }
  EXPECT_GT(replayed, 0);
}

}  // namespace
}  // namespace skein
