// Helpers shared by the knitout tests: profiles by name, emitting, replaying and proving.
#pragma once

#include <sstream>
#include <string>

#include "driver/pipeline.hpp"
#include "golden.hpp"
#include "knitout/emit.hpp"
#include "knitout/fabric_proof.hpp"
#include "knitout/machine_profile.hpp"
#include "knitout/vbed_simulator.hpp"

namespace skein::testing {

inline knitout::MachineProfile shipped_profile(const std::string& name) {
  return knitout::read_machine_profile(source_path("machine_profiles/" + name + ".yaml"));
}

inline std::string emit_knitout_text(const Compilation& c, const knitout::MachineProfile& p) {
  std::ostringstream out;
  knitout::emit_knitout(c, p, out);
  return out.str();
}

// Replays `text` and proves it against `c` (throws ParseError on an invalid operation).
inline knitout::ProofResult replay_and_prove(const std::string& text, const Compilation& c,
                                             const knitout::MachineProfile& p) {
  knitout::Replay replay = knitout::replay_knitout(text, "out.k", p);
  return knitout::prove_fabric(replay, text, c);
}

}  // namespace skein::testing
