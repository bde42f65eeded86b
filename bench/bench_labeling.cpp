// Stitch-mesh generation from a coarse mesh (src/labeling/): labeling and generation at a gauge
// of a coarse cylinder (16 faces round, 10 rings, the radius varying by a quarter so rows
// decrease and increase), for 10K, 100K and 1M stitches. Run:
//   build/skein_bench --benchmark_filter=Labeling
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "labeling/labeling.hpp"
#include "labeling/stitch_generation.hpp"

namespace skein {
namespace {

CoarseMesh coarse_cylinder() {
  constexpr std::uint32_t kSides = 16, kRings = 11;
  std::vector<Vec3> v;
  for (std::uint32_t r = 0; r < kRings; ++r)
    for (std::uint32_t j = 0; j < kSides; ++j) {
      double radius = 1000 / (2 * std::numbers::pi) * (1 + 0.25 * std::sin(r * 0.7));
      double a = 2 * std::numbers::pi * j / kSides;
      v.push_back({static_cast<float>(radius * std::cos(a)), static_cast<float>(r * 100.0),
                   static_cast<float>(-radius * std::sin(a))});
    }
  std::vector<std::vector<std::uint32_t>> faces;
  for (std::uint32_t r = 0; r + 1 < kRings; ++r)
    for (std::uint32_t j = 0; j < kSides; ++j) {
      std::uint32_t k = (j + 1) % kSides;
      faces.push_back({r * kSides + j, r * kSides + k, (r + 1) * kSides + k, (r + 1) * kSides + j});
    }
  return build_coarse_mesh("<bench cylinder>", v, faces);
}

// The mesh is about 1000 x 1000 mesh units: a stitch of `scale` units gives 1M / scale^2.
void BM_LabelingGenerate(benchmark::State& state) {
  CoarseMesh coarse = coarse_cylinder();
  Project project;
  project.stitch_width = project.stitch_height = static_cast<double>(state.range(0)) / 10;
  std::size_t stitches = 0;
  for (auto _ : state) {
    Labeling labeling = label_coarse_mesh(coarse, project);
    GeneratedStitchMesh g = generate_stitch_mesh(coarse, labeling, project);
    stitches = g.mesh.num_faces();
    benchmark::DoNotOptimize(g);
  }
  state.counters["stitches"] = static_cast<double>(stitches);
  state.counters["stitches/s"] = benchmark::Counter(static_cast<double>(stitches),
                                                    benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_LabelingGenerate)
    ->Name("Labeling/generate/10K")
    ->Arg(100)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LabelingGenerate)
    ->Name("Labeling/generate/100K")
    ->Arg(32)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LabelingGenerate)
    ->Name("Labeling/generate/1M")
    ->Arg(10)
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace skein
