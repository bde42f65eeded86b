// A provisional cast-on in the middle of a row (a split worked with the upper piece's own
// yarn): "K1, CO 3 sts with a provisional cast-on, k1", and the piece on the other side started
// on its chain; written, proven in every format, and the simulator's reasons for rejecting it.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "fixtures.hpp"
#include "hand/pattern_document.hpp"
#include "hand/pattern_model.hpp"
#include "hand/pattern_writers.hpp"
#include "hand/program_pattern.hpp"
#include "target_runner.hpp"

namespace skein {
namespace {

using testing::emit;
using testing::failure_of;
using testing::verify;

TEST(HandRowCastOn, AProvisionalCastOnInTheMiddleOfARowIsWrittenAndProven) {
  for (bool rs_row : {false, true}) {
    Compilation c = compile_stitch_mesh(testing::mid_row_split_mesh(rs_row), "mid-row split");
    std::string pattern = emit(c, "hand");
    EXPECT_NE(pattern.find(rs_row ? "**Row 3 (RS):** K1, CO 3 sts with a provisional cast-on, "
                                  : "**Row 2 (WS):** P1, CO 3 sts with a provisional cast-on, "),
              std::string::npos)
        << pattern;
    EXPECT_NE(pattern.find("Join a new yarn to the 3 loops of Piece 1's chain"), std::string::npos)
        << pattern;
    EXPECT_NE(pattern.find("In the middle of a row"), std::string::npos);
    EXPECT_EQ(testing::unproven_hand_formats(c), "") << pattern;
  }
}

// In the round, mirrored (its rnds run left to right; the mirror keeps the cast-on's needle
// and chain, the two sides of the split), and with those rnds worked with the WS facing.
TEST(HandRowCastOn, AProvisionalCastOnInTheMiddleOfARndIsProvenMirroredAndInsideOut) {
  Compilation c = compile_stitch_mesh(testing::mid_round_split_mesh(), "mid-round split");
  std::string pattern = emit(c, "hand");
  EXPECT_NE(pattern.find("**Rnd 2:** K1, CO 3 sts with a provisional cast-on, "), std::string::npos)
      << pattern;
  EXPECT_EQ(testing::unproven_hand_formats(c), "") << pattern;
  EXPECT_NE(verify(c, "hand", pattern).summary.find("mirror image"), std::string::npos);
  std::ostringstream inside_out;
  hand::write_markdown(hand::make_document(hand::build_hand_pattern(c, hand::TurnMethod::german,
                                                                    hand::Rounds::ws_facing)),
                       inside_out);
  EXPECT_NE(inside_out.str().find("**Rnd 2 (WS):** P1, CO 3 sts with a provisional cast-on, "),
            std::string::npos)
      << inside_out.str();
  VerifyReport report = verify(c, "hand", inside_out.str());
  EXPECT_TRUE(report.proven) << report.summary << "\n" << inside_out.str();
}

TEST(HandRowCastOn, ProvesAndRejectsHandWrittenOnes) {
  const std::string row = "Cast on 5 sts.\nRow 1 (RS): K1, BO 3 sts, k1.\n";
  EXPECT_EQ(failure_of(row + "Row 2 (WS): P1, CO 3 sts with a provisional cast-on, p1.\n"
                             "Row 3 (RS): BO all sts.\nFasten off.\n"
                             "Join a new yarn to the 3 loops of Piece 1's chain, the first st "
                             "cast on at the tip.\nRow 1 (RS): BO all sts.\nFasten off.\n"),
            "");
  EXPECT_EQ(failure_of(row + "Row 2 (WS): P1, CO 3 sts with a provisional cast-on, p1.\n"
                             "Row 3 (RS): BO all sts.\nFasten off.\n"),
            "p.md:5: the chain of Piece 1 is left on a spare needle, never worked");
}

// A yarn that has worked casts on sts for a course that takes them later (the teapot's handle
// bridge at 14 and 26 sts to 10 cm): onto a holder, its chain the piece's; the holder is placed
// back "the first st cast on first".
TEST(HandRowCastOn, CastingOnWithTheWorkingYarnOntoAHolderIsWorkedAndRejectedByReason) {
  const std::string before = "Cast on 4 sts.\nRow 1 (RS): Knit.\n";
  const std::string cast_on =
      "With the working yarn, cast on 2 sts with a provisional cast-on onto holder 1.\n";
  const std::string after =
      "Leave the 4 sts on the needle and set the yarn aside (do not cut it).\n"
      "Join a new yarn to the 2 loops of Piece 1's chain, the first st cast on at the tip.\n"
      "Row 1 (RS): BO all sts.\nFasten off.\n"
      "Take up Piece 1 again with its yarn. Place the 2 sts of holder 1 on the needle after the "
      "first 4 sts of the row, the first st cast on first \u2014 6 sts.\n"
      "Row 2 (WS): BO all sts.\nFasten off.\n";
  EXPECT_EQ(failure_of(before + cast_on + after), "");
  EXPECT_EQ(failure_of(before + cast_on + "With the working yarn, cast on 2 sts onto holder 1.\n" +
                       after),
            "p.md:4: With the working yarn, cast on onto holder 1: it already holds 2 sts");
  EXPECT_EQ(failure_of(before + cast_on +
                       "With the working yarn, cast on 1 st with a provisional cast-on onto "
                       "holder 2.\n" +
                       after),
            "p.md:4: With the working yarn, cast on with a provisional cast-on: Piece 1 already "
            "has a chain (one per piece)");
  EXPECT_EQ(failure_of(cast_on + before + after),
            "p.md:1: With the working yarn, cast on: no yarn is being worked");
}

// A backward-loop cast-on over a gap (a machine's thumb gap read back from its fabric): one
// loop each, no chain left to work; the reader names what it expected after "with a".
TEST(HandRowCastOn, ABackwardLoopCastOnLeavesNoChain) {
  const std::string row = "Cast on 5 sts.\nRow 1 (RS): K1, BO 3 sts, k1.\n";
  EXPECT_EQ(failure_of(row + "Row 2 (WS): P1, CO 3 sts with a backward-loop cast-on, p1.\n"
                             "Row 3 (RS): BO all sts.\nFasten off.\n"),
            "");
  try {
    failure_of(row + "Row 2 (WS): P1, CO 3 sts with a long-tail cast-on, p1.\n");
    ADD_FAILURE() << "read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("expected 'with a provisional cast-on' or 'with a "
                                         "backward-loop cast-on', found 'long-tail cast-on"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace skein
