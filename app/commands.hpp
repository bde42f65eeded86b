// The subcommands of `skein`: each takes the parsed command line and returns the exit code.
#pragma once

#include <string>
#include <vector>

#include "driver/registry.hpp"

namespace skein::cli {

// Exit codes, the same for every command.
enum ExitCode : int {
  kDone = 0,          // knittable, written, proven
  kNotKnittable = 1,  // valid input that is not knittable, or a file that does not prove
  kBadInput = 2,      // bad input or usage (the message names the file, line, face or edge)
  kUnsupported = 3,   // valid input that this target cannot do (yet, or on this machine)
  kInternal = 4,      // a bug in skein, or no memory left
};

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
  bool coarse = false;  // render: the labelled coarse mesh
  std::string shape;    // new: KIND
  std::string circumference, width, length;
};

int run_check(const Request& r);
int run_compile(const Registry& registry, const Request& r);
int run_verify(const Registry& registry, const Request& r);
int run_new(const Request& r);
int run_generate(const Request& r);
int run_render(const Request& r);

}  // namespace skein::cli
