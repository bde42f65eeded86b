// The yarn-level model: topology, clearance and length per stitch on samples.
#include <gtest/gtest.h>

#include <filesystem>

#include <iostream>
#include "driver/pipeline.hpp"
#include "yarn/build.hpp"
#include "yarn/checks.hpp"
#include "yarn/contacts.hpp"

namespace skein {
namespace {

std::string sample_path(const std::string& name, const std::string& ext) {
  return std::string(SKEIN_SOURCE_DIR) + "/samples/" + name + "/" + name + ext;
}

YarnBuild yarn_of(const Compilation& c, const std::string& input, int steps) {
  YarnOptions options;
  options.relax.max_steps = steps;
  options.relax_yarn = steps > 0;
  std::vector<std::array<double, 3>> positions;
  if (!c.mesh) positions = read_stitch_positions(input);
  return build_yarn(c.knit, c.yarns, c.mesh ? &*c.mesh : nullptr, positions, options);
}

TEST(YarnDiag, Print) {
  for (std::string input : {sample_path("hat", ".obj"), sample_path("teapot", ".yaml"),
                            sample_path("rib-swatch", ".obj"),
                            std::string(SKEIN_SOURCE_DIR) + "/samples/autoknit/test-A.st"}) {
    Compilation c = compile_model(input);
    YarnBuild y = yarn_of(c, input, 0);
    TopologyReport t = check_yarn_topology(c.knit, y.model);
    Clearance cl = yarn_clearance(y.model, 0.9f);
    std::vector<int> owner(y.model.point.size(), -1), sample(y.model.point.size(), -1);
    for (StitchId s = 0; s < c.knit.size(); ++s)
      for (std::uint32_t k = 0; k < stitch_template(c.knit.type[s]).lobes * kLobeSamples; ++k)
        owner[y.model.stitch_first[s] + k] = int(s), sample[y.model.stitch_first[s] + k] = int(k);
    int shown = 0;
    for (auto p :
         close_segments(y.model.point, y.model.piece_first, 2 * y.model.radius * 0.3f, 1)) {
      if (shown++ > 12) break;
      std::cout << "  close: " << c.knit.describe(owner[p.a]) << " k" << sample[p.a] << " / "
                << c.knit.describe(owner[p.b]) << " k" << sample[p.b] << "\n";
    }
    std::printf(
        "%s: loops %u not held %u wrongly %u (%s); closest %.3f closer %lu of %lu; knit "
        "length %.3f w\n",
        input.c_str(), t.loops, t.not_held, t.wrongly_held, t.first_problem.c_str(), cl.closest,
        (unsigned long)cl.closer, (unsigned long)cl.checked,
        yarn_length_per_stitch(c.knit, y.model, StitchType::k) / y.gauge.stitch_width);
    std::fflush(stdout);
  }
}

}  // namespace
}  // namespace skein
