// Several pieces in hand patterns: pieces left on spare needles and joined by a three-needle
// bind-off with a new yarn, pieces worked on from both sides of a provisional cast-on (a
// split), pieces picked up along another's edge or worked into its rows one st at a time
// (expanding and contracting perpendicular edges), pieces set aside and taken up again with
// others placed into their rnd (the sweater):
// written and proven; and the simulator's reasons for rejecting them.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>

#include "builtin_targets.hpp"
#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "fixtures.hpp"
#include "hand/hand_target.hpp"
#include "mesh/generate.hpp"
#include "target_runner.hpp"

namespace skein {
namespace {

using testing::emit;
using testing::verify;

TEST(HandJoins, TheJoinFixtureReadsLikeAPatternAndIsProven) {
  Compilation c =
      compile_stitch_mesh(testing::join_mesh(MismatchYarn::Kind::extra), "join fixture");
  std::string pattern = emit(c, "hand");
  EXPECT_NE(pattern.find("### Piece 3 (yarn 3): three-needle bind-off\n"), std::string::npos)
      << pattern;
  EXPECT_NE(pattern.find("Leave the 3 sts on a spare needle and cut the yarn.\n"),
            std::string::npos);
  EXPECT_NE(pattern.find("Piece 1 in front, the first st of its last row at the needle tip"),
            std::string::npos);
  EXPECT_NE(pattern.find("**Three-needle bind-off:**"), std::string::npos);
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

// With a piece's own yarn: the piece knit first is set aside until the other is done.
TEST(HandJoins, JoinsWithAPiecesOwnYarnAreProven) {
  for (bool upper : {false, true}) {
    Compilation c =
        compile_stitch_mesh(testing::join_mesh(MismatchYarn::Kind::own, upper), "join fixture");
    std::string pattern = emit(c, "hand");
    EXPECT_NE(pattern.find("; with its yarn bind off all 3 pairs.\n"), std::string::npos)
        << pattern;
    EXPECT_EQ(testing::unproven_hand_formats(c), "");
  }
}

// Forty pairs of random flat pieces meeting on one line (generate.hpp), on a new yarn or either
// piece's own: every pattern is proven.
void expect_random_meeting_sheets_proven(Meeting meeting) {
  const MismatchYarn::Kind kYarns[] = {MismatchYarn::Kind::extra, MismatchYarn::Kind::own};
  for (std::uint32_t trial = 0; trial < 40; ++trial) {
    Compilation c = compile_stitch_mesh(
        meeting_sheets(meeting, 2 + trial % 9, 2 + trial % 5, 2 + (trial / 5) % 6,
                       kYarns[trial % 2], trial % 4 < 2, trial),
        "meeting sheets");
    ASSERT_TRUE(c.knittability.knittable) << check_report(c);
    std::string pattern = emit(c, "hand");
    VerifyReport report = verify(c, "hand", pattern);
    ASSERT_TRUE(report.proven) << "trial " << trial << ": " << report.summary << "\n" << pattern;
  }
}

// Two flat pieces of random stitches knit towards one line (generate.hpp), joined there with a
// new yarn or either piece's own.
TEST(HandJoins, RandomJoinedSheetsAreProven) {
  expect_random_meeting_sheets_proven(Meeting::join);
}

using testing::failure_of;

std::string joined(std::uint32_t front, std::uint32_t back, std::uint32_t pairs) {
  return fmt::format(
      "Three-needle bind-off: hold the pieces with RS together: Piece {} in front, the first st "
      "of its last row at the needle tip; Piece {} behind, the last st of its last row at the "
      "tip; with a new yarn bind off all {} pairs.\n",
      front, back, pairs);
}

TEST(HandJoins, RejectsAJoinThatCannotBeWorkedWithTheReason) {
  const std::string pieces =
      "## Instructions\nCast on 16 sts.\nRow 1 (RS): Knit.\n"
      "Leave the 16 sts on a spare needle and cut the yarn.\nCast on 15 sts.\n"
      "Row 1 (RS): Knit.\nLeave the 15 sts on a spare needle and cut the yarn.\n";
  EXPECT_EQ(failure_of(pieces + joined(1, 2, 16)),
            "p.md:8: three-needle bind-off: 16 sts on front needle, 15 on back");
  EXPECT_EQ(failure_of(pieces + joined(1, 3, 16)),
            "p.md:8: three-needle bind-off: the sts of Piece 3 are not waiting on a spare needle");
  EXPECT_EQ(failure_of(pieces),
            "p.md:7: the sts of Piece 1 are left on a spare needle, never worked");
  EXPECT_EQ(failure_of("Cast on 4 sts.\nRow 1 (RS): Knit.\n"
                       "Leave the 5 sts on a spare needle and cut the yarn.\n"),
            "p.md:3: Leave the sts: the pattern says 5 sts, but 4 sts are on the needle");
  EXPECT_EQ(failure_of("Cast on 4 sts.\nLeave the 4 sts on a spare needle and cut the yarn.\n"
                       "Cast on 4 sts.\nLeave the 4 sts on a spare needle and cut the yarn.\n" +
                       joined(2, 1, 3)),
            "p.md:5: three-needle bind-off: the pattern says 3 pairs, but the needles hold 4");
  EXPECT_EQ(failure_of("Cast on 4 sts.\nLeave the 4 sts on a spare needle and cut the yarn.\n"
                       "Cast on 4 sts.\nLeave the 4 sts on a spare needle and cut the yarn.\n" +
                       joined(2, 1, 4) + "Fasten off.\n"),
            "");
}

// A needle begun in the middle of a piece's last rnd, its sts following round the needle (a
// leg's sts bound off at the crotch from where the other leg meets it).
TEST(HandJoins, ANeedleMayBeginInTheMiddleOfALastRnd) {
  std::string tubes;
  for (int tube = 0; tube < 2; ++tube)
    tubes +=
        "Cast on 4 sts. Pm and join to work in the rnd, being careful not to twist.\n"
        "Rnd 1: Knit.\nLeave the 4 sts on a spare needle and cut the yarn.\n";
  auto join = [](int tip, const char* way) {
    return fmt::format(
        "Three-needle bind-off: hold the pieces with RS together: Piece 1 in front, st {} of "
        "its last rnd at the needle tip, going {} round the needle; Piece 2 behind, the last st "
        "of its last row at the tip; with a new yarn bind off all 4 pairs.\nFasten off.\n",
        tip, way);
  };
  EXPECT_EQ(failure_of(tubes + join(3, "up")), "");
  EXPECT_EQ(failure_of(tubes + join(2, "down")), "");
  EXPECT_EQ(failure_of(tubes + join(5, "up")),
            "p.md:7: three-needle bind-off: Piece 1 has no st 5");
  try {
    failure_of(tubes + join(3, "across"));
    ADD_FAILURE() << "a needle going across was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("p.md:7: expected 'up round the needle' or 'down round "
                                         "the needle'"),
              std::string::npos)
        << e.what();
  }
}

TEST(HandSplits, TheSplitFixturesAreProvenInEveryFormat) {
  using M = MismatchYarn::Kind;
  const std::pair<StitchMesh, const char*> cases[] = {
      {testing::split_mesh(M::extra), "Join a new yarn to the 3 sts of Piece 1, the first st"},
      {testing::split_mesh(M::own), "Join a new yarn to the 3 loops of Piece 1's chain"},
      {testing::split_mesh(M::own, true), "Join a new yarn to the 3 loops of Piece 1's chain"}};
  for (const auto& [mesh, line] : cases) {
    Compilation c = compile_stitch_mesh(mesh, "split fixture");
    std::string pattern = emit(c, "hand");
    EXPECT_NE(pattern.find("Cast on 3 sts with a provisional cast-on.\n"), std::string::npos)
        << pattern;
    EXPECT_NE(pattern.find(line), std::string::npos) << pattern;
    EXPECT_NE(pattern.find("**Provisional cast-on**"), std::string::npos);
    EXPECT_EQ(testing::unproven_hand_formats(c), "");
  }
}

// Two flat pieces of random stitches knit away from one line (generate.hpp), cast on along it
// with a new yarn or with either piece's own.
TEST(HandSplits, RandomSplitSheetsAreProven) {
  expect_random_meeting_sheets_proven(Meeting::split);
}

TEST(HandSplits, RejectsWorkingASplitWrongWithTheReason) {
  const std::string cast_on = "Cast on 4 sts with a provisional cast-on.\nRow 1 (WS): Purl.\n";
  const std::string bound_off = cast_on + "Row 2 (RS): BO all sts.\nFasten off.\n";
  EXPECT_EQ(failure_of(bound_off),
            "p.md:4: the chain of Piece 1 is left on a spare needle, never worked");
  EXPECT_EQ(failure_of(bound_off + "Join a new yarn to the 5 loops of Piece 1's chain, the "
                                   "first st cast on at the tip.\n"),
            "p.md:5: Join a new yarn: the pattern says 5 sts, but the needle holds 4");
  EXPECT_EQ(failure_of(bound_off + "Join a new yarn to the 4 sts of Piece 1, the first st cast "
                                   "on at the tip.\n"),
            "p.md:5: Join a new yarn: the sts of Piece 1 are not waiting on a spare needle");
  EXPECT_EQ(failure_of(bound_off + "Join a new yarn to the 4 loops of Piece 1's chain, the "
                                   "first st cast on at the tip.\nRow 1 (RS): Knit.\n"
                                   "Row 2 (WS): BO all sts.\nFasten off.\n"),
            "");
}

TEST(HandPickUps, TheExpandingFixtureIsProvenInEveryFormat) {
  Compilation c = compile_stitch_mesh(testing::expanding_mesh(), "expanding fixture");
  std::string pattern = emit(c, "hand");
  EXPECT_NE(pattern.find("Pick up 3 sts along the right edge of Piece 1, one in each row from "
                         "Row 2 down to the cast-on.\n"),
            std::string::npos)
      << pattern;
  EXPECT_NE(pattern.find("**Picking up along an edge:**"), std::string::npos);
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

TEST(HandPickUps, TheContractingFixtureIsProvenInEveryFormat) {
  Compilation c = compile_stitch_mesh(testing::contracting_mesh(), "contracting fixture");
  std::string pattern = emit(c, "hand");
  EXPECT_NE(pattern.find("**Row 1 (RS):** Sl1 from spare, k2tog.\n"), std::string::npos) << pattern;
  EXPECT_NE(pattern.find("**Row 2 (WS):** Sl1 from spare behind, p2tog.\n"), std::string::npos);
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
  EXPECT_EQ(failure_of("Cast on 2 sts.\nRow 1 (RS): Sl1 from spare, k2tog, k1.\n"),
            "p.md:2: Row 1 (RS): sl1 from spare: 0 pieces wait on spare needles; which one is "
            "meant?");
}

// A heel turn's decrease across the gap: the row decreases into the st beyond it on the left
// needle (in the rnd, from the far end of the right one), or into the st at the tip of the
// right needle slipped back ("sl1 back"); the beginning-of-rnd marker is removed there and
// placed anew by the next rnd.
TEST(HandGaps, ARowDecreasesAcrossTheGapIntoItsOwnNeedle) {
  const std::string tube =
      "Cast on 8 sts. Pm and join to work in the rnd, being careful not to twist.\nRnd 1: "
      "Knit.\n";
  EXPECT_EQ(failure_of(tube + "Row 2 (RS): Rm, sl1 back, k2tog, k2, turn — 7 sts.\nRow 3 (WS): Sl1 "
                              "back, p2tog, p1, p2tog, turn — 5 sts.\nRnd 4: Pm, k to end.\nRnd 5: "
                              "BO all sts.\nFasten off.\n"),
            "");
  EXPECT_EQ(failure_of(tube + "Row 2 (RS): Sl1 back, k2tog, k2, turn.\n"),
            "p.md:3: Row 2 (RS): sl1 back: the tip of the right needle holds a marker, not a st");
  EXPECT_EQ(failure_of("Cast on 3 sts.\nRow 1 (RS): Sl1 back, k3.\n"),
            "p.md:2: Row 1 (RS): sl1 back: the tip of the right needle holds nothing, not a st");
}

TEST(HandGaps, TheHeelTurnIsProvenInEveryFormat) {
  Compilation c = compile_knit_graph(testing::heel_turn_graph(), "heel turn");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  std::string pattern = emit(c, "hand");
  for (const char* line : {"**Row 2 (RS):** Rm, k1, k2tog, turn — 5 sts.\n",
                           "**Row 3 (WS):** Sl1 back, [p2tog] 2 times, turn — 3 sts.\n",
                           "**Rnd 4:** Pm, k3.\n", "**Decreasing across a gap**"})
    EXPECT_NE(pattern.find(line), std::string::npos) << line << "\n" << pattern;
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

// "Slip sts 1–2 of Row 1 to holder 1": a run of the sts the last row left, counted in the order
// it worked them; the row must be the last one worked, the run among its sts, the holder empty.
TEST(HandGaps, PartingARowOntoHoldersNeedsItsSts) {
  const std::string row = "Cast on 4 sts.\nRow 1 (RS): Knit.\n";
  const std::string bind_off = "Row 1 (RS): BO all sts.\nFasten off.\n";
  EXPECT_EQ(failure_of(row +
                       "Slip sts 1–2 of Row 1 to holder 1 and sts 3–4 to holder 2.\n"
                       "Cut the yarn.\nJoin a new yarn to the 2 sts of holder 1, the first "
                       "st of its last row at the tip.\n" +
                       bind_off +
                       "Join a new yarn to the 2 sts of holder 2, the first st of its last row "
                       "at the tip.\n" +
                       bind_off),
            "");
  EXPECT_EQ(failure_of(row + "Slip sts 1–2 of Row 2 to holder 1.\n"),
            "p.md:3: Slip sts 1–2 of Row 2 to holder 1: the last row worked is Row 1");
  EXPECT_EQ(failure_of(row + "Slip sts 3–5 of Row 1 to holder 1.\n"),
            "p.md:3: Slip sts 3–5 of Row 1 to holder 1: the row left 4 sts on the needle");
  EXPECT_EQ(failure_of(row + "Row 2 (WS): Purl.\nSlip sts 1–2 of Row 1 to holder 1.\n"),
            "p.md:4: Slip sts 1–2 of Row 1 to holder 1: the row left 0 sts on the needle");
  EXPECT_EQ(failure_of(row + "Slip sts 1–2 of Row 1 to holder 1.\nSlip sts 1–2 of Row 1 "
                             "to holder 1.\n"),
            "p.md:4: Slip sts 1–2 of Row 1 to holder 1: it already holds sts");
  EXPECT_EQ(failure_of(row + "Row 2 (WS): BO all sts.\nFasten off.\nSlip sts 1–2 of Row 1 to "
                             "holder 1.\n"),
            "p.md:5: Slip sts 1–2 of Row 1 to holder 1: no piece is on the needle");
  EXPECT_EQ(failure_of(row + "Slip sts 1–2 of Row 1 to holder 1.\nCut the yarn.\n"),
            "p.md:4: Fasten off: 2 sts still on the needle; bind them off first");
}

// A gusset: the rnd after a flap picks up a st in each of the flap's rows along both edges.
TEST(HandGaps, AGussetIsProvenInEveryFormat) {
  Compilation c = compile_knit_graph(testing::gusset_graph(), "gusset");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  std::string pattern = emit(c, "hand");
  for (const char* line :
       {"**Row 3 (WS):** P3, turn.\n\nPick up 2 sts along the left edge of the flap, one in each "
        "row from Row 3 down to Row 2, onto the needle after the first 3 sts of the rnd.\n\n",
        "Pick up 2 sts along the right edge of the flap, one in each row from Row 2 up to Row 3, "
        "onto the needle after the first 8 sts of the rnd — 10 sts.\n\n**Rnd 4:** Knit.\n"})
    EXPECT_NE(pattern.find(line), std::string::npos) << line << "\n" << pattern;
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

// A gusset whose flap goes on as a leg of its own: the flap's sts go to a holder after the
// rnd that picks up along its edges, and a new yarn is joined to them.
TEST(HandGaps, AGussetLeavingItsFlapToALegIsProvenInEveryFormat) {
  Compilation c = compile_knit_graph(testing::gusset_leg_graph(), "gusset leg");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  std::string pattern = emit(c, "hand");
  for (const char* line :
       {"**Row 3 (WS):** P3, turn.\n\nSlip sts 1\u20133 of the rnd to holder 1 \u2014 3 "
        "sts.\n\nPick up 2 sts along the left edge of the flap, one in each row from Row 3 down to "
        "Row 2, onto the needle at the beginning of the rnd.\n\n",
        "Join a new yarn to the 3 sts of holder 1"})
    EXPECT_NE(pattern.find(line), std::string::npos) << line << "\n" << pattern;
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

// The flap the other way round (letter-r's): the knitter turns at the end of the rnd where the
// model has a shift-path, and goes on down the flap's edge where it has a turn; the flap's sts
// are the last of the rnd.
TEST(HandGaps, AFlapWorkedBackFromTheEndOfTheRndIsProvenInEveryFormat) {
  Compilation c = compile_knit_graph(testing::reversed_gusset_leg_graph(), "reversed gusset leg");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  std::string pattern = emit(c, "hand");
  for (const char* line :
       {"**Row 3 (WS):** P3, turn.\n",
        "Slip sts 4\u20136 of the rnd to holder 1 \u2014 3 sts.\n\nPick up 2 sts along the left "
        "edge of the flap, one in each row from Row 4 down to Row 3, onto the needle at the "
        "beginning of the rnd.\n",
        "Join a new yarn to the 3 sts of holder 1"})
    EXPECT_NE(pattern.find(line), std::string::npos) << line << "\n" << pattern;
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

// A flap's edges are picked up into the rnd of the piece worked, each edge st once.
TEST(HandGaps, AFlapsEdgeIsPickedUpOnceIntoTheRnd) {
  std::string flap =
      "Cast on 6 sts. Pm and join to work in the rnd, being careful not to twist.\nRnd 1: "
      "Knit.\nRow 2 (RS): K3, turn.\nRow 3 (WS): P3, turn.\n";
  const std::string left =
      "Pick up 2 sts along the left edge of the flap, one in each row from Row 3 down to Row 2";
  EXPECT_EQ(failure_of(flap + left + ".\n"),
            "p.md:5: Pick up along the flap: only onto the needle of the piece worked, into its "
            "rnd");
  flap += left + ", onto the needle after the first 3 sts of the rnd.\n";
  EXPECT_EQ(failure_of(flap + "Pick up 2 sts along the left edge of the flap, one in each row "
                              "from Row 2 up to Row 3, onto the needle after the first 8 sts of "
                              "the rnd — 10 sts.\n"),
            "p.md:6: Pick up: Row 2 (RS), st 3 (k) already gave a st");
}

TEST(HandGaps, AFoldedTubeIsProvenInEveryFormat) {
  Compilation c = compile_knit_graph(testing::folded_tube_graph(), "folded tube");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  std::string pattern = emit(c, "hand");
  EXPECT_NE(pattern.find("Three-needle bind-off: fold the 6 sts of Piece 1 in half with RS "
                         "together (count them round the needle from the first st of its last "
                         "rnd): sts 3 down to 1 in front, sts 4 up to 6 behind; with a new yarn "
                         "bind off all 3 pairs.\n"),
            std::string::npos)
      << pattern;
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

// The loops of a provisional cast-on's chain are placed into a rnd like a spare needle's sts.
TEST(HandGaps, AChainIsPlacedIntoTheRndLikeASpareNeedle) {
  const std::string pieces =
      "Cast on 3 sts with a provisional cast-on.\nLeave the 3 sts on a spare needle and cut the "
      "yarn.\nCast on 4 sts. Pm and join to work in the rnd, being careful not to twist.\nRnd "
      "1: Knit.\nLeave the 4 sts on the needle and set the yarn aside (do not cut it).\nTake up "
      "Piece 2 again with its yarn. Place the 3 sts of Piece 1 on the needle at the beginning of "
      "the rnd, the first st of its last row first.";
  const std::string rest = "\nRnd 2: Knit — 10 sts.\nRnd 3: BO all sts.\nFasten off.\n";
  EXPECT_EQ(failure_of(pieces +
                       " Place the 3 loops of Piece 1's chain on the needle after the first 7 "
                       "sts of the rnd, the last st cast on first." +
                       rest),
            "");
  EXPECT_EQ(failure_of(pieces +
                       " Place the 4 loops of Piece 1's chain on the needle after the first 7 "
                       "sts of the rnd, the last st cast on first." +
                       rest),
            "p.md:6: Place the sts of Piece 1: the pattern says 4 sts, but its chain holds 3");
}

// After a band across a gap removed the beginning-of-round marker, sts are placed counting
// from where the next rnd starts (it places the new marker).
TEST(HandGaps, AfterTheMarkerWasRemovedStsArePlacedFromWhereTheRndStarts) {
  auto pattern = [](int after) {
    return fmt::format(
        "Cast on 4 sts. Pm and join to work in the rnd, being careful not to twist.\nRnd 1: "
        "Knit.\nLeave the 4 sts on a spare needle and cut the yarn.\nCast on 6 sts. Pm and "
        "join to work in the rnd, being careful not to twist.\nRnd 1: Knit.\nRow 2 (RS): Rm, "
        "k1, k2tog, turn — 5 sts.\nRow 3 (WS): Sl1 back, [p2tog] 2 times, turn — 3 "
        "sts.\nPlace the 4 sts of Piece 1 on the needle after the first {} sts of the rnd, the "
        "first st of its last rnd first — 7 sts.\nRnd 4: Pm, k to end.\nRnd 5: BO all "
        "sts.\nFasten off.\n",
        after);
  };
  EXPECT_EQ(failure_of(pattern(2)), "");
  EXPECT_EQ(failure_of(pattern(4)), "p.md:8: Place the sts of Piece 1: the rnd has only 3 sts");
}

// A piece worked in the rnd is placed from the st the rnd works first: round its spare needle
// from that st.
TEST(HandGaps, APieceIsPlacedFromTheStItsRndWorksFirst) {
  auto pattern = [](const char* first) {
    return fmt::format(
        "Cast on 4 sts. Pm and join to work in the rnd, being careful not to twist.\nRnd 1: "
        "Knit.\nLeave the 4 sts on a spare needle and cut the yarn.\nCast on 4 sts. Pm and "
        "join to work in the rnd, being careful not to twist.\nRnd 1: Knit.\nLeave the 4 sts "
        "on the needle and set the yarn aside (do not cut it).\nTake up Piece 2 again with its "
        "yarn. Place the 4 sts of Piece 1 on the needle after the first 4 sts of the rnd, {} "
        "first \u2014 8 sts.\nRnd 2: Knit.\nRnd 3: BO all sts.\nFasten off.\n",
        first);
  };
  EXPECT_EQ(failure_of(pattern("st 3 of its last rnd")), "");
  EXPECT_EQ(failure_of(pattern("st 5 of its last rnd")),
            "p.md:7: Place the sts of Piece 1: its needle holds no st 5");
}

// A rnd closed by a three-needle bind-off: its sts folded in half on two needles, each run
// counted round the needle from the first st of the last row.
TEST(HandGaps, ARndFoldedInHalfIsBoundOffAndItsRunsAreChecked) {
  auto pattern = [](const char* sts, const char* runs) {
    return fmt::format(
        "Cast on 6 sts. Pm and join to work in the rnd, being careful not to twist.\nRnd 1: "
        "Knit.\nLeave the 6 sts on a spare needle and cut the yarn.\nThree-needle bind-off: "
        "fold the {} sts of Piece 1 in half with RS together (count them round the needle from "
        "the first st of its last row): {}; with a new yarn bind off all 3 pairs.\nFasten "
        "off.\n",
        sts, runs);
  };
  const char* cases[][3] = {
      {"6", "sts 3 down to 1 in front, sts 4 up to 6 behind", ""},
      {"6", "sts 3 down to 2 in front, sts 4 up to 6 behind",
       "p.md:4: three-needle bind-off: 3 sts from st 3 down end at st 1, not 2"},
      {"6", "sts 3 down to 1 in front, sts 3 up to 5 behind",
       "p.md:4: three-needle bind-off: the front and back needles share sts"},
      {"8", "sts 3 down to 1 in front, sts 4 up to 6 behind",
       "p.md:4: three-needle bind-off: the pattern folds 8 sts, but Piece 1 has 6 sts"},
  };
  for (const auto& [sts, runs, failure] : cases)
    EXPECT_EQ(failure_of(pattern(sts, runs)), failure) << runs;
}

TEST(HandPickUps, RejectsAPickUpThatCannotBeWorkedWithTheReason) {
  const std::string piece =
      "Cast on 2 sts.\nRow 1 (RS): Knit.\nRow 2 (WS): BO all sts.\nFasten off.\n";
  EXPECT_EQ(
      failure_of(piece + "Pick up 4 sts along the right edge of Piece 1, one in each row from "
                         "Row 2 down to the cast-on.\nRow 1 (RS): BO all sts.\nFasten off.\n"),
      "p.md:5: Pick up: the pattern says 4 sts, but there are 3 rows from 0 to 2");
  EXPECT_EQ(failure_of(piece + "Pick up 2 sts along the left edge of Piece 1, one in each row from "
                               "Row 3 down to Row 2.\n"),
            "p.md:5: Pick up: Piece 1 has no Row 3");
  EXPECT_EQ(failure_of(piece + "Pick up 3 sts along the left edge of Piece 1, one in each row from "
                               "the cast-on up to Row 2.\nRow 1 (WS): BO all sts.\nFasten off.\n"),
            "");
  // Into the rnd of a piece being worked, after its first 2 sts.
  const std::string into_rnd =
      "Pick up 2 sts along the left edge of Piece 1, one in each row from Row 1 up to Row 2, onto "
      "the needle after the first 2 sts of the rnd.\n";
  EXPECT_EQ(failure_of(piece + "Cast on 4 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n" +
                       into_rnd + "Rnd 2: Knit \u2014 6 sts.\nRnd 3: BO all sts.\nFasten off.\n"),
            "");
  EXPECT_EQ(failure_of(piece + "Cast on 4 sts.\nRow 1 (RS): Knit.\n" + into_rnd),
            "p.md:7: Pick up along Piece 1 onto the needle: only into a piece worked in the rnd");
  // A pick-up onto the needle counts "of the rnd", never "of the row".
  std::string into_row = into_rnd;
  into_row.replace(into_row.find("of the rnd"), 10, "of the row");
  EXPECT_EQ(failure_of(piece + "Cast on 4 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n" +
                       into_row),
            "p.md:7: Pick up along Piece 1 onto the needle: only into a piece worked in the rnd");
}

// A piece worked word for word as one before it is written once: the sweater's second sleeve
// says "Work as Sleeve 1", and the simulator works Sleeve 1's instructions again for it.
TEST(HandPieces, IdenticalPiecesAreWrittenOnce) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model("samples/sweater/sweater.yaml");
  std::string pattern = emit(c, "hand");
  EXPECT_NE(pattern.find("### Sleeve 2 (yarn 2)\n\nWork as Sleeve 1.\n"), std::string::npos)
      << pattern;
  EXPECT_EQ(testing::occurrences(pattern, "Leave the 60 sts on a spare needle"), 1u);
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
  // Only a piece written before can be worked again.
  std::string later = pattern;
  later.replace(later.find("Work as Sleeve 1."), 17, "Work as Sleeve 2.");
  EXPECT_THROW(hand::verify_pattern(later, "p.md", &c), ParseError);
}

TEST(HandPieces, TheSweaterIsProvenInEveryFormat) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model("samples/sweater/sweater.yaml");
  std::string pattern = emit(c, "hand");
  for (const char* line :
       {"**Rnd 107:** *BO 50 sts, k50; rep from * to end \u2014 100 sts.\n",
        "Leave the 100 sts on the needle and set the yarn aside (do not cut it).\n",
        "Leave the 60 sts on a spare needle and cut the yarn.\n",
        "### Body (yarn 1), taken up again for the yoke\n",
        "Take up Body again with its yarn. Place the 60 sts of Sleeve 1 on the needle at the "
        "beginning of the rnd, the first st of its last rnd first. Place the 60 sts of Sleeve 2 on "
        "the needle after the first 110 sts of the rnd, the first st of its last rnd first \u2014 "
        "220 "
        "sts.\n",
        "**Rnd 108:** K110, pm, k to end.\n"})
    EXPECT_NE(pattern.find(line), std::string::npos) << line;
  // The body is taken up once, for the yoke: the program takes its yarn up and sets it aside
  // again between the sleeves, which the pattern does not write.
  const std::string taken_up = "### Body (yarn 1), taken up again";
  auto first = pattern.find(taken_up);
  EXPECT_EQ(pattern.find(taken_up, first + 1), std::string::npos) << pattern;
  EXPECT_NE(pattern.find(taken_up + " for the yoke\n\nTake up Body again with its yarn. Place"),
            std::string::npos);
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

// A sample's hand pattern holds these lines and is proven in every format.
void expect_written_and_proven(const char* sample, std::initializer_list<const char*> lines) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model(sample);
  std::string pattern = emit(c, "hand");
  for (const char* line : lines) EXPECT_NE(pattern.find(line), std::string::npos) << line;
  EXPECT_EQ(testing::unproven_hand_formats(c), "") << sample;
}

// Three arms knit towards the centre, where their sts go four ways: into each arm beyond it
// (with the sts of two provisional cast-ons) and into two three-needle bind-offs.
TEST(HandPieces, TheThreeBarsAreProvenInEveryFormat) {
  expect_written_and_proven(
      "samples/three-bars/three-bars.yaml",
      {"Slip sts 1\u20139 of the rnd to holder 1, sts 10\u201318 to holder 2 and sts "
       "19\u201327 to holder 3 \u2014 9 sts.\n\nLeave the 9 sts on the needle and set the yarn "
       "aside (do not "
       "cut it).\n",
       "Slip sts 10\u201318 of the rnd to holder 7, sts 19\u201327 to holder 8 and sts "
       "28\u201336 to holder 9 \u2014 9 sts.\n\nPlace the 9 sts of Piece 3 on the needle after the "
       "first 9 "
       "sts of the rnd, the first st cast on first.\n",
       "Place the 9 sts of holder 2 on the needle after the first 27 sts of the rnd, the first "
       "st of its last rnd first \u2014 36 sts.\n",
       "Take up Piece 2 again with its yarn. Place the 9 loops of Piece 3's chain on the needle "
       "at the beginning of the rnd, the last st cast on first.",
       "Three-needle bind-off: hold the pieces with RS together: holder 3 in front, the first st "
       "of its last row at the needle tip; holder 9 behind,"});
}

// Two bars knit towards each other: each ends in a flat face that works the other's sts one
// at a time, placed on its needle (decreasing across the gap), and the rnds beyond pick up
// along its edge.
TEST(HandPieces, TheTwoBarsAreProvenInEveryFormat) {
  expect_written_and_proven(
      "samples/two-bars/two-bars.yaml",
      {"Slip sts 10\u201328 of the rnd to holder 1 and sts 29\u201337 to holder 2 \u2014 9 "
       "sts.\n",
       "Take up Piece 1 again with its yarn. Place the 19 sts of holder 3 on the needle after the "
       "first 9 sts of the rnd, the first st of its last rnd first \u2014 28 sts.\n\n**Row 24 "
       "(RS):** Rm, sl1 back, ssk, k8, turn \u2014 27 sts.\n",
       "Pick up 10 sts along the left edge of Piece 2, one in each row from Row 33 down to Row "
       "24, onto the needle after the first 18 sts of the rnd \u2014 37 sts.\n\n**Rnd 34:** Pm, "
       "k to end.\n",
       "Place the 9 loops of Piece 3's chain on the needle after the first 9 sts of the rnd, the "
       "last st cast on first.\n",
       "holder 2 in front, the first st of its last row at the needle tip; holder 4 behind, the "
       "last st"});
}

// A piece whose numbers count rows among its rnds (before it was set aside too) counts plain
// rnds to a row number, not as "rnds in all".
TEST(HandPieces, PlainRndsAfterRowsCountToARowNumber) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  std::string text = emit(compile_model("samples/two-bars/two-bars.yaml"), "hand");
  EXPECT_EQ(testing::occurrences(text, "Knit every rnd through Rnd 39.\n"), 2u) << text;
  EXPECT_EQ(text.find("until 39 rnds in all"), std::string::npos) << text;
}

// The letter H: the bar slips 7 sts to a holder before it is set aside, works a band across
// gaps between the legs when taken up, and its last join folds its needle together with them.
TEST(HandPieces, TheLetterHIsProvenInEveryFormat) {
  expect_written_and_proven(
      "samples/letter-h/letter-h.yaml",
      {"- 1 stitch holder (or a length of waste yarn).\n",
       "Slip sts 1\u20137 of the rnd to holder 1 \u2014 24 sts.\n",
       "Place the 7 sts of holder 1 on the spare needle of Piece 4 after its st 7 (count round "
       "the needle from the first st of its last row), the last st slipped first \u2014 42 sts. "
       "Three-needle bind-off: fold the 42 sts of Piece 4 in half with RS together",
       // The measurements of a piece of a cast-on alone, and of one of short rows alone.
       "- Piece 2: Width: 3 cm (1.3 in), 7 sts at the widest. A cast-on only: no rows of its "
       "own.\n",
       "sts at the widest. 24 short rows (worked on part of the sts), no whole rnds.\n"});
}

// The letter H at 13 sts and 18 rows to 10 cm: its band across the gaps has an odd number of
// rows, so its last (RS) row goes on round the needle past the gap without turning, and the
// rnd after it starts there (the pattern wrote `turn` and a WS rnd, which did not prove).
TEST(HandPieces, TheLetterHAtAnotherGaugeGoesOnPastTheGapAfterAnOddBand) {
  Compilation c = testing::sample_at_gauge("letter-h", 13, 18);
  std::string text = emit(c, "hand");
  EXPECT_NE(text.find("**Row 27 (RS):** Sl1 back, ssk, k2, ssk, do not turn \u2014 12 sts.\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("**Rnd 28:** Pm, k to end.\n"), std::string::npos) << text;
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

// The two bars at 28 sts and 26 rows to 10 cm: each bar's face has an odd number of rows, so
// its last row goes on into the rnd that places the other pieces' sts and comes round to the
// face's (the pattern wrote a turn there, and refused other gauges for rows it could not give a
// RS and a WS).
TEST(HandPieces, TheTwoBarsAtAnotherGaugeGoOnIntoTheRndAfterAnOddFace) {
  Compilation c = testing::sample_at_gauge("two-bars", 28, 26);
  std::string text = emit(c, "hand");
  EXPECT_EQ(testing::occurrences(text, "**Row 30 (RS):** Sl1 back, ssk, k10, do not turn \u2014 "),
            2u)
      << text;
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

// The letter R at 27 sts and 39 rows to 10 cm: its bowl's rows take sts from two holders at
// once, each on a spare needle of its own (the pattern once wrote `sl1 from spare` for both),
// and its flap has an odd number of rows, worked back from the end of the rnd, whose sts are
// still the rnd's last (the pattern slipped the first ones).
TEST(HandPieces, TheLetterRAtAnotherGaugeNamesEachSpareNeedleAndHoldsItsOddFlap) {
  Compilation c = testing::sample_at_gauge("letter-r", 27, 39);
  std::string text = emit(c, "hand");
  for (const char* line :
       {"Slip sts 9\u201332 of the rnd to holder 1 \u2014 8 sts.\n",
        "Put the 11 sts of holder 3 on a spare needle, the last st of its last rnd at the tip.\n\n"
        "Put the 11 sts of holder 5 on a second spare needle, the first st of its last rnd at the "
        "tip.\n\n**Row 28 (RS):** Sl1 from spare, ssk, k24, sl1 from 2nd spare behind, ssk, "
        "turn.\n"})
    EXPECT_NE(text.find(line), std::string::npos) << line << "\n" << text;
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

// The letter R: a flap worked back from the end of a rnd (the model's shift-path there is a
// turn, its turn after the flap a shift down the flap's edge), the model's rnds knit as its
// mirror image (right to left), a last rnd shared out to holders, a three-needle bind-off in
// the middle of a piece's work said before its rnd, two spare needles at once, a new yarn
// joined in the rnd on a chain, and a last rnd bound off with two pieces held behind it.
TEST(HandPieces, TheLetterRIsProvenInEveryFormat) {
  expect_written_and_proven(
      "samples/letter-r/letter-r.yaml",
      {"**Row 20 (RS):** K10, k DS, k17, turn.\n\n**Row 21 (WS):** P21, turn.\n",
       "**Rnd 28:** Knit.\n\nSlip sts 8\u201328 of the rnd to holder 1 \u2014 7 sts.\n",
       "Slip sts 1\u20138 of the rnd to holder 2, sts 9\u201315 to holder 3, sts 16\u201323 to "
       "holder 4 and sts 24\u201330 to holder 5.\n\nCut the yarn.\n",
       "Hold the 7 sts of holder 3 behind the needle, the last st of its last rnd at the "
       "tip.\n\n**Rnd 20:** K3, k DS, k to last 7 sts, 3-needle BO 7 sts \u2014 21 sts.\n",
       "Put the 8 sts of holder 4 on a second spare needle, the first st of its last rnd at the "
       "tip.\n\n**Row 21 (RS):** Sl1 from spare, ssk, k19, sl1 from 2nd spare behind, ssk, "
       "turn.\n",
       "Join a new yarn to the 7 loops of Piece 1's chain, the last st cast on at the tip. Pm and "
       "join to work in the rnd, being careful not to twist.\n",
       "Hold the 7 sts of holder 5 behind the needle, the last st of its last rnd at the tip. "
       "Hold the 21 sts of Piece 2 behind the needle, the first st of its last row at the "
       "tip.\n\n**Rnd 51:** 3-needle BO 28 sts.\n\nFasten off.\n",
       // The notions and techniques follow: two spare needles at once, and the pick-ups into
       // a rnd.
       "- A second spare needle, for rows that take sts from two at once.\n",
       "onto the needle of a rnd** (\"..., onto the needle after the first 18 sts of the "
       "rnd\"): with the RS facing and no new yarn"});
}

// A tube whose last 2 sts wait on a holder and go back on its spare needle before the fold.
std::string fold_with_held_sts(const std::string& place) {
  return "Cast on 6 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\nSlip sts 5\u20136 of "
         "the rnd to holder 1 \u2014 4 sts.\nLeave the 4 sts on a spare needle and cut the "
         "yarn.\n" +
         place +
         " Three-needle bind-off: fold the 6 sts of Piece 1 in half with RS together (count them "
         "round the needle from the first st of its last rnd): sts 3 down to 1 in front, sts 4 up "
         "to 6 behind; with a new yarn bind off all 3 pairs.\nFasten off.\n";
}

TEST(HandPieces, RejectsPlacingHeldStsOnASpareNeedleWrongWithTheReason) {
  const std::string place =
      "Place the 2 sts of holder 1 on the spare needle of Piece 1 after its st 4 (count round "
      "the needle from the first st of its last rnd), the first st slipped first \u2014 6 sts.";
  auto with = [&](const char* from, const char* to) {
    return fold_with_held_sts(std::regex_replace(place, std::regex(from), to));
  };
  EXPECT_EQ(failure_of(fold_with_held_sts(place)), "");
  EXPECT_EQ(failure_of(with("the 2 sts", "the 3 sts")),
            "p.md:5: Place the sts of holder 1: the pattern says 3 sts, but it holds 2");
  EXPECT_EQ(failure_of(with("its st 4", "its st 5")),
            "p.md:5: Place the sts of holder 1: the spare needle of Piece 1 has no st 5");
  EXPECT_EQ(failure_of(with("6 sts\\.", "7 sts.")),
            "p.md:5: Place the sts of holder 1: the pattern says 7 sts, but the spare needle "
            "holds 6");
  EXPECT_EQ(failure_of(with("Piece 1 after", "Piece 2 after")),
            "p.md:5: Place the sts of holder 1: the sts of Piece 2 are not waiting on a spare "
            "needle");
  EXPECT_EQ(failure_of(fold_with_held_sts("")),
            "p.md:5: three-needle bind-off: the pattern folds 6 sts, but Piece 1 has 4 sts");
}

// A tube whose sts 3-4 wait on a holder for a rnd and are placed back.
std::string tube_with_holder(const std::string& slip, const std::string& place) {
  return "Cast on 6 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n" + slip +
         "\nRnd 2: Knit.\n" + place + "\nRnd 3: BO all sts.\nFasten off.\n";
}

TEST(HandPieces, RejectsSlippingToHoldersAndPlacingThemWrongWithTheReason) {
  const std::string slip = "Slip sts 3\u20134 of the rnd to holder 1.";
  const std::string place =
      "Place the 2 sts of holder 1 on the needle after the first 2 sts of the rnd, the first st of "
      "its last rnd first.";
  EXPECT_EQ(failure_of(tube_with_holder(slip, place)), "");
  EXPECT_EQ(failure_of(tube_with_holder(slip, "")),
            "p.md:7: the sts of holder 1 are left on it, never worked");
  EXPECT_EQ(failure_of(tube_with_holder(
                slip, std::regex_replace(place, std::regex("2 sts of"), "3 sts of"))),
            "p.md:5: Place the sts of holder 1: the pattern says 3 sts, but it holds 2");
  EXPECT_EQ(failure_of(tube_with_holder(
                slip, std::regex_replace(place, std::regex("holder 1"), "holder 2"))),
            "p.md:5: Place the sts: holder 2 holds no sts");
  EXPECT_EQ(failure_of(tube_with_holder("Slip sts 5\u20138 of the rnd to holder 1.", place)),
            "p.md:3: Slip sts 5\u20138 to holder 1: the rnd has only 6 sts");
  EXPECT_EQ(failure_of(tube_with_holder("Slip sts 0\u20131 of the rnd to holder 1.", place)),
            "p.md:3: Slip sts to holder 1: the sts count from 1");
  EXPECT_EQ(failure_of(tube_with_holder(
                "Slip sts 1\u20132 of the rnd to holder 1 and sts 3\u20134 to holder 1.", place)),
            "p.md:3: Slip sts to holder 1: it already holds sts");
  EXPECT_EQ(
      failure_of(tube_with_holder("Slip sts 3\u20134 of the rnd to holder 1 \u2014 5 sts.", place)),
      "p.md:3: Slip sts to holders: the pattern says 5 sts, but 4 sts are on the needle");
  EXPECT_EQ(failure_of(tube_with_holder(
                slip, std::regex_replace(place, std::regex("first\\.$"), "first \u2014 5 sts."))),
            "p.md:5: Place the sts: the pattern says 5 sts, but 6 sts are on the needle");
  EXPECT_EQ(failure_of("Cast on 6 sts.\nRow 1 (RS): Knit.\n" + slip + "\n"),
            "p.md:3: Slip sts to holder 1: only from a piece worked in the rnd");
}

// A tube whose last 2 sts wait on a holder, put on a spare needle and worked one per rnd.
std::string tube_taking_back_one_at_a_time(const std::string& slip, const std::string& put,
                                           const std::string& rnd_3) {
  return "Cast on 6 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n" + slip + "\n" + put +
         "\nRnd 2: Sl1 from spare, k2tog, k3.\n" + rnd_3 + "\nRnd 4: BO all sts.\nFasten off.\n";
}

TEST(HandPieces, RejectsPuttingAHolderOnASpareNeedleWrongWithTheReason) {
  const std::string slip = "Slip sts 5\u20136 of the rnd to holder 1.";
  const std::string put =
      "Put the 2 sts of holder 1 on a spare needle, the first st of its last rnd at the tip.";
  const std::string rnd_3 = "Rnd 3: Sl1 from spare, k2tog, k3.";
  EXPECT_EQ(failure_of(tube_taking_back_one_at_a_time(slip, put, rnd_3)), "");
  EXPECT_EQ(failure_of(tube_taking_back_one_at_a_time(
                slip, std::regex_replace(put, std::regex("2 sts"), "3 sts"), rnd_3)),
            "p.md:4: Put the sts of holder 1: the pattern says 3 sts, but it holds 2");
  EXPECT_EQ(
      failure_of(tube_taking_back_one_at_a_time(
          "Slip sts 3\u20134 of the rnd to holder 2 and sts 5\u20136 to holder 1.",
          put + "\n" + std::regex_replace(put, std::regex("holder 1"), "holder 2"), rnd_3)),
      "p.md:5: Put the sts of holder 2 on a spare needle: the spare needle still holds 2 sts");
  EXPECT_EQ(failure_of(tube_taking_back_one_at_a_time(slip, put, "Rnd 3: Knit.")),
            "p.md:8: 1 st left on the spare needle, never worked");
}

// A tube whose sts 3-4 and 7-8 wait on two holders, put on two spare needles and taken back
// one per rnd at both ends of the two halves.
std::string tube_taking_back_from_two_spare_needles(const std::string& puts,
                                                    const std::string& rnd_2) {
  return "Cast on 8 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\nSlip sts 3\u20134 of the "
         "rnd to holder 1, sts 5\u20136 to holder 3 and sts 7\u20138 to holder 2 \u2014 2 "
         "sts.\nPlace the 2 sts of holder 3 on the needle after the first 1 sts of the rnd, the "
         "first st of its last rnd first \u2014 4 sts.\n" +
         puts + "\n" + rnd_2 +
         "\nRnd 3: Sl1 from spare, k2tog, k1, sl1 from 2nd spare, k2tog, k1.\nRnd 4: BO all "
         "sts.\nFasten off.\n";
}

TEST(HandPieces, TwoSpareNeedlesGiveTheirStsAndRejectWrongStepsWithTheReason) {
  const std::string puts =
      "Put the 2 sts of holder 1 on a spare needle, the first st of its last rnd at the tip.\nPut "
      "the 2 sts of holder 2 on a second spare needle, the first st of its last rnd at the tip.";
  const std::string rnd_2 = "Rnd 2: Sl1 from spare, k2tog, k1, sl1 from 2nd spare, k2tog, k1.";
  EXPECT_EQ(failure_of(tube_taking_back_from_two_spare_needles(puts, rnd_2)), "");
  EXPECT_EQ(failure_of(tube_taking_back_from_two_spare_needles(
                puts.substr(0, puts.find('\n')),
                "Rnd 2: Sl1 from spare, k2tog, k1, sl1 from 2nd spare, k2tog, k1.")),
            "p.md:6: Rnd 2: sl1 from 2nd spare: no sts wait on a second spare needle");
  EXPECT_EQ(failure_of(tube_taking_back_from_two_spare_needles(
                puts + "\n" +
                    std::regex_replace(puts.substr(puts.find('\n') + 1), std::regex("holder 2"),
                                       "holder 3"),
                rnd_2)),
            "p.md:7: Put the sts of holder 3 on a second spare needle: the second spare needle "
            "still holds 2 sts");
}

// A pick-up along rows one of which worked no st (it only turned) has nothing to pick up there.
TEST(HandPieces, APickUpAlongARowThatWorkedNoStIsRejected) {
  EXPECT_EQ(failure_of("Cast on 4 sts.\nRow 1 (RS): Knit.\nRow 2 (WS): Turn.\nRow 3 (RS): "
                       "Knit.\nRow 4 (WS): BO all sts.\nFasten off.\nPick up 4 sts along the right "
                       "edge of Piece 1, one in each row from Row 1 up to Row 4.\nRow 1 (WS): BO "
                       "all sts.\nFasten off.\n"),
            "p.md:7: Pick up: Row 2 worked no st to pick up from");
}

std::string body_and_sleeve(const std::string& take_up) {
  return "Cast on 8 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n"
         "Leave the 8 sts on the needle and set the yarn aside (do not cut it).\n"
         "Cast on 4 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n"
         "Leave the 4 sts on a spare needle and cut the yarn.\n" +
         take_up + "Rnd 2: Knit.\nRnd 3: BO all sts.\nFasten off.\n";
}

TEST(HandPieces, RejectsSettingAsideAndTakingUpWrongWithTheReason) {
  const std::string place =
      " Place the 4 sts of Piece 2 on the needle after the first 4 sts of the rnd, the first st "
      "of its last rnd first.\n";
  EXPECT_EQ(failure_of(body_and_sleeve("Take up Piece 1 again with its yarn." + place)), "");
  EXPECT_EQ(failure_of(body_and_sleeve("Take up Piece 3 again with its yarn." + place)),
            "p.md:7: Take up Piece 3: it was not set aside");
  EXPECT_EQ(failure_of(body_and_sleeve("Take up Piece 1 again with its yarn. Place the 5 sts of "
                                       "Piece 2 on the needle at the beginning of the rnd, the "
                                       "first st of its last rnd first.\n")),
            "p.md:7: Place the sts of Piece 2: the pattern says 5 sts, but its needle holds 4");
  EXPECT_EQ(failure_of(body_and_sleeve("Take up Piece 1 again with its yarn. Place the 4 sts of "
                                       "Piece 2 on the needle after the first 9 sts of the rnd, "
                                       "the first st of its last rnd first.\n")),
            "p.md:7: Place the sts of Piece 2: the rnd has only 8 sts");
  EXPECT_EQ(failure_of(body_and_sleeve("")),
            "p.md:7: Rnd: no sts are on the needle (take up Piece 1 again first)");
}

// A provisional cast-on (Piece 1) whose sts or chain a tube (Piece 2) places into a rnd in
// the middle of its work; the other side is worked by Piece 3.
std::string tube_taking_in(const std::string& place, const std::string& other_side) {
  return "Cast on 2 sts with a provisional cast-on.\n"
         "Leave the 2 sts on a spare needle and cut the yarn.\n"
         "Cast on 4 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n" +
         place + "\nRnd 2: Knit \u2014 6 sts.\nRnd 3: BO all sts.\nFasten off.\n" + other_side +
         "Row 1 (RS): BO all sts.\nFasten off.\n";
}

TEST(HandPieces, PlacesASpareNeedleOrAChainIntoARndInTheMiddleOfTheWork) {
  const std::string chain_side =
      "Join a new yarn to the 2 loops of Piece 1's chain, the first st cast on at the tip.\n";
  const std::string needle_side =
      "Join a new yarn to the 2 sts of Piece 1, the first st cast on at the tip.\n";
  EXPECT_EQ(failure_of(tube_taking_in("Place the 2 sts of Piece 1 on the needle after the first 2 "
                                      "sts of the rnd, the first st cast on first.",
                                      chain_side)),
            "");
  EXPECT_EQ(failure_of(tube_taking_in("Place the 2 loops of Piece 1's chain on the needle at the "
                                      "beginning of the rnd, the last st cast on first.",
                                      needle_side)),
            "");
  EXPECT_EQ(failure_of(tube_taking_in("Place the 3 loops of Piece 1's chain on the needle at the "
                                      "beginning of the rnd, the last st cast on first.",
                                      needle_side)),
            "p.md:5: Place the sts of Piece 1: the pattern says 3 sts, but its chain holds 2");
  EXPECT_EQ(failure_of(tube_taking_in("Place the 2 loops of Piece 1's chain on the needle at the "
                                      "beginning of the rnd, the last st cast on first.",
                                      chain_side)),
            "p.md:9: Join a new yarn: the chain of Piece 1 is not waiting on a spare needle");
  EXPECT_EQ(failure_of(tube_taking_in("", needle_side)),
            "p.md:6: Rnd 2: the pattern says 6 sts, but 4 sts are on the needle");
}

// A flat piece's next row works placed sts after the first N sts of the needle it works (the
// teapot's top taken up on a chain and a holder); "of the row" only on a flat piece.
TEST(HandPieces, PlacingOnAFlatNeedleCountsTheRowsSts) {
  const std::string spare =
      "Cast on 3 sts.\nRow 1 (RS): Knit.\nLeave the 3 sts on a spare needle and cut the yarn.\n";
  auto placed = [&](const std::string& where, const char* piece) {
    return spare + piece + "Place the 3 sts of Piece 1 on the needle " + where +
           ", the first st of its last row first \u2014 5 sts.\nRow 2 (WS): P5.\nRow 3 (RS): "
           "BO all sts.\nFasten off.\n";
  };
  const char* flat = "Cast on 2 sts.\nRow 1 (RS): Knit.\n";
  EXPECT_EQ(failure_of(placed("after the first 2 sts of the row", flat)), "");
  EXPECT_EQ(failure_of(placed("after the first 3 sts of the row", flat)),
            "p.md:6: Place the sts of Piece 1: the row has only 2 sts");
  EXPECT_EQ(failure_of(placed("after the first 2 sts of the rnd", flat)),
            "p.md:6: Place the sts of Piece 1: only into a piece worked in the rnd");
  EXPECT_EQ(failure_of(placed("after the first 2 sts of the row",
                              "Cast on 2 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n")),
            "p.md:6: Place the sts of Piece 1: only into a piece worked in the rnd (count them "
            "'of the rnd')");
}

// The teapot: its body parted into two strips going on as tubes; the body's last row parted
// between the pieces that take it (the top's middle strip, its sides joined to it a st a row,
// the back strip); the middle strip turned like a heel on a new yarn, its sides on spare
// needles ("sl1 from spare"); a row of it that leaves sts to another yarn slips them to holders
// first; a second new yarn on them going on as a tube round a provisional cast-on; and the
// strip taken up again on that cast-on's chain and the new yarn's held sts, placed on its flat
// needle after the sts its next row works first.
TEST(HandPieces, TheTeapotIsProvenInEveryFormat) {
  expect_written_and_proven(
      "samples/teapot/teapot.yaml",
      {"Slip sts 1\u20137 of Row 18 to holder 10, sts 8\u201330 to holder 11, sts 31\u201353 to "
       "holder 12, sts 54\u201374 to holder 13 and sts 75\u201382 to holder 14.\n\nCut the yarn.\n",
       "Put the 7 sts of holder 10 on a spare needle, the last st of its last row at the tip.\n\n"
       "Put the 23 sts of holder 12 on a second spare needle, the first st of its last row at the "
       "tip.\n\n**Row 2 (WS):** Sl1 from spare, ssp, p to last st, sl1 from 2nd spare behind, "
       "ssp.\n",
       "Slip sts 1\u20137 of Row 8 to holder 15 and sts 8\u201314 to holder 16 \u2014 7 sts.\n\n"
       "**Row 9 (RS):** Sl1 from 2nd spare, ssk, k to end.\n",
       "Slip the 7 sts of Row 8 to holder 17.\n",
       "Place the 7 sts of holder 16 on the needle after the first 8 sts of the rnd, the last st "
       "of its last row first.\n",
       "**Rnd 9:** CO 7 sts with a provisional cast-on, k to end \u2014 30 sts.\n",
       "Take up Piece 4 again with its yarn. Put the 8 sts of holder 14 on a spare needle, the "
       "last st of its last row at the tip. Place the 7 loops of Piece 5's chain on the needle "
       "after the first 7 sts of the row, the last st cast on first. Place the 7 sts of holder 17 "
       "on the needle after the first 14 sts of the row, the last st of its last row first "
       "\u2014 21 sts.\n\n**Row 17 (RS):** Sl1 from 2nd spare, ssk, k to last st, sl1 from spare "
       "behind, ssk.\n",
       "Three-needle bind-off: hold the pieces with RS together: Piece 4 in front, the first st "
       "of its last row at the needle tip; holder 13 behind, the last st of its last row at the "
       "tip"});
}

// A piece that is only a cast-on, parted between the pieces that take it (a glove's fingers):
// "Slip sts A–B of the cast-on to holder H" counts the sts as cast on, before any is slipped.
TEST(HandHolders, APieceOnlyCastOnIsPartedCountedAsCastOn) {
  const std::string cast_on = "## Piece 1\nCast on 6 sts.\n";
  const std::string rest =
      "Leave the 2 sts on a spare needle and cut the yarn.\n"
      "## Piece 2\nJoin a new yarn to the 2 sts of holder 1, the first st slipped to it at the "
      "tip.\nRow 1 (RS): BO all sts.\nFasten off.\n"
      "## Piece 3\nJoin a new yarn to the 2 sts of holder 2, the first st slipped to it at the "
      "tip.\nRow 1 (RS): BO all sts.\nFasten off.\n"
      "## Piece 4\nJoin a new yarn to the 2 sts of Piece 1, the first st cast on at the tip.\n"
      "Row 1 (RS): BO all sts.\nFasten off.\n";
  const std::string parted =
      "Slip sts 1\u20132 of the cast-on to holder 1 and sts 3\u20134 to holder 2";
  EXPECT_EQ(failure_of(cast_on + parted + " \u2014 2 sts.\n" + rest), "");
  EXPECT_EQ(failure_of(cast_on + parted + " \u2014 3 sts.\n" + rest),
            "p.md:3: Slip sts to holders: the pattern says 3 sts, but 2 sts are on the needle");
  EXPECT_EQ(failure_of(cast_on + "Slip sts 5\u20137 of the cast-on to holder 1.\n" + rest),
            "p.md:3: Slip sts 5\u20137 of the cast-on to holder 1: the cast-on left 6 sts on the "
            "needle");
}

}  // namespace
}  // namespace skein
