// The yarn-level model: laying yarn from the templates on a million stitches, and relaxing
// it (a few steps on a million stitches; the sweater to tolerance: see docs/yarn.md).
//
//   skein_bench --benchmark_filter=Yarn
#include <benchmark/benchmark.h>

#include "driver/pipeline.hpp"
#include "mesh/generate.hpp"
#include "yarn/build.hpp"
#include "yarn/layout.hpp"

namespace skein {
namespace {

struct Laid {
  Compilation c;
  StitchLayout layout;
};

// A hat of 1000 stitches round and 1000 rounds (about 1M stitches), compiled once.
const Laid& million_stitch_hat() {
  static const Laid laid = [] {
    Laid l;
    l.c = compile_stitch_mesh(build_from_rows(hat_rows(1000, 990, 8), Layout::tube), "hat-1M");
    std::vector<Point3> at;
    for (Vertex v : l.c.mesh->vertices()) {
      const Vec3& p = l.c.mesh->position[v];
      at.emplace_back(p.x, p.y, p.z);
    }
    l.layout = layout_from_mesh(*l.c.mesh, at, l.c.knit);
    return l;
  }();
  return laid;
}

void BM_YarnCurves(benchmark::State& state) {
  const Laid& l = million_stitch_hat();
  CurveOptions options;
  options.threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state) {
    YarnModel m = generate_yarn(l.c.knit, l.c.yarns, l.layout, options);
    benchmark::DoNotOptimize(m.point.data());
  }
  state.counters["stitches"] = l.c.knit.size();
}
BENCHMARK(BM_YarnCurves)->Arg(1)->Arg(2)->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);

void BM_YarnMeshRelaxation(benchmark::State& state) {
  const Laid& l = million_stitch_hat();
  for (auto _ : state) {
    std::vector<Point3> x = relax_stitch_mesh(*l.c.mesh, stitch_mesh_gauge(*l.c.mesh));
    benchmark::DoNotOptimize(x.data());
  }
}
BENCHMARK(BM_YarnMeshRelaxation)->Unit(benchmark::kMillisecond)->Iterations(1);

// Ten relaxation steps on the million-stitch hat (a step is linear in yarn length).
void BM_YarnRelaxSteps(benchmark::State& state) {
  const Laid& l = million_stitch_hat();
  RelaxOptions options;
  options.max_steps = 10;
  options.threads = 2;
  for (auto _ : state) {
    state.PauseTiming();
    YarnModel m = generate_yarn(l.c.knit, l.c.yarns, l.layout);
    state.ResumeTiming();
    relax_yarn(m, options);
  }
}
BENCHMARK(BM_YarnRelaxSteps)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace skein
