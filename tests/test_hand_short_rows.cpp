// Short rows in hand patterns: German short rows (turn, DS, k DS) and wrap and turn (w&t, kw),
// flat and in the round, written and proven; and the simulator's reasons for rejecting a turn
// worked wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "fixtures.hpp"
#include "hand/hand_target.hpp"
#include "hand/pattern_document.hpp"
#include "hand/pattern_model.hpp"
#include "hand/pattern_writers.hpp"
#include "labeling/project.hpp"
#include "mesh/generate.hpp"
#include "target_runner.hpp"

namespace skein {
namespace {

using hand::TurnMethod;

std::string markdown(const Compilation& c, TurnMethod turns) {
  std::ostringstream out;
  hand::write_markdown(hand::make_document(hand::build_hand_pattern(c, turns)), out);
  return out.str();
}

bool has_sr5(const Compilation& c) {
  return std::find(c.knit.type.begin(), c.knit.type.end(), StitchType::sr5) != c.knit.type.end();
}

// Random sheets with pairs of short rows (generate.hpp): every sr4 sheet is proven with either
// method; sr5 (the wrap as a loop of its own) is refused by name.
TEST(HandShortRows, RandomShortRowSheetsAreProvenWithEitherMethod) {
  int proven = 0;
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    Compilation c = compile_stitch_mesh(short_row_sheet(5 + seed % 9, 6 + seed % 11, seed), "sr");
    ASSERT_TRUE(c.knittability.knittable) << check_report(c);
    if (has_sr5(c)) {
      try {
        hand::build_hand_pattern(c);
        ADD_FAILURE() << "seed " << seed << ": sr5 was written";
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("(sr5), which hand patterns do not cover yet"),
                  std::string::npos)
            << e.what();
      }
      continue;
    }
    for (TurnMethod turns : {TurnMethod::german, TurnMethod::wrap_and_turn}) {
      std::string pattern = markdown(c, turns);
      VerifyReport report = hand::verify_pattern(pattern, "sr.md", &c);
      ASSERT_TRUE(report.proven) << "seed " << seed << ": " << report.summary << "\n" << pattern;
    }
    ++proven;
  }
  EXPECT_GE(proven, 10);
}

// Fig. 9: a pair of short rows turning at an sr4 face, then a full row and a bind-off.
TEST(HandShortRows, TheFigure9FixtureIsProvenWithEitherMethod) {
  Compilation c = compile_stitch_mesh(testing::short_row_mesh(StitchType::sr4), "fig. 9");
  for (TurnMethod turns : {TurnMethod::german, TurnMethod::wrap_and_turn}) {
    std::string pattern = markdown(c, turns);
    VerifyReport report = hand::verify_pattern(pattern, "fig9.md", &c);
    EXPECT_TRUE(report.proven) << report.summary << "\n" << pattern;
  }
}

TEST(HandShortRows, TheSockHeelReadsInEitherMethod) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model("samples/sock/sock.yaml");
  std::string german = markdown(c, TurnMethod::german);
  EXPECT_NE(german.find("**Row 45 (RS):** K1, pm, k26, turn.\n"), std::string::npos) << german;
  EXPECT_NE(german.find("**Row 46 (WS):** DS, p23, turn.\n"), std::string::npos);
  EXPECT_NE(german.find("**Rnd 49:** DS, k24, k DS, k1, pm, k to end.\n"), std::string::npos);
  EXPECT_NE(german.find("**Short rows (German short rows):**"), std::string::npos);
  std::string wrapped = markdown(c, TurnMethod::wrap_and_turn);
  EXPECT_NE(wrapped.find("**Row 45 (RS):** K1, pm, k25, w&t.\n"), std::string::npos) << wrapped;
  EXPECT_NE(wrapped.find("**Row 47 (RS):** K22, kw, w&t.\n"), std::string::npos);
  EXPECT_NE(wrapped.find("**Short rows (wrap and turn):**"), std::string::npos);
  EXPECT_TRUE(hand::verify_pattern(wrapped, "sock.md", &c).proven);
}

TEST(HandShortRows, TheProjectFileChoosesTheMethod) {
  Project p = parse_project("mesh: sock.obj\nshort_rows: {hand: wrap-and-turn}\n", "p.yaml");
  EXPECT_EQ(p.target.at("short-rows"), "wrap-and-turn");
  Project set = parse_project(
      "mesh: sock.obj\ntarget: {short-rows: german}\nshort_rows: {hand: wrap-and-turn}\n",
      "p.yaml");
  EXPECT_EQ(set.target.at("short-rows"), "german");  // target: says it for the hand target
  try {
    parse_project("mesh: sock.obj\nshort_rows: {hand: wrap}\n", "p.yaml");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("german"), std::string::npos) << e.what();
  }
}

using testing::failure_of;

TEST(HandShortRows, ProvesHandWrittenShortRows) {
  EXPECT_EQ(failure_of("Cast on 6 sts.\nRow 1 (RS): K4, turn.\nRow 2 (WS): DS, p3.\n"
                       "Row 3 (RS): K3, k DS, k2.\nRow 4 (WS): K3, w&t.\nRow 5 (RS): P3.\n"
                       "Row 6 (WS): K3, kw, k2.\nRow 7 (RS): BO all sts.\nFasten off.\n"),
            "");
  EXPECT_EQ(failure_of("Cast on 8 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n"
                       "Row 2 (RS): K5, w&t.\nRow 3 (WS): P3, w&t.\nRnd 4: K3, kw, k to end.\n"
                       "Rnd 5: K1, kw, k to end.\nRnd 6: BO all sts.\nFasten off.\n"),
            "");
}

TEST(HandShortRows, RejectsATurnWorkedWrongWithTheRowAndTheReason) {
  const std::string flat = "Cast on 6 sts.\nRow 1 (RS): K4, turn.\n";
  EXPECT_EQ(failure_of(flat + "Row 2 (WS): DS, p3.\nRow 3 (RS): Knit.\n"),
            "p.md:4: Row 3 (RS): k: the next st is a double stitch: work it with k DS");
  EXPECT_EQ(failure_of(flat + "Row 2 (WS): P1, DS, p2.\n"),
            "p.md:3: Row 2 (WS): DS: only first in a row after a turn, on the st worked last "
            "before it");
  EXPECT_EQ(failure_of(flat + "Row 2 (WS): P4.\nRow 3 (RS): K DS, k5.\n"),
            "p.md:4: Row 3 (RS): k DS: the next st is not a short-row turn");
  EXPECT_EQ(failure_of(flat + "Row 2 (WS): DS, p3, turn, p1.\n"),
            "p.md:3: Row 2 (WS): p after the turn: the row ends where the work turns");
  EXPECT_EQ(failure_of("Cast on 6 sts.\nRow 1 (RS): K3, w&t.\nRow 2 (WS): P3.\n"
                       "Row 3 (RS): K3, k DS, k2.\n"),
            "p.md:4: Row 3 (RS): k DS: the next st is wrapped, not a double stitch");
  const std::string rnd = "Cast on 8 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n";
  EXPECT_EQ(failure_of(rnd + "Row 2 (RS): K5.\n"),
            "p.md:3: Row 2 (RS): a row worked in the rnd ends where the work turns: end it with "
            "w&t or turn");
  EXPECT_EQ(failure_of(rnd + "Row 2 (RS): K5, w&t.\nRow 3 (WS): P to end, turn.\n"),
            "p.md:4: Row 3 (WS): p to end: a row worked in the rnd has no end; give the count");
}

}  // namespace
}  // namespace skein
