// A provisional cast-on in the middle of a row (a split worked with the upper piece's own
// yarn): "K1, CO 3 sts with a provisional cast-on, k1", and the piece on the other side started
// on its chain; written, proven in every format, and the simulator's reasons for rejecting it.
#include <gtest/gtest.h>

#include <string>

#include "driver/pipeline.hpp"
#include "fixtures.hpp"
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

// In the round: the mirror image would swap the cast-on's needle and chain, which the rnd
// worked on from the needle cannot follow, so its left-to-right rnds are worked with the WS
// facing instead, and the pattern is proven as the model itself.
TEST(HandRowCastOn, AProvisionalCastOnInTheMiddleOfARndIsWorkedInsideOutNotMirrored) {
  Compilation c = compile_stitch_mesh(testing::mid_round_split_mesh(), "mid-round split");
  std::string pattern = emit(c, "hand");
  EXPECT_NE(pattern.find("**Rnd 2 (WS):** P1, CO 3 sts with a provisional cast-on, "),
            std::string::npos)
      << pattern;
  EXPECT_EQ(testing::unproven_hand_formats(c), "") << pattern;
  EXPECT_EQ(verify(c, "hand", pattern).summary.find("mirror image"), std::string::npos);
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

}  // namespace
}  // namespace skein
