// Short rows in hand patterns: German short rows (turn, DS, k DS) and wrap and turn (w&t, kw),
// flat and in the round, written and proven; and the simulator's reasons for rejecting a turn
// worked wrong.
#include <fmt/format.h>
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
#include "hand/program_pattern.hpp"
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

// Random sheets with pairs of short rows (generate.hpp), turning at sr4 or sr5 faces: every
// sheet is proven with either method.
TEST(HandShortRows, RandomShortRowSheetsAreProvenWithEitherMethod) {
  int proven[2] = {0, 0};  // sheets without and with sr5 faces
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    Compilation c = compile_stitch_mesh(short_row_sheet(5 + seed % 9, 6 + seed % 11, seed), "sr");
    ASSERT_TRUE(c.knittability.knittable) << check_report(c);
    for (TurnMethod turns : {TurnMethod::german, TurnMethod::wrap_and_turn}) {
      std::string pattern = markdown(c, turns);
      VerifyReport report = hand::verify_pattern(pattern, "sr.md", &c);
      ASSERT_TRUE(report.proven) << "seed " << seed << ": " << report.summary << "\n" << pattern;
    }
    ++proven[has_sr5(c)];
  }
  EXPECT_GE(proven[0], 10);
  EXPECT_GE(proven[1], 10);
}

TargetOptions turning(const char* method) {
  TargetOptions options;
  options.settings["short-rows"] = method;
  return options;
}

// Fig. 9 with an sr5 (the turn's loop a loop of its own, which the k2tog above knits together
// with the sr5's): a knitter's DS or wrap is that loop, so the pattern is the sr4 fixture's
// word for word, and each is proven against either model: the text cannot tell them apart.
TEST(HandShortRows, AnSr5TurnReadsAsAnSr4TurnAndIsProvenInEveryFormat) {
  Compilation sr5 = compile_stitch_mesh(testing::short_row_mesh(StitchType::sr5), "fig. 9");
  Compilation sr4 = compile_stitch_mesh(testing::short_row_mesh(StitchType::sr4), "fig. 9");
  for (const char* method : {"german", "wrap-and-turn"}) {
    EXPECT_EQ(testing::unproven_hand_formats(sr5, turning(method)), "") << method;
    std::string pattern = testing::emit(sr5, "hand", turning(method));
    EXPECT_EQ(pattern, testing::emit(sr4, "hand", turning(method))) << method;
    EXPECT_TRUE(testing::verify(sr4, "hand", pattern).proven) << method;
  }
  std::string german = testing::emit(sr5, "hand", turning("german"));
  EXPECT_NE(german.find("**Row 1 (RS):** K2, pm, k1, turn.\n"), std::string::npos) << german;
  EXPECT_NE(german.find("**Row 2 (WS):** DS, sm, p2.\n"), std::string::npos);
  EXPECT_NE(german.find("**Row 3 (RS):** K to m, rm, k DS, k1.\n"), std::string::npos);
  EXPECT_NE(german.find("- 1 stitch marker.\n"), std::string::npos) << "no rnd to begin";
}

std::string instructions_of(const std::string& pattern) {
  return pattern.substr(pattern.find("## Instructions"));
}

// The sock's and the wedge's projects with `short_rows: {method: sr5}`: the sock's heel turns
// at 13 sr5 faces (and one sr4, where no st of its face is above), the wedge at 4 (and 5 sr4);
// each reads as the sample's own pattern and is proven in every format with either method.
TEST(HandShortRows, SamplesTurningAtSr5FacesAreProvenInEveryFormatWithEitherMethod) {
  for (auto [sample, turns] : {std::pair{"sock", 13}, std::pair{"short-row-wedge", 4}}) {
    Compilation c = testing::sample_turning_at_sr5_faces(sample);
    ASSERT_EQ(std::count(c.knit.type.begin(), c.knit.type.end(), StitchType::sr5), turns);
    Compilation own =
        compile_model(fmt::format("{}/samples/{}/{}.yaml", SKEIN_SOURCE_DIR, sample, sample));
    for (const char* method : {"german", "wrap-and-turn"}) {
      EXPECT_EQ(testing::unproven_hand_formats(c, turning(method)), "") << sample << method;
      EXPECT_EQ(instructions_of(testing::emit(c, "hand", turning(method))),
                instructions_of(testing::emit(own, "hand", turning(method))))
          << sample << method;
    }
  }
  Compilation c = testing::sample_turning_at_sr5_faces("sock");
  std::string german = testing::emit(c, "hand", turning("german"));
  EXPECT_NE(german.find("**Row 46 (WS):** DS, p23, turn.\n"), std::string::npos) << german;
  EXPECT_NE(german.find("**Rnd 49:** DS, k24, k DS, k1, pm, k to end.\n"), std::string::npos);
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

// The sock at a row gauge so tall that its heel's short rows turn again at the st the last one
// turned at: with German short rows the row works that double stitch as one and turns
// (`k DS, turn`); with wrap and turn it wraps the wrapped st again (`w&t`), and `kw` later works
// both wraps with it; either is proven in every format.
TEST(HandShortRows, ATurnAtTheStTheLastShortRowTurnedAtWorksItsDoubleStitchFirstOrWrapsItAgain) {
  Compilation c = testing::sock_turning_twice_at_a_st();
  std::string german = markdown(c, TurnMethod::german);
  EXPECT_NE(german.find("**Row 69 (RS):** DS, k8, k DS, turn.\n"), std::string::npos) << german;
  EXPECT_NE(german.find("**Row 70 (WS):** DS, p8, p DS, turn.\n"), std::string::npos);
  EXPECT_EQ(german.find("two wraps"), std::string::npos);
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
  std::string wrapped = markdown(c, TurnMethod::wrap_and_turn);
  EXPECT_NE(wrapped.find("**Row 69 (RS):** K8, w&t.\n"), std::string::npos) << wrapped;
  EXPECT_NE(wrapped.find("**Row 70 (WS):** P8, w&t.\n"), std::string::npos);
  EXPECT_NE(wrapped.find("When w&t comes to a st that is already wrapped, wrap it again"),
            std::string::npos);
  EXPECT_EQ(testing::unproven_hand_formats(c, turning("wrap-and-turn")), "");
}

// The wedge purled: the decrease over each sr5 is a p2tog (seen from the RS), worked as p DS
// (or pw) on a RS row.
TEST(HandShortRows, APurledWedgeTurningAtSr5FacesIsProvenWithEitherMethod) {
  Compilation c = testing::sample_turning_at_sr5_faces("short-row-wedge", "pattern: purl\n");
  ASSERT_EQ(std::count(c.knit.type.begin(), c.knit.type.end(), StitchType::p2tog), 4);
  for (const char* method : {"german", "wrap-and-turn"})
    EXPECT_EQ(testing::unproven_hand_formats(c, turning(method)), "") << method;
  std::string german = testing::emit(c, "hand", turning("german"));
  EXPECT_NE(german.find("**Row 32 (RS):** P to m, sm, p DS, p4, k1, turn.\n"), std::string::npos)
      << german;
  EXPECT_NE(testing::emit(c, "hand", turning("wrap-and-turn")).find("sm, pw, p"),
            std::string::npos);
}

// A DS (or wrap) over an sr5 is worked as the decrease above it shows from the RS: a k2tog
// knit, not purled.
TEST(HandShortRows, AnSr5sDecreaseWorkedAsAnotherStIsFoundWhenTheFabricIsCompared) {
  Compilation c = compile_stitch_mesh(testing::short_row_mesh(StitchType::sr5), "fig. 9");
  std::string pattern = testing::emit(c, "hand");
  pattern.replace(pattern.find("rm, k DS"), 8, "rm, p DS");
  VerifyReport report = testing::verify(c, "hand", pattern);
  EXPECT_FALSE(report.proven);
  EXPECT_NE(report.summary.find("Row 3 (RS), st 3 (p): the pattern makes p (as seen from the RS) "
                                "where the model has k2tog (worked by hand as k)"),
            std::string::npos)
      << report.summary;
}

// An sr5 whose turn loop goes into another st than its own loop: a knitter works a DS or a wrap
// as one st, so the pattern cannot be written.
TEST(HandShortRows, AnSr5WhoseLoopsAreNotKnitTogetherIsRefusedByName) {
  Compilation fixture = compile_stitch_mesh(testing::short_row_mesh(StitchType::sr5), "fig. 9");
  KnitGraph g = fixture.knit;
  auto sr5 = static_cast<StitchId>(std::find(g.type.begin(), g.type.end(), StitchType::sr5) -
                                   g.type.begin());
  Loop& turn_loop = g.loops[g.loops_made_by(sr5)[1]];
  StitchId next = g.yarn_next[turn_loop.taker];  // the st after the k2tog along the row
  Loop& other = g.loops[g.loops_taken_by(next)[0]];
  std::swap(turn_loop.taker, other.taker);
  std::swap(turn_loop.taker_slot, other.taker_slot);
  g.index_loops();
  Compilation c = compile_knit_graph(std::move(g), "sr5 apart");
  try {
    hand::build_hand_pattern(c);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "hand target: face 7 (sr5, row 2) is an sr5 whose two loops (its st's and the "
              "turn's) are not knit together by one k2tog, ssk or p2tog above it, as a knitter "
              "works a double stitch or a wrap with its st; make it an sr4");
  }
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
  // A w&t at a wrapped st wraps it again; kw works both wraps with it.
  EXPECT_EQ(failure_of("Cast on 8 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\n"
                       "Row 2 (RS): K5, w&t.\nRow 3 (WS): P3, w&t.\nRow 4 (RS): K3, w&t.\n"
                       "Row 5 (WS): P3, w&t.\nRnd 6: K3, kw, k to end.\nRnd 7: K1, kw, k to end.\n"
                       "Rnd 8: BO all sts.\nFasten off.\n"),
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
  EXPECT_EQ(failure_of(rnd + "Row 2 (RS): K5, w&t.\nRow 3 (WS): P3, w&t.\n"
                             "Row 4 (RS): K3, w&t.\nRow 5 (WS): P3, w&t.\nRow 6 (RS): K3, k1.\n"),
            "p.md:7: Row 6 (RS): k: the next st is wrapped (2 wraps): work it with kw");
  EXPECT_EQ(failure_of(rnd + "Row 2 (RS): K5.\n"),
            "p.md:3: Row 2 (RS): a row worked in the rnd ends where the work turns: end it with "
            "w&t or turn");
  EXPECT_EQ(failure_of(rnd + "Row 2 (RS): K5, w&t.\nRow 3 (WS): P to end, turn.\n"),
            "p.md:4: Row 3 (WS): p to end: a row worked in the rnd has no end; give the count");
}

}  // namespace
}  // namespace skein
