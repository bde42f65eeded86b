// Every bundled sample, checked and scheduled, against the golden output kept beside it.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "builtin_targets.hpp"
#include "driver/pipeline.hpp"
#include "golden.hpp"

namespace skein {
namespace {

class SampleTest : public ::testing::TestWithParam<const char*> {
 protected:
  // Reports name the input as given, so run from the root with relative paths.
  void SetUp() override { std::filesystem::current_path(SKEIN_SOURCE_DIR); }
};
class KnittableSample : public SampleTest {};
class UnknittableSample : public SampleTest {};

std::string replace_extension(std::string path, const std::string& extension) {
  return std::filesystem::path(path).replace_extension(extension).string();
}

void expect_check_report_golden(const char* input, bool knittable) {
  Compilation c = compile_model(input);
  EXPECT_EQ(c.knittability.knittable, knittable);
  testing::expect_golden(replace_extension(input, ".check"), check_report(c));
}

TEST_P(KnittableSample, CheckReportMatchesGolden) {
  expect_check_report_golden(GetParam(), true);
}
TEST_P(UnknittableSample, CheckReportMatchesGolden) {
  expect_check_report_golden(GetParam(), false);
}

TEST_P(KnittableSample, ScheduleMatchesGoldenAndIsProven) {
  Compilation c = compile_model(GetParam());
  Registry registry;
  register_builtin_targets(registry);
  std::ostringstream out;
  registry.target("schedule")->emit(c, {}, out);
  testing::expect_golden(replace_extension(GetParam(), ".schedule"), out.str());
  VerifyReport report = registry.simulator_for("schedule")->verify(out.str(), "golden", &c, {});
  EXPECT_TRUE(report.proven) << report.summary;
}

std::string sample_name(const ::testing::TestParamInfo<const char*>& param_info) {
  std::string name = std::filesystem::path(param_info.param).stem().string();
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Samples, KnittableSample,
                         ::testing::Values("samples/rib-swatch/rib-swatch.obj",
                                           "samples/hat/hat.obj", "samples/autoknit/test-A.st",
                                           "samples/autoknit/test-B.st",
                                           "samples/autoknit/test-C.st",
                                           "samples/auto-shift-path/tube.obj"),
                         sample_name);
INSTANTIATE_TEST_SUITE_P(Samples, UnknittableSample,
                         ::testing::Values("samples/unknittable/fig13-deadlock.obj"), sample_name);

}  // namespace
}  // namespace skein
