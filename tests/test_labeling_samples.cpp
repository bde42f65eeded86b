// The samples made from coarse meshes: each project's labelling and counts, and its `skein
// check` report, against the golden files kept beside it (SKEIN_UPDATE_GOLDEN=1 rewrites them).
#include <gtest/gtest.h>

#include <filesystem>

#include "driver/pipeline.hpp"
#include "golden.hpp"
#include "labeling/stitch_generation.hpp"

namespace skein {
namespace {

std::string with_extension(std::string path, const std::string& extension) {
  return std::filesystem::path(path).replace_extension(extension).string();
}

class LabelingSample : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override { std::filesystem::current_path(SKEIN_SOURCE_DIR); }
};

TEST_P(LabelingSample, LabelsAndCountsMatchGolden) {
  Project project = read_project(GetParam());
  CoarseMesh coarse = read_coarse_mesh(project.mesh);
  Labeling labeling = label_coarse_mesh(coarse, project);
  GeneratedStitchMesh generated = generate_stitch_mesh(coarse, labeling, project);
  EXPECT_NO_THROW(validate(generated.mesh));
  testing::expect_golden(with_extension(GetParam(), ".labels"),
                         describe_generation(coarse, labeling, generated));
}

TEST_P(LabelingSample, CheckReportMatchesGolden) {
  Compilation c = compile_model(GetParam());
  EXPECT_TRUE(c.knittability.knittable) << check_report(c);
  testing::expect_golden(with_extension(GetParam(), ".check"), check_report(c));
}

std::string sample_name(const ::testing::TestParamInfo<const char*>& param_info) {
  std::string name = std::filesystem::path(param_info.param).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

// Every sample is knittable; the last seven are built to the paper's structures (Figs. 18-20
// and 1), with the paper's yarn counts where the cubes allow (docs/labeling.md, "Samples").
INSTANTIATE_TEST_SUITE_P(
    Label, LabelingSample,
    ::testing::Values("samples/swatch/swatch.yaml", "samples/beanie/beanie.yaml",
                      "samples/sweater/sweater.yaml",
                      "samples/short-row-wedge/short-row-wedge.yaml", "samples/sock/sock.yaml",
                      "samples/three-bars/three-bars.yaml",
                      "samples/three-bars-own/three-bars-own.yaml",
                      "samples/two-bars/two-bars.yaml", "samples/letter-h/letter-h.yaml",
                      "samples/letter-i/letter-i.yaml", "samples/letter-r/letter-r.yaml",
                      "samples/teapot/teapot.yaml"),
    sample_name);

}  // namespace
}  // namespace skein
