// What each fuzz target does with its input, shared with tests/test_fuzz_findings.cpp, which
// replays every finding kept in tests/data/fuzz/READER/. A reader may refuse an input with a
// skein::Error (the message a user sees); anything else is a finding.
#pragma once

#include <unistd.h>

#include <fstream>
#include <string>
#include <string_view>
#include <utility>

#include "common/error.hpp"
#include "hand/needle_sim.hpp"
#include "hand/pattern_reader.hpp"
#include "knitout/machine_profile.hpp"
#include "knitout/vbed_simulator.hpp"
#include "labeling/coarse_mesh.hpp"
#include "labeling/labeling.hpp"
#include "labeling/project.hpp"
#include "labeling/stitch_generation.hpp"
#include "mesh/autoknit_st.hpp"
#include "mesh/obj_format.hpp"
#include "mesh/stitch_mesh.hpp"

namespace skein::fuzz {

// The stitch-mesh reader (.obj with #~ lines), then validation, which checks what it reads.
inline void stitch_mesh(const std::string& text) {
  StitchMesh mesh = parse_stitch_mesh(text, "fuzz.obj");
  validate(mesh);
}

// AutoKnit's stitch graphs (.st), read straight into a knit graph.
inline void autoknit_st(const std::string& text) {
  parse_autoknit_st(text, "fuzz.st");
}

// A project file and its coarse mesh in one input: the YAML, a line "#obj", then the OBJ
// text. The mesh is labelled and the stitch mesh generated, as `skein generate` does.
inline void project(const std::string& text) {
  constexpr std::string_view kSeparator = "\n#obj\n";
  std::size_t at = text.find(kSeparator);
  Project p = parse_project(text.substr(0, at), "fuzz.yaml");
  CoarseMesh coarse = parse_coarse_mesh(
      at == std::string::npos ? "" : text.substr(at + kSeparator.size()), "fuzz.obj");
  generate_stitch_mesh(coarse, label_coarse_mesh(coarse, p), p);
}

// Machine profiles, read from a file as skein reads them.
inline void machine_profile(const std::string& text) {
  static const std::string path = "/tmp/skein-fuzz-profile-" + std::to_string(::getpid()) + ".yaml";
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  knitout::read_machine_profile(path);
}

// Knitout, replayed by the v-bed simulator on the generic machine as `skein verify` does.
inline void knitout(const std::string& text) {
  static const knitout::MachineProfile profile =
      knitout::read_machine_profile(SKEIN_SOURCE_DIR "/machine_profiles/generic.yaml");
  knitout::replay_knitout(text, "fuzz.k", profile);
}

// Hand patterns (markdown): read, then worked by the needle simulator, as `skein verify`, up
// to a tenth of its work limit: instrumented for coverage and the sanitizers it runs about
// ten times slower than a release build (which works the full limit in under a second), and
// what the fuzzer looks for is reached long before (test_limits.cpp tests the limit itself).
inline void hand_pattern(const std::string& text) {
  hand::replay(hand::read_pattern(text, "fuzz.md"), "fuzz.md", hand::kMaxPatternWork / 10);
}

using Reader = void (*)(const std::string&);
inline constexpr std::pair<const char*, Reader> kReaders[] = {
    {"stitch_mesh", stitch_mesh}, {"autoknit_st", autoknit_st},
    {"project", project},         {"machine_profile", machine_profile},
    {"knitout", knitout},         {"hand_pattern", hand_pattern}};

}  // namespace skein::fuzz
