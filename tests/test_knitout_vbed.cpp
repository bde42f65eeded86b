// The virtual v-bed, one rule at a time: tests/data/knitout/*.k are small hand-written knitout
// files, each ending with '; profile: NAME' and '; expect: valid' or '; expect: line N: message'
// (the exact message of the first invalid line).
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <filesystem>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

std::string trailer(const std::string& text, const std::string& key) {
  std::size_t at = text.rfind("; " + key + ": ");
  if (at == std::string::npos) return "";
  std::size_t start = at + key.size() + 4;
  return text.substr(start, text.find('\n', start) - start);
}

std::vector<std::filesystem::path> rule_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(testing::source_path("tests/data/knitout")))
    if (entry.path().extension() == ".k") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(VbedRules, EachHandWrittenFileGivesItsExactVerdict) {
  std::vector<std::filesystem::path> files = rule_files();
  ASSERT_GE(files.size(), 45u);
  int valid = 0;
  for (const auto& path : files) {
    std::string text = read_file(path.string());
    std::string expect = trailer(text, "expect"), profile = trailer(text, "profile");
    ASSERT_FALSE(expect.empty() || profile.empty())
        << path << " needs '; profile:' and '; expect:' lines";
    std::string verdict = "valid";
    try {
      knitout::replay_knitout(text, path.filename().string(), testing::shipped_profile(profile));
    } catch (const ParseError& e) {
      verdict = fmt::format("line {}: {}", e.line(), e.expected());
      EXPECT_TRUE(std::string(e.what()).starts_with(
          fmt::format("{}:{}: ", path.filename().string(), e.line())));
    }
    EXPECT_EQ(verdict, expect) << path.filename();
    valid += verdict == "valid";
  }
  EXPECT_GE(valid, 3);
}

TEST(VbedRules, ATransferMayNotStretchFurtherThanTheProfileAllows) {
  knitout::MachineProfile p = testing::shipped_profile("generic");
  p.max_transfer_stretch = 2;
  std::string text =
      ";!knitout-2\n;;Carriers: 1 2 3 4 5 6 7 8 9 10\nin 1\ntuck + f5 1\nrack 3\n"
      "xfer f5 b2\n";
  try {
    knitout::replay_knitout(text, "stretch.k", p);
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 6u);
    EXPECT_EQ(e.expected(), "xfer at rack 3 stretches a loop 3 needles, generic allows 2");
  }
}

// The parser reads up to each line's '\n': a last line without one is read all the same.
TEST(VbedRules, ALastLineWithoutANewlineIsReadWhole) {
  knitout::MachineProfile p = testing::shipped_profile("generic");
  std::string text =
      ";!knitout-2\n;;Carriers: 1 2 3 4 5 6 7 8 9 10\nin 1\ntuck + f1 1\nknit - f1 1\nout 1";
  EXPECT_EQ(knitout::replay_knitout(text, "last.k", p).stats.operations, 4u);
  try {
    knitout::replay_knitout(text + " x", "last.k", p);
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 6u);
    EXPECT_EQ(e.expected(), "carrier 'x' is not named in the ;;Carriers: header");
  }
}

// What a shop reads: passes, transfers, racks, drops, yarn pieces and time.
TEST(VbedRules, ShopSummaryCountsWhatTheFileDoes) {
  std::string path = testing::source_path("tests/data/knitout/valid-swg-sheet.k");
  knitout::MachineProfile p = testing::shipped_profile("swg091n2");
  knitout::Replay r = knitout::replay_knitout(read_file(path), path, p);
  EXPECT_EQ(r.stats.knits, 8u);
  EXPECT_EQ(r.stats.tucks, 4u);
  EXPECT_EQ(r.stats.splits, 1u);
  EXPECT_EQ(r.stats.misses, 1u);
  EXPECT_EQ(r.stats.transfers, 2u);
  EXPECT_EQ(r.stats.racks, 2u);
  EXPECT_EQ(r.stats.yarn_pieces, 1u);
  EXPECT_EQ(r.stats.loops_dropped, 4u);  // f3 is empty after its transfer
  EXPECT_EQ(r.stats.stitch_passes, 5u);
  EXPECT_GT(r.stats.seconds, 0);
  std::string summary = knitout::shop_summary(r, p);
  EXPECT_NE(summary.find("carriage passes: "), std::string::npos) << summary;
  EXPECT_NE(
      summary.find("transfers: 2, rack changes: 2, loops dropped: 4, loops left on the needles: 0"),
      std::string::npos)
      << summary;
}

// The v-bed reads the commonest lines in one scan (parse_plain_op) and every other line
// with parse_op: where the scan reads a line it gives parse_op's operation, and it leaves
// every line outside its narrow form to parse_op.
TEST(VbedRules, ThePlainLineScanReadsItsLinesAsParseOpDoes) {
  knitout::Header h;
  h.carriers = {"1", "2", "3", "4", "5", "6", "7", "8", "9", "10"};
  h.numbered = true;
  auto same = [](const knitout::Op& a, const knitout::Op& b) {
    return a.code == b.code && a.dir == b.dir && a.a == b.a && a.b == b.b &&
           a.carriers == b.carriers && a.rack_quarters == b.rack_quarters;
  };
  for (std::string line : {"knit + f0 1", "tuck - b123456789 10", "knit - f007 03", "tuck + b5 2",
                           "xfer f12 b12", "xfer b3 f0"}) {
    std::string text = line + "\nknit + f1 1\n";
    knitout::Op fast, slow;
    std::size_t next = 0;
    std::string error;
    ASSERT_TRUE(knitout::parse_plain_op(text, 0, h, fast, next)) << line;
    ASSERT_TRUE(knitout::parse_op(text.substr(0, line.size() + 1), h, slow, error)) << line;
    EXPECT_TRUE(same(fast, slow)) << line;
    EXPECT_EQ(next, line.size() + 1) << line;
  }
  for (std::string line :
       {"knit + f0 11", "knit + f0 0",     "knit + f1234567890 1", "knit + fs3 1",
        "knit + f-3 1", "knit  + f3 1",    "knit + f3 1 2",        "knit + f3 1 ; comment",
        "knit + f3",    "split + f3 b3 1", "knit + f3 1\r",        "miss + f3 1",
        "tuck x f3 1",  "knit + f3 +1",    "xfer f1 bs1",          "xfer f1 b1 2",
        "xfer  f1 b1",  "xfer f1",         "xfer f-1 b1",          "rack 1"}) {
    std::string text = line + "\n";
    knitout::Op op;
    std::size_t next = 0;
    EXPECT_FALSE(knitout::parse_plain_op(text, 0, h, op, next)) << line;
  }
  std::string unterminated = "knit + f3 1";  // the last line without its '\n'
  knitout::Op op;
  std::size_t next = 0;
  EXPECT_FALSE(knitout::parse_plain_op(unterminated, 0, h, op, next));
  h.numbered = false;  // named carriers: looked up by parse_op (a transfer names none)
  EXPECT_FALSE(knitout::parse_plain_op("knit + f3 1\n", 0, h, op, next));
  EXPECT_TRUE(knitout::parse_plain_op("xfer f3 b3\n", 0, h, op, next));
}

}  // namespace
}  // namespace skein
