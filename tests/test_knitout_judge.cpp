// The fabric proof is a judge of its own: it reads the knit graph and the replayed fabric, never
// the live-loop program or the emitter's layout. A wrong program (here every course turned the
// other way, which the emitter follows faithfully) makes a valid file that is not the model.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_knitout_util.hpp"

namespace skein {
namespace {

// Every course of the program runs the other way: the emitter lays each one out mirrored.
void turn_every_course(Program& program) {
  for (Step& step : program.steps)
    step.direction = step.direction == CourseDirection::left_to_right
                         ? CourseDirection::right_to_left
                         : CourseDirection::left_to_right;
}

TEST(KnitoutJudge, AWrongProgramMakesAFileTheProofRejects) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  for (const char* model : {"samples/swatch/swatch.yaml", "samples/hat/hat.obj"}) {
    Compilation c = compile_model(model);
    knitout::MachineProfile p = testing::shipped_profile("generic");
    ASSERT_TRUE(testing::replay_and_prove(testing::emit_knitout_text(c, p), c, p).proven);
    turn_every_course(c.program);
    std::string mirrored = testing::emit_knitout_text(c, p);
    knitout::ProofResult proof = testing::replay_and_prove(mirrored, c, p);
    EXPECT_FALSE(proof.proven) << model;
    EXPECT_NE(proof.summary.find("NOT proven against"), std::string::npos) << proof.summary;
  }
}

// In a tube the half a st belongs to comes from its bed (a purl's is the other one): a knit of
// the front half made on the back bed instead (moved there, knit, moved back) is a purl seen
// from the right side, which the proof finds where the round's halves break.
TEST(KnitoutJudge, AKnitMadeOnTheOtherBedOfATubeIsRefused) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model("samples/auto-shift-path/tube.obj");
  knitout::MachineProfile p = testing::shipped_profile("generic");
  std::string text = testing::emit_knitout_text(c, p);
  ASSERT_TRUE(testing::replay_and_prove(text, c, p).proven);
  std::size_t at = text.find("knit - f502 1\n");  // its rounds run right to left
  for (int round = 0; round < 4; ++round) at = text.find("knit - f502 1\n", at + 1);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 14, "xfer f502 b502\nknit + b502 1\nxfer b502 f502\n");
  knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
  EXPECT_FALSE(proof.proven);
  EXPECT_NE(proof.summary.find("made on the other bed (a purl seen from the right side)"),
            std::string::npos)
      << proof.summary;
}

}  // namespace
}  // namespace skein
