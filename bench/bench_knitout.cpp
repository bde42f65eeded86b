// The knitout target on 1M-stitch models: writing the knitout, replaying it on the virtual
// v-bed (every rule checked), replaying as `skein verify FILE` does with its fabric report,
// and replaying plus proving the fabric against the model, each
// timed on its own. The model is compiled once per case, outside the timing. The profile is
// the generic one widened to 4000 needles so that every case fits.
//
//   skein_bench --benchmark_filter=Knitout
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include "driver/pipeline.hpp"
#include "knitout/emit.hpp"
#include "knitout/fabric_report.hpp"
#include "knitout/machine_profile.hpp"
#include "knitout/vbed_simulator.hpp"
#include "knitout/whole_file_proof.hpp"
#include "labeling/shapes.hpp"
#include "mesh/generate.hpp"

namespace skein {
namespace {

using T = StitchType;

enum class KnitoutCase { hat_tube, ribbed_sheet, shaped_tube, short_row_sheet, sock, shorts };

// About a million stitches each, about 1000 a row (the short-row sheet: pairs of short rows
// turning at random stitches, about one row in three; the sock: a tube of 704 stitches round
// with a short-row heel and a shaped toe; the shorts: a body of 1232 round parting into two legs).
const Compilation& model(KnitoutCase c) {
  static std::map<KnitoutCase, std::unique_ptr<Compilation>> cache;
  auto& slot = cache[c];
  if (slot) return *slot;
  RandomShaping shaping{
      .purl = 0.3, .increase = 0.03, .decrease = 0.03, .min_width = 900, .max_width = 1100};
  if (c == KnitoutCase::sock || c == KnitoutCase::shorts) {
    // `skein new sock`, 330 cm round: 1.18M stitches; `skein new shorts`, 560 cm round, legs
    // 110 cm: 1.16M stitches, its legs parting at a crotch of 406 sts (cast on along a split).
    bool sock = c == KnitoutCase::sock;
    ShapeSize size;
    size.circumference = sock ? 330 : 560;
    size.length = sock ? 200 : 110;
    std::string name = sock ? "skein-bench-sock" : "skein-bench-shorts";
    std::string project = write_shape(make_shape(sock ? "sock" : "shorts", size, name),
                                      (std::filesystem::temp_directory_path() / name).string());
    slot = std::make_unique<Compilation>(compile_model(project));
    return *slot;
  }
  if (c == KnitoutCase::short_row_sheet) {
    slot = std::make_unique<Compilation>(
        compile_stitch_mesh(short_row_sheet(1000, 800, 2026), "bench"));
    return *slot;
  }
  RowPlan plan = c == KnitoutCase::hat_tube       ? hat_rows(1000, 990, 8)
                 : c == KnitoutCase::ribbed_sheet ? ribbed_rows(1000, 998, {T::k, T::k, T::p, T::p})
                                                  : random_rows(1000, 1000, shaping, 2026);
  Layout layout = c == KnitoutCase::ribbed_sheet ? Layout::sheet : Layout::tube;
  slot = std::make_unique<Compilation>(compile_stitch_mesh(build_from_rows(plan, layout), "bench"));
  return *slot;
}

const knitout::MachineProfile& profile() {
  static knitout::MachineProfile p = [] {
    knitout::MachineProfile wide = knitout::load_machine_profile("generic");
    wide.needles = 4000;
    return wide;
  }();
  return p;
}

const std::string& knitout_of(KnitoutCase c) {
  static std::map<KnitoutCase, std::string> cache;
  std::string& text = cache[c];
  if (text.empty()) {
    std::ostringstream out;
    knitout::emit_knitout(model(c), profile(), out);
    text = out.str();
  }
  return text;
}

void BM_KnitoutEmit(benchmark::State& state) {
  const Compilation& c = model(static_cast<KnitoutCase>(state.range(0)));
  for (auto _ : state) {
    std::ostringstream out;
    knitout::emit_knitout(c, profile(), out);
    benchmark::DoNotOptimize(out);
  }
  state.counters["stitches"] = c.knit.size();
}

void BM_KnitoutReplay(benchmark::State& state) {
  const std::string& text = knitout_of(static_cast<KnitoutCase>(state.range(0)));
  std::uint64_t ops = 0;
  for (auto _ : state) {
    knitout::Replay r = knitout::replay_knitout(text, "bench.k", profile());
    ops = r.stats.operations;
    benchmark::DoNotOptimize(r);
  }
  state.counters["operations"] = static_cast<double>(ops);
  state.counters["ops_per_second"] =
      benchmark::Counter(static_cast<double>(ops), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_KnitoutVerify(benchmark::State& state) {
  const Compilation& c = model(static_cast<KnitoutCase>(state.range(0)));
  const std::string& text = knitout_of(static_cast<KnitoutCase>(state.range(0)));
  for (auto _ : state) {
    knitout::Replay r = knitout::replay_knitout(text, "bench.k", profile());
    knitout::ProofResult proof = knitout::prove_whole_file(r, text, c);
    if (!proof.proven) state.SkipWithError(proof.summary.c_str());
  }
  state.counters["stitches"] = c.knit.size();
}

// What `skein verify FILE` does without --against: the replay by each rule's severity, and the
// fabric report.
void BM_KnitoutFabricReport(benchmark::State& state) {
  const std::string& text = knitout_of(static_cast<KnitoutCase>(state.range(0)));
  std::uint64_t ops = 0, loops = 0;
  for (auto _ : state) {
    knitout::Replay r = knitout::replay_knitout(text, "bench.k", profile(), {.strict = false});
    knitout::FabricReport f = knitout::fabric_report(r);
    ops = r.stats.operations;
    loops = f.knits + f.purls + f.tucks + f.splits;
    benchmark::DoNotOptimize(f);
  }
  state.counters["operations"] = static_cast<double>(ops);
  state.counters["loops"] = static_cast<double>(loops);
  state.counters["ops_per_second"] =
      benchmark::Counter(static_cast<double>(ops), benchmark::Counter::kIsIterationInvariantRate);
}

#define KNITOUT_CASES \
  ->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Arg(4)->Arg(5)->Unit(benchmark::kMillisecond)->Iterations(3)
BENCHMARK(BM_KnitoutEmit) KNITOUT_CASES;
BENCHMARK(BM_KnitoutReplay) KNITOUT_CASES;
BENCHMARK(BM_KnitoutVerify) KNITOUT_CASES;
BENCHMARK(BM_KnitoutFabricReport) KNITOUT_CASES;

}  // namespace
}  // namespace skein
