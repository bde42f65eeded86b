// The yarn-level model's checks that can fail: no yarn passes through another after
// relaxation, every loop is held by the stitch the knit graph says (and not by its unrelated
// neighbours) before and after relaxation, and the yarn's length per stitch is the gauge's.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <random>

#include "common/atomic_file.hpp"
#include "driver/pipeline.hpp"
#include "labeling/shapes.hpp"
#include "mesh/autoknit_st.hpp"
#include "random_garments.hpp"
#include "target_runner.hpp"
#include "yarn/build.hpp"
#include "yarn/checks.hpp"
#include "yarn/mesh_relax.hpp"

namespace skein {
namespace {

// Yarns may come this close after relaxation, in diameters (the relaxation stops when no
// overlap is deeper than RelaxOptions::overlap = 0.1).
constexpr float kClearance = 0.9f;
constexpr int kRandomGarments = 30;

std::string sample_path(const std::string& name, const std::string& extension) {
  return std::string(SKEIN_SOURCE_DIR) + "/samples/" + name + "/" + name + extension;
}

YarnBuild yarn_of(const Compilation& c, int steps) {
  YarnOptions options;
  options.relax.max_steps = steps;
  options.relax_yarn = steps > 0;
  std::vector<std::array<double, 3>> positions;
  if (!c.mesh) positions = read_stitch_positions(c.input);
  return build_yarn(c.knit, c.yarns, c.mesh ? &*c.mesh : nullptr, positions, options);
}

// `unrelated`: the share of loops an unrelated neighbour's yarn may pierce as well (cells
// next to short-row faces are skewed); `missed`: the share its taker's yarn may miss.
void expect_held(const Compilation& c, const YarnModel& model, const std::string& when,
                 double unrelated = 0, double missed = 0) {
  TopologyReport t = check_yarn_topology(c.knit, model);
  EXPECT_GT(t.loops, 0u) << c.input;
  EXPECT_LE(t.not_held, missed * t.loops) << c.input << " " << when << ": " << t.first_problem;
  EXPECT_LE(t.wrongly_held, unrelated * t.loops)
      << c.input << " " << when << ": " << t.first_problem;
}

void expect_clear(const Compilation& c, const YarnModel& model) {
  Clearance clear = yarn_clearance(model, kClearance);
  EXPECT_EQ(clear.closer, 0u) << c.input << ": closest approach " << clear.closest << " diameters";
}

// Builds, checks the topology, relaxes, checks topology and clearance.
void check_sample(const std::string& input) {
  Compilation c = compile_model(input);
  YarnBuild laid = yarn_of(c, 0);
  expect_held(c, laid.model, "as laid");
  YarnBuild relaxed = yarn_of(c, 3000);
  EXPECT_TRUE(relaxed.relaxation.converged) << input;
  expect_held(c, relaxed.model, "relaxed");
  expect_clear(c, relaxed.model);
}

TEST(YarnModel, HatHoldsEveryLoopAndNoYarnPassesThroughAnother) {
  check_sample(sample_path("hat", ".obj"));
}

TEST(YarnModel, RibSwatchKnitAndPurl) {
  check_sample(sample_path("rib-swatch", ".obj"));
}

TEST(YarnModel, EveryPieceIsOneCurveInYarnOrder) {
  Compilation c = compile_model(sample_path("hat", ".obj"));
  YarnModel m = yarn_of(c, 0).model;
  ASSERT_EQ(m.pieces(), c.yarns.size());
  // Consecutive stitches along the yarn are consecutive runs of points, and no step between
  // two points is longer than a stitch, 8 radii (the yarn is continuous).
  for (StitchId s = 0; s < c.knit.size(); ++s) {
    StitchId next = c.knit.yarn_next[s];
    if (next == kNoStitch) continue;
    EXPECT_LT(m.stitch_first[s], m.stitch_first[next]) << c.knit.describe(s);
  }
  for (std::uint32_t p = 0; p < m.pieces(); ++p)
    for (std::uint32_t i = m.piece_first[p]; i + 1 < m.piece_first[p + 1]; ++i)
      ASSERT_LT((m.point[i + 1] - m.point[i]).norm(), 8 * m.radius) << i;
}

// Munden's constants for dry-relaxed plain knitting: loop length = 3.8 stitch widths (kw)
// = 5.0 row heights (kc). At a gauge (w, h) the relaxed knit stitch's yarn must lie within
// 25% of their mean, (3.8 w + 5.0 h) / 2, on plain knitting (the hat, in the round; ribbing
// takes more yarn where it goes between front and back, and Munden's figures are not for it).
TEST(YarnModel, KnitLengthPerStitchMatchesTheGauge) {
  for (std::string input : {sample_path("hat", ".obj")}) {
    Compilation c = compile_model(input);
    YarnBuild y = yarn_of(c, 3000);
    double per_stitch = yarn_length_per_stitch(c.knit, y.model, StitchType::k);
    double munden = (3.8 * y.gauge.stitch_width + 5.0 * y.gauge.row_height) / 2;
    EXPECT_NEAR(per_stitch / munden, 1.0, 0.25)
        << input << ": " << per_stitch << " per stitch at w " << y.gauge.stitch_width << ", h "
        << y.gauge.row_height;
  }
}

// Every sample's yarn as laid: its loops held as the knit graph says, with at most the loops
// each still misses (not held) or lets an unrelated neighbour's yarn through (held wrongly)
// today: the teapot's at a k2tog where two cells meet at its body's corner (row 57), the
// sweater's where its round steps up and a cast-on's loop a purl takes, letter-r's at a join.
// Before a decrease's loops stacked as the catalogue says and their legs turned to the
// stack's depth before leaning: teapot 0 / 6, sweater 0 / 14 (k2togs), letter-r 0 / 0.
// An edge stitch that makes a loop besides its own across an expanding perpendicular edge
// lays no lobe for it: the teapot has 52 such loops (letter-r 16, two-bars 20), picked up
// through a side and not checked. Before they were told apart, lobes bent their heads to the
// wrong taker: the teapot's loops were 79 not held and 37 held wrongly, letter-r's 26 and 16,
// two-bars' 15 and 10. Before a join's bind-off stood as a ridge (its loops' heads bent across
// its cell from one side) and the stitch mesh bent everywhere at 0.3 (the sweater's yoke
// stayed folded): letter-h 7 / 0, letter-r 0 / 1, teapot 4 / 5, sweater 72 / 86.
TEST(YarnModel, EverySampleAsLaidHoldsItsLoops) {
  struct Expected {
    std::string sample;
    std::uint32_t picked_up, not_held, wrongly_held;
  };
  const std::vector<Expected> samples = {
      {"hat", 0, 0, 0},       {"rib-swatch", 0, 0, 0},      {"swatch", 0, 0, 0},
      {"beanie", 0, 0, 0},    {"short-row-wedge", 0, 0, 0}, {"sock", 0, 0, 0},
      {"letter-i", 0, 0, 0},  {"letter-h", 0, 0, 0},        {"letter-r", 16, 0, 1},
      {"two-bars", 20, 0, 0}, {"three-bars", 0, 0, 0},      {"three-bars-own", 0, 0, 0},
      {"teapot", 52, 0, 1},   {"sweater", 0, 0, 6}};
  for (const Expected& e : samples) {
    std::string yaml = std::string(SKEIN_SOURCE_DIR) + "/samples/" + e.sample + "/" + e.sample;
    Compilation c =
        compile_model(std::filesystem::exists(yaml + ".yaml") ? yaml + ".yaml" : yaml + ".obj");
    TopologyReport t = check_yarn_topology(c.knit, yarn_of(c, 0).model);
    std::cout << e.sample << ": " << t.loops << " loops, " << t.not_held << " not held, "
              << t.wrongly_held << " held wrongly\n";
    EXPECT_GT(t.loops, 0u) << e.sample;
    EXPECT_EQ(t.picked_up, e.picked_up) << e.sample;
    EXPECT_LE(t.not_held, e.not_held) << e.sample << ": " << t.first_problem;
    EXPECT_LE(t.wrongly_held, e.wrongly_held) << e.sample << ": " << t.first_problem;
  }
}

// The relaxed stitch mesh the yarn is laid on does not fold back on itself: springs alone
// buckled every band the input gives less room than its rows need (the teapot had 936 faces
// turned over a neighbour, letter-h 477, three-bars 642, the sock's heel 78); bending unfolds
// them, and the sweater's yoke, folded in the input (872 faces). Before join edges bent and
// bending was 0.3 (0.1) with an anchor of 0.1 (0.05): letter-h 28, two-bars 36, three-bars
// 72, teapot 4, sweater 384.
TEST(YarnModel, RelaxedStitchMeshDoesNotFold) {
  for (const std::string sample :
       {"hat", "rib-swatch", "swatch", "beanie", "short-row-wedge", "sock", "letter-i", "letter-h",
        "letter-r", "two-bars", "three-bars", "three-bars-own", "teapot", "sweater"}) {
    std::string yaml = std::string(SKEIN_SOURCE_DIR) + "/samples/" + sample + "/" + sample;
    Compilation c =
        compile_model(std::filesystem::exists(yaml + ".yaml") ? yaml + ".yaml" : yaml + ".obj");
    ASSERT_TRUE(c.mesh.has_value()) << sample;
    std::vector<Point3> relaxed = relax_stitch_mesh(*c.mesh, stitch_mesh_gauge(*c.mesh));
    EXPECT_EQ(folded_faces(*c.mesh, relaxed), 0u) << sample;
  }
}

// Random garments from `skein new`'s shapes (tubes, sheets, hats with decreases, socks with
// short rows) at random sizes and gauges.
TEST(YarnModel, RandomShapesHoldEveryLoopAndStayClear) {
  std::mt19937 rng(17);
  const std::vector<std::string> kinds = {"sheet", "tube", "hat", "sock"};
  auto dir = std::filesystem::temp_directory_path() /
             ("skein-yarn-" + std::to_string(static_cast<long>(::getpid())));
  std::filesystem::create_directories(dir);
  for (int trial = 0; trial < 4; ++trial) {
    const std::string& kind = kinds[trial % kinds.size()];
    ShapeSize size;
    size.circumference = std::uniform_real_distribution<double>(6, 12)(rng);
    size.width = std::uniform_real_distribution<double>(3, 6)(rng);
    size.length = std::uniform_real_distribution<double>(4, 8)(rng);
    std::string name = fmt::format("{}{}", kind, trial);
    std::string project = write_shape(make_shape(kind, size, name), (dir / name).string());
    SCOPED_TRACE(project);
    Compilation c = compile_model(project);
    EXPECT_EQ(folded_faces(*c.mesh, relax_stitch_mesh(*c.mesh, stitch_mesh_gauge(*c.mesh))), 0u);
    YarnBuild laid = yarn_of(c, 0);
    expect_held(c, laid.model, "as laid", 0.02);
    YarnBuild relaxed = yarn_of(c, 3000);
    expect_held(c, relaxed.model, "relaxed", 0.02);
    expect_clear(c, relaxed.model);
  }
  std::filesystem::remove_all(dir);
}

// A small sweater (`skein new sweater`, 20 cm round, body 6 cm, at half the default gauge:
// 1,660 stitches, three pieces joined at the yoke) relaxes in a bounded number of steps with
// no yarn through another and every loop held by its taker; 28 of 1,636 loops are pierced by
// a neighbour's yarn as well as laid (1.7%: cast-on loops a purl takes, pierced by the next
// stitch since legs turn to their taker's depth below the lean; 26 before, 22 before the
// stitch mesh bent at 0.3), 5 after 800 steps (0.3%). Before the sleeves' last
// rings stood out from the body, the armholes folded back and yarn crossed yarn there.
TEST(YarnModel, SmallSweaterRelaxesClearWithEveryLoopHeld) {
  auto dir = std::filesystem::temp_directory_path() /
             ("skein-yarn-sweater-" + std::to_string(static_cast<long>(::getpid())));
  std::filesystem::create_directories(dir);
  ShapeSize size;
  size.circumference = 20;
  size.length = 6;
  Shape shape = make_shape("sweater", size, "sweater");
  const std::string gauge = "gauge: {stitches: 22, rows: 30}";
  ASSERT_NE(shape.project.find(gauge), std::string::npos) << shape.project;
  shape.project.replace(shape.project.find(gauge), gauge.size(), "gauge: {stitches: 11, rows: 15}");
  Compilation c = compile_model(write_shape(shape, (dir / "sweater").string()));
  EXPECT_EQ(c.knit.size(), 1660u);
  expect_held(c, yarn_of(c, 0).model, "as laid", 0.018);
  YarnBuild relaxed = yarn_of(c, 1200);
  expect_held(c, relaxed.model, "relaxed", 0.005);
  expect_clear(c, relaxed.model);
  std::filesystem::remove_all(dir);
}

// AutoKnit's stitch graphs get yarn from their stitches' positions alone (no stitch mesh).
// Their rows come in close pairs (0.10 apart, then 0.27) and lean beside decreases; the layout
// spaces the rows evenly and squares the cells. All three relax to tolerance with no yarn
// through another, and every loop is held by its taker, as laid and relaxed; test-B and test-C
// pass the samples' checks, test-A's loops are pierced by an unrelated neighbour too at 3 of
// 381 as laid and 2 relaxed (beside a decrease whose wales lean a stitch and a half, and at a
// short row's tuck).
TEST(YarnModel, AutoKnitStitchGraphsHoldEveryLoopAndStayClear) {
  const std::vector<std::pair<std::string, double>> samples = {
      {"test-A", 0.008}, {"test-B", 0}, {"test-C", 0}};  // and the share wrongly held
  for (const auto& [name, unrelated] : samples) {
    std::string input = std::string(SKEIN_SOURCE_DIR) + "/samples/autoknit/" + name + ".st";
    SCOPED_TRACE(input);
    std::vector<std::array<double, 3>> positions;
    KnitGraph graph = parse_autoknit_st(read_file(input), input, &positions);
    Compilation c = compile_knit_graph(std::move(graph), input);
    YarnOptions options;
    options.relax_yarn = false;
    YarnBuild laid = build_yarn(c.knit, c.yarns, nullptr, positions, options);
    expect_held(c, laid.model, "as laid", unrelated);
    options.relax_yarn = true;
    YarnBuild relaxed = build_yarn(c.knit, c.yarns, nullptr, positions, options);
    EXPECT_TRUE(relaxed.relaxation.converged);
    expect_held(c, relaxed.model, "relaxed", unrelated);
    expect_clear(c, relaxed.model);
  }
}

// The machine's fabric gets yarn too: the hat's knitout, replayed by the v-bed (not the
// emitter), rebuilt as a stitch graph, laid with yarn. A tube lies flat on the two beds, so
// the stitches at its folds get rough frames: 1 loop in 1,000 may be missed there (the hat
// misses 1 of 2,048, at a fold).
TEST(YarnModel, FabricOfAKnitoutFileHoldsEveryLoop) {
  Compilation hat = compile_model(sample_path("hat", ".obj"));
  TargetOptions options;
  options.machine = "generic";
  std::string knitout = testing::emit(hat, "knitout", options);
  Registry registry;
  register_builtin_targets(registry);
  std::optional<std::string> fabric =
      registry.simulator_for("knitout")->fabric_stitch_graph(knitout, "hat.k", options);
  ASSERT_TRUE(fabric.has_value());
  std::vector<std::array<double, 3>> positions;
  Compilation c = compile_knit_graph(parse_autoknit_st(*fabric, "hat.k", &positions), "hat.k");
  EXPECT_EQ(c.knit.size(), hat.knit.size());
  YarnOptions laid;
  laid.relax_yarn = false;
  YarnBuild yarn = build_yarn(c.knit, c.yarns, nullptr, positions, laid);
  EXPECT_EQ(yarn.model.pieces(), c.yarns.size());
  expect_held(c, yarn.model, "as laid", 0.02, 0.001);
}

// Random garments (tests/random_garments.hpp: trees of tubes that part and join, bent by short
// rows; sheets whose flaps part or join), as laid: a ratchet on the loops not held and held
// wrongly over the 30 garments (163,575 loops; 156,479 before bent tubes knit from their
// branches could be labelled, and 101 and 105 of them). What is left is mostly at joins and splits:
// loops a three-needle bind-off takes that it misses (33) or whose taker's loop it pierces
// (49), split cast-on loops their takers miss (34); then 34 knit loops not held in bands (24
// in one garment's row 26) and 24 purl loops pierced by a knit neighbour. Before a decrease's
// loops stacked as the catalogue says and legs turned to their stack's depth before leaning
// (a k2tog's first loop was pierced by its second maker's yarn, a knit beside a purl in rib):
// 117 and 222; before a join's bind-off stood as a ridge and the stitch mesh bent
// everywhere: 153 and 236.
TEST(YarnModel, RandomGarmentsAsLaidHoldTheirLoops) {
  std::uint32_t loops = 0, not_held = 0, wrongly_held = 0;
  testing::tally_random_garments(kRandomGarments, [&](const Compilation& c, testing::Dice&) {
    TopologyReport t = check_yarn_topology(c.knit, yarn_of(c, 0).model);
    loops += t.loops, not_held += t.not_held, wrongly_held += t.wrongly_held;
    return testing::Verdict{true, ""};
  });
  std::cout << loops << " loops, " << not_held << " not held, " << wrongly_held
            << " held wrongly\n";
  EXPECT_GT(loops, 150000u);
  EXPECT_LE(not_held, 103u);
  EXPECT_LE(wrongly_held, 110u);
}

}  // namespace
}  // namespace skein
