// Every rule of the v-bed (targets/knitout/vbed_rules.*), as `skein verify` applies it to a
// foreign file (without --strict): a file that breaks it, with the exact line it reports, and the
// same file done right, which breaks nothing. (tests/data/knitout/ holds the --strict cases.)
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <set>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "knitout/fabric_picture.hpp"
#include "knitout/fabric_report.hpp"
#include "knitout/vbed_simulator.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

using knitout::Rule;

struct RuleCase {
  Rule rule;
  const char* profile;
  const char* invalid;  // the lines after ";!knitout-2"
  const char* valid;
  const char* message;  // "error line N: ..." or the finding's line
};

constexpr const char* kSwg = ";;Carriers: 1 2 3 4 5 6 7 8 9 10\n";

// clang-format off
const RuleCase kCases[] = {
    {Rule::carriers_line, "swg091n2", ";;Carriers: 1 2 3\nin 1\ntuck + f1 1\nout 1\n",
     ";;Carriers: 1 2 3 4 5 6 7 8 9 10\nin 1\ntuck + f1 1\nout 1\n",
     "error line 2: swg091n2 needs ';;Carriers: 1 2 3 4 5 6 7 8 9 10'"},
    {Rule::machine_header, "swg091n2", ";;Machine: Kniterate\nSWG\nin 3\ntuck - f1 3\nout 3\n",
     ";;Machine: swg091n2\nSWG\nin 3\ntuck - f1 3\nout 3\n",
     "warning: line 2: the file is for machine 'Kniterate', profile swg091n2 is 'SWGN2' [machine-header: profile swg091n2]"},
    {Rule::gauge_header, "swg091n2", ";;Gauge: 7\nSWG\nin 3\ntuck - f1 3\nout 3\n",
     ";;Gauge: 15\nSWG\nin 3\ntuck - f1 3\nout 3\n",
     "warning: line 2: the file is for gauge 7, swg091n2 is gauge 15 [gauge-header: profile swg091n2]"},
    {Rule::width_header, "swg091n2", ";;Width: 600\nSWG\nin 3\ntuck - f1 3\nout 3\n",
     ";;Width: 540\nSWG\nin 3\ntuck - f1 3\nout 3\n",
     "error line 2: the file asks for 600 needles, swg091n2 has 540"},
    {Rule::needle_off_bed, "swg091n2", "SWG\nin 3\ntuck - f-2 3\nout 3\n",
     "SWG\nin 3\ntuck - f2 3\nout 3\n",
     "note: line 4: needle f-2 is outside the bed: swg091n2 has needles 0..539 [needle-off-bed: knitout-to-dat]"},
    {Rule::needle_span, "swg091n2", "SWG\nin 3\ntuck - f539 3\ntuck - f-1 3\nout 3\n",
     "SWG\nin 3\ntuck - f539 3\ntuck - f0 3\nout 3\n",
     "error line 5: the needles used span -1..539 (541 needles), swg091n2 has 540"},
    {Rule::no_sliders, "kniterate", "KN\nin 6\ntuck + f1 6\nxfer f1 bs1\nout 6\n",
     "KN\nin 6\ntuck + f1 6\nxfer f1 b1\nout 6\n",
     "error line 5: bs1 is a slider, and kniterate has no sliders"},
    {Rule::loops_per_needle, "swg091n2", "SWG\nin 3\ntuck - f1 3\ntuck + f1 3\ntuck - f1 3\ntuck + f1 3\ntuck - f1 3\nout 3\n",
     "SWG\nin 3\ntuck - f1 3\ntuck + f1 3\ntuck - f1 3\ntuck + f1 3\nout 3\n",
     "warning: line 8: f1 would hold 5 loops, swg091n2 allows 4 per needle [loops-per-needle: knitout-to-dat]"},
    {Rule::needle_overfull, "generic", "GEN\nin 1\nTUCK16\nout 1\n", "GEN\nin 1\nTUCK15\nout 1\n",
     "error line 19: f1 would hold 16 loops, more than the v-bed tracks"},
    {Rule::knit_empty_needle, "swg091n2", "SWG\nin 3\nknit - f1 3\nout 3\n",
     "SWG\nin 3\ntuck - f1 3\nknit + f1 3\nout 3\n",
     "note: line 4: knit on f1, which holds no loop: a new loop held by nothing [knit-empty-needle: knitout spec]"},
    {Rule::carrier_not_in, "swg091n2", "SWG\nin 3\ntuck - f1 4\nout 3\n",
     "SWG\nin 4\ntuck - f1 4\nout 4\n",
     "error line 4: carrier 4 is not in (bring it in with inhook first)"},
    {Rule::carrier_already_in, "swg091n2", "SWG\nin 3\ntuck - f1 3\nin 3\nout 3\n",
     "SWG\nin 3\ntuck - f1 3\nout 3\nin 3\ntuck - f1 3\nout 3\n",
     "error line 5: carrier 3 is already in"},
    {Rule::first_use_set, "swg091n2", "SWG\nin 3 4\ntuck - f1 3\nout 3 4\n",
     "SWG\nin 3 4\ntuck - f1 3 4\nout 3 4\n",
     "error line 4: the first use of carriers 3 must use exactly the set brought in together (3 4)"},
    {Rule::first_pass_direction, "swg091n2", "SWG\ninhook 3\ntuck + f1 3\nreleasehook 3\nouthook 3\n",
     "SWG\ninhook 3\ntuck - f1 3\nreleasehook 3\nouthook 3\n",
     "warning: line 4: the first pass after bringing in carrier 3 must go - on swg091n2, found + [first-pass-direction: Hofmann's SWG091N2 simulator]"},
    {Rule::no_hook, "kniterate", "KN\ninhook 6\ntuck + f1 6\nreleasehook 6\nouthook 6\n",
     "KN\nin 6\ntuck + f1 6\nout 6\n",
     "note: line 3: kniterate has no yarn-inserting hook: its back end knits inhook as in, outhook as out [no-hook: knitout-to-kcode] (3 times)"},
    {Rule::hook_busy, "swg091n2", "SWG\ninhook 3\ntuck - f1 3\ninhook 4\n",
     "SWG\ninhook 3\ntuck - f1 3\nreleasehook 3\ninhook 4\ntuck - f3 4\nreleasehook 4\nout 3 4\n",
     "error line 5: the yarn-inserting hook still holds carrier 3: releasehook it first"},
    {Rule::hook_blocks, "swg091n2", "SWG\ninhook 3\ntuck - f10 3\ntuck + f11 3\nreleasehook 3\nout 3\n",
     "SWG\ninhook 3\ntuck - f10 3\nreleasehook 3\ntuck + f11 3\nout 3\n",
     "warning: line 5: f11 is blocked by the yarn-inserting hook, which holds carrier 3 right of needle 10 until releasehook [hook-blocks: Hofmann's SWG091N2 simulator]"},
    {Rule::releasehook_mismatch, "swg091n2", "SWG\ninhook 3\ntuck - f1 3\nreleasehook 4\n",
     "SWG\ninhook 3\ntuck - f1 3\nreleasehook 3\nout 3\n",
     "error line 5: the hook holds carrier 3, not 4"},
    {Rule::releasehook_early, "swg091n2", "SWG\ninhook 3\nreleasehook 3\n",
     "SWG\ninhook 3\ntuck - f1 3\nreleasehook 3\nout 3\n",
     "error line 4: releasehook before carrier 3 has made a stitch"},
    {Rule::out_not_in, "swg091n2", "SWG\nin 3\ntuck - f1 3\nout 3\nout 3\n",
     "SWG\nin 3\ntuck - f1 3\nout 3\n",
     "error line 6: carrier 3 is not in"},
    {Rule::out_without_stitch, "swg091n2", "SWG\nin 3\nout 3\n",
     "SWG\nin 3\nmiss - f1 3\nout 3\n",
     "error line 4: carrier 3 is taken out without having made a stitch"},
    {Rule::out_while_hooked, "swg091n2", "SWG\ninhook 3\ntuck - f1 3\nout 3\n",
     "SWG\ninhook 3\ntuck - f1 3\nreleasehook 3\nout 3\n",
     "error line 5: carrier 3 is still held by the hook: releasehook 3 first"},
    {Rule::carrier_left_in, "swg091n2", "SWG\nin 3\ntuck - f1 3\n",
     "SWG\nin 3\ntuck - f1 3\nout 3\n",
     "warning: line 4: carrier 3 is still in at the end of the file (take it out with outhook) [carrier-left-in: Hofmann's SWG091N2 simulator]"},
    {Rule::rack_limit, "swg091n2", "SWG\nrack 5\n", "SWG\nrack 4\n",
     "warning: line 3: rack 5 is beyond the racking limit of swg091n2 (±4) [rack-limit: profile swg091n2]"},
    {Rule::rack_fraction, "swg091n2", "SWG\nrack 0.5\n", "SWG\nrack -0.75\n",
     "error line 3: rack 0.5 has a fraction swg091n2 does not allow"},
    {Rule::transfer_misaligned, "swg091n2", "SWG\nxfer f1 b2\n", "SWG\nrack -1\nxfer f1 b2\n",
     "error line 3: f1 and b2 are not aligned at rack 0 (b2 faces f2)"},
    {Rule::transfer_same_bed, "swg091n2", "SWG\nxfer f1 f2\n", "SWG\nxfer f1 b1\n",
     "error line 3: xfer f1 f2 stays on one bed: loops move only between front and back"},
    {Rule::transfer_slider_slider, "swg091n2", "SWG\nxfer fs1 bs1\n", "SWG\nxfer fs1 b1\n",
     "error line 3: xfer fs1 bs1 moves from slider to slider"},
    {Rule::transfer_stretch, "generic", "GEN\nrack 8\nxfer f9 b1\n", "GEN\nrack 8\nin 1\nmiss + f9 1\nout 1\n",
     "warning: line 4: xfer at rack 8 stretches a loop 8 needles, generic allows 4 [transfer-stretch: profile generic]"},
    {Rule::split_from_slider, "swg091n2", "SWG\nin 3\nsplit - fs1 b1 3\nout 3\n",
     "SWG\nin 3\nsplit - f1 b1 3\nout 3\n",
     "error line 4: split cannot start from a slider (fs1)"},
    {Rule::stitch_on_slider, "swg091n2", "SWG\nin 3\nknit - fs1 3\nout 3\n",
     "SWG\nin 3\nknit - f1 3\nout 3\n",
     "error line 4: knit on a slider (fs1): sliders only hold loops moved there"},
    {Rule::miss_without_carriers, "generic", "GEN\nmiss + f1\n", "GEN\nin 1\nmiss + f1 1\nout 1\n",
     "error line 3: miss needs carriers (a miss without yarn does nothing)"},
};
// clang-format on

// SWG / KN / GEN: the carriers line of the profile; TUCKn: n tucks on f1 with carrier 1.
std::string expand(const std::string& body) {
  std::string out = ";!knitout-2\n";
  std::size_t pos = 0;
  while (pos < body.size()) {
    std::size_t end = body.find('\n', pos);
    std::string line = body.substr(pos, end - pos);
    pos = end + 1;
    if (line == "SWG" || line == "GEN")
      out += kSwg;
    else if (line == "KN")
      out += ";;Carriers: 1 2 3 4 5 6\n";
    else if (line.starts_with("TUCK"))
      for (int i = 0, n = std::stoi(line.substr(4)); i < n; ++i)
        out += fmt::format("tuck {} f1 1\n", i % 2 ? '-' : '+');
    else
      out += line + '\n';
  }
  return out;
}

knitout::MachineProfile profile_for(const RuleCase& c) {
  knitout::MachineProfile p = testing::shipped_profile(c.profile);
  if (c.rule == Rule::transfer_stretch) p.max_transfer_stretch = 4;
  return p;
}

// The error, or the finding of the case's rule ("" if the replay broke no rule of it).
std::string outcome(const RuleCase& c, const std::string& body) {
  knitout::MachineProfile p = profile_for(c);
  try {
    knitout::Replay r = knitout::replay_knitout(expand(body), "case.k", p, {.strict = false});
    for (const knitout::Finding& f : r.findings)
      if (f.rule == c.rule) return knitout::finding_line(f, p);
    return "";
  } catch (const ParseError& e) {
    return fmt::format("error line {}: {}", e.line(), e.expected());
  }
}

TEST(VbedRuleTable, EachRuleHasAnInvalidCaseWithItsExactMessageAndAValidOne) {
  std::set<Rule> covered;
  for (const RuleCase& c : kCases) {
    std::string name = knitout::rule_info(c.rule).name;
    EXPECT_EQ(outcome(c, c.invalid), c.message) << name;
    EXPECT_EQ(outcome(c, c.valid), "") << name << " (valid case)";
    covered.insert(c.rule);
  }
  EXPECT_EQ(covered.size(), static_cast<std::size_t>(Rule::count));
}

TEST(VbedRuleTable, StrictMakesEveryRuleAnError) {
  for (const RuleCase& c : kCases) {
    knitout::MachineProfile p = profile_for(c);
    bool allowed = c.rule == Rule::knit_empty_needle && !p.knit_empty_needle_is_error;
    EXPECT_EQ(knitout::rule_severity(c.rule, p, true),
              allowed ? knitout::Severity::note : knitout::Severity::error)
        << knitout::rule_info(c.rule).name;
  }
}

// docs/knitout.md's table names each source in words that fit every profile.
const char* docs_source(knitout::RuleSource s) {
  using S = knitout::RuleSource;
  switch (s) {
    case S::spec:
      return "knitout spec";
    case S::back_end:
      return "the profile's back end";
    case S::simulator:
      return "Hofmann's SWG091N2 simulator";
    case S::machine:
      return "the machine";
    case S::profile:
      return "the profile";
    case S::virtual_bed:
      return "the v-bed";
  }
  return "?";
}

// Every rule of the code has its row, as the code has it: severity, source and why; and the
// table has no row the code lacks.
TEST(VbedRuleTable, TheDocsTableIsTheCodes) {
  std::string docs = read_file(testing::source_path("docs/knitout.md"));
  std::size_t table = docs.find("| rule | without `--strict` | source | why |");
  ASSERT_NE(table, std::string::npos);
  std::size_t rows = 0;
  for (const knitout::RuleInfo& r : knitout::all_rules()) {
    std::string row = fmt::format("\n| `{}` | {} | {} | {} |\n", r.name,
                                  knitout::severity_name(r.severity), docs_source(r.source), r.why);
    EXPECT_NE(docs.find(row, table), std::string::npos) << "docs/knitout.md lacks the row" << row;
    ++rows;
  }
  std::size_t in_docs = 0;
  for (std::size_t at = docs.find("\n| `", table);
       at != std::string::npos && at == docs.find("\n|", at); at = docs.find("\n", at + 1))
    ++in_docs;
  EXPECT_EQ(in_docs, rows);
}

// Two rows of four on a tuck cast-on, a second piece of two loops far away (a long float),
// a tuck nothing is pulled through, all dropped at the end.
TEST(VbedFabricReport, SaysWhatTheFileKnits) {
  std::string text = expand(
      "GEN\nin 1\ntuck + f1 1\ntuck + f2 1\ntuck + f3 1\ntuck + f4 1\n"
      "knit - f4 1\nknit - f3 1\nknit - f2 1\nknit - f1 1\n"
      "knit + f1 1\nknit + f2 1\nknit + f3 1\nknit + f4 1\n"
      "knit + b30 1\ntuck + b31 1\nout 1\ndrop f1\ndrop f2\ndrop f3\ndrop f4\ndrop b31\n");
  knitout::MachineProfile p = testing::shipped_profile("generic");
  knitout::Replay r = knitout::replay_knitout(text, "f.k", p, {.strict = false});
  knitout::FabricReport f = knitout::fabric_report(r);
  EXPECT_EQ(f.pieces, 1u);  // the yarn joins the far loops to the rows
  EXPECT_EQ(f.knits, 8u);
  EXPECT_EQ(f.purls, 1u);
  EXPECT_EQ(f.tucks, 5u);
  EXPECT_EQ(f.through_nothing, 1u);  // b30
  EXPECT_EQ(f.unravelling, 5u);      // the last row and the tuck on b31, dropped unheld
  EXPECT_EQ(f.left_on_needles, 1u);  // b30
  EXPECT_EQ(f.long_floats, 1u);      // f4 to b30: 26 needles, generic's max_float is 10
  EXPECT_EQ(f.idle_tucks, 1u);       // b31
  EXPECT_EQ(
      knitout::fabric_summary(f, p),
      "  fabric: 1 piece; 8 knit on the front bed, 1 on the back, 5 tuck, 0 split (0 decreases)\n"
      "  loops dropped that unravel: 5, loops left on the needles: 1\n"
      "  stitches pulled through nothing: 1, floats longer than 10 needles: 1, tucks that "
      "hold nothing: 1");
}

}  // namespace
}  // namespace skein
