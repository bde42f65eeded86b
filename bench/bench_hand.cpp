// The hand target on 1M-stitch models: writing the pattern (markdown) and proving it with the
// hand simulator (read, work on the needles, compare with the model), each timed on its own.
// The model is compiled once per case, outside the timing.
//
//   skein_bench --benchmark_filter=Hand
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <sstream>
#include <string>

#include "driver/pipeline.hpp"
#include "hand/hand_target.hpp"
#include "hand/pattern_document.hpp"
#include "hand/pattern_model.hpp"
#include "hand/pattern_writers.hpp"
#include "hand/program_pattern.hpp"
#include "mesh/generate.hpp"

namespace skein {
namespace {

using T = StitchType;

enum class HandCase { hat_tube, ribbed_sheet, random_sheet, random_tube };

// A million stitches or more each, about 1000 a row.
RowPlan plan_of(HandCase c) {
  RandomShaping shaping{
      .purl = 0.3, .increase = 0.03, .decrease = 0.03, .min_width = 900, .max_width = 1100};
  switch (c) {
    case HandCase::hat_tube:
      return hat_rows(1000, 990, 8);
    case HandCase::ribbed_sheet:
      return ribbed_rows(1000, 998, {T::k, T::k, T::p, T::p});
    case HandCase::random_sheet:
    case HandCase::random_tube:
      break;
  }
  RowPlan plan = random_rows(1000, 1150, shaping, 2026);
  // A make-one needs a strand on both sides: none last in a flat row.
  for (std::size_t r = 1; c == HandCase::random_sheet && r < plan.size(); ++r) {
    T& last = r % 2 == 0 ? plan[r].back() : plan[r].front();
    if (last == T::m1l || last == T::m1r) last = T::kfb;
  }
  return plan;
}

const Compilation& model(HandCase c) {
  static std::map<HandCase, std::unique_ptr<Compilation>> cache;
  auto& slot = cache[c];
  if (!slot) {
    Layout layout =
        c == HandCase::hat_tube || c == HandCase::random_tube ? Layout::tube : Layout::sheet;
    slot = std::make_unique<Compilation>(
        compile_stitch_mesh(build_from_rows(plan_of(c), layout), "bench"));
  }
  return *slot;
}

// The pattern as markdown.
std::string pattern_of(const Compilation& c) {
  hand::HandPattern pattern = hand::build_hand_pattern(c);
  std::ostringstream out;
  hand::write_markdown(hand::make_document(pattern), out);
  return out.str();
}

void BM_HandEmit(benchmark::State& state) {
  const Compilation& c = model(static_cast<HandCase>(state.range(0)));
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::string text = pattern_of(c);
    bytes = text.size();
    benchmark::DoNotOptimize(text);
  }
  state.counters["stitches"] = c.knit.size();
  state.counters["pattern_bytes"] = static_cast<double>(bytes);
}

void BM_HandVerify(benchmark::State& state) {
  const Compilation& c = model(static_cast<HandCase>(state.range(0)));
  std::string text = pattern_of(c);
  for (auto _ : state) {
    VerifyReport report = hand::verify_pattern(text, "bench.md", &c);
    if (!report.proven) state.SkipWithError(report.summary.c_str());
  }
  state.counters["stitches"] = c.knit.size();
}

void hand_cases(benchmark::internal::Benchmark* b) {
  b->ArgName("case")->Unit(benchmark::kMillisecond)->Iterations(3);
  for (HandCase c :
       {HandCase::hat_tube, HandCase::ribbed_sheet, HandCase::random_sheet, HandCase::random_tube})
    b->Arg(static_cast<int>(c));
}

BENCHMARK(BM_HandEmit)->Apply(hand_cases);
BENCHMARK(BM_HandVerify)->Apply(hand_cases);

}  // namespace
}  // namespace skein
