// The knittable transforms (shift-paths, mismatches) on generated models with many short rows,
// joins and splits, up to a million stitches. Run: build/skein_bench --benchmark_filter=Transform
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>

#include "knitgraph/from_mesh.hpp"
#include "labeling/labeling.hpp"
#include "labeling/project.hpp"
#include "labeling/shapes.hpp"
#include "labeling/stitch_generation.hpp"
#include "mesh/generate.hpp"
#include "transforms/mismatches.hpp"
#include "transforms/shift_paths.hpp"

namespace skein {
namespace {

enum class Model { tube, sock, short_rows, joined, split };

// A `skein new sock` scaled to roughly `stitches` stitches (4,606 at 20 cm by 15 cm).
StitchMesh sock(std::uint32_t stitches) {
  double scale = std::sqrt(stitches / 4606.0);
  Shape s = make_shape("sock", {20 * scale, 0, 15 * scale}, "sock");
  Project p = parse_project(s.project, "sock.yaml");
  return generate_stitch_mesh(s.mesh, label_coarse_mesh(s.mesh, p), p).mesh;
}

// Roughly `stitches` stitches: a square tube or a sock (its heel rounds are rings of short
// rows) without shift-path marks, a square short-row sheet, or two square sheets meeting on a
// join or split line of extra-yarn 3nbo or cast-ons.
const StitchMesh& model(Model kind, std::uint32_t stitches) {
  static std::map<std::pair<Model, std::uint32_t>, StitchMesh> cache;
  auto [it, added] = cache.try_emplace({kind, stitches});
  if (added) {
    auto side = static_cast<std::uint32_t>(std::sqrt(static_cast<double>(stitches)));
    if (kind == Model::tube || kind == Model::sock) {
      it->second = kind == Model::sock
                       ? sock(stitches)
                       : build_from_rows(ribbed_rows(side, side, {StitchType::k}), Layout::tube);
      for (Edge e : it->second.edges()) it->second.shift_path[e] = kNotShifted;  // placed anew
    } else if (kind == Model::short_rows) {
      it->second = short_row_sheet(side, side * 2 / 3, 1);
    } else {
      it->second = meeting_sheets(kind == Model::joined ? Meeting::join : Meeting::split, side,
                                  side / 2, side / 2, MismatchYarn::Kind::extra, false, 1);
    }
  }
  return it->second;
}

void BM_TransformShiftPaths(benchmark::State& state, Model kind) {
  const StitchMesh& base = model(kind, static_cast<std::uint32_t>(state.range(0)));
  for (auto _ : state) {
    state.PauseTiming();
    StitchMesh mesh = base;
    state.ResumeTiming();
    benchmark::DoNotOptimize(place_shift_paths(mesh));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * base.num_faces());
}

void BM_TransformMismatches(benchmark::State& state, Model kind) {
  const StitchMesh& base = model(kind, static_cast<std::uint32_t>(state.range(0)));
  KnitGraph graph = build_knit_graph(base, "bench");
  for (auto _ : state) {
    state.PauseTiming();
    KnitGraph g = graph;
    state.ResumeTiming();
    make_mismatches_knittable(g);
    benchmark::DoNotOptimize(g.loops.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * base.num_faces());
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->MinTime(0.5);
}

BENCHMARK_CAPTURE(BM_TransformShiftPaths, tube, Model::tube)->Apply(sizes);
BENCHMARK_CAPTURE(BM_TransformShiftPaths, sock, Model::sock)->Apply(sizes);
BENCHMARK_CAPTURE(BM_TransformMismatches, short_rows, Model::short_rows)->Apply(sizes);
BENCHMARK_CAPTURE(BM_TransformMismatches, joined, Model::joined)->Apply(sizes);
BENCHMARK_CAPTURE(BM_TransformMismatches, split, Model::split)->Apply(sizes);

}  // namespace
}  // namespace skein
