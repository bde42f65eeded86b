// AutoKnit stitch graphs (.st) as hand patterns: a tube parted along its helix into two legs,
// the second leg's sts (the last st of one rnd and the first of the next) slipped to one
// holder and worked with a new yarn (test-C.st) or with the same yarn carried on from the first
// leg's bind-off (test-B.st); short rows turned on a tuck (test-A.st: sl1yo, turn, sl1, brk),
// going round past the beginning of the rnd; and the simulator's reasons for rejecting those
// steps.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "mesh/autoknit_st.hpp"
#include "target_runner.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

using testing::emit;
using testing::failure_of;

// One line of a stitch graph: its yarn, AutoKnit's letter and the stitches whose loops it
// takes (-1: none); the outs are filled in from the ins, in the order the loops are taken.
struct StLine {
  int yarn;
  char letter;
  int in = -1;
  char dir = 'a';  // flips at a turn
};

std::string st_text(const std::vector<StLine>& lines) {
  std::vector<std::vector<int>> outs(lines.size());
  for (std::size_t s = 0; s < lines.size(); ++s)
    if (lines[s].in >= 0)
      outs[static_cast<std::size_t>(lines[s].in)].push_back(static_cast<int>(s));
  std::string text;
  for (std::size_t s = 0; s < lines.size(); ++s) {
    int out = outs[s].empty() ? -1 : outs[s][0];
    text += fmt::format("{} {} {} {} -1 {} -1 0 0 0\n", lines[s].yarn, lines[s].letter,
                        lines[s].dir, lines[s].in, out);
  }
  return text;
}

// A 6-st tube whose second rnd works 5 sts: its last 3 are one leg (a rnd, then bound off);
// the 6th st of the first rnd and the first 2 of the second are the other leg, worked by
// `second_yarn` (the same yarn goes on from the bind-off when it is 0), whose helix steps up a
// st before its bind-off.
std::string two_legs_st(int second_yarn) {
  std::vector<StLine> lines;
  for (int i = 0; i < 6; ++i) lines.push_back({0, 's'});
  for (int i = 0; i < 6; ++i) lines.push_back({0, 'k', i});             // 6..11
  for (int i = 0; i < 5; ++i) lines.push_back({0, 'k', 6 + i});         // 12..16
  for (int i = 0; i < 3; ++i) lines.push_back({0, 'k', 14 + i});        // 17..19: leg 1
  for (int i = 0; i < 3; ++i) lines.push_back({0, 'e', 17 + i});        // 20..22
  for (int in : {11, 12, 13}) lines.push_back({second_yarn, 'k', in});  // 23..25: leg 2
  lines.push_back({second_yarn, 'k', 23});                              // 26: the helix steps up
  for (int in : {24, 25, 26}) lines.push_back({second_yarn, 'e', in});
  return st_text(lines);
}

// A 6-st tube with two short rows turned on tucks: the first turns after 3 sts, the second
// goes back past the beginning of the rnd and turns 2 sts before it; the rnd from there goes
// all the way round (the rnds begin there from then on), then one more rnd and the bind-off.
std::string tuck_short_rows_st() {
  const int first = 0;
  std::vector<StLine> lines;
  for (int i = 0; i < 6; ++i) lines.push_back({0, 's'});
  for (int i = 0; i < 6; ++i) lines.push_back({0, 'k', i});              // 6..11: at 0..5
  auto at = [&](int position) { return 6 + (position % 6); };            // rnd 1's st there
  for (int i = 0; i < 3; ++i) lines.push_back({0, 'k', at(first + i)});  // 12..14
  lines.push_back({0, 't', at(first + 3)});                              // 15: turns
  lines.push_back({0, 'm', 15, 'c'});                                    // 16
  for (int in : {14, 13, 12}) lines.push_back({0, 'k', in, 'c'});        // 17..19
  lines.push_back({0, 't', at(first + 5), 'c'});                         // 20: turns
  lines.push_back({0, 'm', 20});                                         // 21
  for (int in : {19, 18, 17, 16}) lines.push_back({0, 'k', in});         // 22..25
  lines.push_back({0, 'k', at(first + 4)});                              // 26: round the rnd
  for (int i = 0; i < 6; ++i) lines.push_back({0, 'k', 21 + i});         // 27..32
  for (int i = 0; i < 6; ++i) lines.push_back({0, 'e', 27 + i});
  return st_text(lines);
}

// A flat sheet: cast on `width` sts, `rows` rows, each taking the row before's loops in the
// other order (AutoKnit's dir flips at every turn), and the bind-off.
std::string flat_sheet_st(int width, int rows) {
  std::vector<StLine> lines;
  std::vector<int> below;
  for (int i = 0; i < width; ++i) {
    below.push_back(static_cast<int>(lines.size()));
    lines.push_back({0, 's'});
  }
  for (int r = 0; r <= rows; ++r) {
    char dir = r % 2 == 0 ? 'c' : 'a';
    std::vector<int> row;
    for (auto in = below.rbegin(); in != below.rend(); ++in) {
      row.push_back(static_cast<int>(lines.size()));
      lines.push_back({0, r == rows ? 'e' : 'k', *in, dir});
    }
    below = row;
  }
  return st_text(lines);
}

Compilation compile_st(const std::string& text, const std::string& name) {
  return compile_knit_graph(parse_autoknit_st(text, name), name);
}

void expect_lines(const std::string& pattern, const std::vector<std::string>& lines) {
  for (const std::string& line : lines)
    EXPECT_NE(pattern.find(line), std::string::npos) << line << "\n" << pattern;
}

// Rows inferred from a stitch graph worked flat (dir flips at each turn) are open rows.
TEST(HandStitchGraphs, AFlatSheetIsWrittenInRowsAndProvenInEveryFormat) {
  Compilation c = compile_st(flat_sheet_st(4, 4), "sheet.st");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  EXPECT_EQ(c.knit.row_shape, std::vector<RowShape>(6, RowShape::open));
  expect_lines(emit(c, "hand"), {"Cast on 4 sts.\n\n**Row 1 (RS):** Knit.\n\n**Row 2 (WS):** "
                                 "Purl.\n\nRep Rows 1\u20132 once more.\n"});
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
  // The knitout target knits it too, now that its rows are known (it refused a stitch graph
  // whose yarn turns while it read every one as a helix).
  knitout::MachineProfile generic = testing::shipped_profile("generic");
  EXPECT_TRUE(testing::replay_and_prove(testing::emit_knitout_text(c, generic), c, generic).proven);
}

TEST(HandStitchGraphs, ALegWithANewYarnIsJoinedToTheHeldStsInEveryFormat) {
  Compilation c = compile_st(two_legs_st(1), "legs.st");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  expect_lines(emit(c, "hand"),
               {"**Rnd 1:** Knit.\n\nSlip st 6 of the rnd to holder 1 \u2014 5 sts.\n\n**Rnd 2:** "
                "Knit.\n\nSlip sts 1\u20132 of the rnd to holder 1 (after the 1 st on it) \u2014 3 "
                "sts.\n",
                "Join a new yarn to the 3 sts of holder 1, the first st slipped to it at the tip. "
                "Pm and join to work in the rnd, being careful not to twist.\n\n**Rnd 1:** "
                "Knit.\n\n**Rnd 2:** K1, BO 2 sts "
                "\u2014 1 st.\n\n**Rnd 3:** BO all sts.\n"});
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

TEST(HandStitchGraphs, ALegWithTheSameYarnIsCarriedOnFromTheBindOffInEveryFormat) {
  Compilation c = compile_st(two_legs_st(0), "legs.st");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  expect_lines(
      emit(c, "hand"),
      {"**Rnd 4:** BO all sts.\n\nDo not fasten off: carry the yarn to the 3 sts of holder "
       "1, the first st slipped to it at the tip. Pm and join to work in the rnd.\n\n**Rnd "
       "5:** Knit.\n"});
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

TEST(HandStitchGraphs, ShortRowsTurnedOnATuckAreProvenInEveryFormat) {
  Compilation c = compile_st(tuck_short_rows_st(), "tucks.st");
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  std::string pattern = emit(c, "hand");
  expect_lines(pattern,
               {"- **sl1yo**: slip 1 yarn over", "**Short rows (turned on a tuck):**",
                "**Row 2 (RS):** K3, sl1yo, turn.\n\n**Row 3 (WS):** Sl1, p to m, rm, sl1yo, "
                "turn.\n\n**Rnd 4:** Pm, sl1, k3, brk, k1.\n\n**Rnd 5:** "
                "Brk, k to end.\n"});
  EXPECT_EQ(testing::unproven_hand_formats(c), "") << pattern;
}

TEST(HandStitchGraphs, AutoKnitsShortRowsTurnedOnTucksAreProvenInEveryFormat) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model("samples/autoknit/test-A.st");
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
  expect_lines(emit(c, "hand"),
               {"**Row 3 (RS):** K11, sl1yo, turn.\n\n**Row 4 (WS):** Sl1, p4, sl1yo, turn.\n\n"
                "**Row 5 (RS):** Sl1, k4, brk, k to m, sm, k3, sl1yo, turn.\n",
                "**Row 8 (WS):** Sl1, p to m, rm, p1, sl1yo, turn.\n\n**Rnd 9:** Pm, sl1, k2, "
                "brk, k1, brk, k2, brk, k to last 2 sts, brk, k1.\n"});
}

TEST(HandStitchGraphs, AutoKnitsTubesPartedIntoLegsAreProvenInEveryFormat) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  for (const char* sample : {"samples/autoknit/test-B.st", "samples/autoknit/test-C.st"}) {
    Compilation c = compile_model(sample);
    EXPECT_EQ(testing::unproven_hand_formats(c), "") << sample;
  }
  Compilation b = compile_model("samples/autoknit/test-B.st");
  expect_lines(emit(b, "hand"),
               {"Slip st 17 of the rnd to holder 1 \u2014 16 sts.\n",
                "Slip sts 1\u20138 of the rnd to holder 1 (after the 1 st on it) \u2014 8 sts.\n",
                "Do not fasten off: carry the yarn to the 9 sts of holder 1, the first st slipped "
                "to it at the tip. Pm and join to work in the rnd.\n"});
}

// A 4-st tube: 1 st to holder 1 after Rnd 1, then 2 more after Rnd 2; the yarn bound off the
// other 1 st and is carried on to them.
const std::string kTube =
    "Cast on 4 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\nSlip st 4 of the rnd to "
    "holder 1 \u2014 3 sts.\nRnd 2: Knit.\n";

TEST(HandStitchGraphs, RejectsStsSlippedOntoAHolderThatDoesNotHoldWhatItSays) {
  std::string onto =
      "Slip sts 1\u20132 of the rnd to holder 1 (after the 1 st on it) \u2014 1 st.\n";
  EXPECT_EQ(failure_of(kTube + onto +
                       "Rnd 3: BO all sts.\nDo not fasten off: carry the yarn to "
                       "the 3 sts of holder 1, the first st slipped to it at the "
                       "tip. Pm and join to work in the rnd.\nRnd 4: BO all "
                       "sts.\nFasten off.\n"),
            "");
  EXPECT_EQ(failure_of(kTube + "Slip sts 1\u20132 of the rnd to holder 2 (after the 1 st on it) "
                               "\u2014 1 st.\n"),
            "p.md:5: Slip sts to holder 2 after the 1 st on it: it holds no sts");
  EXPECT_EQ(failure_of(kTube + "Slip sts 1\u20132 of the rnd to holder 1 (after the 2 sts on it) "
                               "\u2014 1 st.\n"),
            "p.md:5: Slip sts to holder 1 after the 2 sts on it: it holds 1 st");
}

TEST(HandStitchGraphs, RejectsCarryingTheYarnOnWithTheReason) {
  std::string held = kTube +
                     "Slip sts 1\u20132 of the rnd to holder 1 (after the 1 st on it) "
                     "\u2014 1 st.\n";
  std::string carry =
      "Do not fasten off: carry the yarn to the 3 sts of holder 1, the first st "
      "slipped to it at the tip.";
  EXPECT_EQ(failure_of(held + carry + "\n"),
            "p.md:6: Carry the yarn to holder 1: 1 st still on the needle; bind them off first");
  held += "Rnd 3: BO all sts.\n";
  EXPECT_EQ(failure_of(held + "Do not fasten off: carry the yarn to the 2 sts of holder 1, the "
                              "first st slipped to it at the tip.\n"),
            "p.md:7: Carry the yarn: the pattern says 2 sts, but the holder holds 3");
  EXPECT_EQ(failure_of(held + "Do not fasten off: carry the yarn to the 3 sts of holder 2, the "
                              "first st slipped to it at the tip.\n"),
            "p.md:7: Carry the yarn: holder 2 holds no sts");
  EXPECT_EQ(failure_of("Do not fasten off: carry the yarn to the 3 sts of holder 1, the first st "
                       "slipped to it at the tip.\n"),
            "p.md:1: Carry the yarn: no yarn is being worked");
  EXPECT_EQ(failure_of(kTube + "Pm and join to work in the rnd.\n"),
            "p.md:5: Join to work in the rnd: only before a piece's first row, or after the yarn "
            "is carried to held sts");
}

// A 6-st tube with a short row turned on a tuck after 2 sts; the row back goes past the
// beginning of the rnd ("p to m" goes round the needle to it).
const std::string kTucked =
    "Cast on 6 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\nRow 2 (RS): K2, sl1yo, "
    "turn.\nRow 3 (WS): Sl1, p to m, sm, p1, sl1yo, turn.\n";

// Every step of a pattern that stops after Row 4 is worked: only the sts left are refused.
TEST(HandStitchGraphs, RejectsAStWithItsYoWorkedWrongWithTheReason) {
  const std::pair<const char*, const char*> row_4[] = {
      {"Sl1, k1, sm, k2, brk", "p.md:5: the pattern ends with 6 sts still on the needle"},
      {"Sl1, k1, sm, k3",
       "p.md:5: Row 4 (RS): k: the next st has a yo over it (sl1yo): work it with brk"},
      {"Sl1, brk, sm, k2, brk", "p.md:5: Row 4 (RS): brk: the next st has no yo over it"},
      {"Sl1, k1, sm, k1, k2tog", "p.md:5: the pattern ends with 5 sts still on the needle"},
  };
  for (const auto& [row, failure] : row_4)
    EXPECT_EQ(failure_of(kTucked + "Row 4 (RS): " + row + ", turn.\n"), failure) << row;
}

}  // namespace
}  // namespace skein
