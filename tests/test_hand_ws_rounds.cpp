// Rounds worked with the WS facing (the tube inside out): written where a model's rounds run
// left to right seen from the RS and are not mirrored, proven as the model itself (not its
// mirror image) in every format; and the simulator's reasons for rejecting such a rnd.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <sstream>

#include "driver/pipeline.hpp"
#include "hand/hand_target.hpp"
#include "hand/pattern_document.hpp"
#include "hand/pattern_model.hpp"
#include "hand/pattern_writers.hpp"
#include "hand/program_pattern.hpp"
#include "mesh/generate.hpp"
#include "target_runner.hpp"

namespace skein {
namespace {

using hand::Rounds;

// The pattern in markdown, HTML and KnitSpeak, every rnd that runs left to right worked with the
// WS facing.
std::vector<std::string> inside_out_patterns(const Compilation& c) {
  hand::HandPattern pattern =
      hand::build_hand_pattern(c, hand::TurnMethod::german, Rounds::ws_facing);
  std::ostringstream md, html, knitspeak;
  hand::write_markdown(hand::make_document(pattern), md);
  hand::write_html(hand::make_document(pattern), pattern, {}, html);
  hand::write_knitspeak(hand::make_document(pattern, hand::Dialect::knitspeak), knitspeak);
  return {md.str(), html.str(), knitspeak.str()};
}

void expect_proven_unmirrored(const Compilation& c, const std::string& what) {
  const char* targets[] = {"hand", "hand-html", "hand-knitspeak"};
  std::vector<std::string> patterns = inside_out_patterns(c);
  for (std::size_t i = 0; i < patterns.size(); ++i) {
    VerifyReport report = testing::verify(c, targets[i], patterns[i]);
    ASSERT_TRUE(report.proven) << what << " " << targets[i] << ": " << report.summary << "\n"
                               << patterns[i];
    EXPECT_EQ(report.summary.find("mirror image"), std::string::npos) << report.summary;
  }
}

TEST(HandWsRounds, TheHatWorkedInsideOutIsTheModelItself) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model("samples/hat/hat.obj");
  std::string pattern = inside_out_patterns(c)[0];
  EXPECT_NE(pattern.find("Cast on 64 sts. Pm and join to work in the rnd with the WS facing "
                         "(the tube inside out), being careful not to twist.\n"),
            std::string::npos)
      << pattern;
  EXPECT_NE(pattern.find("**Rnd 1 (WS):** Purl.\n"), std::string::npos) << pattern;
  EXPECT_NE(pattern.find("**Rnd 25 (WS):** *P to 2 sts before m, p2tog, sm; rep from * to end "
                         "\u2014 56 sts.\n"),
            std::string::npos)
      << pattern;
  EXPECT_NE(pattern.find("**Rounds worked with the WS facing**"), std::string::npos);
  EXPECT_EQ(pattern.find("mirror image"), std::string::npos);
  expect_proven_unmirrored(c, "hat");
}

// AutoKnit's stitch graphs run left to right: inside out, their short rows turned on a tuck
// (brp on the WS rnds), held legs and the yarn carried on are proven as the model itself.
TEST(HandWsRounds, AutoKnitsStitchGraphsWorkedInsideOutAreTheModelsThemselves) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  for (const char* sample : {"test-A", "test-B", "test-C"}) {
    Compilation c = compile_model(std::string("samples/autoknit/") + sample + ".st");
    expect_proven_unmirrored(c, sample);
  }
}

// Every stitch a WS rnd works (p2tog, ssp, s2pp, pfb, M1PL, M1PR, yo) on random tubes.
TEST(HandWsRounds, RandomShapedTubesWorkedInsideOutAreProven) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 40; ++trial) {
    RandomShaping shaping;
    shaping.purl = trial % 3 == 0 ? 0 : 0.3;
    auto width = static_cast<std::uint32_t>(4 + rng() % 30);
    auto rows = static_cast<std::uint32_t>(1 + rng() % 20);
    RowPlan plan = random_rows(width, rows, shaping, rng());
    Compilation c = compile_stitch_mesh(build_from_rows(plan, Layout::tube), "tube");
    ASSERT_TRUE(c.knittability.knittable) << check_report(c);
    expect_proven_unmirrored(c, "trial " + std::to_string(trial));
  }
}

using testing::failure_of;

// In the rnd a turn makes the WS face the knitter: rnds go on with it facing, labelled (WS).
TEST(HandWsRounds, ProvesAHandWrittenRndWorkedWithTheWSFacingAfterATurn) {
  EXPECT_EQ(failure_of("Cast on 8 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n"
                       "Row 2 (RS): K5, w&t.\nRnd 3 (WS): P to end.\nRnd 4 (WS): P2, pw, p5.\n"
                       "Rnd 5 (WS): BO all sts.\nFasten off.\n"),
            "");
}

TEST(HandWsRounds, RejectsARndLabelledWithTheOtherSide) {
  const std::string rnd = "Cast on 8 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n";
  EXPECT_EQ(failure_of(rnd + "Row 2 (RS): K5, w&t.\nRnd 3: Knit.\n"),
            "p.md:4: Rnd 3: the WS faces you (the work was turned): a rnd worked with the WS "
            "facing is labelled (WS)");
  EXPECT_EQ(failure_of(rnd + "Rnd 2 (WS): Purl.\n"),
            "p.md:3: Rnd 2: labelled WS, but the RS faces you: the work was not turned");
}

}  // namespace
}  // namespace skein
