#include "commands.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/output_file.hpp"
#include "driver/pipeline.hpp"
#include "labeling/coarse_mesh.hpp"
#include "labeling/project.hpp"
#include "labeling/shapes.hpp"
#include "labeling/stitch_generation.hpp"
#include "mesh/autoknit_st.hpp"
#include "mesh/obj_format.hpp"
#include "render/svg.hpp"
#include "yarn/checks.hpp"
#include "yarn/export.hpp"

namespace skein::cli {
namespace {

StageObserver progress_printer(bool verbose) {
  if (!verbose) return {};
  return [](const char* stage, std::chrono::duration<double> took) {
    std::cerr << fmt::format("skein: {:<18} {:8.1f} ms\n", stage, took.count() * 1000);
  };
}

// Where a command reports: standard output, unless its output goes there.
std::ostream& report_stream(const OutputFile& out) {
  return out.is_standard_output() ? std::cerr : std::cout;
}

// The files a command reads besides INPUT's own: a project's coarse mesh, a machine profile
// named by path. An output may replace none of them.
std::vector<std::string> inputs_of(const std::string& input, const std::string& machine = "") {
  std::vector<std::string> inputs{input};
  if (is_project_file(input)) inputs.push_back(read_project(input).mesh);
  std::error_code ec;
  if (!machine.empty() && std::filesystem::exists(machine, ec)) inputs.push_back(machine);
  return inputs;
}

const Target& find_target(const Registry& registry, const std::string& name) {
  if (const Target* t = registry.target(name)) return *t;
  std::string known;
  for (const Target* t : registry.targets()) known += (known.empty() ? "" : ", ") + t->name();
  throw UsageError(fmt::format("unknown target '{}'; known targets: {}", name, known));
}

const Simulator& simulator_for(const Registry& registry, const Target& target) {
  if (const Simulator* s = registry.simulator_for(target.name())) return *s;
  throw UsageError(fmt::format("target '{}' has no simulator", target.name()));
}

void check_dialect(const Target& target, const std::string& dialect) {
  if (dialect.empty()) return;
  std::vector<std::string> valid = target.dialects();
  if (std::find(valid.begin(), valid.end(), dialect) != valid.end()) return;
  if (valid.empty())
    throw UsageError(fmt::format("target '{}' has no dialects; drop --dialect", target.name()));
  throw UsageError(fmt::format("unknown dialect '{}' for target '{}'; valid dialects: {}", dialect,
                               target.name(), fmt::join(valid, ", ")));
}

void check_setting_value(const TargetSetting& s, const std::string& value,
                         const std::string& where) {
  if (std::find(s.values.begin(), s.values.end(), value) == s.values.end())
    throw UsageError(fmt::format("{} {}: expected {}, found '{}'", where, s.key,
                                 fmt::join(s.values, " or "), value));
}

// `--set KEY=VALUE` pairs, checked against what the target offers, over the project file's
// `target:` keys that the target knows (the others are for other targets).
std::map<std::string, std::string> settings_for(const Target& target, const std::string& input,
                                                const std::vector<std::string>& given) {
  std::vector<TargetSetting> known = target.settings();
  std::map<std::string, std::string> settings;
  std::map<std::string, std::string> project =
      is_project_file(input) ? read_project(input).target : std::map<std::string, std::string>{};
  for (const TargetSetting& s : known) {
    auto value = project.find(s.key);
    if (value == project.end()) continue;
    check_setting_value(s, value->second, input + ": target:");
    settings[s.key] = value->second;
  }
  for (const std::string& pair : given) {
    std::size_t eq = pair.find('=');
    std::string key = pair.substr(0, eq);
    auto s = std::find_if(known.begin(), known.end(), [&](const auto& k) { return k.key == key; });
    if (s == known.end()) {
      std::vector<std::string> keys;
      for (const TargetSetting& k : known) keys.push_back(k.key);
      throw UsageError(fmt::format(
          "target '{}' has no setting '{}'; {}", target.name(), key,
          keys.empty() ? "it has none" : fmt::format("its settings: {}", fmt::join(keys, ", "))));
    }
    std::string value = eq == std::string::npos ? "" : pair.substr(eq + 1);
    check_setting_value(*s, value, "--set");
    settings[key] = value;
  }
  return settings;
}

// Proven against the model, or (without one) replayed as written: done.
int report_verification(const VerifyReport& report, std::ostream& out) {
  out << report.summary << '\n';
  return report.proven || report.valid ? kDone : kNotKnittable;
}

// The model to compile or prove against; prints why not and returns false when it is not
// knittable.
bool knittable(const Compilation& c, const std::string& nothing_done) {
  if (c.knittability.knittable) return true;
  std::cerr << check_report(c) << fmt::format("skein: {}\n", nothing_done);
  return false;
}

// The target whose output `file` is: --target if given, else the one whose extension it has.
const Target& target_of(const Registry& registry, const std::string& file,
                        const std::string& given) {
  if (!given.empty()) return find_target(registry, given);
  std::string extension = std::filesystem::path(file).extension().string();
  for (const Target* t : registry.targets())
    for (const std::string& known : t->extensions())
      if (known == extension) return *t;
  throw UsageError(fmt::format("cannot tell which target wrote {}; pass --target", file));
}

// `new -o NAME`, `-o NAME.yaml` (or .yml) and `-o NAME.obj` all mean the project NAME.yaml
// beside the coarse mesh NAME.obj: {project, mesh}.
std::pair<std::filesystem::path, std::filesystem::path> new_project_paths(const std::string& o) {
  if (o == "-")
    throw UsageError("skein new writes two files (NAME.obj and NAME.yaml): -o - cannot hold them");
  std::filesystem::path given(o), stem = given;
  std::string extension = given.extension().string();
  bool project_given = extension == ".yaml" || extension == ".yml";
  if (project_given || extension == ".obj") stem.replace_extension();
  if (stem.filename().empty() || stem.filename() == "." || stem.filename() == "..")
    throw UsageError(
        fmt::format("-o {}: expected a project NAME (writes NAME.obj and NAME.yaml)", o));
  std::filesystem::path mesh = stem;
  mesh += ".obj";
  std::filesystem::path project = stem;
  project += ".yaml";
  return {project_given ? given : project, mesh};
}

}  // namespace

int run_check(const Request& r) {
  Compilation c = compile_model(r.input, progress_printer(r.verbose));
  std::cout << check_report(c);
  if (r.program && c.knittability.knittable) {
    std::cout << program_text(c.knit, c.program) << std::flush;
    verify_program(c.knit, c.program);
  }
  return c.knittability.knittable ? kDone : kNotKnittable;
}

int run_compile(const Registry& registry, const Request& r) {
  const Target& target = find_target(registry, r.target);
  check_dialect(target, r.options.dialect);
  TargetOptions options = r.options;
  options.settings = settings_for(target, r.input, r.settings);
  if (options.machine.empty()) options.machine = project_target_option(r.input, "machine");
  // A simulator proves the output before it is written: an unproven output is never left behind.
  const Simulator* simulator = r.verify ? registry.simulator_for(target.name()) : nullptr;
  OutputFile out(r.output, {r.force, inputs_of(r.input, options.machine)});
  Compilation c = compile_model(r.input, progress_printer(r.verbose));
  if (!knittable(c, fmt::format("nothing written to {}", out.name()))) return kNotKnittable;
  std::ostringstream text;
  target.emit(c, options, text);
  std::optional<VerifyReport> proof;
  options.strict = true;  // skein's own output keeps to every rule
  if (simulator) proof = simulator->verify(text.str(), out.name(), &c, options);
  if (proof && !proof->proven) {
    std::cerr << proof->summary << '\n'
              << fmt::format("skein: not proven; nothing written to {} (--no-verify writes it)\n",
                             out.name());
    return kNotKnittable;
  }
  out.write_text(text.str());
  std::ostream& report = report_stream(out);
  report << fmt::format("wrote {} ({} target, {} stitches, {} yarn piece{})\n", out.name(),
                        target.name(), c.knit.size(), c.yarns.size(),
                        c.yarns.size() == 1 ? "" : "s");
  return proof ? report_verification(*proof, report) : kDone;
}

int run_verify(const Registry& registry, const Request& r) {
  const Target& target = target_of(registry, r.input, r.target);
  const Simulator& simulator = simulator_for(registry, target);
  std::vector<std::string> inputs = inputs_of(r.input, r.options.machine);
  if (!r.against.empty())
    for (std::string& against : inputs_of(r.against)) inputs.push_back(std::move(against));
  for (const std::string& drawn : {r.options.picture, r.options.fabric})
    if (!drawn.empty()) OutputFile(drawn, {r.force, inputs});  // refused now, before the replay
  std::string text = read_file(r.input);
  if (r.against.empty())
    return report_verification(simulator.verify(text, r.input, nullptr, r.options), std::cout);
  Compilation c = compile_model(r.against, progress_printer(r.verbose));
  if (!knittable(c, fmt::format("{} cannot be proven against it", r.input))) return kNotKnittable;
  return report_verification(simulator.verify(text, r.input, &c, r.options), std::cout);
}

int run_new(const Request& r) {
  ShapeSize size;
  if (!r.circumference.empty()) size.circumference = parse_length_cm(r.circumference);
  if (!r.width.empty()) size.width = parse_length_cm(r.width);
  if (!r.length.empty()) size.length = parse_length_cm(r.length);
  auto [project_path, mesh_path] = new_project_paths(r.output);
  // Both checked before either is written: an edited project is never half replaced.
  OutputFile project(project_path.string(), {r.force, {}}), mesh(mesh_path.string(), {r.force, {}});
  Shape shape = make_shape(r.shape, size, mesh_path.stem().string());
  mesh.write([&](std::ostream& out) { write_coarse_mesh(shape.mesh, out); });
  project.write_text(shape.project);
  std::cout << fmt::format("wrote {} and {}\n", mesh.name(), project.name());
  return kDone;
}

int run_generate(const Request& r) {
  OutputFile out(r.output, {r.force, inputs_of(r.input)});
  GeneratedStitchMesh g = build_project(read_project(r.input));
  out.write([&](std::ostream& o) { write_stitch_mesh(g.mesh, o); });
  report_stream(out) << fmt::format("wrote {} (the stitch mesh of {}, {} stitches)\n", out.name(),
                                    r.input, g.mesh.num_faces());
  return kDone;
}

int run_render(const Request& r) {
  OutputFile out(r.output, {r.force, inputs_of(r.input)});
  std::string drawn;
  out.write([&](std::ostream& o) { drawn = render_file(r.input, r.coarse, o); });
  report_stream(out) << fmt::format("wrote {} ({})\n", out.name(), drawn);
  return kDone;
}

// What `skein yarn` lays yarn along: a model (its stitch mesh, or a stitch graph's `positions`),
// or the fabric a target's output makes, as its simulator rebuilds it (a stitch graph).
Compilation yarn_input(const Registry& registry, const Request& r,
                       std::vector<std::array<double, 3>>& positions) {
  std::string extension = std::filesystem::path(r.input).extension().string();
  if (extension == ".st") {  // read once, with the stitches' positions
    KnitGraph graph = parse_autoknit_st(read_file(r.input), r.input, &positions);
    return compile_knit_graph(std::move(graph), r.input, progress_printer(r.verbose));
  }
  if (extension == ".obj" || extension == ".yaml" || extension == ".yml")
    return compile_model(r.input, progress_printer(r.verbose));
  const Target& target = target_of(registry, r.input, r.target);
  std::optional<std::string> fabric =
      simulator_for(registry, target).fabric_stitch_graph(read_file(r.input), r.input, r.options);
  if (!fabric)
    throw UnsupportedError(fmt::format(
        "skein yarn: the {} simulator does not rebuild the fabric of {}", target.name(), r.input));
  std::string name = r.input + " (its fabric)";
  KnitGraph graph = parse_autoknit_st(*fabric, name, &positions);
  return compile_knit_graph(std::move(graph), name, progress_printer(r.verbose));
}

namespace {

// The yarn's checks (docs/yarn.md): loops held by the stitches the knit graph says, and yarns
// closer than the tests allow (0.9 diameters).
void report_yarn_checks(const KnitGraph& graph, const YarnModel& model, std::ostream& report) {
  constexpr float kAllowed = 0.9f;
  TopologyReport t = check_yarn_topology(graph, model);
  Clearance clear = yarn_clearance(model, kAllowed);
  std::string picked_up =
      t.picked_up ? fmt::format(" ({} more picked up through a side: not checked)", t.picked_up)
                  : "";
  report << fmt::format("checks: {} loops{}, {} not held, {} held wrongly{}{}\n", t.loops,
                        picked_up, t.not_held, t.wrongly_held,
                        t.first_problem.empty() ? "" : " (first: ",
                        t.first_problem.empty() ? "" : t.first_problem + ")");
  report << fmt::format(
      "checks: {} segment pairs closer than {} diameters (closest {:.2f} d; {} pairs within one)\n",
      clear.closer, kAllowed, clear.closest, clear.checked);
}

}  // namespace

// `skein yarn`: the yarn-level model of INPUT, written as OBJ/PLY polylines or tubes and drawn.
int run_yarn(const Registry& registry, const Request& r) {
  if (r.output.empty() && r.yarn_picture.empty())
    throw UsageError("skein yarn: give -o MODEL (.obj or .ply), --picture PNG, or both");
  std::optional<OutputFile> model, picture;
  if (!r.output.empty()) model.emplace(r.output, OutputRules{r.force, inputs_of(r.input)});
  if (!r.yarn_picture.empty())
    picture.emplace(r.yarn_picture, OutputRules{r.force, inputs_of(r.input)});
  std::vector<std::array<double, 3>> positions;
  Compilation c = yarn_input(registry, r, positions);
  YarnOptions options = r.yarn;
  options.relax_yarn = options.relax.max_steps > 0;
  options.relax.progress = [](const RelaxProgress& p) {
    std::cerr << fmt::format(
        "skein: yarn relaxation step {}: largest move {:.3f} r, overlap {:.3f} d\n", p.step,
        p.max_move, p.overlap);
  };
  YarnBuild yarn = build_yarn(c.knit, c.yarns, c.mesh ? &*c.mesh : nullptr, positions, options);
  const RelaxReport& relaxed = yarn.relaxation;
  std::ostream& report = model ? report_stream(*model) : std::cout;
  report << fmt::format("yarn: {} stitches, {} yarn piece{}, {} points, yarn radius {:.4g}\n",
                        c.knit.size(), yarn.model.pieces(), yarn.model.pieces() == 1 ? "" : "s",
                        yarn.model.point.size(), yarn.model.radius);
  if (relaxed.steps > 0)
    report << fmt::format(
        "relaxed: {} steps in {:.2f} s, {} (largest move {:.4f} r, overlap {:.3f} d; contact "
        "pairs found {} times)\n",
        relaxed.steps, relaxed.seconds, relaxed.converged ? "converged" : "step limit",
        relaxed.max_move, relaxed.overlap, relaxed.pair_builds);
  if (r.yarn_check) report_yarn_checks(c.knit, yarn.model, report);
  if (model) {
    bool ply = std::filesystem::path(r.output).extension() == ".ply";
    model->write([&](std::ostream& out) {
      if (ply) return write_yarn_ply(yarn.model, out);
      if (r.tube) return write_yarn_tubes_obj(yarn.model, out);
      write_yarn_obj(yarn.model, out);
    });
    report << fmt::format("wrote {}\n", model->name());
  }
  if (picture) {
    PictureOptions view = r.view;
    view.height = view.width;
    picture->write([&](std::ostream& out) { write_yarn_png(yarn.model, out, view); });
    report << fmt::format("wrote {}\n", picture->name());
  }
  return kDone;
}

}  // namespace skein::cli
