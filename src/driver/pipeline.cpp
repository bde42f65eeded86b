#include "driver/pipeline.hpp"

#include <fmt/format.h>

#include <array>
#include <map>
#include <type_traits>

#include "knitgraph/from_mesh.hpp"
#include "labeling/stitch_generation.hpp"
#include "mesh/autoknit_st.hpp"
#include "mesh/obj_format.hpp"
#include "transforms/corner_links.hpp"
#include "transforms/mismatches.hpp"
#include "transforms/shift_paths.hpp"

namespace skein {
namespace {

bool ends_with(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Runs one stage and reports its duration.
template <class F>
auto timed(const StageObserver& observe, const char* stage, F&& run) {
  auto start = std::chrono::steady_clock::now();
  if constexpr (std::is_void_v<decltype(run())>) {
    run();
    if (observe) observe(stage, std::chrono::steady_clock::now() - start);
  } else {
    auto result = run();
    if (observe) observe(stage, std::chrono::steady_clock::now() - start);
    return result;
  }
}

}  // namespace

Compilation compile_model(const std::string& input, const StageObserver& observe) {
  if (ends_with(input, ".st"))
    return compile_knit_graph(
        timed(observe, "read stitch graph", [&] { return read_autoknit_st(input); }), input,
        observe);
  if (is_project_file(input)) {
    Project project = read_project(input);
    Compilation c = compile_stitch_mesh(
        timed(observe, "label and generate", [&] { return build_project(project).mesh; }), input,
        observe);
    c.gauge = project.yarn_gauge();
    return c;
  }
  return compile_stitch_mesh(
      timed(observe, "read stitch mesh", [&] { return read_stitch_mesh(input); }), input, observe);
}

Compilation compile_stitch_mesh(StitchMesh mesh, const std::string& name,
                                const StageObserver& observe) {
  timed(observe, "validate", [&] { validate(mesh); });
  ShiftPathSummary paths = timed(observe, "shift-paths", [&] { return place_shift_paths(mesh); });
  KnitGraph graph = timed(observe, "knit graph", [&] { return build_knit_graph(mesh, name); });
  timed(observe, "mismatches", [&] { make_mismatches_knittable(graph); });
  Compilation c = compile_knit_graph(std::move(graph), name, observe);
  c.mesh = std::move(mesh);
  c.shift_paths = paths;
  return c;
}

Compilation compile_knit_graph(KnitGraph graph, const std::string& name,
                               const StageObserver& observe) {
  Compilation c;
  c.input = name;
  c.knit = std::move(graph);
  timed(observe, "corner links", [&] { correct_corner_links(c.knit); });
  timed(observe, "consistency", [&] { check_consistency(c.knit); });
  c.yarns = timed(observe, "yarn pieces", [&] { return find_yarn_pieces(c.knit); });
  c.deps = timed(observe, "dependency graph", [&] { return build_dependency_graph(c.knit); });
  c.knittability =
      timed(observe, "knittability", [&] { return check_knittability(c.knit, c.deps); });
  if (!c.knittability.knittable) return c;
  c.schedule =
      timed(observe, "schedule", [&] { return schedule_stitches(c.knit, c.deps, c.yarns); });
  c.program =
      timed(observe, "lowering", [&] { return lower_to_program(c.knit, c.yarns, c.schedule); });
  return c;
}

namespace {

std::string stitch_counts(const KnitGraph& g) {
  std::map<std::string_view, std::uint32_t> counts;
  for (StitchType t : g.type) ++counts[abbreviation(t)];
  std::string out;
  for (const auto& [name, n] : counts)
    out += fmt::format("{}{} {}", out.empty() ? "" : ", ", name, n);
  return out;
}

std::string row_counts(const KnitGraph& g) {
  std::array<std::uint32_t, 3> shapes{};
  for (RowShape s : g.row_shape) ++shapes[static_cast<int>(s)];
  return fmt::format("{} (closed {}, open {}, short {})", g.row_shape.size(),
                     shapes[static_cast<int>(RowShape::closed)],
                     shapes[static_cast<int>(RowShape::open)],
                     shapes[static_cast<int>(RowShape::short_row)]);
}

void append_yarn_pieces(const Compilation& c, std::string& out) {
  const YarnPieces& y = c.yarns;
  out += fmt::format("  yarn pieces: {}\n", y.size());
  constexpr std::uint32_t kListed = 20;
  for (std::uint32_t p = 0; p < y.size() && p < kListed; ++p)
    out += fmt::format(
        "    yarn {}: {} stitch{}, {} {}\n", p + 1, y.length[p], y.length[p] == 1 ? "" : "es",
        y.ring[p] ? "closes on itself at" : "starts at", c.knit.describe(y.first[p]));
  if (y.size() > kListed) out += fmt::format("    ... and {} more\n", y.size() - kListed);
}

void append_mismatch_groups(const KnitGraph& g, std::string& out) {
  out += fmt::format("  mismatch groups: {}\n", g.groups.size());
  for (std::uint32_t i = 0; i < g.groups.size(); ++i) {
    const MismatchGroup& grp = g.groups[i];
    std::string yarn;
    if (grp.kind == MismatchKind::join || grp.kind == MismatchKind::split)
      yarn = grp.yarn == MismatchYarnUse::extra
                 ? ", extra yarn"
                 : fmt::format(", yarn of row {}", g.row[grp.own_side] + 1);
    if (grp.kind == MismatchKind::expanding && grp.edges % 2 == 1) yarn = ", odd: one tied end";
    out += fmt::format("    group {}: {}, {} edge{} between rows {} and {}{}\n", i + 1,
                       mismatch_kind_name(grp.kind), grp.edges, grp.edges == 1 ? "" : "s",
                       grp.rows[0] + 1, grp.rows[1] + 1, yarn);
  }
}

}  // namespace

std::string check_report(const Compilation& c) {
  const KnitGraph& g = c.knit;
  std::string out =
      fmt::format("{}: {}\n", c.input, c.knittability.knittable ? "knittable" : "NOT knittable");
  out += fmt::format("  stitches: {} ({})\n", g.size(), stitch_counts(g));
  out += fmt::format("  rows: {}\n", row_counts(g));
  if (c.mesh)
    out += fmt::format(
        "  shift-paths: {} ({} placed by skein{})\n", c.shift_paths.paths, c.shift_paths.placed,
        c.shift_paths.reversed_rows
            ? fmt::format(", {} rounds turned by their shift option", c.shift_paths.reversed_rows)
            : "");
  append_yarn_pieces(c, out);
  append_mismatch_groups(g, out);
  if (c.knittability.knittable) {
    out +=
        fmt::format("  schedule: {} stitches, {} holds\n", c.schedule.stitches, c.schedule.holds);
    return out;
  }
  const auto& cycle = c.knittability.cycle;
  out += fmt::format("  dependency cycle ({} arrows):\n", cycle.size());
  constexpr std::size_t kEachEnd = 10;  // a long cycle shows its first and last arrows
  for (std::size_t i = 0; i < cycle.size(); ++i) {
    if (cycle.size() > 3 * kEachEnd && i == kEachEnd) {
      out += fmt::format("    ... {} more arrows ...\n", cycle.size() - 2 * kEachEnd);
      i = cycle.size() - kEachEnd;
    }
    out += fmt::format("    {}\n", describe(g, cycle[i]));
  }
  out += fmt::format("  how to fix: {}\n", c.knittability.hint);
  return out;
}

}  // namespace skein
