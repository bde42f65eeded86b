// Issue 14, the input side: every input that hung, crashed or was accepted as nonsense is now
// refused with a typed error naming the file and line (or coarse face), and exit code 2 where
// the CLI is involved. Limits: docs/formats.md, "Limits".
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"
#include "common/error.hpp"
#include "hand/needle_sim.hpp"
#include "hand/pattern_reader.hpp"
#include "labeling/coarse_mesh.hpp"
#include "labeling/project.hpp"
#include "labeling/stitch_generation.hpp"

namespace skein {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;

class Limits : public testing::SkeinCliTest {
 protected:
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(in_dir(name), std::ios::binary) << text;
  }
  // Runs skein, expects exit 2 and the message on stderr.
  void expect_refused(const std::string& args, const std::string& message) const {
    CliRun run = skein(args);
    EXPECT_EQ(run.exit_code, 2) << args << "\n" << run.err;
    EXPECT_NE(run.err.find(message), std::string::npos) << args << "\n" << run.err;
  }
  // Replaces `from` (which must be there) by `to` in the file.
  void edit(const std::string& name, const std::string& from, const std::string& to) const {
    std::string text = read(name);
    std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << name << " has no '" << from << "'";
    write(name, text.replace(at, from.size(), to));
  }
  // A tube from `skein new`, with `extra` appended to its project.
  void tube(const std::string& extra) const {
    ASSERT_EQ(skein("new tube --circumference 40cm --length 20cm -o " + in_dir("t1")).exit_code, 0);
    std::ofstream(in_dir("t1.yaml"), std::ios::app) << extra;
  }
};

// --- hangs ----------------------------------------------------------------------------------

TEST_F(Limits, OneShortRowFaceInARingIsRefusedNotALoopForever) {
  tube("short_rows: {faces: [5]}\n");
  expect_refused(
      "check " + in_dir("t1.yaml"),
      "cannot generate stitches for face 5 at (-5.58, 2.5, 2.31): a short-row face's wide "
      "side needs more rows than its narrow side, but the quads of its row join the "
      "two (a quad's sides have the same rows); mark a second short-row face in this "
      "row, or none");
}

TEST_F(Limits, ShortRowFacesAskingEachOtherForRowsAreRefusedNotALoopForever) {
  // Faces 5 and 7 of the first ring: the wide side of each is on the other's narrow side.
  tube("short_rows: {faces: [{face: 5, wide_edge: [6, 14]}, {face: 7, wide_edge: [8, 16]}]}\n");
  expect_refused("check " + in_dir("t1.yaml"),
                 "cannot generate stitches for face 5 at (-5.58, 2.5, 2.31): its rows keep "
                 "growing past 100000: short-row faces in one row whose wide sides each ask the "
                 "other's narrow side for more rows (mark their wide_edge on the same side of "
                 "the row)");
}

TEST_F(Limits, MeshAtDevZeroIsRefusedNotReadForever) {
  write("p.yaml", "mesh: /dev/zero\n");
  expect_refused("check " + in_dir("p.yaml"),
                 "cannot read '/dev/zero': it is a device or socket; expected a regular file");
}

TEST_F(Limits, FifoAndDirectoryInputsAreRefused) {
  ASSERT_EQ(::mkfifo(in_dir("fifo.obj").c_str(), 0600), 0);
  expect_refused("check " + in_dir("fifo.obj"),
                 "cannot read '" + in_dir("fifo.obj") + "': it is a FIFO; expected a regular file");
  fs::create_directory(in_dir("dir.obj"));
  expect_refused("check " + in_dir("dir.obj"), "cannot read '" + in_dir("dir.obj") +
                                                   "': it is a directory; expected a regular "
                                                   "file");
}

TEST_F(Limits, HugeRepeatsAndCastOnsInAHandPatternAreRefusedByLine) {
  write("rep.md",
        "## Instructions\n\nCast on 8 sts. Pm and join to work in the rnd.\n\n"
        "Rnd 1: K to end.\n\nRep Rnd 1 999999999 more times.\n");
  expect_refused("verify " + in_dir("rep.md"),
                 "rep.md:7: expected a number of at most 1000000 (docs/formats.md, \"Limits\"), "
                 "found 999999999");
  write("co.md", "## Instructions\n\nCast on 1000000000 sts.\n");
  expect_refused("verify " + in_dir("co.md"),
                 "co.md:3: expected a number of at most 1000000 (docs/formats.md, \"Limits\"), "
                 "found 1000000000");
}

TEST(LimitsHand, WorkWithinTheNumberLimitStopsAtTheWorkLimit) {
  // Each number is allowed, but the repeats inside repeats would slip a st there and back
  // 10^18 times.
  std::string text =
      "## Instructions\n\nCast on 8 sts. Pm and join to work in the rnd.\n\n"
      "Rnd 1: [[[sl1, sl1 back] 1000000 times] 1000000 times] 1000000 times, k to end.\n";
  hand::Replay r = hand::replay(hand::read_pattern(text, "deep.md"), "deep.md");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.failure,
            "deep.md:5: Rnd 1: the pattern works more than 4000000 sts and "
            "instructions, skein's limit (docs/formats.md, \"Limits\")");
}

TEST_F(Limits, SizesHaveACap) {
  expect_refused("new hat --circumference 1e9cm -o " + in_dir("h"),
                 "'1e9cm' is not a length skein can knit; expected a number with its unit (mm, "
                 "cm, m or in) from 1 cm to 10 m, e.g. 40cm");
  tube("");
  edit("t1.yaml", "stitches: 22", "stitches: 1e6");
  expect_refused("check " + in_dir("t1.yaml"),
                 "t1.yaml:4: expected stitches per 10 cm (a number from 1 to 100), found '1e6'");
}

TEST(LimitsGeneration, CountsBeyondTheLimitNameTheEdge) {
  std::string yaml = "mesh: x.obj\nunit: m\ngauge: {stitches: 100, rows: 100}\n";
  Project p = parse_project(yaml, "p.yaml");
  CoarseMesh m = parse_coarse_mesh("v 0 0 0\nv 900 0 0\nv 900 1 0\nv 0 1 0\nf 1 2 3 4\n", "x.obj");
  try {
    generate_stitch_mesh(m, label_coarse_mesh(m, p), p);
    FAIL() << "900 m at 100 sts per 10 cm was accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "x.obj: edge 1-2 of face 1 would have 900000 stitches; at most 100000 are "
                 "allowed per coarse edge (is the gauge or the unit right? docs/formats.md, "
                 "\"Limits\")");
  }
}

// --- a crash --------------------------------------------------------------------------------

TEST_F(Limits, DeeplyNestedBracketsAreRefusedNotAStackOverflow) {
  write("deep.md", "## Instructions\n\nCast on 8 sts.\n\nRow 1 (RS): " + std::string(20000, '[') +
                       "k1" + std::string(20000, ']') + ".\n");
  expect_refused("verify " + in_dir("deep.md"),
                 "deep.md:5: expected repeats nested at most 32 deep (docs/formats.md, "
                 "\"Limits\"), found '[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[['");
}

// --- nonsense accepted ----------------------------------------------------------------------

TEST_F(Limits, InfiniteOrUnitlessLengthsAreRefused) {
  expect_refused("new hat --circumference infcm -o " + in_dir("h"), "'infcm' is not a length");
  expect_refused("new hat --circumference nancm -o " + in_dir("h"), "'nancm' is not a length");
  expect_refused("new hat --circumference 54 -o " + in_dir("h"),
                 "'54' is not a length skein can knit; expected a number with its unit");
  EXPECT_FALSE(fs::exists(in_dir("h.obj")));
}

TEST(LimitsCoarseMesh, NanInfAndWordsAreRefusedByLine) {
  for (std::string v : {"nan", "inf", "-inf", "x", "1e7"}) {
    try {
      parse_coarse_mesh("v 0 0 0\n  v 1 " + v + " 0\nv 1 1 0\nf 1 2 3\n", "m.obj");
      FAIL() << v << " accepted";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.line(), 2u);
      EXPECT_EQ(e.expected(),
                "expected 3 coordinates (finite numbers of at most 1e+06 in "
                "magnitude) after 'v', found '" +
                    v + "'");
    }
  }
  EXPECT_THROW(parse_coarse_mesh("v 0 0 0\nv 1 0\nv 1 1 0\nf 1 2 3\n", "m.obj"), ParseError);
}

TEST(LimitsCoarseMesh, CoincidentCornersAreRefused) {
  try {
    parse_coarse_mesh("v 0 0 0\nv 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 4\n", "m.obj");
    FAIL() << "coincident corners accepted";
  } catch (const MeshError& e) {
    EXPECT_STREQ(e.what(),
                 "m.obj: edge 2-3 of face 1 has no length (vertices 2 and 3 are at "
                 "(1, 0, 0)); expected the corners of a face at different points");
  }
}

TEST_F(Limits, GaugeOutOfRangeIsRefused) {
  tube("");
  edit("t1.yaml", "stitches: 22", "stitches: 1e308");
  expect_refused("check " + in_dir("t1.yaml"),
                 "t1.yaml:4: expected stitches per 10 cm (a number from 1 to 100), found "
                 "'1e308'");
}

TEST_F(Limits, UnknownGroupNamesAreRefused) {
  ASSERT_EQ(skein("new hat -o " + in_dir("h")).exit_code, 0);
  edit("h.yaml", "brim: k2p2", "brimm: k2p2");
  CliRun run = skein("check " + in_dir("h.yaml"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("h.yaml:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(": 'patterns' names the group 'brimm', but " + in_dir("h.obj") +
                         " has no such group; did you mean 'brim'?"),
            std::string::npos)
      << run.err;
}

TEST(LimitsProject, DuplicateKeysAreRefusedWithBothLines) {
  auto message = [](const std::string& yaml) {
    try {
      parse_project(yaml, "p.yaml");
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("mesh: a.obj\ngauge: {stitches: 20}\ngauge: {rows: 20}\n"),
            "p.yaml:3: 'gauge' is given twice (first on line 2); expected each key once\n"
            "      3 | gauge: {rows: 20}");
  EXPECT_EQ(message("mesh: a.obj\ngauge: {stitches: 20, stitches: 30}\n"),
            "p.yaml:2: 'stitches' is given twice (first on line 2); expected each key once\n"
            "      2 | gauge: {stitches: 20, stitches: 30}");
  EXPECT_EQ(message("mesh: a.obj\npatterns:\n  cuff: k2p2\n  cuff: knit\n"),
            "p.yaml:4: 'cuff' is given twice (first on line 3); expected each key once\n"
            "      4 |   cuff: knit");
  EXPECT_TRUE(message("mesh: a.obj\n? [a]\n: b\n")
                  .starts_with("p.yaml:2: expected a field name (a single value)"));
}

// --- the gauge honoured ---------------------------------------------------------------------

TEST(LimitsProject, YarnAndNeedleDefaultByGauge) {
  auto gauge = [](const std::string& yaml) { return parse_project(yaml, "p.yaml").yarn_gauge(); };
  YarnGauge g = gauge("mesh: a.obj\n");
  EXPECT_EQ(g.stitches_per_10cm, 22);
  EXPECT_EQ(g.weight, YarnWeight::dk);
  EXPECT_EQ(g.needle_mm, 4);
  g = gauge("mesh: a.obj\ngauge: {stitches: 28, rows: 40}\n");
  EXPECT_EQ(g.weight, YarnWeight::fingering);
  EXPECT_EQ(g.needle_mm, 2.75);
  g = gauge("mesh: a.obj\ngauge: {stitches: 18, yarn: aran}\n");
  EXPECT_EQ(g.weight, YarnWeight::aran);
  EXPECT_EQ(g.needle_mm, 5);
  g = gauge("mesh: a.obj\ngauge: {yarn: dk, needle: 3.75 mm}\n");
  EXPECT_EQ(g.needle_mm, 3.75);
  g = gauge("mesh: a.obj\nunit: mm\nstitch_size: {width: 5, height: 4}\n");
  EXPECT_DOUBLE_EQ(g.stitches_per_10cm, 20);
  EXPECT_DOUBLE_EQ(g.rows_per_10cm, 25);
  EXPECT_THROW(gauge("mesh: a.obj\ngauge: {needle: 4.5}\n"), ParseError);  // no unit
  EXPECT_THROW(gauge("mesh: a.obj\ngauge: {needle: 45mm}\n"), ParseError);
  EXPECT_THROW(gauge("mesh: a.obj\ngauge: {yarn: chunky}\n"), ParseError);
}

TEST_F(Limits, TheHandPatternGivesTheProjectsGauge) {
  ASSERT_EQ(skein("new hat --circumference 54cm -o " + in_dir("h")).exit_code, 0);
  CliRun run = skein("compile " + in_dir("h.yaml") + " -t hand -o " + in_dir("h.md"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::string md = read("h.md");
  EXPECT_NE(md.find("22 sts and 30 rows = 10 cm (4 in) in stockinette stitch with DK-weight "
                    "yarn on 4 mm (US 6) needles, the project's gauge"),
            std::string::npos)
      << md;
  // 120 sts at 22 per 10 cm: 54.5 cm (the 8 sides of the hat's coarse mesh each have 15 sts).
  EXPECT_NE(md.find("Circumference: 55 cm (21.5 in), 120 sts at the widest."), std::string::npos)
      << md;
  EXPECT_NE(md.find("of DK-weight yarn"), std::string::npos);
  EXPECT_EQ(md.find("worsted"), std::string::npos);

  edit("h.yaml", "stitches: 22, rows: 30", "stitches: 28, rows: 40");
  run = skein("compile " + in_dir("h.yaml") + " -t hand -o " + in_dir("h.md") + " --force");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  md = read("h.md");
  EXPECT_NE(md.find("28 sts and 40 rows = 10 cm (4 in) in stockinette stitch with "
                    "fingering-weight yarn on 2.75 mm (US 2) needles"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("20 sts and 28 rows"), std::string::npos);
}

TEST_F(Limits, AStitchMeshSaysItsGaugeIsAssumed) {
  CliRun run = skein("compile samples/hat/hat.obj -t hand -o " + in_dir("h.md"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(read("h.md").find("20 sts and 28 rows = 10 cm (4 in) in stockinette stitch with "
                              "worsted-weight yarn on 4.5 mm (US 7) needles. The model does not "
                              "say its gauge: the measurements and yarn amounts assume this one, "
                              "skein's default."),
            std::string::npos);
}

}  // namespace
}  // namespace skein
