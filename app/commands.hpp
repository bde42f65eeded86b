// The subcommands of `skein`: each takes the parsed command line and returns the exit code.
#pragma once

#include <string>
#include <vector>

#include "common/error.hpp"  // ExitCode
#include "driver/registry.hpp"
#include "yarn/build.hpp"
#include "yarn/picture.hpp"

namespace skein::cli {

// Everything the command line can say; each command reads the fields it has options for.
struct Request {
  std::string input;   // check, compile, generate, render: INPUT; verify: OUT
  std::string output;  // -o; "-" is standard output
  std::string target;  // -t
  std::string against;
  TargetOptions options;
  std::vector<std::string> settings;  // --set KEY=VALUE
  bool verify = false;
  bool force = false;  // replace an existing output file
  bool verbose = false;
  bool coarse = false;   // render: the labelled coarse mesh
  bool program = false;  // check: print and verify the live-loop program
  std::string shape;     // new: KIND
  std::string circumference, width, length;
  std::string yarn_picture;  // yarn: --picture PNG
  bool tube = false;         // yarn: a tube mesh instead of polylines
  bool yarn_check = false;   // yarn: report the topology and clearance checks
  YarnOptions yarn;
  PictureOptions view;
};

int run_check(const Request& r);
int run_compile(const Registry& registry, const Request& r);
int run_verify(const Registry& registry, const Request& r);
int run_new(const Request& r);
int run_generate(const Request& r);
int run_render(const Request& r);
int run_yarn(const Registry& registry, const Request& r);

}  // namespace skein::cli
