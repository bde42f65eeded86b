// The skein command line as a user meets it: exit codes, messages, and no partial outputs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "cli_runner.hpp"

namespace skein {
namespace {

using testing::CliRun;
class Cli : public testing::SkeinCliTest {};

TEST_F(Cli, CheckKnittableModelExitsZero) {
  CliRun r = skein("check samples/hat/hat.obj");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("samples/hat/hat.obj: knittable"), std::string::npos) << r.out;
}

TEST_F(Cli, CheckUnknittableModelExitsOneAndShowsTheCycle) {
  CliRun r = skein("check samples/unknittable/fig13-deadlock.obj");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("dependency cycle"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("how to fix: this is the special deadlock"), std::string::npos) << r.out;
}

TEST_F(Cli, MalformedInputExitsTwoNamingFileAndLine) {
  std::ofstream(in_dir("bad.obj")) << "#~skein-stitch-mesh 1\nv 0 0\n";
  CliRun r = skein("check " + in_dir("bad.obj"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("skein: error: " + in_dir("bad.obj") + ":2:"), std::string::npos) << r.err;
}

TEST_F(Cli, MissingInputExitsTwo) {
  CliRun r = skein("check no/such/file.obj");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no/such/file.obj"), std::string::npos) << r.err;
}

TEST_F(Cli, CompileWritesTheOutputAndVerifiesIt) {
  CliRun r = skein("compile samples/rib-swatch/rib-swatch.obj --target schedule -o " +
                   in_dir("swatch.schedule") + " --verify");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + in_dir("swatch.schedule")), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("proven against samples/rib-swatch/rib-swatch.obj: all 360 stitches"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(outputs(), std::vector<std::string>{"swatch.schedule"});
}

// Compile proves what it writes unless told not to; --verify is still accepted.
TEST_F(Cli, CompileProvesByDefaultAndNoVerifySkipsTheProof) {
  CliRun proven = skein("compile samples/hat/hat.obj -t hand -o " + in_dir("hat.md"));
  EXPECT_EQ(proven.exit_code, 0) << proven.err;
  EXPECT_NE(proven.out.find("hat.md: proven against samples/hat/hat.obj"), std::string::npos)
      << proven.out;
  CliRun unproven =
      skein("compile samples/hat/hat.obj -t hand --no-verify -o " + in_dir("hat2.md"));
  EXPECT_EQ(unproven.exit_code, 0) << unproven.err;
  EXPECT_EQ(unproven.out.find("proven"), std::string::npos) << unproven.out;
  EXPECT_EQ(read("hat.md"), read("hat2.md"));
  EXPECT_EQ(outputs().size(), 2u);
}

TEST_F(Cli, CompileOfAnUnknittableModelWritesNothing) {
  CliRun r = skein("compile samples/unknittable/fig13-deadlock.obj -t schedule -o " +
                   in_dir("fig13.schedule"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("nothing written to"), std::string::npos) << r.err;
  EXPECT_TRUE(outputs().empty());
}

TEST_F(Cli, UnknownTargetIsAUsageErrorAndWritesNothing) {
  CliRun r = skein("compile samples/hat/hat.obj -t loom -o " + in_dir("hat.out"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown target 'loom'; known targets: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("schedule"), std::string::npos) << r.err;
  EXPECT_TRUE(outputs().empty());
}

TEST_F(Cli, DialectChoosesHowTheHandTargetSpellsItsRows) {
  CliRun r = skein("compile samples/sock/sock.yaml --target hand --dialect knitspeak -o " +
                   in_dir("sock.knitspeak") + " --verify");
  EXPECT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("proven against samples/sock/sock.yaml"), std::string::npos) << r.out;
  CliRun bad =
      skein("compile samples/hat/hat.obj --target hand --dialect klingon -o " + in_dir("hat.md"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("unknown dialect 'klingon' for target 'hand'; valid dialects: standard, "
                         "knitspeak"),
            std::string::npos)
      << bad.err;
  CliRun none = skein("compile samples/hat/hat.obj --target schedule --dialect knitspeak -o " +
                      in_dir("hat.schedule"));
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("target 'schedule' has no dialects"), std::string::npos) << none.err;
  EXPECT_EQ(outputs(), std::vector<std::string>{"sock.knitspeak"});
}

TEST_F(Cli, SettingsChooseHowTheHandTargetKnitsRoundsAndShortRows) {
  // The sock's rounds run left to right: by default the pattern knits its mirror image.
  CliRun r = skein(
      "compile samples/sock/sock.yaml -t hand --set rounds=inside-out --set "
      "short-rows=wrap-and-turn -o " +
      in_dir("sock.md") + " --verify");
  EXPECT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("stitch for stitch (4606 stitches: their types, loops and yarn order)\n"),
            std::string::npos)
      << r.out;  // not ", as its mirror image"
  std::string pattern = read("sock.md");
  EXPECT_NE(pattern.find("**Rnd 1 (WS):** *P2, k2; rep from * to end."), std::string::npos);
  EXPECT_NE(pattern.find("**Row 46 (RS):** K22, w&t."), std::string::npos);
  EXPECT_EQ(pattern.find("mirror image"), std::string::npos);
  CliRun unknown = skein("compile samples/hat/hat.obj -t hand --set round=x -o " + in_dir("h.md"));
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("target 'hand' has no setting 'round'; its settings: short-rows, "
                             "rounds"),
            std::string::npos)
      << unknown.err;
  CliRun bad = skein("compile samples/hat/hat.obj -t hand --set rounds=x -o " + in_dir("h.md"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--set rounds: expected mirror or inside-out, found 'x'"),
            std::string::npos)
      << bad.err;
  EXPECT_EQ(outputs(), std::vector<std::string>{"sock.md"});
}

// tube.obj marks no shift-path: skein places one, up-left, so its rnds run right to left as hands
// knit them and the pattern knits the model itself. hat.obj's bare '#~shift' lines mean up-right
// (left to right): that given direction is kept, so its pattern knits the mirror image.
TEST_F(Cli, RoundsSkeinPlacesRunRightToLeftAndGivenOptionsKeepTheirDirection) {
  CliRun tube = skein("compile samples/auto-shift-path/tube.obj -t hand -o " + in_dir("tube.md"));
  EXPECT_EQ(tube.exit_code, 0) << tube.err << tube.out;
  EXPECT_EQ(read("tube.md").find("mirror image"), std::string::npos) << read("tube.md");
  CliRun hat = skein("compile samples/hat/hat.obj -t hand -o " + in_dir("hat.md"));
  EXPECT_EQ(hat.exit_code, 0) << hat.err << hat.out;
  EXPECT_NE(read("hat.md").find("mirror image"), std::string::npos);
}

TEST_F(Cli, AProjectFileCanChooseTheHandTargetsSettings) {
  std::ifstream sample("samples/sock/sock.yaml");
  std::string project((std::istreambuf_iterator<char>(sample)), {});
  project.replace(project.find("sock.obj"), 8, std::filesystem::absolute("samples/sock/sock.obj"));
  std::ofstream(in_dir("sock.yaml")) << project << "target: {rounds: inside-out}\n";
  CliRun r = skein("compile " + in_dir("sock.yaml") + " -t hand -o " + in_dir("sock.md"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read("sock.md").find("**Rnd 1 (WS):**"), std::string::npos);
  std::ofstream(in_dir("sock.yaml")) << project << "target: {rounds: sideways}\n";
  CliRun bad =
      skein("compile " + in_dir("sock.yaml") + " -t hand -o " + in_dir("sock.md") + " --force");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("sock.yaml: target: rounds: expected mirror or inside-out, found "
                         "'sideways'"),
            std::string::npos)
      << bad.err;
  std::string wrapped = project;  // short_rows: {hand: ...} is the short-rows setting
  wrapped.replace(wrapped.find("method: sr4"), 11, "method: sr4\n  hand: wrap-and-turn");
  std::ofstream(in_dir("sock.yaml")) << wrapped;
  CliRun w =
      skein("compile " + in_dir("sock.yaml") + " -t hand -o " + in_dir("sock.md") + " --force");
  EXPECT_EQ(w.exit_code, 0) << w.err;
  EXPECT_NE(read("sock.md").find("**Row 45 (RS):** K1, pm, k25, w&t."), std::string::npos);
}

TEST_F(Cli, UnwritableOutputLeavesNoTemporaryFile) {
  CliRun r =
      skein("compile samples/hat/hat.obj -t schedule -o " + in_dir("missing-dir/hat.schedule"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
  EXPECT_TRUE(outputs().empty());
}

// A well-formed schedule that is not the model's is not proven (exit 1), like a hand pattern or
// knitout that knits other fabric; a malformed one is bad input (exit 2).
TEST_F(Cli, VerifyRejectsATamperedScheduleWithItsLine) {
  ASSERT_EQ(
      skein("compile samples/rib-swatch/rib-swatch.obj -t schedule -o " + in_dir("s.schedule"))
          .exit_code,
      0);
  std::string text = read("s.schedule");
  std::size_t at = text.find("    21 k\n");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 9, "    21 p\n");
  std::ofstream(in_dir("s.schedule")) << text;
  CliRun r =
      skein("verify " + in_dir("s.schedule") + " --against samples/rib-swatch/rib-swatch.obj");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.out,
            in_dir("s.schedule") + ":47: face 21 (k, row 2) is a k, not a p\n     47 |     21 p\n");
  text.replace(text.find("    21 p\n"), 9, "    21\n");
  std::ofstream(in_dir("s.schedule")) << text;
  CliRun malformed =
      skein("verify " + in_dir("s.schedule") + " --against samples/rib-swatch/rib-swatch.obj");
  EXPECT_EQ(malformed.exit_code, 2);
  EXPECT_EQ(malformed.err, "skein: error: " + in_dir("s.schedule") +
                               ":47: expected a stitch line '<number> <stitch>', a 'yarn', 'row', "
                               "'turn' or 'marker' line\n     47 |     21\n");
}

TEST_F(Cli, AValidInputTheTargetCannotKnitExitsThree) {
  CliRun r =
      skein("compile samples/sweater/sweater.yaml -t knitout -m swg091n2 -o " + in_dir("s.k"));
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(r.err,
            "skein: unsupported: not yet supported by the knitout target: a course that binds off "
            "its run in two places (several runs on the bed), at face 21276 (bo, row 108)\n");
  EXPECT_TRUE(outputs().empty());
}

TEST_F(Cli, VerifyingAgainstAnUnknittableModelIsNotProven) {
  ASSERT_EQ(
      skein("compile samples/rib-swatch/rib-swatch.obj -t schedule -o " + in_dir("s.schedule"))
          .exit_code,
      0);
  CliRun r =
      skein("verify " + in_dir("s.schedule") + " --against samples/unknittable/fig13-deadlock.obj");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("samples/unknittable/fig13-deadlock.obj: NOT knittable\n"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.substr(r.err.rfind("skein: ")),
            "skein: " + in_dir("s.schedule") + " cannot be proven against it\n");
}

TEST_F(Cli, AnOverlongPathIsBadInputSaidInWords) {
  std::string name = in_dir(std::string(5000, 'a'));
  CliRun read = skein("check " + name + ".obj");
  EXPECT_EQ(read.exit_code, 2);
  EXPECT_EQ(read.err, "skein: error: cannot open '" + name + ".obj': File name too long\n");
  CliRun written = skein("compile samples/hat/hat.obj -t schedule -o " + name);
  EXPECT_EQ(written.exit_code, 2);
  EXPECT_EQ(written.err, "skein: error: cannot write " + name + ": File name too long\n");
}

TEST_F(Cli, EachCommandsHelpHasItsOwnExamplesNotTheTargetList) {
  CliRun compile = skein("compile --help");
  EXPECT_EQ(compile.exit_code, 0);
  EXPECT_NE(compile.out.find(
                "Targets: hand, hand-html, hand-knitspeak, hand-web, knitout, schedule (skein "
                "--help describes each and its --set settings).\n"),
            std::string::npos)
      << compile.out;
  EXPECT_NE(compile.out.find("  skein compile samples/hat/hat.obj -t schedule -o -"),
            std::string::npos)
      << compile.out;
  EXPECT_EQ(compile.out.find("Simulators"), std::string::npos) << compile.out;
  EXPECT_EQ(compile.out.find("--set rounds=mirror|inside-out"), std::string::npos) << compile.out;
  for (const char* command : {"check", "new", "generate", "render"}) {
    CliRun r = skein(std::string(command) + " --help");
    EXPECT_EQ(r.exit_code, 0) << command;
    EXPECT_NE(r.out.find("Examples:\n  skein " + std::string(command) + " "), std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find("Targets"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Exit codes: 0 done"), std::string::npos) << r.out;
  }
  EXPECT_NE(skein("new --help")
                .out.find("NAME or NAME.yaml: writes the project NAME.yaml and its "
                          "mesh NAME.obj"),
            std::string::npos);
}

TEST_F(Cli, HelpListsTargetsAndSimulatorsFromTheRegistry) {
  CliRun r = skein("--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("Exit codes: 0 done (knittable, written, proven; verify without --against: "
                       "replays as\nwritten); 1 not knittable or not proven; 2 bad input or "
                       "usage; 3 valid input that the\ntarget cannot do (yet, or on this "
                       "machine); 4 internal error.\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("schedule "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("schedule-replay"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Examples:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--set rounds=mirror|inside-out"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace skein
