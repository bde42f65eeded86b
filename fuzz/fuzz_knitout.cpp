// The knitout reader: the v-bed simulator replays the text on the generic machine, as
// `skein verify` does before it compares the fabric.
#include "fuzz_reader.hpp"
#include "knitout/machine_profile.hpp"
#include "knitout/vbed_simulator.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const skein::knitout::MachineProfile profile =
      skein::knitout::read_machine_profile(SKEIN_SOURCE_DIR "/machine_profiles/generic.yaml");
  return skein::fuzz::run_reader(data, size, [](const std::string& text) {
    skein::knitout::replay_knitout(text, "fuzz.k", profile);
  });
}
