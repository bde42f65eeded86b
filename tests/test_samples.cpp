// Every bundled sample, checked and scheduled, against the golden output kept beside it.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "builtin_targets.hpp"
#include "driver/pipeline.hpp"
#include "golden.hpp"

namespace skein {
namespace {

struct Sample {
  const char* input;  // relative to the repository root
  bool knittable;
};

class SampleTest : public ::testing::TestWithParam<Sample> {
 protected:
  // Reports name the input as given, so run from the root with relative paths.
  void SetUp() override { std::filesystem::current_path(SKEIN_SOURCE_DIR); }
};

std::string replace_extension(std::string path, const std::string& extension) {
  return std::filesystem::path(path).replace_extension(extension).string();
}

TEST_P(SampleTest, CheckReportMatchesGolden) {
  Compilation c = compile_model(GetParam().input);
  EXPECT_EQ(c.knittability.knittable, GetParam().knittable);
  testing::expect_golden(replace_extension(GetParam().input, ".check"), check_report(c));
}

TEST_P(SampleTest, ScheduleMatchesGoldenAndIsProven) {
  if (!GetParam().knittable) GTEST_SKIP() << "no schedule for an unknittable model";
  Compilation c = compile_model(GetParam().input);
  Registry registry;
  register_builtin_targets(registry);
  std::ostringstream out;
  registry.target("schedule")->emit(c, {}, out);
  testing::expect_golden(replace_extension(GetParam().input, ".schedule"), out.str());
  VerifyReport report = registry.simulator_for("schedule")->verify(out.str(), "golden", &c, {});
  EXPECT_TRUE(report.proven) << report.summary;
}

INSTANTIATE_TEST_SUITE_P(Samples, SampleTest,
                         ::testing::Values(Sample{"samples/rib-swatch/rib-swatch.obj", true},
                                           Sample{"samples/hat/hat.obj", true},
                                           Sample{"samples/autoknit/test-A.st", true},
                                           Sample{"samples/autoknit/test-B.st", true},
                                           Sample{"samples/autoknit/test-C.st", true},
                                           Sample{"samples/unknittable/fig13-deadlock.obj", false},
                                           Sample{"samples/unknittable/tube-without-shift-path.obj", false}),
                         [](const auto& param_info) {
                           std::string name = std::filesystem::path(param_info.param.input).stem().string();
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace skein
