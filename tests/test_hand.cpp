// The hand target and its simulator: golden patterns of the samples, every format proven,
// randomized shaped sheets and tubes proven, and the simulator's reasons for rejecting steps.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>

#include "builtin_targets.hpp"
#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "fixtures.hpp"
#include "golden.hpp"
#include "hand/hand_target.hpp"
#include "hand/pattern_model.hpp"
#include "hand/program_pattern.hpp"
#include "hand/row_text.hpp"
#include "labeling/project.hpp"
#include "labeling/shapes.hpp"
#include "labeling/stitch_generation.hpp"
#include "mesh/generate.hpp"
#include "mesh/obj_format.hpp"
#include "target_runner.hpp"
#include "test_hand_plans.hpp"

namespace skein {
namespace {

using T = StitchType;

using testing::emit;
using testing::verify;

using testing::failure_of;

class HandSample : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override { std::filesystem::current_path(SKEIN_SOURCE_DIR); }
};

TEST_P(HandSample, PatternMatchesGoldenAndIsProven) {
  Compilation c = compile_model(GetParam());
  std::string pattern = emit(c, "hand");
  testing::expect_golden(std::filesystem::path(GetParam()).replace_extension(".md").string(),
                         pattern);
  VerifyReport report = verify(c, "hand", pattern);
  EXPECT_TRUE(report.proven) << report.summary;
}

TEST_P(HandSample, HtmlPageAndKnitSpeakRowsAreProvenToo) {
  Compilation c = compile_model(GetParam());
  for (const char* target : {"hand-html", "hand-knitspeak"}) {
    VerifyReport report = verify(c, target, emit(c, target));
    EXPECT_TRUE(report.proven) << target << ": " << report.summary;
  }
  std::string html = emit(c, "hand-html");
  hand::HandPattern pattern = hand::build_hand_pattern(c);
  EXPECT_EQ(testing::occurrences(html, "<use href=\"#skein-model\"/>"), pattern.sections.size())
      << "a schematic at the start of each section";
  EXPECT_EQ(testing::occurrences(html, "<g id=\"skein-model\">"), 1u) << "the model drawn once";
  EXPECT_NE(html.find("@media print"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos) << "self-contained";
  EXPECT_EQ(html.find(" src="), std::string::npos) << "self-contained";
}

INSTANTIATE_TEST_SUITE_P(Samples, HandSample,
                         ::testing::Values("samples/rib-swatch/rib-swatch.obj",
                                           "samples/hat/hat.obj", "samples/sock/sock.yaml",
                                           "samples/short-row-wedge/short-row-wedge.yaml"),
                         [](const auto& param_info) {
                           std::string stem =
                               std::filesystem::path(param_info.param).stem().string();
                           std::replace(stem.begin(), stem.end(), '-', '_');
                           return stem;
                         });

TEST(HandTarget, SwatchRowsReadLikeAPublishedPattern) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  std::string pattern = emit(compile_model("samples/rib-swatch/rib-swatch.obj"), "hand");
  EXPECT_NE(pattern.find("Cast on 20 sts.\n"), std::string::npos);
  EXPECT_NE(pattern.find("**Row 1 (RS):** *P2, k2; rep from * to end.\n"), std::string::npos);
  EXPECT_NE(pattern.find("Rep Row 1 15 more times.\n"), std::string::npos);
}

// The Error the hand target throws for a model it cannot write, or "".
std::string emit_error(const Compilation& c) {
  try {
    emit(c, "hand");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(HandTarget, StitchesNotCoveredYetAreNamed) {
  const std::pair<StitchMesh, const char*> cases[] = {
      {testing::short_row_mesh(T::srn), "(srn), which hand patterns do not cover yet"},
  };
  for (const auto& [mesh, named] : cases) {
    Compilation c = compile_stitch_mesh(mesh, "uncovered");
    ASSERT_TRUE(c.knittability.knittable) << check_report(c);
    std::string error = emit_error(c);
    EXPECT_NE(error.find(named), std::string::npos) << error;
  }
}

// Every knittable sample's pattern is written and proven; a new sample is covered by this test
// without being listed.
TEST(HandTarget, EverySampleIsProven) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  std::uint32_t proven = 0;
  for (const auto& dir : std::filesystem::directory_iterator("samples")) {
    if (dir.path().filename() == "unknittable") continue;
    for (const auto& file : std::filesystem::directory_iterator(dir.path())) {
      std::string ext = file.path().extension().string();
      bool project = ext == ".yaml" || ext == ".st";
      bool stitch_mesh =
          ext == ".obj" &&
          !std::filesystem::exists(std::filesystem::path(file.path()).replace_extension(".yaml"));
      if (!project && !stitch_mesh) continue;
      Compilation c = compile_model(file.path().string());
      VerifyReport report = verify(c, "hand", emit(c, "hand"));
      EXPECT_TRUE(report.proven) << file.path() << ": " << report.summary;
      ++proven;
    }
  }
  EXPECT_GE(proven, 18u);
}

// A knit graph fixture's hand pattern, each of its formats proven, and each of `lines` in it.
void expect_proven_with_lines(KnitGraph graph, const char* name,
                              std::initializer_list<const char*> lines) {
  Compilation c = compile_knit_graph(std::move(graph), name);
  ASSERT_TRUE(c.knittability.knittable) << check_report(c);
  std::string pattern = emit(c, "hand");
  for (const char* line : lines)
    EXPECT_NE(pattern.find(line), std::string::npos) << line << "\n" << pattern;
  EXPECT_EQ(testing::unproven_hand_formats(c), "");
}

// A heel turn with a new yarn on some of a flat piece's last row (the teapot's top): the row
// is parted onto holders, the new yarn joined to the middle one, the others put on spare needles
// for the rows to take one st at a time at each end.
TEST(HandTarget, AHeelTurnOnANewYarnIsProvenInEveryFormat) {
  expect_proven_with_lines(
      testing::heel_turn_on_new_yarn_graph(), "heel turn",
      {"Slip st 1 of Row 1 to holder 1, sts 2–5 to holder 2 and st 6 to holder 3.\n\nCut the "
       "yarn.\n",
       "Join a new yarn to the 4 sts of holder 2, the last st of its last row at the tip.\n",
       "Put the 1 st of holder 3 on a second spare needle, the first st of its last row at the "
       "tip.\n",
       "**Row 2 (WS):** Sl1 from spare, p2tog, sl1 from 2nd spare behind, p2tog.\n",
       "counts them in the order the row worked them"});
}

// A new yarn on sts of a flat piece's row that the piece's own next rows do not work (the
// teapot's yarn 4, flaps parting): they go to a holder right after that row, counted in the
// order it worked them, and the piece works on with the others.
TEST(HandTarget, ANewYarnOnASetAsidePiecesStsIsProvenInEveryFormat) {
  expect_proven_with_lines(testing::new_yarn_on_set_aside_needle_graph(), "set-aside needle",
                           {"**Row 1 (WS):** Purl.\n\nSlip sts 1–2 of Row 1 to holder 1 — 2 "
                            "sts.\n\n**Row 2 (RS):** Knit.\n\n**Row 3 (WS):** Purl.\n\nLeave "
                            "the 2 sts on the needle and set the yarn aside (do not cut it).\n",
                            "Join a new yarn to the 2 sts of holder 1, the last st of its last "
                            "row at the tip.\n",
                            "counts them in the order the row worked them"});
}

// The teapot's top in small: a flat piece set aside with an earlier row's sts on two holders,
// a new yarn on one going on in the rnd round a provisional cast-on and taking the other, the
// piece taken up again on the chain and the new yarn's held sts, placed on its flat needle.
TEST(HandTarget, AFlatPieceTakenUpOnAChainIsProvenInEveryFormat) {
  expect_proven_with_lines(
      testing::flat_piece_taken_up_on_a_chain_graph(), "flat piece on a chain",
      {"Slip sts 1–2 of Row 1 to holder 1 and sts 3–4 to holder 2 — 2 sts.\n",
       "Place the 2 sts of holder 2 on the needle after the first 2 sts of the rnd, the last st "
       "of its last row first.\n",
       "**Rnd 3:** CO 2 sts with a provisional cast-on, k to end — 8 sts.\n",
       "Take up Piece 1 again with its yarn. Place the 2 loops of Piece 2's chain on the needle "
       "after the first 2 sts of the row, the last st cast on first. Place the 2 sts of holder 3 "
       "on the needle after the first 4 sts of the row, the last st of its last row first — 6 "
       "sts.\n\n**Row 4 (RS):** Knit.\n"});
}

// A piece worked flat that goes on in the rnd by picking up along its own edges (the
// teapot's second strip): its sts go to a holder, the rnd picks up onto the empty needle.
TEST(HandTarget, AFlatPieceJoinedInTheRndByItsOwnEdgesIsProvenInEveryFormat) {
  expect_proven_with_lines(
      testing::strip_joined_in_the_rnd_graph(), "strip",
      {"**Row 2 (WS):** Purl.\n\nSlip the 3 sts of Row 2 to holder 1.\n\nPm and join to work in "
       "the rnd: the sts picked up and placed below go on the needle after the marker, in "
       "order.\n\nPick up 2 sts along the left edge of this piece, one in each row from Row 2 "
       "down to Row 1, onto the needle at the beginning of the rnd.\n\n",
       "onto the needle after the first 2 sts of the rnd \u2014 4 sts.\n\n**Rnd 3:** Knit.\n",
       "Join a new yarn to the 3 sts of holder 1, the last st of its last row at the tip.",
       "**Joining a flat piece in the round**", "4 rows and rnds."});
}

// A strip whose yarn goes round a corner into a rnd (the teapot's tube after its strip): the
// last row ends without turning, and the rnd works the sts its short rows left the same way.
TEST(HandTarget, AStripGoingRoundACornerIntoTheRndIsProvenInEveryFormat) {
  expect_proven_with_lines(
      testing::corner_strip_graph(), "corner strip",
      {"**Row 3 (RS):** K3, do not turn.\n\nSlip sts 1\u20133 of Row 3 to holder 1 \u2014 2 "
       "sts.\n\nPm and join to work in the rnd",
       "onto the needle after the first 5 sts of the rnd \u2014 8 sts.\n\n**Rnd 4:** Knit.\n"});
}

// A tube set aside after its flap, while a strip beside it is worked, slips the flap's sts to
// a holder as it is taken up again (the teapot's Piece 1).
TEST(HandTarget, ATubeTakenUpAfterItsFlapSlipsTheFlapsSts) {
  expect_proven_with_lines(testing::flap_and_strip_graph(), "flap and strip",
                           {"Take up Piece 1 again with its yarn. Slip sts 1\u20133 of the rnd to "
                            "holder 2 \u2014 1 st. Pick up 2 sts along the left edge of the flap"});
}

// A flap in the rnd whose last row starts at the beginning of the rnd and goes round a corner
// into the next rnd (the teapot's Piece 1) is a row that does not turn: it leaves the sts
// before the marker, and the flap's sts are the first of the rnd when the tube is taken up.
TEST(HandTarget, AFlapsLastRowRoundACornerInTheRndDoesNotTurn) {
  expect_proven_with_lines(
      testing::flap_and_strip_graph(true), "corner flap and strip",
      {"**Row 4 (RS):** K3, do not turn.\n",
       "Take up Piece 1 again with its yarn. Slip sts 1\u20133 of the rnd to holder 2 \u2014 1 "
       "st. Pick up 3 sts along the left edge of the flap, one in each row from Row 4 down to "
       "Row 2"});
}

// A new yarn joined to the strip's held sts works them in the rnd: it joins at once.
TEST(HandTarget, ANewYarnJoinedToHeldStsWorksThemInTheRnd) {
  expect_proven_with_lines(testing::strip_joined_in_the_rnd_graph(true), "strip leg",
                           {"Join a new yarn to the 3 sts of holder 1, the last st of its last row "
                            "at the tip. Pm and join to work in the rnd, being careful not to "
                            "twist.\n\n**Rnd 1:** Knit.\n"});
}

// A new yarn on held sts that goes on around places another piece's sts into its first rnd.
TEST(HandTarget, ANewYarnJoinedInTheRndPlacesAnotherPiecesSts) {
  expect_proven_with_lines(
      testing::strip_and_tube_joined_graph(), "strip and tube",
      {"at the tip. Pm and join to work in the rnd, being careful not to twist.\n\nPlace the 4 sts "
       "of Piece 1 on the needle after the first 3 sts of the rnd, the first st of its last rnd "
       "first \u2014 7 sts.\n\n**Rnd 1:** Knit.\n"});
}

// Joining a flat piece in the rnd in the middle of its work: its sts first go to a holder,
// and a marker marks the beginning of the rnd on the empty needle.
TEST(HandTarget, AFlatPieceIsJoinedInTheRndWithAnEmptyNeedleAndAMarker) {
  const std::string strip = "Cast on 3 sts.\nRow 1 (RS): Knit.\nRow 2 (WS): Purl.\n";
  const std::pair<std::string, const char*> cases[] = {
      {strip + "Pm and join to work in the rnd.\n",
       "p.md:4: Join to work in the rnd: the sts of Row 2 are still on the needle (slip them to a "
       "holder first: the rnd is made of the sts picked up and placed, and those left)"},
      {strip + "Slip the 3 sts of Row 2 to holder 1.\nJoin to work in the rnd.\n",
       "p.md:5: Join to work in the rnd: pm for the beginning of the rnd first (where the yarn "
       "is)"},
      {strip + "Slip the 2 sts of Row 2 to holder 1.\n",
       "p.md:4: Slip the sts of Row 2 to holder 1: the pattern says 2 sts, but the row left 3 sts "
       "on the needle"},
      {"Cast on 5 sts.\nRow 1 (RS): K3, do not turn.\nRow 2 (WS): P3.\n",
       "p.md:3: Row 2 (RS): labelled WS, but the RS faces you: the work was not turned"},
      {"Cast on 6 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\nSlip sts 1\u20133 of the rnd "
       "to "
       "holder 1 \u2014 3 sts.\nRnd 2: BO all sts.\nFasten off.\n" +
           strip + "Slip the 3 sts of Row 2 to holder 1.\n",
       "p.md:9: Slip the sts of Row 2 to holder 1: it already holds sts"},
      {strip + "Slip the 3 sts of Row 1 to holder 1.\n",
       "p.md:4: Slip the sts of Row 1 to holder 1: the last row worked is Row 2"},
      {"Cast on 6 sts. Pm and join to work in the rnd.\nRnd 1: Knit.\nSlip the 6 sts of Row 1 to "
       "holder 1.\n",
       "p.md:3: Slip the sts of Row 1 to holder 1: only from a piece worked flat (in the rnd, say "
       "which sts)"},
  };
  for (const auto& [pattern, failure] : cases) EXPECT_EQ(failure_of(pattern), failure) << pattern;
}

// Generates many sheets and tubes with random shaping: the hand simulator is the judge.
TEST(HandRandomized, ShapedSheetsAndTubesAreProven) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    RandomShaping shaping;
    shaping.min_width = 4;
    shaping.purl = trial % 3 == 0 ? 0 : 0.3;
    std::uint32_t width = 4 + static_cast<std::uint32_t>(rng() % 40);
    std::uint32_t rows = 1 + static_cast<std::uint32_t>(rng() % 30);
    Layout layout = trial % 2 ? Layout::tube : Layout::sheet;
    RowPlan plan =
        testing::without_edge_make_ones(random_rows(width, rows, shaping, rng()), layout);
    Compilation c = compile_stitch_mesh(build_from_rows(plan, layout), "random");
    ASSERT_TRUE(c.knittability.knittable) << check_report(c);
    for (const char* target : {"hand", "hand-html", "hand-knitspeak"}) {
      if (trial % 10 != 0 && target != std::string("hand")) continue;
      std::string pattern = emit(c, target);
      VerifyReport report = verify(c, target, pattern);
      ASSERT_TRUE(report.proven) << "trial " << trial << " " << target << ": " << report.summary
                                 << "\n"
                                 << pattern;
    }
  }
}

// Every shape `skein new` makes, at 50 random sizes and gauges each, with either short-row
// method, through the hand target: per shape, how many patterns are proven and how many the hand
// target refuses by name; every one is knittable and none is written unproven.
std::map<std::string, std::array<int, 2>> shapes_at_random_sizes() {
  std::mt19937_64 rng(23);
  const std::string dir = ::testing::TempDir();
  std::map<std::string, std::array<int, 2>> tally;  // proven, refused
  for (const std::string& kind : shape_kinds()) {
    for (int trial = 0; trial < 50; ++trial) {
      ShapeSize size;
      bool big = kind == "sweater" || kind == "set-in-sweater" || kind == "shorts" ||
                 kind == "trousers" || kind == "bag";
      size.circumference = (big ? 50 : 10) + static_cast<double>(rng() % (big ? 80 : 40));
      size.width = 5 + static_cast<double>(rng() % 40);
      size.length = 4 + static_cast<double>(rng() % (kind == "sweater" ? 80 : 40));
      std::string name = fmt::format("hand-{}{}", kind, trial);
      Shape shape = make_shape(kind, size, name);
      const std::string gauge = "gauge: {stitches: 22, rows: 30}";
      shape.project.replace(
          shape.project.find(gauge), gauge.size(),
          fmt::format("gauge: {{stitches: {}, rows: {}}}", 12 + rng() % 19, 16 + rng() % 25));
      std::string project = write_shape(shape, dir + "/" + name);
      SCOPED_TRACE(project + "\n" + shape.project);
      Compilation c = compile_model(project);
      EXPECT_TRUE(c.knittability.knittable) << project << "\n" << check_report(c);
      if (!c.knittability.knittable) continue;
      TargetOptions options;
      options.settings["short-rows"] = trial % 2 ? "wrap-and-turn" : "german";
      std::string target = trial % 4 == 0 ? "hand-html" : "hand";
      std::string pattern;
      try {
        pattern = emit(c, target, options);
      } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("hand target: ", 0), 0u) << e.what();
        ++tally[kind][1];
        std::cout << kind << " refused: " << e.what() << "\n";
        continue;
      }
      VerifyReport report = verify(c, target, pattern);
      EXPECT_TRUE(report.proven) << target << ": " << report.summary;
      tally[kind][0] += report.proven;
    }
  }
  for (const auto& [kind, n] : tally)
    std::cout << fmt::format("{}: {} proven, {} refused by name\n", kind, n[0], n[1]);
  return tally;
}

// Every shape at every size is proven: tubes, hats, socks, the yoke and the set-in sweaters, the
// mitten, glove, shorts, trousers and bag (docs/hand-patterns.md keeps the figures). A glove's
// fingers each take part of one provisional cast-on, parted onto holders right after it ("Slip sts
// 1–11 of the cast-on to holder 5 and ..."); a bag's rim binds off in four places and each flap
// between its handles is worked in rows, the others waiting on holders; a set-in sweater's front
// and back are worked in rows, each yarn going on from them to a sleeve picked up round its armhole
// ("Slip the 75 sts of Row 30 to holder 3. Pm and join to work in the rnd: ...").
TEST(HandRandomized, ShapesOfRandomSizesAndGaugesAreProven) {
  for (const auto& [kind, n] : shapes_at_random_sizes()) EXPECT_EQ(n[0], 50) << kind;
}

// A pattern names its pieces after the parts of the garment (the coarse mesh's OBJ groups):
// a mitten's first piece is named after its palm (below the thumb), taken up again for the
// thumb, then the hand; shorts' body goes on into the right leg, then the left leg. The
// simulator reads the names from the headings and proves the pattern.
TEST(HandPieceNames, AMittenSaysThumbAndHandShortsRightLegAndLeftLeg) {
  const std::string dir = ::testing::TempDir();
  const std::map<std::string, std::vector<std::string>> headings = {
      {"mitten",
       {"### Palm (yarn 1)\n", "### Palm (yarn 1), taken up again for the thumb\n",
        "### Hand (yarn 2)\n"}},
      {"shorts",
       {"### Body (yarn 1)\n", "### Body (yarn 1), taken up again for the right leg\n",
        "### Left leg (yarn 2)\n"}}};
  for (const auto& [kind, expected] : headings) {
    SCOPED_TRACE(kind);
    Shape shape = make_shape(kind, {kind == "mitten" ? 20.0 : 90.0, 0, 0}, "named-" + kind);
    Compilation c = compile_model(write_shape(shape, dir + "/named-" + kind));
    ASSERT_TRUE(c.knittability.knittable);
    std::string pattern = emit(c, "hand");
    EXPECT_TRUE(verify(c, "hand", pattern).proven);
    for (const std::string& heading : expected)
      EXPECT_NE(pattern.find(heading), std::string::npos) << heading << pattern;
    EXPECT_NE(pattern.find("Take up " + expected[0].substr(4, expected[0].find(" (") - 4) +
                           " again with its yarn."),
              std::string::npos);
  }
}

// A stitch mesh file names no parts: the same model written as one keeps "Piece N".
TEST(HandPieceNames, AStitchMeshFileKeepsPieceNumbers) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  std::ostringstream obj;
  write_stitch_mesh(build_project(read_project("samples/three-bars/three-bars.yaml")).mesh, obj);
  std::string pattern =
      emit(compile_stitch_mesh(parse_stitch_mesh(obj.str(), "bars.obj"), "bars.obj"), "hand");
  EXPECT_NE(pattern.find("### Piece 2 (yarn"), std::string::npos) << pattern;
}

// The samples of more than one piece at seeded random gauges (the same mesh and project): each
// pattern is proven, or the hand target refuses it by name; none is written wrong (letter-h's
// band with an odd number of rows wrote a turn, letter-r's rows `sl1 from spare` from two).
TEST(HandRandomized, MultiPieceSamplesAtRandomGaugesAreProvenOrRefusedByName) {
  std::mt19937_64 rng(11);
  const char* targets[] = {"hand", "hand-html", "hand-knitspeak"};
  int proven = 0, trial = 0;
  for (const char* sample : {"letter-h", "letter-r", "letter-i", "three-bars", "three-bars-own",
                             "two-bars", "teapot", "sweater"}) {
    for (int i = 0; i < 5; ++i, ++trial) {
      int stitches = 12 + static_cast<int>(rng() % 20), rows = 16 + static_cast<int>(rng() % 30);
      SCOPED_TRACE(fmt::format("{} at {} sts/{} rows", sample, stitches, rows));
      Compilation c;
      try {
        c = testing::sample_at_gauge(sample, stitches, rows);
      } catch (const Error&) {
        continue;  // a mesh the gauge makes unknittable (the teapot's kfb on a contracting edge)
      }
      if (!c.knittability.knittable) continue;
      const char* target = targets[trial % 3];
      std::string pattern;
      try {
        pattern = emit(c, target);
      } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("hand target: ", 0), 0u) << e.what();
        continue;
      }
      VerifyReport report = verify(c, target, pattern);
      EXPECT_TRUE(report.proven) << target << ": " << report.summary;
      proven += report.proven;
    }
  }
  EXPECT_GT(proven, trial / 2);
}

// Crowns and wedge increases, flat and in the round, proven; in the round with section markers.
TEST(HandRandomized, WedgeShapingGetsSectionMarkersAndIsProven) {
  std::mt19937_64 rng(3);
  const T kTubeShapers[] = {T::k2tog, T::ssk, T::s2kp, T::kfb, T::yo, T::m1l, T::m1r};
  for (int trial = 0; trial < 60; ++trial) {
    Layout layout = trial % 2 ? Layout::tube : Layout::sheet;
    T shaper = kTubeShapers[rng() % (layout == Layout::tube ? 7 : 5)];
    auto sections = 2 + static_cast<std::uint32_t>(rng() % 6);
    auto shapings = 2 + static_cast<std::uint32_t>(rng() % 3);
    auto wedge = 3 + 2 * shapings + static_cast<std::uint32_t>(rng() % 8);  // never runs out
    auto plain = static_cast<std::uint32_t>(rng() % 3);
    Compilation c = compile_stitch_mesh(
        build_from_rows(testing::wedge_plan(sections, wedge, shapings, plain, shaper), layout),
        "wedges");
    std::string pattern = emit(c, "hand");
    VerifyReport report = verify(c, "hand", pattern);
    ASSERT_TRUE(report.proven) << "trial " << trial << ": " << report.summary << "\n" << pattern;
    if (layout == Layout::tube) {
      EXPECT_NE(pattern.find(", sm; rep from * to end"), std::string::npos)
          << "trial " << trial << "\n"
          << pattern;
    }
  }
}

// Lines under "## Instructions" per 1,000 stitches: plain knitting compresses to a few lines.
double lines_per_thousand(const Compilation& c, const std::string& pattern) {
  std::istringstream in(pattern.substr(pattern.find("## Instructions\n") + 16));
  int lines = 0;
  for (std::string line; std::getline(in, line) && line.rfind("## ", 0) != 0;)
    lines += !line.empty();
  return 1000.0 * lines / c.knit.size();
}

TEST(HandReadability, PlainKnittingTakesAFewLines) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  for (auto [input, most] :
       {std::pair{"samples/rib-swatch/rib-swatch.obj", 14.0}, std::pair{"samples/hat/hat.obj", 4.5},
        std::pair{"samples/sock/sock.yaml", 8.0},
        std::pair{"samples/short-row-wedge/short-row-wedge.yaml", 12.5},
        std::pair{"samples/sweater/sweater.yaml", 2.6},
        std::pair{"samples/three-bars/three-bars.yaml", 8.5},
        std::pair{"samples/letter-h/letter-h.yaml", 27.5},
        std::pair{"samples/two-bars/two-bars.yaml", 13.5},
        std::pair{"samples/three-bars-own/three-bars-own.yaml", 7.0},
        std::pair{"samples/letter-r/letter-r.yaml", 34.0},
        std::pair{"samples/teapot/teapot.yaml", 26.5},
        std::pair{"samples/autoknit/test-A.st", 78.5},
        std::pair{"samples/autoknit/test-B.st", 101.2},
        std::pair{"samples/autoknit/test-C.st", 62.0}}) {
    Compilation c = compile_model(input);
    double figure = lines_per_thousand(c, emit(c, "hand"));
    std::cout << input << ": " << figure << " instruction lines per 1,000 sts\n";
    EXPECT_LE(figure, most) << input;
  }
  Compilation tube =
      compile_stitch_mesh(build_from_rows(hat_rows(200, 500, 8), Layout::tube), "tube");
  double figure = lines_per_thousand(tube, emit(tube, "hand"));
  std::cout << "a 200-st hat of 500 rnds (" << tube.knit.size() << " sts): " << figure
            << " instruction lines per 1,000 sts\n";
  EXPECT_LE(figure, 0.1);
}

TEST(HandRowText, RepeatsAndCountsAKnitterNeedNotKeep) {
  using O = hand::HandOp;
  auto text = [](std::vector<O> ops) { return hand::row_instructions(ops); };
  EXPECT_EQ(text({O::k, O::k, O::p, O::p, O::k, O::k, O::p, O::p, O::k, O::k}),
            "*K2, p2; rep from * to last 2 sts, k2");
  std::vector<O> decrease = {O::k, O::ssk};
  decrease.resize(16, O::k);
  decrease.push_back(O::k2tog);
  decrease.push_back(O::k);
  EXPECT_EQ(text(decrease), "K1, ssk, k to last 3 sts, k2tog, k1");
  std::vector<O> crown;
  for (int i = 0; i < 12; ++i) crown.push_back(i % 4 == 3 ? O::k2tog : O::k);
  EXPECT_EQ(text(crown), "*K3, k2tog; rep from * to end");
  EXPECT_EQ(text({O::k, O::yo, O::k, O::k}), "K1, yo, k2");
  EXPECT_EQ(text({O::p, O::p, O::p}), "Purl");
  EXPECT_EQ(text({O::bo, O::bo}), "BO all sts");
  // A st slipped onto the left needle from a spare one is no st the row leaves there.
  std::vector<O> heel = {O::from_spare, O::ssk};
  heel.resize(20, O::k);
  heel.push_back(O::from_second_spare_behind);
  heel.push_back(O::ssk);
  EXPECT_EQ(text(heel), "Sl1 from spare, ssk, k to last st, sl1 from 2nd spare behind, ssk");
  EXPECT_EQ(hand::row_instructions(crown, hand::Dialect::knitspeak), "*K3, k2tog, repeat from *");
}

TEST(HandSimulator, ProvesAHandWrittenPatternWithRepeatsAndMarkers) {
  EXPECT_EQ(failure_of("## Instructions\nCast on 8 sts. Pm and join to work in the rnd.\n"
                       "Rnd 1: K4, pm, k4.\nRnd 2: K to m, sm, k2tog, k to end — 7 sts.\n"
                       "Rep Rnd 2 twice more — 5 sts.\nKnit every rnd until 6 rnds in all.\n"
                       "Rnd 7: BO all sts.\nFasten off.\n"),
            "");
  EXPECT_EQ(
      failure_of("Cast on 6 sts.\nRow 1 (RS): *K1, p1; rep from * to end.\n"
                 "Rows 2\u20134: *k1, p1, repeat from *.\nRow 5 (RS): K2tog, k to end (5 sts).\n"
                 "Row 6 (WS): [P1, yo] twice, p to end — 7 sts.\nRow 7 (RS): BO all sts.\n"
                 "Fasten off.\n"),
      "");
}

TEST(HandSimulator, RejectsTheFirstImpossibleStepWithTheRowAndTheReason) {
  const std::string rnd = "Cast on 6 sts. Pm and join to work in the rnd.\nRnd 1: K2, pm, k4.\n";
  EXPECT_EQ(failure_of(rnd + "Rnd 2: K1, k2tog, sm, k4.\n"),
            "p.md:3: Rnd 2: k2tog needs 2 sts before the marker, 1 left");
  EXPECT_EQ(failure_of(rnd + "Rnd 2: K to m, sm, k2tog, k to end — 6 sts.\n"),
            "p.md:3: Rnd 2: the pattern says 6 sts, but 5 sts are on the needle");
  EXPECT_EQ(failure_of(rnd + "Rnd 2: K3, k to end.\n"),
            "p.md:3: Rnd 2: k needs 1 st before the marker, 0 left");
  const std::string flat = "Cast on 10 sts.\nRow 1 (RS): K7.\n";
  EXPECT_EQ(failure_of(flat), "p.md:2: Row 1 (RS): 3 sts left unworked at the end of the row");
  EXPECT_EQ(failure_of("Cast on 10 sts.\nRow 1 (RS): *K2, p2; rep from * to end.\n"),
            "p.md:2: Row 1 (RS): the repeat: 10 sts to go, not a whole number of repeats of 4 sts");
  EXPECT_EQ(failure_of("Cast on 4 sts.\nRow 1 (RS): Knit.\nRow 2 (RS): Knit.\n"),
            "p.md:3: Row 2 (WS): labelled RS, but the WS faces you: every row turns the work");
  EXPECT_EQ(failure_of("Cast on 4 sts.\nRow 1 (RS): Knit.\nRow 2 (WS): Ssk, p2.\n"),
            "p.md:3: Row 2 (WS): ssk is a RS stitch: worked with the WS facing it makes a stitch "
            "the model cannot have (on WS rows work ssp)");
  EXPECT_EQ(
      failure_of("Cast on 4 sts.\nRow 1 (RS): K3, M1L, k1.\nRow 2 (WS): P5, M1PL.\n"),
      "p.md:3: Row 2 (WS): M1PL at the end of a row: there is no strand after the last st to lift");
  EXPECT_EQ(failure_of("Cast on 4 sts.\nRow 1 (RS): Knit.\nRow 2 (WS): Purl.\nRow 3 (RS): Knit.\n"
                       "Rep Rows 1\u20132 once more.\n"),
            "p.md:5: Rep Rows 1\u20132: the rows to repeat must be the last ones worked (Row 3)");
  EXPECT_EQ(failure_of("Cast on 4 sts.\nRow 1 (RS): Knit.\nRow 3 (RS): Knit.\n"),
            "p.md:3: Row 2 comes next, not Row 3");
  EXPECT_EQ(failure_of("Cast on 4 sts.\nRow 1 (RS): Knit.\nFasten off.\n"),
            "p.md:3: Fasten off: 4 sts still on the needle; bind them off first");
}

TEST(HandSimulator, UnreadableTextIsAParseErrorQuotingTheLine) {
  try {
    hand::verify_pattern("Cast on 4 sts.\nRow 1 (RS): K2, frob, k1.\n", "p.md", nullptr);
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_NE(std::string(e.what()).find("found 'frob'"), std::string::npos) << e.what();
  }
}

TEST(HandSimulator, AWrongStitchIsFoundWhenTheFabricIsCompared) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model("samples/rib-swatch/rib-swatch.obj");
  std::string pattern = emit(c, "hand");
  std::size_t at = pattern.find("*P2, k2;");
  ASSERT_NE(at, std::string::npos);
  pattern.replace(at, 8, "*K2, p2;");
  VerifyReport report = verify(c, "hand", pattern);
  EXPECT_FALSE(report.proven);
  EXPECT_NE(report.summary.find("Row 1 (RS), st 1 (k): the pattern makes k (as seen from the RS) "
                                "where the model has p"),
            std::string::npos)
      << report.summary;
}

}  // namespace
}  // namespace skein
