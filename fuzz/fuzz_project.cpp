// A project file and its coarse mesh in one input: the YAML, a line "#obj", then the OBJ text.
// Both are read, the mesh labelled and the stitch mesh generated, as `skein generate` does:
// the loops that choose counts and rows run on what the two files say.
#include <string_view>

#include "fuzz_reader.hpp"
#include "labeling/coarse_mesh.hpp"
#include "labeling/labeling.hpp"
#include "labeling/project.hpp"
#include "labeling/stitch_generation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return skein::fuzz::run_reader(data, size, [](const std::string& text) {
    constexpr std::string_view kSeparator = "\n#obj\n";
    std::size_t at = text.find(kSeparator);
    std::string yaml = text.substr(0, at);
    std::string obj = at == std::string::npos ? "" : text.substr(at + kSeparator.size());
    skein::Project project = skein::parse_project(yaml, "fuzz.yaml");
    skein::CoarseMesh coarse = skein::parse_coarse_mesh(obj, "fuzz.obj");
    skein::generate_stitch_mesh(coarse, skein::label_coarse_mesh(coarse, project), project);
  });
}
