#include "knitout/knitout_target.hpp"

#include <fmt/format.h>

#include <optional>
#include <sstream>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "knitout/emit.hpp"
#include "knitout/fabric_picture.hpp"
#include "knitout/fabric_report.hpp"
#include "knitout/fabric_stitch_graph.hpp"
#include "knitout/fabric_stitch_mesh.hpp"
#include "knitout/machine_profile.hpp"
#include "knitout/vbed_simulator.hpp"
#include "knitout/whole_file_proof.hpp"

namespace skein {
namespace {

class KnitoutTarget : public Target {
 public:
  std::string name() const override { return "knitout"; }
  std::string description() const override {
    return "knitout for v-bed knitting machines (--machine swg091n2, kniterate, generic or a "
           "profile .yaml): sheets and tubes with shaping and short rows, one yarn piece after "
           "another, cast-on to bind-off";
  }
  std::string default_extension() const override { return ".k"; }
  std::vector<std::string> extensions() const override { return {".k", ".knitout"}; }
  void emit(const Compilation& c, const TargetOptions& options, std::ostream& out) const override {
    knitout::emit_knitout(c, knitout::load_machine_profile(options.machine), out);
  }
};

std::string findings_text(const knitout::Replay& replay, const knitout::MachineProfile& p) {
  std::string out;
  for (const knitout::Finding& f : replay.findings)
    out += fmt::format("  {}\n", knitout::finding_line(f, p));
  return out;
}

// Writes the fabric to `path` (a stitch mesh for .obj, else a stitch graph) through a temporary
// file that a refusal removes: a refusal writes none. Of a proven file, the piece's border in its
// own yarn is left out as its cast-on's border (the model's cast-on is knit through it).
std::string write_fabric(const knitout::Replay& replay, const std::string& file,
                         const std::string& path,
                         const std::optional<knitout::ProofResult>& proof) {
  std::vector<bool> border;
  if (proof && proof->proven) border = knitout::own_yarn_border(replay, *proof);
  const std::vector<bool>* given = border.empty() ? nullptr : &border;
  bool as_mesh = path.ends_with(".obj");
  write_file_atomically(path, [&](std::ostream& out) {
    if (as_mesh)
      knitout::write_fabric_stitch_mesh(replay, file, out, given);
    else
      knitout::write_fabric_stitch_graph(replay, file, out, given);
  });
  return fmt::format("\n  the fabric written as a stitch {} in {} (skein check reads it)",
                     as_mesh ? "mesh" : "graph", path);
}

class VbedSimulator : public Simulator {
 public:
  std::string name() const override { return "vbed"; }
  std::string target() const override { return "knitout"; }
  std::string description() const override {
    return "replays any knitout on the machine its header names (or --machine), stops at the "
           "first error, reports warnings, passes, time and the fabric it makes, and proves the "
           "fabric against the input";
  }
  VerifyReport verify(const std::string& text, const std::string& file, const Compilation* against,
                      const TargetOptions& options) const override {
    bool as_mesh = options.fabric.ends_with(".obj");
    if (!options.fabric.empty() && !as_mesh && !options.fabric.ends_with(".st"))
      throw UsageError(
          fmt::format("--fabric {}: the fabric is written as a stitch mesh (.obj) or an AutoKnit "
                      "stitch graph (.st), so the file must end in one of them",
                      options.fabric));
    knitout::ProfileChoice chosen =
        knitout::choose_profile(text, file, options.machine, options.strict);
    const knitout::MachineProfile& profile = chosen.profile;
    knitout::Replay replay = knitout::replay_knitout(text, file, profile, chosen.options);
    std::string shop = knitout::shop_summary(replay, profile) + "\n" +
                       knitout::fabric_summary(knitout::fabric_report(replay), profile);
    if (!options.picture.empty()) {
      write_file_atomically(options.picture, [&](std::ostream& out) {
        knitout::write_fabric_svg(replay, file, out);
      });
      shop += fmt::format("\n  the fabric drawn in {}", options.picture);
    }
    std::optional<knitout::ProofResult> proof;
    if (against) {
      if (!against->knittability.knittable)
        throw Error(
            fmt::format("{} is not knittable, so no knitout of it can be proven", against->input));
      proof = knitout::prove_whole_file(replay, text, *against);
    }
    if (!options.fabric.empty()) shop += write_fabric(replay, file, options.fabric, proof);
    std::string valid =
        fmt::format("{}: every operation is valid on {}{}", file, profile.name, chosen.how);
    VerifyReport report;
    if (!proof) {
      report.summary = fmt::format("{}\n{}{}\n  give --against INPUT to prove the fabric", valid,
                                   findings_text(replay, profile), shop);
      report.valid = true;
      return report;
    }
    report.proven = proof->proven;
    report.summary =
        fmt::format("{}; {}\n{}{}", valid, proof->summary, findings_text(replay, profile), shop);
    return report;
  }

  std::optional<std::string> fabric_stitch_graph(const std::string& text, const std::string& file,
                                                 const TargetOptions& options) const override {
    knitout::ProfileChoice chosen =
        knitout::choose_profile(text, file, options.machine, options.strict);
    knitout::Replay replay = knitout::replay_knitout(text, file, chosen.profile, chosen.options);
    std::ostringstream out;
    knitout::write_fabric_stitch_graph(replay, file, out);
    return std::move(out).str();
  }
};

}  // namespace

void register_knitout_target(Registry& registry) {
  registry.add(std::make_unique<KnitoutTarget>());
  registry.add(std::make_unique<VbedSimulator>());
}

}  // namespace skein
