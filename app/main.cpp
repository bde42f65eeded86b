// skein: a knitting compiler. This file parses the command line, runs one command
// (commands.cpp) and turns whatever it throws into a message and an exit code.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <functional>
#include <iostream>

#include "builtin_targets.hpp"
#include "commands.hpp"
#include "common/error.hpp"
#include "help.hpp"
#include "labeling/shapes.hpp"

namespace {

using namespace skein;
using namespace skein::cli;

// Runs `command`; an exception becomes a message on stderr and its exit code.
int run_reporting_errors(const std::string& doing, const std::function<int()>& command) {
  try {
    return command();
  } catch (...) {
    Failure failure = describe_current_exception(doing);
    std::cerr << "skein: " << failure.message << '\n';
    return failure.exit_code;
  }
}

CLI::Option* add_output(CLI::App& command, Request& r, const std::string& what) {
  return command.add_option("-o,--output", r.output, what + "; - for standard output")->required();
}

void add_force(CLI::App& command, Request& r) {
  command.add_flag("--force", r.force,
                   "replace an existing output file (never an input, folder or device)");
}

// A million-stitch model takes hundreds of MB in a few large arrays; on 4 KB pages much of
// the time goes to page faults and TLB misses (a 1M-stitch tube through `compile -t hand`:
// 1.56 s user + 0.80 s system, against 0.60 + 0.46 with huge pages, on an idle 2-core VM).
// glibc's malloc asks for transparent huge pages only when its tunable is set before the
// process starts, so skein sets it and starts itself again, once; a tunable the user set
// wins.
void restart_with_huge_pages(char** argv) {
  if (std::getenv("GLIBC_TUNABLES") != nullptr) return;
  if (setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 0) != 0) return;
  execv("/proc/self/exe", argv);  // returns only on failure: go on as we are
}

}  // namespace

int main(int argc, char** argv) {
  restart_with_huge_pages(argv);
  Registry registry;
  register_builtin_targets(registry);

  CLI::App app{
      "skein: compiles knittable stitch meshes into knitting instructions and proves them"};
  app.require_subcommand(1);
  Request r;
  app.add_flag("-v,--verbose", r.verbose, "print each stage and its time to stderr");

  auto* check =
      app.add_subcommand("check", "validate INPUT and report knittability, rows, yarn pieces");
  check->add_option("INPUT", r.input, "stitch mesh (.obj), project (.yaml) or AutoKnit .st")
      ->required();
  check->add_flag("--program", r.program, "verify and print the live-loop program, a step a line");

  auto* compile = app.add_subcommand("compile", "compile INPUT for a target and write OUT");
  compile->add_option("INPUT", r.input, "stitch mesh (.obj), project (.yaml) or AutoKnit .st")
      ->required();
  compile->add_option("-t,--target", r.target, "back end (listed below)")->required();
  add_output(*compile, r, "file to write (never left half-written)");
  add_force(*compile, r);
  compile->add_option("-m,--machine", r.options.machine, "machine profile name or path");
  compile->add_option("--dialect", r.options.dialect,
                      "how the target spells its output (hand: standard or knitspeak)");
  compile->add_option("--set", r.settings,
                      "KEY=VALUE: a target's setting (skein --help lists them); repeatable");
  bool no_verify = false;
  compile->add_flag("--no-verify", no_verify,
                    "write without replaying the output in the target's simulator first");
  compile->add_flag("--verify")
      ->description("kept for old scripts: compile proves its output by default");

  auto* verify = app.add_subcommand("verify", "replay OUT in its target's simulator");
  verify->add_option("OUT", r.input, "a file a target wrote")->required();
  verify->add_option("--against", r.against, "the input it must reproduce, stitch for stitch");
  verify->add_option("-t,--target", r.target, "the target that wrote OUT (default: by extension)");
  verify->add_option("-m,--machine", r.options.machine,
                     "machine profile name or path (default: from the file's ;;Machine:)");
  verify->add_flag("--strict", r.options.strict,
                   "every rule an error, as for skein's own output (compile)");
  verify->add_option("--picture", r.options.picture,
                     "an .svg to draw the fabric OUT makes in (knitout)");
  verify->add_option("--fabric", r.options.fabric,
                     "a stitch mesh (.obj) or AutoKnit stitch graph (.st) to write the fabric OUT "
                     "makes in, for skein check (knitout; cast-on tucks, dropped loops and tags "
                     "left out; .obj: whole rows or rounds of one yarn only)");
  add_force(*verify, r);

  auto* new_cmd = app.add_subcommand("new", "write a parametric coarse mesh and its project file");
  new_cmd->add_option("KIND", r.shape, fmt::format("{}", fmt::join(shape_kinds(), ", ")))
      ->required();
  new_cmd->add_option("--circumference", r.circumference,
                      "tube, hat, sock, mitten or hip size, chest (e.g. 40cm)");
  new_cmd->add_option("--width", r.width, "sheet width (e.g. 20cm)");
  new_cmd->add_option("--length", r.length, "length or height (e.g. 20cm)");
  new_cmd
      ->add_option("-o,--output", r.output,
                   "NAME or NAME.yaml: writes the project NAME.yaml and its mesh NAME.obj")
      ->required();
  add_force(*new_cmd, r);

  auto* generate =
      app.add_subcommand("generate", "label a project's coarse mesh and write its stitch mesh");
  generate->add_option("PROJECT", r.input, "project file (.yaml)")->required();
  add_output(*generate, r, "the stitch mesh (.obj) to write");
  add_force(*generate, r);

  auto* render = app.add_subcommand("render", "draw INPUT as an SVG picture");
  render->add_option("INPUT", r.input, "stitch mesh (.obj), project (.yaml) or coarse mesh (.obj)")
      ->required();
  add_output(*render, r, "the .svg file to write");
  add_force(*render, r);
  render->add_flag("--coarse", r.coarse, "for a project: draw the labelled coarse mesh");

  auto* yarn = app.add_subcommand("yarn", "lay yarn along INPUT's stitches, relax it, export it");
  yarn->add_option("INPUT", r.input,
                   "stitch mesh (.obj), project (.yaml), stitch graph (.st), or a target's output "
                   "(.k): the fabric its simulator rebuilds")
      ->required();
  yarn->add_option("-m,--machine", r.options.machine,
                   "for knitout: machine profile name or path (default: from ;;Machine:)");
  yarn->add_option("-o,--output", r.output, "yarn polylines (.obj or .ply); - for standard output");
  yarn->add_flag("--tube", r.tube, "write a tube mesh instead of polylines (.obj)");
  yarn->add_option("--picture", r.yarn_picture, "draw the yarn into this .png");
  yarn->add_flag("--check", r.yarn_check,
                 "report loops not held or held wrongly and yarns closer than 0.9 diameters");
  add_force(*yarn, r);
  yarn->add_option("--steps", r.yarn.relax.max_steps,
                   "relaxation step limit (0: the templates' yarn, unrelaxed)");
  yarn->add_option("--tolerance", r.yarn.relax.tolerance,
                   "stop when no point moves more than this many yarn radii in a step");
  yarn->add_option("--threads", r.yarn.relax.threads, "threads (default: all)");
  yarn->add_option("--azimuth", r.view.azimuth, "picture: degrees round the y axis");
  yarn->add_option("--elevation", r.view.elevation, "picture: degrees above");
  yarn->add_option("--size", r.view.width, "picture: width and height in pixels");

  for (CLI::App* command : app.get_subcommands({}))
    command->footer(command_footer(registry, command->get_name()));
  app.footer(overview_footer(registry));  // after the subcommands, which would inherit it

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kDone : kBadInput;
  }

  if (*check) return run_reporting_errors("checking " + r.input, [&] { return run_check(r); });
  r.verify = !no_verify;
  if (*compile)
    return run_reporting_errors(fmt::format("compiling {} for the {} target", r.input, r.target),
                                [&] { return run_compile(registry, r); });
  if (*verify)
    return run_reporting_errors("verifying " + r.input, [&] { return run_verify(registry, r); });
  if (*new_cmd)
    return run_reporting_errors(fmt::format("writing a new {} project", r.shape),
                                [&] { return run_new(r); });
  if (*generate)
    return run_reporting_errors("generating the stitch mesh of " + r.input,
                                [&] { return run_generate(r); });
  if (*yarn)
    return run_reporting_errors("laying yarn along " + r.input,
                                [&] { return run_yarn(registry, r); });
  return run_reporting_errors("rendering " + r.input, [&] { return run_render(r); });
}
