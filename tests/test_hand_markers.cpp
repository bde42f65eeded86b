// Markers around the regions Algorithm 1's schedule marks (paper §5.1): short-row turns and
// groups of stitches beside mismatched edges get a marker at each end of the region, placed by
// the first row that passes it, slipped by later rows, removed by the row that finishes the
// region; and the simulator's reasons for rejecting markers worked wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>

#include "driver/pipeline.hpp"
#include "fixtures.hpp"
#include "hand/pattern_document.hpp"
#include "hand/pattern_model.hpp"
#include "hand/pattern_writers.hpp"
#include "hand/program_pattern.hpp"
#include "hand/region_markers.hpp"
#include "mesh/generate.hpp"
#include "target_runner.hpp"
#include "test_hand_plans.hpp"

namespace skein {
namespace {

using hand::HandOp;
using hand::TurnMethod;
using testing::failure_of;

std::string markdown(const hand::HandPattern& pattern) {
  std::ostringstream out;
  hand::write_markdown(hand::make_document(pattern), out);
  return out.str();
}

// Occurrences of a word in the instructions.
std::size_t count(const std::string& pattern, const std::string& what) {
  const std::string text = pattern.substr(pattern.find("## Instructions") + 1);
  const std::regex word("\\b" + what + "\\b");
  return static_cast<std::size_t>(
      std::distance(std::sregex_iterator(text.begin(), text.end(), word), std::sregex_iterator()));
}

std::string line_of(const std::string& text, const std::string& label) {
  std::size_t at = text.find("**" + label + ":**");
  return at == std::string::npos ? "" : text.substr(at, text.find('\n', at) - at);
}

// The wedge's short rows turn between sts 26 and 40: a marker at each end of that span,
// placed where a row first goes past it, slipped on, removed by the row that works every st.
TEST(HandMarkers, ShortRowRegionsAreMarkedSlippedAndRemoved) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model("samples/short-row-wedge/short-row-wedge.yaml");
  for (TurnMethod turns : {TurnMethod::german, TurnMethod::wrap_and_turn}) {
    std::string text = markdown(hand::build_hand_pattern(c, turns));
    EXPECT_TRUE(hand::verify_pattern(text, "wedge.md", &c).proven) << text;
    EXPECT_EQ(count(text, "pm"), 2u) << text;
    EXPECT_EQ(count(text, "rm"), 2u) << text;
    EXPECT_NE(line_of(text, "Row 30 (RS)").find("K26, pm,"), std::string::npos) << text;
    EXPECT_NE(line_of(text, "Row 46 (RS)").find("K to m, sm,"), std::string::npos) << text;
    EXPECT_NE(line_of(text, "Row 48 (RS)").find("K to m, rm,"), std::string::npos) << text;
    EXPECT_EQ(count(line_of(text, "Row 49 (WS)"), "m"), 0u) << text;
  }
}

// Random short-row sheets (sr4 and sr5 turns): every marker placed is removed before the
// bind-off.
TEST(HandMarkers, EveryShortRowMarkerPlacedIsRemoved) {
  int marked = 0;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    Compilation c = compile_stitch_mesh(short_row_sheet(5 + seed % 9, 6 + seed % 11, seed), "sr");
    std::string text = markdown(hand::build_hand_pattern(c, TurnMethod::german));
    ASSERT_TRUE(hand::verify_pattern(text, "sr.md", &c).proven) << "seed " << seed << "\n" << text;
    EXPECT_EQ(count(text, "pm"), count(text, "rm")) << "seed " << seed << "\n" << text;
    marked += count(text, "pm") > 0;
  }
  EXPECT_GE(marked, 5);
}

// A flat piece of 10 sts whose rows 1-2 work sts 4-7 beside a mismatched edge, as the
// schedule's marker events say (before the 4th and the 8th st of each row), then a row that
// decreases, a plain row and the bind-off.
hand::HandPattern mismatch_group_pattern(std::vector<HandOp> row3) {
  hand::HandPattern p;
  p.source = "mismatch group";
  hand::PatternSection s;
  s.cast_on = s.live_at_end = 10;
  s.piece = 1;
  s.end_row = 5;
  p.sections.push_back(s);
  std::vector<std::vector<HandOp>> rows = {
      std::vector<HandOp>(10, HandOp::k), std::vector<HandOp>(10, HandOp::p), std::move(row3),
      std::vector<HandOp>(9, HandOp::p), std::vector<HandOp>(9, HandOp::bo)};
  for (std::uint32_t i = 0; i < rows.size(); ++i) {
    hand::PatternRow r;
    r.number = i + 1;
    r.side = i % 2 ? hand::Side::ws : hand::Side::rs;
    r.first_op = static_cast<std::uint32_t>(p.ops.size());
    p.ops.insert(p.ops.end(), rows[i].begin(), rows[i].end());
    r.end_op = static_cast<std::uint32_t>(p.ops.size());
    r.sts_before = i < 3 ? 10 : 9;
    r.sts_after = i == 4 ? 0 : i < 2 ? 10 : 9;
    r.bind_off = i == 4;
    p.rows.push_back(r);
    if (i < 2)
      for (std::uint32_t op : {3u, 7u})
        p.region_marks.push_back(
            {i, op, op == 3 ? MarkerKind::mismatch_begin : MarkerKind::mismatch_end});
  }
  return p;
}

TEST(HandMarkers, MismatchGroupsAreMarkedFromTheScheduleMarkerEvents) {
  std::vector<HandOp> row3(10, HandOp::k);
  row3[8] = HandOp::k2tog;  // after the group: 9 sts
  row3.pop_back();
  hand::HandPattern p = mismatch_group_pattern(row3);
  hand::place_region_markers(p);
  std::string text = markdown(p);
  EXPECT_EQ(failure_of(text), "") << text;
  EXPECT_EQ(line_of(text, "Row 1 (RS)"), "**Row 1 (RS):** K3, pm, k to last 3 sts, pm, k3.");
  EXPECT_EQ(line_of(text, "Row 2 (WS)"), "**Row 2 (WS):** Purl.");  // slipping the markers
  EXPECT_EQ(line_of(text, "Row 3 (RS)"),
            "**Row 3 (RS):** K to m, rm, k to m, rm, k1, k2tog \u2014 9 sts.");
  EXPECT_EQ(line_of(text, "Row 4 (WS)"), "**Row 4 (WS):** Purl.");
  EXPECT_EQ(p.markers, 2u);
}

// A decrease over the place of a marker would have to cross it: that marker is left out.
TEST(HandMarkers, AMarkerADecreaseWouldCrossIsLeftOut) {
  std::vector<HandOp> row3(10, HandOp::k);
  row3[6] = HandOp::k2tog;  // the 7th and 8th sts, across the group's end
  row3.pop_back();
  hand::HandPattern p = mismatch_group_pattern(row3);
  hand::place_region_markers(p);
  std::string text = markdown(p);
  EXPECT_EQ(failure_of(text), "") << text;
  EXPECT_EQ(line_of(text, "Row 1 (RS)"), "**Row 1 (RS):** K3, pm, k to end.");
  EXPECT_EQ(count(text, "pm"), 1u) << text;
  EXPECT_EQ(count(text, "rm"), 1u) << text;
}

// A crown's section markers and a region's markers on the needle at once: the region's mark
// that falls where a section marker is gives none, the other is placed, slipped between the
// section markers and removed, and the pattern still knits the model.
TEST(HandMarkers, RegionMarkersKeepClearOfSectionMarkers) {
  Compilation c = compile_stitch_mesh(
      build_from_rows(testing::wedge_plan(6, 9, 3, 1, StitchType::k2tog), Layout::tube), "crown");
  std::string before = markdown(hand::build_hand_pattern(c));
  std::string text = markdown(testing::with_region_marks_in_a_crown(c));
  EXPECT_TRUE(hand::verify_pattern(text, "crown.md", &c).proven) << text;
  EXPECT_EQ(count(text, "pm"), count(before, "pm") + 1) << text;
  EXPECT_EQ(count(text, "rm"), count(before, "rm") + 1) << text;
  EXPECT_EQ(line_of(text, "Rnd 1"), "**Rnd 1:** K4, pm, k5, *pm, k9; rep from * to end.") << text;
  EXPECT_EQ(line_of(text, "Rnd 3"), "**Rnd 3:** K to m, rm, [k to m, sm] 5 times, k to m.") << text;
}

// A knitted-on edging: the st beside the contracting edge is a mismatch group the schedule
// marks, and a marker parts it from the body, as a publisher's edging reads.
TEST(HandMarkers, AKnittedOnEdgingIsMarkedOffFromTheBody) {
  Compilation c = compile_stitch_mesh(testing::edging_mesh(6, 4), "edging");
  std::string text = testing::emit(c, "hand");
  EXPECT_TRUE(hand::verify_pattern(text, "edging.md", &c).proven) << text;
  EXPECT_EQ(line_of(text, "Row 1 (RS)"), "**Row 1 (RS):** Sl1 from spare, k2tog, pm, k to end.");
  EXPECT_EQ(line_of(text, "Row 2 (WS)"),
            "**Row 2 (WS):** P to m, sm, sl1 from spare behind, p2tog.");
  EXPECT_EQ(line_of(text, "Row 4 (WS)"),
            "**Row 4 (WS):** P to m, sm, sl1 from spare behind, p2tog.");
  EXPECT_EQ(line_of(text, "Row 5 (RS)"), "**Row 5 (RS):** BO all sts.");
}

// The simulator holds short-row markers to what the pattern says: a count that runs past one,
// a marker slipped where a st is next, a double stitch made after slipping a marker.
TEST(HandMarkers, TheSimulatorRejectsShortRowMarkersWorkedWrong) {
  const std::string row1 = "Cast on 8 sts.\nRow 1 (RS): K3, pm, k1, turn.\n";
  EXPECT_EQ(failure_of(row1 + "Row 2 (WS): DS, sm, p to end.\n"
                              "Row 3 (RS): K to m, rm, k DS, k to end.\n"
                              "Row 4 (WS): BO all sts.\nFasten off.\n"),
            "");
  EXPECT_EQ(failure_of(row1 + "Row 2 (WS): DS, p3.\n"),
            "p.md:3: Row 2 (WS): p needs 1 st before the marker, 0 left");
  EXPECT_EQ(failure_of(row1 + "Row 2 (WS): Sm, DS, p to end.\n"),
            "p.md:3: Row 2 (WS): sm: the next thing on the left needle is a st, not a marker");
  EXPECT_EQ(failure_of(row1 + "Row 2 (WS): DS, sm, p to end.\nRow 3 (RS): K4, k DS, k3.\n"),
            "p.md:4: Row 3 (RS): k needs 1 st before the marker, 0 left");
  EXPECT_EQ(failure_of(row1 + "Row 2 (WS): DS, sm, p to end.\nRow 3 (RS): K3, k DS, k4.\n"),
            "p.md:4: Row 3 (RS): k DS needs 1 st before the marker, 0 left");
}

}  // namespace
}  // namespace skein
