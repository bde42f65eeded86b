// `skein verify FILE.k --fabric OUT.st`: the fabric the v-bed rebuilt from a knitout file,
// written as an AutoKnit stitch graph, reads back, checks as knittable and has the model's
// stitches, class by class, where the file knits only the model; and what else the file knits
// (a pass bringing the yarn to the first row, a waste section and its draw thread, short-row
// wraps) adds exactly that.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <array>
#include <filesystem>
#include <sstream>

#include "builtin_targets.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "knitout/fabric_stitch_graph.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

namespace fs = std::filesystem;

// The classes both formats carry: `.st` has one increase and one decrease (and skein's `p`).
enum Class { kCastOn, kBindOff, kKnit, kPurl, kIncrease, kDecrease, kHeld, kClasses };

Class class_of(StitchType type) {
  if (type == StitchType::tuck || type == StitchType::sl) return kHeld;
  if (type == StitchType::p) return kPurl;
  const StitchTypeInfo& i = info(type);
  if (i.loops_in == 0) return kCastOn;
  if (i.loops_out == 0) return kBindOff;
  if (i.loops_out >= 2) return kIncrease;
  if (i.loops_in >= 2) return kDecrease;
  return kKnit;
}

using Counts = std::array<std::int64_t, kClasses>;

Counts counts(const KnitGraph& g) {
  Counts c{};
  for (StitchType t : g.type) ++c[class_of(t)];
  return c;
}

std::string fabric_st(const std::string& text, const std::string& name,
                      const knitout::MachineProfile& p, knitout::ReplayOptions options = {}) {
  knitout::Replay replay = knitout::replay_knitout(text, name, p, options);
  std::ostringstream out;
  knitout::write_fabric_stitch_graph(replay, name, out);
  return out.str();
}

struct RoundTrip {
  const char* sample;
  const char* profile;
  std::int64_t extra_knits;  // knit stitches the file makes besides the model's
  std::int64_t extra_held;   // tucks the file makes besides the model's tucks and slips
};

// `.st` has no short-row letter: a short row's end (sr4) is a knit, in the knit class. Where the
// counts differ, and why:
// - kniterate knits 8 waste rows and a draw thread's row before the piece: 9 rows of it;
// - a short row's turn the file wraps: each wrap is a tuck (all 14 of the sock's turns, 10 of
//   letter I's 12, 8 of the wedge's 9);
// - test-B's first leg drops its bind-off chain's last loop (the yarn goes on to the second
//   leg): dropped with nothing through it, it is left out as every such loop is, and the loop
//   it was knit through ends its wale as a bind-off (one knit fewer).
// The v-bed rebuilds a slip as the loop below it taken by the stitch above, and test-A's
// slips are knit by skein as tucks, so tucks and slips are one class.
constexpr RoundTrip kRoundTrips[] = {
    {"rib-swatch/rib-swatch.obj", "generic", 0, 0},
    {"rib-swatch/rib-swatch.obj", "swg091n2", 0, 0},
    {"rib-swatch/rib-swatch.obj", "kniterate", 180, 0},
    {"hat/hat.obj", "generic", 0, 0},
    {"hat/hat.obj", "swg091n2", 0, 0},
    {"hat/hat.obj", "kniterate", 576, 0},
    {"swatch/swatch.yaml", "generic", 0, 0},
    {"swatch/swatch.yaml", "swg091n2", 0, 0},
    {"swatch/swatch.yaml", "kniterate", 396, 0},
    {"sock/sock.yaml", "generic", 0, 14},
    {"sock/sock.yaml", "swg091n2", 0, 14},
    {"sock/sock.yaml", "kniterate", 360, 14},
    {"autoknit/test-A.st", "generic", 0, 0},
    {"autoknit/test-A.st", "swg091n2", 0, 0},
    {"autoknit/test-B.st", "generic", -1, 0},
    {"autoknit/test-B.st", "swg091n2", -1, 0},
    {"autoknit/test-C.st", "generic", 0, 0},
    {"autoknit/test-C.st", "swg091n2", 0, 0},
    {"letter-i/letter-i.yaml", "generic", 0, 10},
    {"letter-i/letter-i.yaml", "swg091n2", 0, 10},
    {"short-row-wedge/short-row-wedge.yaml", "generic", 0, 8},
    {"short-row-wedge/short-row-wedge.yaml", "swg091n2", 0, 8},
    {"beanie/beanie.yaml", "generic", 0, 0},
    {"beanie/beanie.yaml", "swg091n2", 0, 0},
    {"auto-shift-path/tube.obj", "generic", 0, 0},
    {"auto-shift-path/tube.obj", "swg091n2", 0, 0},
};

TEST(KnitoutFabricGraph, EveryProvenSampleRoundTripsWithItsStitchCounts) {
  fs::current_path(SKEIN_SOURCE_DIR);
  for (const RoundTrip& trip : kRoundTrips) {
    SCOPED_TRACE(fmt::format("{} on {}", trip.sample, trip.profile));
    Compilation model = compile_model(fmt::format("samples/{}", trip.sample));
    knitout::MachineProfile p = testing::shipped_profile(trip.profile);
    std::string text = testing::emit_knitout_text(model, p);
    ASSERT_TRUE(testing::replay_and_prove(text, model, p).proven);
    Compilation fabric =
        compile_knit_graph(parse_autoknit_st(fabric_st(text, "out.k", p), "out.st"), "out.st");
    EXPECT_TRUE(fabric.knittability.knittable) << check_report(fabric);
    EXPECT_FALSE(fabric.program.gap) << fabric.program.gap->why << " at "
                                     << fabric.knit.describe(fabric.program.gap->stitch);
    Counts expected = counts(model.knit);
    expected[kKnit] += trip.extra_knits;
    expected[kHeld] += trip.extra_held;
    EXPECT_EQ(counts(fabric.knit), expected) << check_report(fabric);
  }
}

// The third-party files that replay without an error: each one's fabric reads back as a
// stitch graph, and every one of them checks as knittable.
TEST(KnitoutFabricGraph, ForeignFilesReadBack) {
  int written = 0;
  for (const auto& entry :
       fs::recursive_directory_iterator(testing::source_path("tests/data/knitout-foreign"))) {
    std::string ext = entry.path().extension().string();
    if (ext != ".k" && ext != ".knitout") continue;
    std::string name = entry.path().filename().string();
    std::string text = read_file(entry.path().string());
    knitout::ProfileChoice chosen = knitout::choose_profile(text, name, "", false);
    std::string st;
    try {
      st = fabric_st(text, name, chosen.profile, chosen.options);
    } catch (const ParseError&) {
      continue;  // AutoKnit's files: carrier 0 is not in their ;;Carriers: header
    }
    Compilation fabric = compile_knit_graph(parse_autoknit_st(st, name + ".st"), name + ".st");
    EXPECT_TRUE(fabric.knittability.knittable) << name << "\n" << check_report(fabric);
    EXPECT_GT(fabric.knit.type.size(), 0u) << name;
    ++written;
  }
  EXPECT_EQ(written, 28);  // of 31: AutoKnit's three are refused
}

// A loop dropped with nothing through it is left out (row B but its last loop), and so is the
// cord it ends (knit back and forth on f1); the loops nothing left is knit through end their
// wales (`e`). The cast-on's tucks are its border: the cast-on row's loops are the `s` stitches.
TEST(KnitoutFabricGraph, DroppedLoopsAndTheCordTheyEndAreLeftOut) {
  knitout::MachineProfile p = testing::shipped_profile("generic");
  const char* text =
      ";!knitout-2\n;;Carriers: 1\nin 1\n"
      "tuck - f3 1\ntuck - f1 1\ntuck + f2 1\ntuck + f4 1\n"  // border
      "knit - f4 1\nknit - f3 1\nknit - f2 1\nknit - f1 1\n"  // cast-on row
      "knit + f1 1\nknit + f2 1\nknit + f3 1\nknit + f4 1\n"  // row A
      "knit - f4 1\nknit - f3 1\nknit - f2 1\nknit - f1 1\n"  // row B
      "knit + f1 1\nknit - f1 1\n"                            // a cord on f1
      "out 1\ndrop f1\ndrop f2\ndrop f3\ndrop f4\n";
  EXPECT_EQ(fabric_st(text, "t.k", p, {.strict = false}),
            "1 s c -1 -1 7 -1 4 1 0\n"
            "1 s c -1 -1 6 -1 3 1 0\n"
            "1 s c -1 -1 5 -1 2 1 0\n"
            "1 s c -1 -1 4 -1 1 1 0\n"
            "1 k a 3 -1 8 -1 1 2 0\n"
            "1 e a 2 -1 -1 -1 2 2 0\n"
            "1 e a 1 -1 -1 -1 3 2 0\n"
            "1 e a 0 -1 -1 -1 4 2 0\n"
            "1 e c 4 -1 -1 -1 1 3 0\n");
}

// Written atomically like every output; `.st` and `.obj` (test_knitout_fabric_mesh.cpp) are the
// formats the fabric is written in.
TEST(KnitoutFabricGraph, OnlyAStitchGraphOrMeshIsWritten) {
  fs::current_path(SKEIN_SOURCE_DIR);
  Registry registry;
  register_builtin_targets(registry);
  TargetOptions options;
  options.fabric = "/tmp/never-written.ply";
  const Simulator* vbed = registry.simulator_for("knitout");
  std::string text = read_file("samples/hat/hat.generic.k");
  EXPECT_THROW(vbed->verify(text, "hat.generic.k", nullptr, options), UsageError);
  EXPECT_FALSE(fs::exists(options.fabric));
}

}  // namespace
}  // namespace skein
