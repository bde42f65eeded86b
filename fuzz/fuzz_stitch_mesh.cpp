// libFuzzer target: skein::fuzz::stitch_mesh (fuzz_inputs.hpp). Refusing an input with a
// skein::Error is what a reader should do; any other exception, crash or sanitizer report is a
// finding.
#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    skein::fuzz::stitch_mesh(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const skein::Error&) {
  }
  return 0;
}
