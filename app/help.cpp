#include "help.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>

namespace skein::cli {
namespace {

constexpr const char* kExitCodes =
    "Exit codes: 0 done (knittable, written, proven; verify without --against: replays as\n"
    "written); 1 not knittable or not proven; 2 bad input or usage; 3 valid input that the\n"
    "target cannot do (yet, or on this machine); 4 internal error.\n";

// Each command's examples; the overview shows the first of a few.
const std::map<std::string, std::string>& examples() {
  static const std::map<std::string, std::string> kExamples{
      {"check",
       R"(  skein check samples/hat/hat.obj                 # knittable? rows, yarn pieces, counts
  skein check samples/sweater/sweater.yaml        # a project: coarse mesh -> stitch mesh
  skein check samples/autoknit/test-B.st          # an AutoKnit stitch graph
)"},
      {"compile",
       R"(  skein compile samples/hat/hat.obj -t hand -o hat.md   # a pattern, proven before it is written
  skein compile samples/hat/hat.obj -t knitout -m swg091n2 -o hat.k
  skein compile samples/sock/sock.yaml -t hand --set rounds=inside-out -o sock.md
  skein compile samples/hat/hat.obj -t schedule -o -              # to standard output
  skein compile samples/hat/hat.obj -t hand -o hat.md --force     # replace hat.md
)"},
      {"verify", R"(  skein verify hat.k -m swg091n2 --against samples/hat/hat.obj
  skein verify hat.md --against samples/hat/hat.obj
  skein verify hat.schedule                       # well formed? (no proof without --against)
)"},
      {"new",
       R"(  skein new sock --circumference 20cm --length 15cm -o mysock   # mysock.obj + mysock.yaml
  skein new hat --circumference 54cm -o hats/hat.yaml  # hats/hat.yaml + hats/hat.obj
  skein new sheet --width 20cm --length 10cm -o swatch --force  # replace an older swatch
)"},
      {"generate", R"(  skein generate samples/beanie/beanie.yaml -o beanie.obj
  skein generate samples/sock/sock.yaml -o - | head   # to standard output
)"},
      {"render", R"(  skein render samples/sock/sock.yaml -o sock.svg            # short rows red
  skein render samples/sock/sock.yaml --coarse -o coarse.svg  # the labelled coarse mesh
  skein render samples/hat/hat.obj -o hat.svg                 # a stitch mesh
)"},
      {"yarn", R"(  skein yarn samples/hat/hat.obj --picture hat-yarn.png   # relaxed yarn, drawn
  skein yarn samples/hat/hat.obj -o hat-yarn.obj --tube       # a tube mesh for a renderer
  skein yarn samples/autoknit/test-A.st -o a.ply --steps 0    # the templates' yarn, unrelaxed
  skein yarn swatch.k --picture swatch-yarn.png               # the fabric a knitout file makes
)"},
  };
  return kExamples;
}

// The width of the widest name, so that the descriptions line up.
template <class Items>
std::size_t name_column(const Items& items) {
  std::size_t width = 0;
  for (const auto* item : items) width = std::max(width, item->name().size());
  return width;
}

std::string target_listing(const Registry& registry) {
  std::string out = "Targets (--target):\n";
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
  out += "\nSimulators (skein verify; compile proves with them unless --no-verify):\n";
  const std::size_t simulators = name_column(registry.simulators());
  for (const Simulator* s : registry.simulators())
    out += fmt::format("  {:<{}} replays --target {}: {}\n", s->name(), simulators, s->target(),
                       s->description());
  return out;
}

std::string target_names(const Registry& registry) {
  std::vector<std::string> names;
  for (const Target* t : registry.targets()) names.push_back(t->name());
  return fmt::format("Targets: {} (skein --help describes each and its --set settings).\n\n",
                     fmt::join(names, ", "));
}

}  // namespace

std::string overview_footer(const Registry& registry) {
  std::string first_examples;
  for (const char* command : {"check", "compile", "verify", "new", "render"}) {
    const std::string& text = examples().at(command);
    first_examples += text.substr(0, text.find('\n') + 1);
  }
  return fmt::format(
      "\n{}\nExamples:\n{}Run 'skein COMMAND --help' for a command's options and more "
      "examples.\n\n{}",
      target_listing(registry), first_examples, kExitCodes);
}

std::string command_footer(const Registry& registry, const std::string& command) {
  bool names_targets = command == "compile" || command == "verify";
  return fmt::format("\n{}Examples:\n{}\n{}", names_targets ? target_names(registry) : "",
                     examples().at(command), kExitCodes);
}

}  // namespace skein::cli
