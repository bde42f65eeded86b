// Google Benchmark suite for the core pipeline (src/driver/pipeline.hpp): every stage timed on
// its own, and the whole of compile_model(), on generated tubes of 10K, 100K and 1M stitches.
// bench/README.md says how to run it, what each case measures, and lists measured figures.
// This file holds skein_bench's main(); the other bench/*.cpp suites register themselves.
//
//   skein_bench --benchmark_filter=^pipeline/   these cases (about a minute on 2 cores)
//   skein_bench --write=FILE [--stitches=N]     write the 1M-stitch random tube (FILE.st: the
//                                               AutoKnit helix) and exit, for /usr/bin/time -v
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include "driver/pipeline.hpp"
#include "knitgraph/from_mesh.hpp"
#include "mesh/autoknit_st.hpp"
#include "mesh/generate.hpp"
#include "mesh/obj_format.hpp"
#include "transforms/mismatches.hpp"

namespace skein {
namespace {

constexpr std::uint32_t kRoundWidth = 1000;  // stitches per round of every tube
constexpr std::uint32_t kSizes[] = {10'000, 100'000, 1'000'000};
constexpr std::uint32_t kLargeSize = 1'000'000;
constexpr std::uint32_t kMinStitches = 3 * kRoundWidth;  // cast-on, one round, bind-off
constexpr int kLargeIterations = 3;       // 1M cases: a fixed count keeps the suite short
constexpr double kSmallMinSeconds = 0.2;  // smaller cases: repeat for at least this long

enum class Shape {
  random_tube,  // random_rows: purls, increases and decreases, width drifting around 1000
  ribbed_tube,  // ribbed_rows: k2p2 rib, exactly 1000 stitches a round
  st_helix,     // AutoKnit .st stitch graph: one yarn winding up a 1000-stitch tube
};
constexpr Shape kShapes[] = {Shape::random_tube, Shape::ribbed_tube, Shape::st_helix};

const char* shape_name(Shape shape) {
  switch (shape) {
    case Shape::random_tube:
      return "random_tube";
    case Shape::ribbed_tube:
      return "ribbed_tube";
    case Shape::st_helix:
      return "st_helix";
  }
  return "?";
}

std::string size_label(std::uint32_t stitches) {
  return stitches % 1'000'000 == 0 ? fmt::format("{}M", stitches / 1'000'000)
                                   : fmt::format("{}K", stitches / 1000);
}

// ------------------------------------------------------------------ generated inputs

// A cast-on round, `target / kRoundWidth - 2` rounds, a bind-off round.
RowPlan tube_plan(Shape shape, std::uint32_t target) {
  const std::uint32_t rounds = target / kRoundWidth - 2;
  if (shape == Shape::ribbed_tube) {
    using T = StitchType;
    return ribbed_rows(kRoundWidth, rounds, {T::k, T::k, T::p, T::p});
  }
  const RandomShaping shaping{.purl = 0.2,
                              .increase = 0.025,
                              .decrease = 0.02,
                              .min_width = kRoundWidth * 9 / 10,
                              .max_width = kRoundWidth * 11 / 10};
  return random_rows(kRoundWidth, rounds, shaping, /*seed=*/20261121);
}

// An AutoKnit stitch graph of a tube: `s` stitches for the first round, `e` for the last, `k`
// between, each taking the loop of the stitch one round earlier; one yarn id throughout, so
// the yarn is a single helix (docs/formats-st.md).
std::string helix_st(std::uint32_t stitches) {
  std::string text;
  text.reserve(std::size_t{stitches} * 48);
  const auto width = static_cast<std::int64_t>(kRoundWidth);
  const double radius = static_cast<double>(width) / (2 * std::numbers::pi);  // 1 per stitch
  for (std::int64_t s = 0; s < stitches; ++s) {
    const bool first_round = s < width, last_round = s + width >= stitches;
    const char type = first_round ? 's' : last_round ? 'e' : 'k';
    const double angle = static_cast<double>(s % width) / radius;
    fmt::format_to(std::back_inserter(text), "0 {} {} {} -1 {} -1 {:.4f} {:.4f} {:.4f}\n", type,
                   type == 'k' ? 'c' : 'a', first_round ? -1 : s - width,
                   last_round ? -1 : s + width, radius * std::cos(angle),
                   static_cast<double>(s) / width, radius * std::sin(angle));
  }
  return text;
}

// The content of the input file for a shape: a stitch mesh (.obj) or a stitch graph (.st).
std::string input_text(Shape shape, std::uint32_t target) {
  if (shape == Shape::st_helix) return helix_st(target);
  std::ostringstream out;
  write_stitch_mesh(build_from_rows(tube_plan(shape, target), Layout::tube), out);
  return std::move(out).str();
}

void write_file(const std::string& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out.flush()) throw std::runtime_error(fmt::format("cannot write '{}'", path));
}

// A fresh directory under the system's temp dir, removed with its files on destruction.
class TempDir {
 public:
  TempDir() {
    std::string name = (std::filesystem::temp_directory_path() / "skein-bench-XXXXXX").string();
    if (mkdtemp(name.data()) == nullptr)
      throw std::runtime_error(fmt::format("cannot create a directory like '{}'", name));
    path_ = name;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(std::string_view name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// ------------------------------------------------------------------ the fixture

// Everything the cases of one shape and size read, built before their timed loops: the input
// file (in a temp dir and in memory) and every stage's output, which is the next stage's input.
struct Workload {
  Shape shape = Shape::random_tube;
  std::uint32_t target = 0;    // requested stitches: with `shape`, the fixture's key
  std::uint32_t stitches = 0;  // actual stitches (random shaping drifts a little)
  TempDir dir;
  std::string path;          // the input file in `dir`
  std::string text;          // its content
  KnitGraph knit_from_mesh;  // build_knit_graph()'s output, before make_mismatches_knittable()
  Compilation compiled;
};

std::unique_ptr<Workload> make_workload(Shape shape, std::uint32_t target) {
  auto w = std::make_unique<Workload>();
  w->shape = shape;
  w->target = target;
  w->text = input_text(shape, target);
  w->path = w->dir.file(shape == Shape::st_helix ? "tube.st" : "tube.obj");
  write_file(w->path, w->text);
  w->compiled = compile_model(w->path);
  if (!w->compiled.knittability.knittable)
    throw std::logic_error(fmt::format("generated {} is not knittable", shape_name(shape)));
  w->stitches = w->compiled.knit.size();
  if (w->compiled.mesh) w->knit_from_mesh = build_knit_graph(*w->compiled.mesh, w->path);
  return w;
}

// Cases run in registration order, grouped by workload, so one workload is kept at a time:
// building the next frees the last (a 1M-stitch one holds several hundred MB).
const Workload& fixture(Shape shape, std::uint32_t target) {
  static std::unique_ptr<Workload> current;
  if (!current || current->shape != shape || current->target != target) {
    current.reset();
    current = make_workload(shape, target);
  }
  return *current;
}

// ------------------------------------------------------------------ stages

// The timed loop: runs `run` once per iteration and keeps its result from being optimised out.
// The result is destroyed inside the loop, as it would be in the CLI.
template <class Run>
void time_each(benchmark::State& state, Run run) {
  for (auto _ : state) {
    if constexpr (std::is_void_v<std::invoke_result_t<Run&>>) {
      run();
    } else {
      auto result = run();
      benchmark::DoNotOptimize(result);
    }
  }
}

bool is_st(const Workload& w) {
  return w.shape == Shape::st_helix;
}
const StitchMesh& mesh(const Workload& w) {
  return *w.compiled.mesh;
}

void bench_write(benchmark::State& state, const Workload& w) {
  const std::string path = w.dir.file("written.obj");
  time_each(state, [&] {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    write_stitch_mesh(mesh(w), out);
    return out.flush().good();
  });
}

void bench_parse(benchmark::State& state, const Workload& w) {
  if (is_st(w)) return time_each(state, [&] { return parse_autoknit_st(w.text, w.path); });
  time_each(state, [&] { return parse_stitch_mesh(w.text, w.path); });
}

void bench_read(benchmark::State& state, const Workload& w) {
  if (is_st(w)) return time_each(state, [&] { return read_autoknit_st(w.path); });
  time_each(state, [&] { return read_stitch_mesh(w.path); });
}

void bench_validate(benchmark::State& state, const Workload& w) {
  time_each(state, [&] { validate(mesh(w)); });
}

void bench_knit_graph(benchmark::State& state, const Workload& w) {
  time_each(state, [&] { return build_knit_graph(mesh(w), w.path); });
}

// The stage rewrites the graph in place, so each iteration starts from an untimed copy.
void bench_mismatches(benchmark::State& state, const Workload& w) {
  KnitGraph graph;
  for (auto _ : state) {
    state.PauseTiming();
    graph = w.knit_from_mesh;
    state.ResumeTiming();
    make_mismatches_knittable(graph);
  }
}

void bench_consistency(benchmark::State& state, const Workload& w) {
  time_each(state, [&] { check_consistency(w.compiled.knit); });
}

void bench_yarn_pieces(benchmark::State& state, const Workload& w) {
  time_each(state, [&] { return find_yarn_pieces(w.compiled.knit); });
}

void bench_dependency_graph(benchmark::State& state, const Workload& w) {
  time_each(state, [&] { return build_dependency_graph(w.compiled.knit); });
}

void bench_knittability(benchmark::State& state, const Workload& w) {
  time_each(state, [&] { return check_knittability(w.compiled.knit, w.compiled.deps); });
}

void bench_schedule(benchmark::State& state, const Workload& w) {
  const Compilation& c = w.compiled;
  time_each(state, [&] { return schedule_stitches(c.knit, c.deps, c.yarns); });
}

void bench_lowering(benchmark::State& state, const Workload& w) {
  const Compilation& c = w.compiled;
  time_each(state, [&] { return lower_to_program(c.knit, c.yarns, c.schedule); });
}

void bench_compile(benchmark::State& state, const Workload& w) {
  time_each(state, [&] { return compile_model(w.path); });
}

struct Stage {
  const char* name;
  void (*run)(benchmark::State&, const Workload&);
  bool mesh_only;   // needs a stitch mesh: skipped for .st stitch graphs
  bool file_bytes;  // reads or writes the input text: report its size
};

// In pipeline order; "compile" is compile_model(path), the file-to-schedule total.
constexpr Stage kStages[] = {
    {"write", bench_write, true, true},
    {"parse", bench_parse, false, true},
    {"read", bench_read, false, true},
    {"validate", bench_validate, true, false},
    {"knit_graph", bench_knit_graph, true, false},
    {"mismatches", bench_mismatches, true, false},
    {"consistency", bench_consistency, false, false},
    {"yarn_pieces", bench_yarn_pieces, false, false},
    {"dependency_graph", bench_dependency_graph, false, false},
    {"knittability", bench_knittability, false, false},
    {"schedule", bench_schedule, false, false},
    {"lowering", bench_lowering, false, false},
    {"compile", bench_compile, false, true},
};

// Stitches per second (items_per_second), time per stitch, and the file's size where it counts.
void report(benchmark::State& state, const Workload& w, const Stage& stage) {
  using benchmark::Counter;
  const auto stitches = static_cast<std::int64_t>(w.stitches);
  state.SetItemsProcessed(state.iterations() * stitches);
  state.counters["per_stitch"] =
      Counter(static_cast<double>(stitches), Counter::kIsIterationInvariantRate | Counter::kInvert);
  state.counters["stitches"] = static_cast<double>(stitches);
  if (!stage.file_bytes) return;
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(w.text.size()));
  state.counters["bytes_per_stitch"] = static_cast<double>(w.text.size()) / stitches;
}

void run_case(benchmark::State& state, const Stage* stage, Shape shape, std::uint32_t target) {
  const Workload& w = fixture(shape, target);
  stage->run(state, w);
  report(state, w, *stage);
}

void register_case(const Stage& stage, Shape shape, std::uint32_t target) {
  const std::string name =
      fmt::format("pipeline/{}/{}/{}", stage.name, shape_name(shape), size_label(target));
  auto* bench = benchmark::RegisterBenchmark(name.c_str(), run_case, &stage, shape, target);
  bench->Unit(benchmark::kMillisecond);
  if (target >= kLargeSize)
    bench->Iterations(kLargeIterations);
  else
    bench->MinTime(kSmallMinSeconds);
}

void register_all() {
  for (Shape shape : kShapes)
    for (std::uint32_t target : kSizes)
      for (const Stage& stage : kStages)
        if (!(stage.mesh_only && shape == Shape::st_helix)) register_case(stage, shape, target);
}

std::optional<std::string_view> flag_value(std::string_view arg, std::string_view flag) {
  if (!arg.starts_with(flag)) return std::nullopt;
  return arg.substr(flag.size());
}

// The N of `--stitches=N` after `--write=FILE` (1M when absent); nothing when malformed.
std::optional<std::uint32_t> requested_stitches(int argc, char** argv) {
  if (argc == 2) return kLargeSize;
  const std::optional<std::string_view> count =
      argc == 3 ? flag_value(argv[2], "--stitches=") : std::nullopt;
  if (!count) return std::nullopt;
  std::uint32_t stitches = 0;
  const char* end = count->data() + count->size();
  const auto [stop, error] = std::from_chars(count->data(), end, stitches);
  if (error != std::errc() || stop != end || stitches < kMinStitches) return std::nullopt;
  return stitches;
}

// `--write=FILE [--stitches=N]`: writes a case's input file and exits (FILE.st: the helix, any
// other name: the random tube), for measuring the CLI. Returns the exit code, or nothing when
// the arguments are Google Benchmark's.
std::optional<int> write_requested_input(int argc, char** argv) {
  const std::optional<std::string_view> path =
      argc > 1 ? flag_value(argv[1], "--write=") : std::nullopt;
  if (!path) return std::nullopt;
  const std::optional<std::uint32_t> stitches = requested_stitches(argc, argv);
  if (path->empty() || !stitches) {
    std::fprintf(stderr, "usage: %s --write=FILE [--stitches=N]  (N >= %u)\n", argv[0],
                 kMinStitches);
    return 2;
  }
  const Shape shape = path->ends_with(".st") ? Shape::st_helix : Shape::random_tube;
  write_file(std::string(*path), input_text(shape, *stitches));
  return 0;
}

}  // namespace
}  // namespace skein

int main(int argc, char** argv) {
  if (std::optional<int> exit_code = skein::write_requested_input(argc, argv)) return *exit_code;
  skein::register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
