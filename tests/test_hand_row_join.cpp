// A three-needle bind-off in the middle of a row, with the piece's own yarn: "Hold the 3 sts of
// Piece 2 behind the needle, ..." when it is taken up, then "3-needle BO 3 sts, k2"; written,
// proven in every format, and the simulator's reasons for rejecting it.
#include <gtest/gtest.h>

#include <string>

#include "driver/pipeline.hpp"
#include "fixtures.hpp"
#include "target_runner.hpp"

namespace skein {
namespace {

using testing::emit;
using testing::failure_of;

TEST(HandRowJoin, AThreeNeedleBindOffInTheMiddleOfARowIsWrittenAndProven) {
  Compilation c = compile_stitch_mesh(testing::mid_row_join_mesh(), "mid-row join");
  std::string pattern = emit(c, "hand");
  for (const char* line :
       {"Take up Piece 1 again with its yarn. Hold the 3 sts of Piece 2 behind the needle, the "
        "first st of its last row at the tip.\n",
        "**Row 1 (RS):** 3-needle BO 3 sts, k2 \u2014 2 sts.\n",
        "**Three-needle bind-off in a row**"})
    EXPECT_NE(pattern.find(line), std::string::npos) << line << "\n" << pattern;
  EXPECT_EQ(testing::unproven_hand_formats(c), "") << pattern;
}

TEST(HandRowJoin, RejectsAThreeNeedleBindOffWorkedWrongWithTheReason) {
  const std::string spare =
      "Cast on 3 sts.\nRow 1 (RS): Knit.\nLeave the 3 sts on a spare needle and cut the yarn.\n"
      "Cast on 5 sts.\n";
  const std::string held =
      spare +
      "Hold the 3 sts of Piece 1 behind the needle, the first st of its last row at the "
      "tip.\n";
  EXPECT_EQ(failure_of(held + "Row 1 (RS): 3-needle BO 3 sts, k2.\nRow 2 (WS): BO all sts.\n"
                              "Fasten off.\n"),
            "");
  EXPECT_EQ(failure_of(spare + "Row 1 (RS): 3-needle BO 3 sts, k2.\n"),
            "p.md:5: Row 1 (RS): 3-needle BO: no sts are held behind the needle");
  EXPECT_EQ(failure_of(held + "Row 1 (RS): 3-needle BO 2 sts, k3.\n"),
            "p.md:6: Row 1 (RS): 1 st held behind the needle left unworked at the end of the row");
  EXPECT_EQ(failure_of(spare + "Hold the 4 sts of Piece 1 behind the needle, the first st of its "
                               "last row at the tip.\n"),
            "p.md:5: Hold the sts of Piece 1: the pattern says 4 sts, but its needle holds 3");
}

}  // namespace
}  // namespace skein
