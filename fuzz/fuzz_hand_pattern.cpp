// Hand patterns (markdown): the reader turns the text into steps, and the needle simulator
// works them, as `skein verify` does before it compares the fabric.
#include "fuzz_reader.hpp"
#include "hand/needle_sim.hpp"
#include "hand/pattern_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return skein::fuzz::run_reader(data, size, [](const std::string& text) {
    skein::hand::Script script = skein::hand::read_pattern(text, "fuzz.md");
    skein::hand::replay(script, "fuzz.md");
  });
}
