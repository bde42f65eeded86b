// Real third-party knitout (tests/data/knitout-foreign/: the knitout authors' examples and
// AutoKnit's output, unmodified, see ORIGIN.md there) replayed as `skein verify FILE` replays it:
// on the machine the file's ;;Machine: header names, else the generic v-bed, without --strict.
// Each file has its expected verdict and the reason for it: clean, or only the warnings and
// notes it deserves, and a rejection only where the spec or a named back end rejects it.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <map>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "knitout/vbed_simulator.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

namespace fs = std::filesystem;

// "profile: error line N: message" or "profile: warning rule-a, note rule-b" (in rule order).
std::string verdict_of(const fs::path& path, const std::string& machine = "") {
  std::string text = read_file(path.string());
  std::string name = path.filename().string();
  knitout::ProfileChoice chosen = knitout::choose_profile(
      text, name,
      machine.empty() ? "" : testing::source_path("machine_profiles/" + machine + ".yaml"), false);
  std::string verdict = chosen.profile.name + ":";
  try {
    knitout::Replay replay = knitout::replay_knitout(text, name, chosen.profile, chosen.options);
    std::string sep = " ";
    for (const knitout::Finding& f : replay.findings) {
      verdict += fmt::format("{}{} {}", sep, knitout::severity_name(f.severity),
                             knitout::rule_info(f.rule).name);
      sep = ", ";
    }
    if (replay.findings.empty()) verdict += " clean";
  } catch (const ParseError& e) {
    verdict += fmt::format(" error line {}: {}", e.line(), e.expected());
  }
  return verdict;
}

// Why each verdict is deserved:
// - Files without ;;Machine: (most knitout-frontend-js output) replay on the generic v-bed, which
//   has a hook wherever a file uses one and no back end's carriers line. Their knits of empty
//   needles (a knit cast-on, yarn-overs) are legal knitout and only noted.
// - needle-off-bed (note): needles below 0 (f-3 after a lace transfer, icord's f-1), which the
//   back ends accept and shift.
// - hook-blocks (warning, image-tube-diag.k): its first round tucks b201, right of the hook that
//   holds carrier 2 beside f200 before releasehook; Hofmann's simulator refuses that, so the
//   file may well snag the hook. knitout-to-dat translates it.
// - AutoKnit's files (error): they bring in carrier "0" (AutoKnit numbers yarns from 0), which
//   the ;;Carriers: header does not name; the spec and knitout-to-dat ("Can't use carrier '0'
//   which isn't named in the Carriers comment header") both reject it.
const std::map<std::string, std::string>& expected() {
  static const std::map<std::string, std::string> verdicts{
      {"autoknit-knitout/test-A.k",
       "generic: error line 162: carrier '0' is not named in the ;;Carriers: header"},
      {"autoknit-knitout/test-B.k",
       "generic: error line 151: carrier '0' is not named in the ;;Carriers: header"},
      {"autoknit-knitout/test-C.k",
       "generic: error line 217: carrier '0' is not named in the ;;Carriers: header"},
      {"knitout-examples/Tutorial1/helloworld.k", "generic: clean"},
      {"knitout-examples/Tutorial2/rib1x1.k", "generic: clean"},
      {"knitout-examples/basic-vol-1/MilanoRib.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/basic-vol-1/altjersey.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/basic-vol-1/fullrib.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/basic-vol-1/garter.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/basic-vol-1/halfmil-mb.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/basic-vol-1/halfmilano.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/basic-vol-1/interlock.knitout", "swg091n2: note knit-empty-needle"},
      {"knitout-examples/basic-vol-1/rib-1x1.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/basic-vol-1/rib-2x1.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/basic-vol-1/rib-2x2.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/basic-vol-1/rib-4x4.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/basic-vol-1/singlejersey.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/entrelac.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/hyperbolic-plane.knitout", "generic: clean"},
      {"knitout-examples/icord-bind-off.k", "swg091n2: note knit-empty-needle"},
      {"knitout-examples/icord-cast-on.k", "swg091n2: note needle-off-bed"},
      {"knitout-examples/image-kp-half-rib.k",
       "generic: note needle-off-bed, note knit-empty-needle"},
      {"knitout-examples/image-lace-test-2.knitout",
       "generic: note needle-off-bed, note knit-empty-needle"},
      {"knitout-examples/image-lace-test.knitout",
       "generic: note needle-off-bed, note knit-empty-needle"},
      {"knitout-examples/image-tube-accordian.k", "swg091n2: clean"},
      {"knitout-examples/image-tube-diag.k", "swg091n2: warning hook-blocks"},
      {"knitout-examples/intarsia.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/interlock.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/k.knitout", "generic: clean"},
      {"knitout-examples/lace.knitout", "generic: note knit-empty-needle"},
      {"knitout-examples/rectangle.knitout", "generic: clean"},
  };
  return verdicts;
}

fs::path foreign_dir() {
  return testing::source_path("tests/data/knitout-foreign");
}

TEST(KnitoutForeign, EveryFileGivesItsExpectedVerdict) {
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(foreign_dir())) {
    std::string ext = entry.path().extension().string();
    if (ext != ".k" && ext != ".knitout") continue;
    std::string key = fs::relative(entry.path(), foreign_dir()).generic_string();
    ++files;
    auto want = expected().find(key);
    std::string got = verdict_of(entry.path());
    if (want == expected().end()) {
      ADD_FAILURE() << "no expected verdict for " << key << ": " << got;
      continue;
    }
    EXPECT_EQ(got, want->second) << key;
  }
  EXPECT_EQ(files, expected().size());
  EXPECT_EQ(files, 31u);  // 28 knitout-examples, 3 AutoKnit
}

// The same files on --machine swg091n2, the machine most of them were written for (inhook,
// x-stitch-number, carriers 1 to 10). Beyond the notes above:
// - Tutorial1/2 (error): ;;Carriers: 6 and 1..8 are not the line knitout-to-dat accepts.
// - hyperbolic-plane (warnings): rack 5 and a transfer across 5 needles, past the 4 of Hofmann's
//   simulator (knitout-to-dat allows 8).
// - entrelac (warning): `inhook 3` is first used going +, away from the hook's side.
TEST(KnitoutForeign, TheExamplesOnTheShimaProfile) {
  const std::map<std::string, std::string> differs{
      {"Tutorial1/helloworld.k",
       "swg091n2: error line 4: swg091n2 needs ';;Carriers: 1 2 3 4 5 6 7 8 9 10'"},
      {"Tutorial2/rib1x1.k",
       "swg091n2: error line 2: swg091n2 needs ';;Carriers: 1 2 3 4 5 6 7 8 9 10'"},
      {"hyperbolic-plane.knitout", "swg091n2: warning rack-limit, warning transfer-stretch"},
      {"entrelac.knitout", "swg091n2: note knit-empty-needle, warning first-pass-direction"},
      {"k.knitout", "swg091n2: clean"},
      {"rectangle.knitout", "swg091n2: clean"},
  };
  for (const auto& entry : fs::recursive_directory_iterator(foreign_dir() / "knitout-examples")) {
    std::string ext = entry.path().extension().string();
    if (ext != ".k" && ext != ".knitout") continue;
    std::string key =
        fs::relative(entry.path(), foreign_dir() / "knitout-examples").generic_string();
    auto want = differs.find(key);
    std::string expect =
        want != differs.end() ? want->second : expected().at("knitout-examples/" + key);
    if (want == differs.end()) expect.replace(0, expect.find(':'), "swg091n2");
    EXPECT_EQ(verdict_of(entry.path(), "swg091n2"), expect) << key;
  }
}

}  // namespace
}  // namespace skein
