// Machine profiles (machine_profiles/*.yaml), read from a file as skein reads them.
#include <unistd.h>

#include <fstream>

#include "fuzz_reader.hpp"
#include "knitout/machine_profile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/skein-fuzz-profile-" + std::to_string(::getpid()) + ".yaml";
  return skein::fuzz::run_reader(data, size, [](const std::string& text) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
    skein::knitout::read_machine_profile(path);
  });
}
