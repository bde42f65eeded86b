// skein: a knitting compiler. This file only parses the command line and calls the driver.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>

#include "builtin_targets.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "labeling/project.hpp"
#include "labeling/shapes.hpp"
#include "labeling/stitch_generation.hpp"
#include "render/svg.hpp"

namespace {

using namespace skein;

// Exit codes of `skein check` (and of every command on bad input).
constexpr int kKnittable = 0;
constexpr int kNotKnittable = 1;
constexpr int kBadInput = 2;

// The width of the widest name, so that the descriptions line up.
template <class Items>
std::size_t name_column(const Items& items) {
  std::size_t width = 0;
  for (const auto* item : items) width = std::max(width, item->name().size());
  return width;
}

std::string registry_listing(const Registry& registry) {
  std::string out = "\nTargets (--target):\n";
  const std::size_t targets = name_column(registry.targets());
  std::string listed, listed_by;  // the last settings listed, and whose they were
  for (const Target* t : registry.targets()) {
    out += fmt::format("  {:<{}} {}\n", t->name(), targets, t->description());
    std::string settings;
    for (const TargetSetting& s : t->settings())
      settings += fmt::format("    --set {}={}: {}\n", s.key, fmt::join(s.values, "|"), s.help);
    if (!settings.empty() && settings == listed) {
      out += fmt::format("    --set: as {}\n", listed_by);
      continue;
    }
    out += settings;
    listed = settings;
    listed_by = t->name();
  }
  out += "\nSimulators (skein verify, compile --verify):\n";
  const std::size_t simulators = name_column(registry.simulators());
  for (const Simulator* s : registry.simulators())
    out += fmt::format("  {:<{}} replays --target {}: {}\n", s->name(), simulators, s->target(),
                       s->description());
  out += R"(
Examples:
  skein check samples/hat/hat.obj
  skein compile samples/hat/hat.obj --target schedule -o hat.schedule
  skein compile samples/rib-swatch/rib-swatch.obj --target schedule -o swatch.schedule --verify
  skein verify hat.schedule --against samples/hat/hat.obj
  skein compile samples/hat/hat.obj --target hand -o hat.md --verify      # a printable pattern
  skein compile samples/hat/hat.obj -t knitout -m swg091n2 -o hat.k --verify
  skein verify hat.k -m kniterate --against samples/hat/hat.obj
  skein check samples/autoknit/test-B.st
  skein new sock --circumference 20cm --length 15cm -o mysock   # writes mysock.obj + mysock.yaml
  skein check mysock.yaml                   # a project: coarse mesh -> labeling -> stitch mesh
  skein render samples/sock/sock.yaml -o sock.svg   # short rows red, shift-path green

Exit codes: 0 success (knittable / proven), 1 not knittable or not proven, 2 bad input.
)";
  return out;
}

StageObserver progress_printer(bool verbose) {
  if (!verbose) return {};
  return [](const char* stage, std::chrono::duration<double> took) {
    std::cerr << fmt::format("skein: {:<18} {:8.1f} ms\n", stage, took.count() * 1000);
  };
}

const Target& find_target(const Registry& registry, const std::string& name) {
  if (const Target* t = registry.target(name)) return *t;
  std::string known;
  for (const Target* t : registry.targets()) known += (known.empty() ? "" : ", ") + t->name();
  throw UsageError(fmt::format("unknown target '{}'; known targets: {}", name, known));
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

int run_check(const std::string& input, bool verbose) {
  Compilation c = compile_model(input, progress_printer(verbose));
  std::cout << check_report(c);
  return c.knittability.knittable ? kKnittable : kNotKnittable;
}

int report_verification(const VerifyReport& report) {
  std::cout << report.summary << '\n';
  return report.proven ? kKnittable : kNotKnittable;
}

int run_compile(const Registry& registry, const std::string& input, const std::string& target_name,
                TargetOptions options, const std::vector<std::string>& settings,
                const std::string& output, bool verify, bool verbose) {
  const Target& target = find_target(registry, target_name);
  check_dialect(target, options.dialect);
  options.settings = settings_for(target, input, settings);
  if (options.machine.empty()) options.machine = project_target_option(input, "machine");
  Compilation c = compile_model(input, progress_printer(verbose));
  if (!c.knittability.knittable) {
    std::cerr << check_report(c) << fmt::format("skein: nothing written to {}\n", output);
    return kNotKnittable;
  }
  write_file_atomically(output, [&](std::ostream& out) { target.emit(c, options, out); });
  std::cout << fmt::format("wrote {} ({} target, {} stitches, {} yarn piece{})\n", output,
                           target.name(), c.knit.size(), c.yarns.size(),
                           c.yarns.size() == 1 ? "" : "s");
  if (!verify) return kKnittable;
  options.strict = true;  // skein's own output keeps to every rule
  const Simulator* simulator = registry.simulator_for(target.name());
  if (!simulator) throw UsageError(fmt::format("target '{}' has no simulator", target.name()));
  return report_verification(simulator->verify(read_file(output), output, &c, options));
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

int run_verify(const Registry& registry, const std::string& file, const std::string& against,
               const std::string& target_name, const TargetOptions& options, bool verbose) {
  const Target& target = target_of(registry, file, target_name);
  const Simulator* simulator = registry.simulator_for(target.name());
  if (!simulator) throw UsageError(fmt::format("target '{}' has no simulator", target.name()));
  std::string text = read_file(file);
  if (against.empty()) return report_verification(simulator->verify(text, file, nullptr, options));
  Compilation c = compile_model(against, progress_printer(verbose));
  return report_verification(simulator->verify(text, file, &c, options));
}

int run_new(const std::string& kind, const std::string& circumference, const std::string& width,
            const std::string& length, const std::string& output) {
  ShapeSize size;
  if (!circumference.empty()) size.circumference = parse_length_cm(circumference);
  if (!width.empty()) size.width = parse_length_cm(width);
  if (!length.empty()) size.length = parse_length_cm(length);
  std::string name = std::filesystem::path(output).filename().string();
  std::cout << fmt::format("wrote {}.obj and {}\n", output,
                           write_shape(make_shape(kind, size, name), output));
  return kKnittable;
}

}  // namespace

int main(int argc, char** argv) {
  Registry registry;
  register_builtin_targets(registry);

  CLI::App app{
      "skein: compiles knittable stitch meshes into knitting instructions and proves them"};
  app.footer(registry_listing(registry));
  app.require_subcommand(1);
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "print each stage and its time to stderr");

  std::string input, output, target_name, against, file;
  TargetOptions options;
  bool verify = false;

  auto* check =
      app.add_subcommand("check", "validate INPUT and report knittability, rows, yarn pieces");
  check->add_option("INPUT", input, "stitch mesh (.obj) or AutoKnit stitch graph (.st)")
      ->required();

  auto* compile = app.add_subcommand("compile", "compile INPUT for a target and write OUT");
  compile->add_option("INPUT", input, "stitch mesh (.obj) or AutoKnit stitch graph (.st)")
      ->required();
  compile->add_option("-t,--target", target_name, "back end (see the list below)")->required();
  compile->add_option("-o,--output", output, "file to write (never left half-written)")->required();
  compile->add_option("-m,--machine", options.machine, "machine profile name or path");
  compile->add_option("--dialect", options.dialect,
                      "how the target spells its output (hand: standard or knitspeak)");
  std::vector<std::string> settings;
  compile->add_option("--set", settings,
                      "KEY=VALUE: a target's setting (see the list below); repeatable");
  compile->add_flag("--verify", verify, "replay the output in the target's simulator");

  auto* verify_cmd = app.add_subcommand("verify", "replay OUT in its target's simulator");
  verify_cmd->add_option("OUT", file, "a file a target wrote")->required();
  verify_cmd->add_option("--against", against, "the input it must reproduce, stitch for stitch");
  verify_cmd->add_option("-t,--target", target_name,
                         "the target that wrote OUT (default: by extension)");
  verify_cmd->add_option("-m,--machine", options.machine,
                         "machine profile name or path (default: from the file's ;;Machine:)");
  verify_cmd->add_flag("--strict", options.strict,
                       "every rule an error, as for skein's own output (compile --verify)");
  verify_cmd->add_option("--picture", options.picture,
                         "an .svg to draw the fabric OUT makes in (knitout)");
  verify_cmd->add_option(
      "--fabric", options.fabric,
      "an AutoKnit stitch graph (.st) to write the fabric OUT makes in, "
      "for skein check (knitout; cast-on tucks, dropped loops and tags left out)");

  std::string shape_kind;
  std::string circumference, width, length;
  auto* new_cmd = app.add_subcommand("new", "write a parametric coarse mesh and its project file");
  new_cmd->add_option("KIND", shape_kind, "sheet, tube, hat, sock or sweater")->required();
  new_cmd->add_option("--circumference", circumference,
                      "tube, hat, sock or chest size (e.g. 40cm)");
  new_cmd->add_option("--width", width, "sheet width (e.g. 20cm)");
  new_cmd->add_option("--length", length, "length or height (e.g. 20cm)");
  new_cmd->add_option("-o,--output", output, "NAME: writes NAME.obj and NAME.yaml")->required();

  auto* generate =
      app.add_subcommand("generate", "label a project's coarse mesh and write its stitch mesh");
  generate->add_option("PROJECT", input, "project file (.yaml)")->required();
  generate->add_option("-o,--output", output, "the stitch mesh (.obj) to write")->required();

  bool coarse = false;
  auto* render = app.add_subcommand("render", "draw INPUT as an SVG picture");
  render->add_option("INPUT", input, "stitch mesh (.obj), project (.yaml) or coarse mesh (.obj)")
      ->required();
  render->add_option("-o,--output", output, "the .svg file to write")->required();
  render->add_flag("--coarse", coarse, "for a project: draw the labelled coarse mesh");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : kBadInput;
  }

  try {
    if (*check) return run_check(input, verbose);
    if (*new_cmd) return run_new(shape_kind, circumference, width, length, output);
    if (*render) return render_file(input, output, coarse), kKnittable;
    if (*generate) return write_generated_stitch_mesh(input, output), kKnittable;
    if (*compile)
      return run_compile(registry, input, target_name, options, settings, output, verify, verbose);
    return run_verify(registry, file, against, target_name, options, verbose);
  } catch (const Error& e) {
    std::cerr << "skein: error: " << e.what() << '\n';
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "skein: " << e.what() << '\n';
    return 3;
  }
}
