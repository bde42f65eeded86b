// AutoKnit's stitch graphs (.st), read straight into a knit graph.
#include "fuzz_reader.hpp"
#include "mesh/autoknit_st.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return skein::fuzz::run_reader(
      data, size, [](const std::string& text) { skein::parse_autoknit_st(text, "fuzz.st"); });
}
