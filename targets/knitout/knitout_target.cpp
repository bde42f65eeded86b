#include "knitout/knitout_target.hpp"

#include <fmt/format.h>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "knitout/emit.hpp"
#include "knitout/fabric_proof.hpp"
#include "knitout/machine_profile.hpp"
#include "knitout/vbed_simulator.hpp"

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
  void emit(const Compilation& c, const TargetOptions& options, std::ostream& out) const override {
    knitout::emit_knitout(c, knitout::load_machine_profile(options.machine), out);
  }
};

class VbedSimulator : public Simulator {
 public:
  std::string name() const override { return "vbed"; }
  std::string target() const override { return "knitout"; }
  std::string description() const override {
    return "replays any knitout on a machine profile, rejects the first invalid operation, "
           "reports passes, transfers and time, and proves the fabric against the input";
  }
  VerifyReport verify(const std::string& text, const std::string& file, const Compilation* against,
                      const TargetOptions& options) const override {
    knitout::MachineProfile profile = knitout::load_machine_profile(options.machine);
    knitout::Replay replay = knitout::replay_knitout(text, file, profile);
    std::string shop = knitout::shop_summary(replay, profile);
    VerifyReport report;
    if (!against) {
      report.summary = fmt::format(
          "{}: every operation is valid on {}\n{}\n  give --against INPUT "
          "to prove the fabric",
          file, profile.name, shop);
      return report;
    }
    if (!against->knittability.knittable)
      throw Error(
          fmt::format("{} is not knittable, so no knitout of it can be proven", against->input));
    knitout::ProofResult proof = knitout::prove_fabric(replay, text, *against);
    report.proven = proof.proven;
    report.summary = fmt::format("{}: every operation is valid on {}; {}\n{}", file, profile.name,
                                 proof.summary, shop);
    return report;
  }
};

}  // namespace

void register_knitout_target(Registry& registry) {
  registry.add(std::make_unique<KnitoutTarget>());
  registry.add(std::make_unique<VbedSimulator>());
}

}  // namespace skein
