// The hand pattern, built on the lowering's live-loop program (issue 13), on the models the
// issue names: the samples at the gauges it lists and AutoKnit's stitch graphs in
// ../shared/data. Every pattern written is proven by the hand simulator; the rest are refused by
// name. The test prints the tallies (docs/hand-patterns.md keeps them).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "fixtures.hpp"
#include "target_runner.hpp"

namespace skein {
namespace {

namespace fs = std::filesystem;

struct Tally {
  int proven = 0, refused = 0;
  std::map<std::string, int> refusals;  // by message
};

// Writes the model's pattern and proves it, or counts the refusal.
void measure(const Compilation& c, const std::string& name, Tally& tally) {
  std::string pattern;
  try {
    pattern = testing::emit(c, "hand");
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("hand target: ", 0), 0u) << name << ": " << e.what();
    ++tally.refused;
    ++tally.refusals[name + ": " + std::string(e.what()).substr(0, 140)];
    return;
  }
  VerifyReport report = testing::verify(c, "hand", pattern);
  EXPECT_TRUE(report.proven) << name << ": " << report.summary;
  tally.proven += report.proven;
}

void print(const std::string& what, const Tally& t) {
  std::cout << fmt::format("{}: {} proven, {} refused by name\n", what, t.proven, t.refused);
  for (const auto& [refusal, n] : t.refusals) std::cout << "  " << refusal << "\n";
}

// Each sample at the issue's five gauges (a gauge that cannot make the mesh, or makes it
// unknittable, is skipped).
Tally samples_at_gauges() {
  const std::pair<int, int> gauges[] = {{14, 20}, {18, 24}, {20, 26}, {23, 32}, {26, 36}};
  Tally tally;
  for (const char* sample :
       {"swatch", "short-row-wedge", "sock", "beanie", "letter-h", "letter-i", "letter-r",
        "three-bars", "three-bars-own", "two-bars", "teapot", "sweater"}) {
    for (auto [stitches, rows] : gauges) {
      std::string name = fmt::format("{} at {}/{}", sample, stitches, rows);
      Compilation c;
      try {
        c = testing::sample_at_gauge(sample, stitches, rows);
      } catch (const Error&) {
        continue;
      }
      if (c.knittability.knittable) measure(c, name, tally);
    }
  }
  print("samples at 5 gauges", tally);
  return tally;
}

// 57 of 60 proven (the schedule's builder, before the lowering, 55); the letter R at 14/20 and
// two more refused by name.
TEST(HandProgramBuilder, SamplesAtTheIssuesGauges) {
  EXPECT_GE(samples_at_gauges().proven, 57);
}

// test-A, test-B and test-C, each proven.
TEST(HandProgramBuilder, AutoKnitStitchGraphs) {
  const fs::path shared = SKEIN_SOURCE_DIR "/../shared/data/autoknit-st";
  if (!fs::exists(shared)) GTEST_SKIP() << shared << " is absent";
  Tally tally;
  for (const auto& f : fs::directory_iterator(shared)) {
    if (f.path().extension() != ".st") continue;
    Compilation c = compile_model(f.path().string());
    if (c.knittability.knittable) measure(c, f.path().filename().string(), tally);
  }
  print("AutoKnit stitch graphs", tally);
  EXPECT_GE(tally.proven, 3);
}

}  // namespace
}  // namespace skein
