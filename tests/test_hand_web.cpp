// The knitting page's data: every stitch once, in the lowering's program order, each named by
// the row of the proven pattern that works it; and the row text read back operation by
// operation.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "builtin_targets.hpp"
#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "driver/registry.hpp"
#include "hand_web/page_writer.hpp"
#include "hand_web/row_spans.hpp"

namespace skein {
namespace {

using hand::HandOp;

// The numbers of the JSON array `"name":[...]` in `html` (the page's data).
std::vector<long> json_numbers(const std::string& html, const std::string& name) {
  std::size_t at = html.find("\"" + name + "\":[");
  EXPECT_NE(at, std::string::npos) << name;
  std::vector<long> out;
  if (at == std::string::npos) return out;
  std::istringstream in(
      html.substr(at + name.size() + 4, html.find(']', at) - at - name.size() - 4));
  for (std::string n; std::getline(in, n, ',');) out.push_back(std::stol(n));
  return out;
}

std::string emit(const Registry& registry, const std::string& target, const Compilation& c) {
  std::ostringstream out;
  registry.target(target)->emit(c, {}, out);
  return out.str();
}

class HandWebPage : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    register_builtin_targets(registry_);
    hat_ = new Compilation(compile_model(SKEIN_SOURCE_DIR "/samples/hat/hat.obj"));
    page_ = new std::string(emit(registry_, "hand-web", *hat_));
  }
  static void TearDownTestSuite() {
    delete hat_;
    delete page_;
  }
  static Registry registry_;
  static const Compilation* hat_;
  static const std::string* page_;
};
Registry HandWebPage::registry_;
const Compilation* HandWebPage::hat_ = nullptr;
const std::string* HandWebPage::page_ = nullptr;

TEST_F(HandWebPage, StepsThroughEveryStitchOnceInTheProgramsOrder) {
  const Program& p = hat_->program;
  ASSERT_TRUE(p.complete());
  std::vector<long> stitch = json_numbers(*page_, "stitch"), step = json_numbers(*page_, "step");
  ASSERT_EQ(stitch.size(), hat_->knit.size());
  ASSERT_EQ(step.size(), stitch.size());
  std::vector<int> seen(hat_->knit.size(), 0);
  for (std::size_t i = 0; i < stitch.size(); ++i) {
    EXPECT_EQ(stitch[i], p.stitches[i].stitch) << "program index " << i;
    const Step& s = p.steps[static_cast<std::size_t>(step[i])];
    EXPECT_TRUE(s.stitches.begin <= i && i < s.stitches.end) << "program index " << i;
    ++seen[static_cast<std::size_t>(stitch[i])];
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

TEST_F(HandWebPage, NamesEachStitchByItsRowAndPlaceThere) {
  std::vector<long> row = json_numbers(*page_, "row"), pos = json_numbers(*page_, "pos");
  std::vector<long> begin = json_numbers(*page_, "b"), end = json_numbers(*page_, "e");
  ASSERT_EQ(row.size(), pos.size());
  // Within a row the places count up from 1 (the hat's pattern works in the program's order).
  for (std::size_t i = 0; i < row.size(); ++i) {
    bool starts = i == 0 || row[i] != row[i - 1];
    EXPECT_EQ(pos[i], starts ? 1 : pos[i - 1] + 1) << i;
  }
  // Rnd 25 of the hat: "*K to 2 sts before m, ssk, sm; rep from * to end": its first stitch is
  // the "K to 2 sts before m" of the first repeat.
  std::vector<std::string> labels;
  for (std::size_t at = 0; (at = page_->find("\"l\":\"", at)) != std::string::npos; at += 5)
    labels.push_back(page_->substr(at + 5, page_->find('"', at + 5) - at - 5));
  long rnd_25 = std::find(labels.begin(), labels.end(), "Rnd 25") - labels.begin();
  ASSERT_LT(rnd_25, static_cast<long>(labels.size()));
  std::size_t first = std::find(row.begin(), row.end(), rnd_25) - row.begin();
  ASSERT_LT(first, row.size());
  std::string text = "Rnd 25: *K to 2 sts before m, ssk, sm; rep from * to end \u2014 56 sts.";
  EXPECT_NE(page_->find(text), std::string::npos);
  EXPECT_EQ(text.substr(begin[first], end[first] - begin[first]), "K to 2 sts before m");
}

// A piece the pattern writes "Work as Sleeve 1." shows each of its rows as that piece's row
// it works again, and says which line told it so.
TEST_F(HandWebPage, APieceWorkedAsAnotherShowsThatPiecesRows) {
  Compilation sweater = compile_model(SKEIN_SOURCE_DIR "/samples/sweater/sweater.yaml");
  std::string page = emit(registry_, "hand-web", sweater);
  std::string rnd_6 =
      "\"l\":\"Rnd 6\",\"t\":\"Rnd 6: [K2, p2] 3 times, k3, [p2, k2] 3 times, [p3, k2, p2, "
      "k2, p2, k2] 2 times, p2, k1.\"";
  EXPECT_NE(page.find("{\"h\":\"Sleeve 1 (yarn 3)\"," + rnd_6 + ",\"s\":\"\""), std::string::npos);
  EXPECT_NE(page.find("{\"h\":\"Sleeve 2 (yarn 2)\"," + rnd_6 + ",\"s\":\"Work as Sleeve 1.\""),
            std::string::npos);
}

TEST_F(HandWebPage, EmbedsTheProvenHandPatternAndItsSimulatorProvesIt) {
  std::optional<std::string> pattern = hand_web::embedded_pattern(*page_);
  ASSERT_TRUE(pattern.has_value());
  EXPECT_EQ(*pattern, emit(registry_, "hand", *hat_));
  VerifyReport proof = registry_.simulator_for("hand-web")->verify(*page_, "hat.html", hat_, {});
  EXPECT_TRUE(proof.proven) << proof.summary;
  EXPECT_THROW(registry_.simulator_for("hand-web")->verify("<html></html>", "x.html", hat_, {}),
               Error);
}

TEST_F(HandWebPage, IsOneFileThatFetchesNothing) {
  for (const char* fetch : {"<script src", "<link", "<img", "@import", "url("})
    EXPECT_EQ(page_->find(fetch), std::string::npos) << fetch;
  if (hand_web::find_three_js()) {
    EXPECT_NE(page_->find("three.js r111"), std::string::npos);
  }
}

// The squares of the printable page's chart (hand-html), its first row (the bottom) first:
// 'p' where a square has a dot, 'k' where it is blank.
std::vector<std::string> printed_chart(const std::string& html) {
  std::map<int, std::map<int, char>, std::greater<>> squares;  // by y (down the page), x
  const std::regex square(R"re(<rect x="(\d+)" y="(\d+)" width="12" height="12" fill="#fff")re");
  const std::regex dot(R"re(<circle cx="(\d+)" cy="(\d+)" r="2")re");
  for (std::sregex_iterator m(html.begin(), html.end(), square), end; m != end; ++m)
    squares[std::stoi((*m)[2])][std::stoi((*m)[1])] = 'k';
  for (std::sregex_iterator m(html.begin(), html.end(), dot), end; m != end; ++m)
    squares.at(std::stoi((*m)[2]) - 6).at(std::stoi((*m)[1]) - 6) = 'p';
  std::vector<std::string> rows;
  for (const auto& [y, row] : squares) {
    rows.emplace_back();
    for (const auto& [x, ch] : row) rows.back() += ch;
  }
  return rows;
}

// The page's charts' rows, each chart's first row first, the charts one after another.
std::vector<std::string> page_chart_rows(const std::string& page) {
  std::vector<std::string> rows;
  const std::regex cells(R"re("cells":\[([^\]]*)\])re"), row(R"re("([kp]+)")re");
  for (std::sregex_iterator m(page.begin(), page.end(), cells), end; m != end; ++m) {
    std::string list = (*m)[1];
    for (std::sregex_iterator r(list.begin(), list.end(), row); r != end; ++r)
      rows.push_back((*r)[1]);
  }
  return rows;
}

TEST_F(HandWebPage, EmbedsTheChartThePrintablePageDrawsAndNoneWhereItDrawsNone) {
  Compilation rib = compile_model(SKEIN_SOURCE_DIR "/samples/rib-swatch/rib-swatch.obj");
  std::vector<std::string> printed = printed_chart(emit(registry_, "hand-html", rib));
  ASSERT_FALSE(printed.empty());
  std::string page = emit(registry_, "hand-web", rib);
  EXPECT_EQ(page_chart_rows(page), printed);
  // Each charted row of the page names its chart row; every worked row but the bind-off has one.
  std::vector<long> chart_rows;
  for (std::size_t at = 0; (at = page.find("\"cr\":", at)) != std::string::npos; at += 5)
    if (page.compare(at - 7, 7, "\"c\":-1,") != 0)
      chart_rows.push_back(std::stol(page.substr(at + 5)));
  EXPECT_EQ(chart_rows.size(), printed.size());
  for (std::size_t r = 0; r < chart_rows.size(); ++r)
    EXPECT_EQ(chart_rows[r], static_cast<long>(r));

  EXPECT_TRUE(printed_chart(emit(registry_, "hand-html", *hat_)).empty());
  EXPECT_NE(page_->find("\"charts\":[]"), std::string::npos);
  EXPECT_EQ(page_->find("\"c\":0,"), std::string::npos);
}

std::string marked(std::string_view text, const std::vector<hand_web::OpSpan>& spans,
                   std::size_t op) {
  std::string out(text.substr(spans[op].begin, spans[op].end - spans[op].begin));
  if (spans[op].repeats)
    out += " " + std::to_string(spans[op].repeat) + "/" + std::to_string(spans[op].repeats);
  return out;
}

TEST(HandWebRowSpans, NameEachOperationByItsTokenAndRepeat) {
  using O = HandOp;
  std::string_view text = "*K2, p2; rep from * to last 2 sts, k2";
  std::vector<O> ops = {O::k, O::k, O::p, O::p, O::k, O::k, O::p, O::p, O::k, O::k};
  auto spans = hand_web::op_spans(text, ops);
  ASSERT_TRUE(spans.has_value());
  EXPECT_EQ(marked(text, *spans, 0), "K2 1/2");
  EXPECT_EQ(marked(text, *spans, 7), "p2 2/2");
  EXPECT_EQ(marked(text, *spans, 9), "k2");

  text = "K3, [k2tog, yo] 2 times, M1L, k1";
  ops = {O::k, O::k, O::k, O::k2tog, O::yo, O::k2tog, O::yo, O::m1l, O::k};
  spans = hand_web::op_spans(text, ops);
  ASSERT_TRUE(spans.has_value());
  EXPECT_EQ(marked(text, *spans, 5), "k2tog 2/2");
  EXPECT_EQ(marked(text, *spans, 7), "M1L");

  // The beginning-of-round marker ends the round: the last repeat slips none.
  text = "*K to 2 sts before m, ssk, sm; rep from * to end";
  ops = {O::k, O::ssk, O::sm, O::k, O::k, O::ssk};
  spans = hand_web::op_spans(text, ops);
  ASSERT_TRUE(spans.has_value());
  EXPECT_EQ(marked(text, *spans, 4), "K to 2 sts before m 2/2");

  EXPECT_TRUE(hand_web::op_spans("BO 3 sts, k to end", std::vector<O>{O::bo, O::bo, O::bo, O::k}));
  EXPECT_FALSE(hand_web::op_spans("K4", std::vector<O>{O::k, O::k, O::k}));
  EXPECT_FALSE(hand_web::op_spans("Knit every rnd until 23 rnds in all", std::vector<O>{O::k}));
}

}  // namespace
}  // namespace skein
