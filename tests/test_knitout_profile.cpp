// Machine profiles: the shipped ones load, and a bad or unknown field is an error naming the
// file, the line and the field.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

TEST(KnitoutProfile, ShippedProfilesLoadWithTheirBackEndsCarriers) {
  knitout::MachineProfile swg = testing::shipped_profile("swg091n2");
  EXPECT_EQ(swg.carriers_line(), "1 2 3 4 5 6 7 8 9 10");
  EXPECT_EQ(swg.needles, 540u);
  EXPECT_EQ(swg.hook, knitout::YarnHook::inhook);
  EXPECT_EQ(swg.first_pass, knitout::Direction::minus);
  EXPECT_TRUE(swg.rack_allowed(4 * 4 + 1 - 4));  // 3.25
  EXPECT_FALSE(swg.rack_allowed(2));             // 0.5
  EXPECT_FALSE(swg.rack_allowed(-5 * 4));
  knitout::MachineProfile kn = testing::shipped_profile("kniterate");
  EXPECT_EQ(kn.carriers_line(), "1 2 3 4 5 6");
  EXPECT_EQ(kn.needles, 252u);
  EXPECT_EQ(kn.hook, knitout::YarnHook::in);
  EXPECT_EQ(kn.first_pass, knitout::Direction::plus);
  EXPECT_EQ(kn.max_loops_per_needle, 2u);
  EXPECT_TRUE(kn.rack_allowed(-6));  // -1.5
  EXPECT_EQ(testing::shipped_profile("generic").needles, 1000u);
}

TEST(KnitoutProfile, ShippedNamesAreFoundFromTheSourceTree) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  EXPECT_EQ(knitout::load_machine_profile("kniterate").name, "kniterate");
  EXPECT_EQ(knitout::load_machine_profile("machine_profiles/generic.yaml").name, "generic");
  std::vector<std::string> names = knitout::shipped_profile_names();
  EXPECT_EQ(names, (std::vector<std::string>{"generic", "kniterate", "swg091n2"}));
  try {
    knitout::load_machine_profile("swg999");
    FAIL() << "expected a UsageError";
  } catch (const UsageError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        "no machine profile 'swg999' (looked for machine_profiles/ in the current directory, in "
        "$XDG_DATA_HOME/skein or ~/.local/share/skein, beside the skein executable and in its "
        "prefix's share/skein); known profiles: generic, kniterate, swg091n2");
  }
  EXPECT_THROW(knitout::load_machine_profile(""), UsageError);
}

// The swg091n2 profile with one line replaced, read back: the ParseError's line and message.
std::string error_after_edit(const std::string& from, const std::string& to) {
  std::string text = read_file(testing::source_path("machine_profiles/swg091n2.yaml"));
  std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  std::string path = (std::filesystem::temp_directory_path() / "skein-bad-profile.yaml").string();
  std::ofstream(path) << text;
  try {
    knitout::read_machine_profile(path);
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), path);
    return fmt::format("line {}: {}", e.line(), e.expected());
  }
  return "no error";
}

TEST(KnitoutProfile, ABadOrUnknownFieldNamesTheFileLineAndField) {
  EXPECT_EQ(error_after_edit("sliders: true", "slider: true"),
            "line 16: unknown field 'slider' in the profile; did you mean 'sliders'? (known: name, "
            "description, machine, machine_names, back_end, gauge, "
            "needles, position, width_header, carriers, racking, max_loops_per_needle, sliders, "
            "knit_empty_needle, yarn, stitch_number, speed_number, max_float, cast_on, bind_off, "
            "timing)");
  EXPECT_EQ(error_after_edit("  max: 4 ", "  maximum: 4 "),
            "line 12: unknown field 'maximum' in 'racking'; did you mean 'max'? (known: max, "
            "fractions, max_transfer_stretch)");
  EXPECT_EQ(error_after_edit("needles: 540", "needles: many"),
            "line 7: field 'needles' must be a number from 8 to 100000, found 'many'");
  EXPECT_EQ(error_after_edit("needles: 540", "needles: 540.5"),
            "line 7: field 'needles' must be a whole number, found '540.5'");
  EXPECT_EQ(error_after_edit("  first_pass: \"-\"", "  first_pass: left"),
            "line 20: field 'yarn.first_pass' must be one of +, -, found 'left'");
  EXPECT_EQ(error_after_edit("  carrier: \"3\"", "  carrier: \"12\""),
            "line 21: field 'yarn.carrier' names carrier '12', which is not in 'carriers'");
  EXPECT_EQ(error_after_edit("width_header: true\n", ""), "line 3: missing field 'width_header'");
  EXPECT_EQ(error_after_edit("  max_transfer_stretch: 4", "  max_transfer_stretch: 6"),
            "line 14: field 'racking.max_transfer_stretch' cannot exceed 'racking.max'");
  // swg091n2 knits no waste section, so a draw thread has nothing to run between.
  EXPECT_EQ(error_after_edit("  carrier: \"3\"", "  carrier: \"3\"\n  draw_carrier: \"2\""),
            "line 22: field 'yarn.draw_carrier' needs 'cast_on.waste_rows' and a carrier of "
            "'carriers' other than 'yarn.carrier' and 'yarn.waste_carrier'");
  EXPECT_EQ(error_after_edit("sliders: true", "sliders: [yes"),
            "line 17: not valid YAML: end of sequence flow not found");
}

}  // namespace
}  // namespace skein
