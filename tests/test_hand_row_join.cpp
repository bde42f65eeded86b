// A three-needle bind-off in the middle of a row, with the piece's own yarn: "Hold the 3 sts of
// Piece 2 behind the needle, ..." when it is taken up, then "3-needle BO 3 sts, k2"; written,
// proven in every format, and the simulator's reasons for rejecting it.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include <filesystem>

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

// Three arms knit towards the centre with their own yarns: each arm's last rnd is shared out
// 9 by 9 (holders), Piece 1 binds off two runs of its rnd with held sts, and each arm beyond
// casts on 9 sts provisionally in the middle of its first rnd.
TEST(HandRowJoin, TheThreeBarsWithTheirOwnYarnsAreProvenInEveryFormat) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model("samples/three-bars-own/three-bars-own.yaml");
  std::string pattern = emit(c, "hand");
  for (const char* line :
       {"Take up Piece 1 again with its yarn. Hold the 9 sts of holder 2 behind the needle, the "
        "last st of its last rnd at the tip. Hold the 9 sts of holder 6 behind the needle, the "
        "last st of its last rnd at the tip.\n",
        "**Rnd 23:** *3-needle BO 9 sts, k9; rep from * to end \u2014 18 sts.\n",
        "**Rnd 24:** K9, CO 9 sts with a provisional cast-on, k to end \u2014 36 sts.\n",
        "Place the 9 loops of Piece 1's chain on the needle after the first 18 sts of the rnd, "
        "the last st cast on first \u2014 36 sts.\n"})
    EXPECT_NE(pattern.find(line), std::string::npos) << line << "\n" << pattern;
  EXPECT_EQ(testing::unproven_hand_formats(c), "") << pattern;
}

// A tube that goes on as two flaps: sts 1-3 slipped to a holder, the tube set aside, a new
// yarn joined to the holder's sts (as the teapot's body's second strip starts).
TEST(HandRowJoin, ProvesAndRejectsANewYarnJoinedToAHoldersSts) {
  const std::string tube =
      "Cast on 6 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n"
      "Slip sts 1\u20133 of the rnd to holder 1 \u2014 3 sts.\n"
      "Leave the 3 sts on the needle and set the yarn aside (do not cut it).\n";
  const std::string rest =
      "Row 1 (RS): BO all sts.\nFasten off.\nTake up Piece 1 again with "
      "its yarn.\nRnd 2: BO all sts.\nFasten off.\n";
  EXPECT_EQ(failure_of(tube +
                       "Join a new yarn to the 3 sts of holder 1, the first st of its last "
                       "rnd at the tip.\n" +
                       rest),
            "");
  EXPECT_EQ(failure_of(tube + "Join a new yarn to the 4 sts of holder 1, the first st of its last "
                              "rnd at the tip.\n"),
            "p.md:5: Join a new yarn: the pattern says 4 sts, but the holder holds 3");
}

TEST(HandRowJoin, RejectsAThreeNeedleBindOffWorkedWrongWithTheReason) {
  const std::string spare =
      "Cast on 3 sts.\nRow 1 (RS): Knit.\nLeave the 3 sts on a spare needle and cut the yarn.\n"
      "Cast on 5 sts.\n";
  const std::string held =
      spare +
      "Hold the 3 sts of Piece 1 behind the needle, the first st of its last row at the "
      "tip.\n";
  const std::pair<std::string, std::string> cases[] = {
      {held + "Row 1 (RS): 3-needle BO 3 sts, k2.\nRow 2 (WS): BO all sts.\nFasten off.\n", ""},
      {spare + "Row 1 (RS): 3-needle BO 3 sts, k2.\n",
       "p.md:5: Row 1 (RS): 3-needle BO: no sts are held behind the needle"},
      {held + "Row 1 (RS): 3-needle BO 2 sts, k3.\n",
       "p.md:6: Row 1 (RS): 1 st held behind the needle left unworked at the end of the row"},
      {spare + "Hold the 4 sts of Piece 1 behind the needle, the first st of its last row at the "
               "tip.\n",
       "p.md:5: Hold the sts of Piece 1: the pattern says 4 sts, but its needle holds 3"}};
  for (const auto& [pattern, failure] : cases) EXPECT_EQ(failure_of(pattern), failure) << pattern;
}

}  // namespace
}  // namespace skein
