// The stitch-mesh reader (.obj with #~ lines), then validation, which checks what it reads.
#include "fuzz_reader.hpp"
#include "mesh/obj_format.hpp"
#include "mesh/stitch_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return skein::fuzz::run_reader(data, size, [](const std::string& text) {
    skein::StitchMesh mesh = skein::parse_stitch_mesh(text, "fuzz.obj");
    skein::validate(mesh);
  });
}
