#include "mesh/autoknit_st.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "common/error.hpp"
#include "knitgraph/knit_graph.hpp"

#ifndef SKEIN_SOURCE_DIR
#define SKEIN_SOURCE_DIR "."
#endif

namespace skein {
namespace {

std::string sample_path(std::string_view name) {
  return std::string(SKEIN_SOURCE_DIR) + "/samples/autoknit/" + std::string(name);
}

// Facts about AutoKnit's samples, computed with awk straight from the files: lines; in-links
// that are not -1; yarn pieces (lines whose yarn id differs from the line before); lines per
// type letter; the last row (0-based), a row ending before a line that takes a loop made in
// it or where a bind-off ends; rows beside a turn (dir flips) and whole rounds.
struct SampleFacts {
  std::string_view name;
  std::uint32_t stitches;
  std::size_t loops;
  std::size_t yarn_pieces;
  std::map<StitchType, std::size_t> type_counts;
  std::uint32_t max_row;
  std::size_t short_rows, rounds;
};

const std::vector<SampleFacts>& sample_facts() {
  using T = StitchType;
  static const std::vector<SampleFacts> facts{
      {"test-A.st",
       446,
       435,
       1,
       {{T::co, 14},
        {T::bo, 20},
        {T::k, 364},
        {T::tuck, 18},
        {T::sl, 18},
        {T::kfb, 9},
        {T::k2tog, 3}},
       33,
       23,
       11},
      {"test-B.st", 178, 165, 1, {{T::co, 13}, {T::bo, 17}, {T::k, 144}, {T::kfb, 4}}, 14, 0, 15},
      {"test-C.st", 404, 385, 2, {{T::co, 19}, {T::bo, 26}, {T::k, 352}, {T::kfb, 7}}, 22, 0, 23},
  };
  return facts;
}

std::size_t count_yarn_pieces(const KnitGraph& graph) {
  std::vector<bool> has_predecessor(graph.size(), false);
  for (StitchId next : graph.yarn_next)
    if (next != kNoStitch) has_predecessor[next] = true;
  return static_cast<std::size_t>(
      std::count(has_predecessor.begin(), has_predecessor.end(), false));
}

std::map<StitchType, std::size_t> count_types(const KnitGraph& graph) {
  std::map<StitchType, std::size_t> counts;
  for (StitchType type : graph.type) ++counts[type];
  return counts;
}

TEST(AutoknitSt, SamplesImportWithTheirKnownShape) {
  for (const SampleFacts& facts : sample_facts()) {
    SCOPED_TRACE(std::string(facts.name));
    KnitGraph graph = read_autoknit_st(sample_path(facts.name));
    EXPECT_EQ(graph.size(), facts.stitches);
    EXPECT_EQ(graph.loops.size(), facts.loops);
    EXPECT_EQ(count_yarn_pieces(graph), facts.yarn_pieces);
    EXPECT_EQ(count_types(graph), facts.type_counts);
    EXPECT_EQ(*std::max_element(graph.row.begin(), graph.row.end()), facts.max_row);
    EXPECT_EQ(graph.row_shape.size(), std::size_t{facts.max_row} + 1);
    EXPECT_EQ(std::count(graph.row_shape.begin(), graph.row_shape.end(), RowShape::short_row),
              facts.short_rows);
    EXPECT_EQ(std::count(graph.row_shape.begin(), graph.row_shape.end(), RowShape::closed),
              facts.rounds);
    EXPECT_EQ(graph.source_name, sample_path(facts.name));
    EXPECT_EQ(graph.element, "line");
  }
}

TEST(AutoknitSt, SampleLoopsGoFromEarlierToLaterStitches) {
  for (const SampleFacts& facts : sample_facts()) {
    SCOPED_TRACE(std::string(facts.name));
    KnitGraph graph = read_autoknit_st(sample_path(facts.name));
    for (const Loop& loop : graph.loops) {
      ASSERT_NE(loop.taker, kNoStitch);
      EXPECT_LT(loop.maker, loop.taker);
      EXPECT_EQ(loop.kind, LoopKind::wale);
    }
  }
}

TEST(AutoknitSt, SamplesAreConsistent) {
  for (const SampleFacts& facts : sample_facts()) {
    SCOPED_TRACE(std::string(facts.name));
    EXPECT_NO_THROW(check_consistency(read_autoknit_st(sample_path(facts.name))));
  }
}

// Three starts, three knits, three ends; the ends are knit with a second yarn.
constexpr std::string_view kTiny =
    "0 s a -1 -1 3 -1 0 0 0\n"
    "0 s a -1 -1 4 -1 1 0 0\n"
    "0 s a -1 -1 5 -1 2 0 0\n"
    "0 k c 0 -1 6 -1 0 1 0\n"
    "0 k c 1 -1 7 -1 1 1 0\n"
    "0 k c 2 -1 8 -1 2 1 0\n"
    "7 e a 3 -1 -1 -1 0 2 0\n"
    "7 e a 4 -1 -1 -1 1 2 0\n"
    "7 e a 5 -1 -1 -1 2 2.5e-1 -0.5\n";

TEST(AutoknitSt, TinyGraphMapsEveryField) {
  KnitGraph graph = parse_autoknit_st(kTiny, "tiny.st");
  using T = StitchType;
  EXPECT_EQ(graph.source_name, "tiny.st");
  EXPECT_EQ(graph.element, "line");
  EXPECT_EQ(graph.type, (std::vector{T::co, T::co, T::co, T::k, T::k, T::k, T::bo, T::bo, T::bo}));
  EXPECT_EQ(graph.row, (std::vector<std::uint32_t>{0, 0, 0, 1, 1, 1, 2, 2, 2}));
  EXPECT_EQ(graph.source, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
  constexpr StitchId kNo = kNoStitch;
  EXPECT_EQ(graph.yarn_next, (std::vector<StitchId>{1, 2, 3, 4, 5, kNo, 7, 8, kNo}));
  using Y = YarnLink;  // dir flips from a to c: the work turns after the cast-on
  EXPECT_EQ(graph.yarn_link, (std::vector{Y::course, Y::course, Y::turn, Y::course, Y::course,
                                          Y::none, Y::course, Y::course, Y::none}));
  EXPECT_EQ(graph.flags, std::vector<std::uint8_t>(9, 0));
  EXPECT_EQ(graph.row_shape, std::vector<RowShape>(3, RowShape::open));
  ASSERT_EQ(graph.loops.size(), 6u);
  for (StitchId taker = 3; taker < 9; ++taker) {
    const Loop& loop = graph.loops[taker - 3];
    EXPECT_EQ(loop.maker, taker - 3);
    EXPECT_EQ(loop.taker, taker);
    EXPECT_EQ(loop.kind, LoopKind::wale);
    ASSERT_EQ(graph.loops_taken_by(taker).size(), 1u);
    EXPECT_EQ(graph.loops_taken_by(taker)[0], taker - 3);
  }
  for (StitchId s = 0; s < 3; ++s) EXPECT_TRUE(graph.loops_taken_by(s).empty());
  EXPECT_TRUE(graph.groups.empty());
  EXPECT_TRUE(graph.mismatch_edges.empty());
  EXPECT_EQ(graph.describe(4), "line 5 (k)");
  EXPECT_NO_THROW(check_consistency(graph));
}

TEST(AutoknitSt, DecreaseMayTakeBothLoopsOfOneIncrease) {
  KnitGraph graph = parse_autoknit_st(
      "0 s a -1 -1 1 -1 0 0 0\n"
      "0 i a 0 -1 2 2 0 0 0\n"
      "0 d a 1 1 3 -1 0 0 0\n"
      "0 e a 2 -1 -1 -1 0 0 0",  // no final newline
      "incdec.st");
  EXPECT_EQ(graph.type,
            (std::vector{StitchType::co, StitchType::kfb, StitchType::k2tog, StitchType::bo}));
  EXPECT_EQ(graph.row, (std::vector<std::uint32_t>{0, 1, 2, 3}));
  ASSERT_EQ(graph.loops_taken_by(2).size(), 2u);
  for (std::uint32_t loop : graph.loops_taken_by(2)) EXPECT_EQ(graph.loops[loop].maker, 1u);
}

TEST(AutoknitSt, AcceptsTabsRepeatedBlanksAndCrlf) {
  KnitGraph graph = parse_autoknit_st(
      "0\ts a  -1 -1 1 -1 0 0 0\r\n"
      "  0 m c 0 -1 2 -1 0 0 0  \r\n"
      "0 t a 1 -1 3 -1 0 0 0\r\n"
      "0 e a 2 -1 -1 -1 0 0 0\r\n",
      "blanks.st");
  EXPECT_EQ(graph.type,
            (std::vector{StitchType::co, StitchType::sl, StitchType::tuck, StitchType::bo}));
}

// Replaces line `index` (0-based) of kTiny.
std::string tiny_with(std::size_t index, std::string_view replacement) {
  std::string text;
  std::string_view rest = kTiny;
  for (std::size_t i = 0; !rest.empty(); ++i) {
    std::size_t end = rest.find('\n');
    text += i == index ? replacement : rest.substr(0, end);
    text += '\n';
    rest.remove_prefix(end + 1);
  }
  return text;
}

void expect_parse_error(std::string_view text, std::size_t line, std::string_view message) {
  try {
    parse_autoknit_st(text, "bad.st");
    ADD_FAILURE() << "no ParseError; expected one at line " << line << ": " << message;
  } catch (const ParseError& error) {
    EXPECT_EQ(error.file(), "bad.st");
    EXPECT_EQ(error.line(), line) << error.what();
    EXPECT_NE(std::string_view(error.what()).find(message), std::string_view::npos) << error.what();
  }
}

TEST(AutoknitStErrors, WrongFieldCount) {
  expect_parse_error(tiny_with(3, "0 k c 0 -1 6 -1"), 4,
                     "expected 10 fields: yarn type dir in0 in1 out0 out1 x y z, found 7");
  expect_parse_error(tiny_with(3, "0 k c 0 -1 6 -1 0 1 0 9"), 4, "found 11");
}

TEST(AutoknitStErrors, QuotesTheLine) {
  expect_parse_error(tiny_with(3, "0 k c 0 -1 6 -1"), 4, "| 0 k c 0 -1 6 -1");
}

TEST(AutoknitStErrors, BlankLines) {
  expect_parse_error(tiny_with(3, ""), 4, "found a blank line");
  expect_parse_error(std::string(kTiny) + "\n", 10, "found a blank line");
  expect_parse_error("", 1, "found an empty file");
}

TEST(AutoknitStErrors, UnknownTypeLetter) {
  expect_parse_error(tiny_with(3, "0 x c 0 -1 6 -1 0 1 0"), 4,
                     "expected a stitch type s, e, k, p, t, m, i or d, found 'x'");
  expect_parse_error(tiny_with(3, "0 kk c 0 -1 6 -1 0 1 0"), 4, "found 'kk'");
}

// `p` is skein's letter for a purl (AutoKnit has none): a stitch like `k`, one loop in and out.
TEST(AutoknitSt, SkeinsPurlLetterReadsAsAPurl) {
  KnitGraph graph = parse_autoknit_st(tiny_with(4, "0 p c 1 -1 7 -1 1 1 0"), "purl.st");
  EXPECT_EQ(graph.type[3], StitchType::k);
  EXPECT_EQ(graph.type[4], StitchType::p);
  EXPECT_EQ(graph.loops_taken_by(4).size(), 1u);
}

TEST(AutoknitStErrors, BadDirection) {
  expect_parse_error(tiny_with(3, "0 k x 0 -1 6 -1 0 1 0"), 4,
                     "expected dir c (clockwise) or a (anticlockwise), found 'x'");
}

TEST(AutoknitStErrors, BadYarnId) {
  expect_parse_error(tiny_with(3, "-1 k c 0 -1 6 -1 0 1 0"), 4,
                     "expected a yarn id (a non-negative integer), found '-1'");
}

TEST(AutoknitStErrors, NonIntegerIndex) {
  expect_parse_error(tiny_with(3, "0 k c 0.0 -1 6 -1 0 1 0"), 4,
                     "expected in0 to be an integer (a stitch index or -1), found '0.0'");
  expect_parse_error(tiny_with(3, "0 k c 0 -1 six -1 0 1 0"), 4, "out0 to be an integer");
}

TEST(AutoknitStErrors, IndexOutOfRange) {
  expect_parse_error(tiny_with(3, "0 k c 0 -1 9 -1 0 1 0"), 4,
                     "expected out0 to be -1 or a stitch index 0..8, found 9");
  expect_parse_error(tiny_with(3, "0 k c 0 -2 6 -1 0 1 0"), 4, "in1 to be -1 or a stitch index");
  expect_parse_error(tiny_with(3, "0 k c 0 -1 6 99999999999999999999 0 1 0"), 4,
                     "out1 to be -1 or a stitch index");
}

TEST(AutoknitStErrors, InPointsForward) {
  expect_parse_error(tiny_with(3, "0 k c 4 -1 6 -1 0 1 0"), 4,
                     "expected in0 to name an earlier stitch (< 3), found 4");
  expect_parse_error(tiny_with(3, "0 k c 3 -1 6 -1 0 1 0"), 4, "earlier stitch (< 3), found 3");
}

TEST(AutoknitStErrors, OutPointsBackward) {
  expect_parse_error(tiny_with(3, "0 k c 0 -1 2 -1 0 1 0"), 4,
                     "expected out0 to name a later stitch (> 3), found 2");
}

TEST(AutoknitStErrors, BadCoordinate) {
  expect_parse_error(tiny_with(3, "0 k c 0 -1 6 -1 0 one 0"), 4,
                     "expected y to be a number, found 'one'");
}

TEST(AutoknitStErrors, LinkNotMirrored) {
  // Line 4's out0 names stitch 7, whose in0 names stitch 4.
  expect_parse_error(tiny_with(3, "0 k c 0 -1 7 -1 0 1 0"), 4,
                     "out0 = 7 is not mirrored: expected stitch 7 (line 8) to name 3 once in its "
                     "in0 in1, found 4 -1");
  // The last end names the increase, which lists only the two ends before it.
  expect_parse_error(
      "0 s a -1 -1 1 -1 0 0 0\n"
      "0 i a 0 -1 2 3 0 0 0\n"
      "0 e a 1 -1 -1 -1 0 0 0\n"
      "0 e a 1 -1 -1 -1 0 0 0\n"
      "0 e a 1 -1 -1 -1 0 0 0\n",
      5,
      "in0 = 1 is not mirrored: expected stitch 1 (line 2) to name 4 once in its out0 out1, "
      "found 2 3");
  // A decrease taking both loops of a stitch that lists it only once.
  expect_parse_error(
      "0 s a -1 -1 1 -1 0 0 0\n"
      "0 k a 0 -1 2 -1 0 0 0\n"
      "0 d a 1 1 3 -1 0 0 0\n"
      "0 e a 2 -1 -1 -1 0 0 0\n",
      2,
      "out0 = 2 is not mirrored: expected stitch 2 (line 3) to name 1 once in its in0 in1, "
      "found 1 1");
}

TEST(AutoknitStErrors, LinkCountsMustMatchTheType) {
  expect_parse_error(tiny_with(3, "0 k c 0 -1 -1 -1 0 1 0"), 4,
                     "expected a 'k' stitch (loops in/out: 1/1) to set only in0 out0, found in0 "
                     "in1 out0 out1 = 0 -1 -1 -1");
  // AutoKnit fills slots in order: in1 set and in0 unused is malformed too.
  expect_parse_error(tiny_with(3, "0 k c -1 0 6 -1 0 1 0"), 4, "to set only in0 out0");
  expect_parse_error(tiny_with(0, "0 s a -1 -1 3 4 0 0 0"), 1,
                     "expected a 's' stitch (loops in/out: 0/1) to set only out0");
  expect_parse_error(tiny_with(3, "0 i c 0 -1 6 -1 0 1 0"), 4,
                     "'i' stitch (loops in/out: 1/2) to set only in0 out0 out1");
  expect_parse_error(tiny_with(3, "0 d c 0 -1 6 -1 0 1 0"), 4,
                     "'d' stitch (loops in/out: 2/1) to set only in0 in1 out0");
  expect_parse_error(tiny_with(6, "7 e a 3 -1 8 -1 0 2 0"), 7,
                     "'e' stitch (loops in/out: 1/0) to set only in0,");
}

TEST(AutoknitStErrors, MissingFileIsAnIoError) {
  EXPECT_THROW(read_autoknit_st("/nonexistent/skein/missing.st"), IoError);
}

}  // namespace
}  // namespace skein
