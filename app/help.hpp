// The text of `skein --help` and of each `skein COMMAND --help` below the options.
#pragma once

#include <string>

#include "driver/registry.hpp"

namespace skein::cli {

// `skein --help`: the registered targets with their settings, the simulators, a few examples
// and the exit codes.
std::string overview_footer(const Registry& registry);

// `skein COMMAND --help`: that command's examples and exit codes; compile and verify name the
// targets (without their descriptions, which `skein --help` gives).
std::string command_footer(const Registry& registry, const std::string& command);

}  // namespace skein::cli
