// Short rows on the knitout target: partial passes that turn beside waiting loops with a tuck
// over the first waiting needle (no hole), on sheets and in a tube (a sock heel), proven by the
// virtual v-bed on every profile.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "fixtures.hpp"
#include "knitout/course_layout.hpp"
#include "labeling/shapes.hpp"
#include "mesh/generate.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

using T = StitchType;
using testing::shipped_profile;

const char* const kProfiles[] = {"swg091n2", "kniterate", "generic"};

// The fixture: four stitches; a short row knits three and turns at an sr4, the next row comes
// back, and a full row takes every loop, the first stitch's cast-on loop included.
TEST(KnitoutShortRows, TheCoursesTakeARunOfTheWaitingLoopsAndTheTurnWrapsTheNextOne) {
  Compilation c = compile_stitch_mesh(testing::short_row_mesh(T::sr4), "short rows");
  knitout::CourseLayout l = knitout::lay_out_pieces(c).front();
  ASSERT_EQ(l.courses.size(), 5u);
  std::vector<bool> partial, wrapped;
  for (const knitout::Course& course : l.courses) {
    partial.push_back(course.partial);
    wrapped.push_back(course.wrap != knitout::kNoWrap);
  }
  EXPECT_EQ(partial, (std::vector<bool>{false, true, true, false, false}));
  // Only the turn at the sr4 has a loop waiting beyond it; the other turns are at the edge.
  EXPECT_EQ(wrapped, (std::vector<bool>{false, true, false, false, false}));
  const knitout::Course& turning = l.courses[1];
  EXPECT_EQ(c.knit.type[l.order[turning.end - 1]], T::sr4);
  EXPECT_EQ(c.knit.type[c.knit.loops[turning.wrap].maker], T::co);
}

// The proof finds every wrap of the sock's heel, each pulled through by the st that takes the
// loop it wraps. The model has no wraps (they close the turn's hole): without one, the file
// still knits the sock's sts and is proven with one wrap fewer; made going the other way, it is
// either the same fabric or not proven.
TEST(KnitoutShortRows, EachWrapOfTheSockHeelIsFoundByTheProof) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  Compilation c = compile_model("samples/sock/sock.yaml");
  knitout::MachineProfile p = shipped_profile("swg091n2");
  std::string text = testing::emit_knitout_text(c, p);
  knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
  ASSERT_TRUE(proof.proven) << proof.summary;
  EXPECT_EQ(proof.wrap_lines.size(), 14u);  // one per sr4 turn
  std::vector<std::size_t> starts{0};       // each line's offset
  for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 1))
    starts.push_back(at + 1);
  for (std::uint32_t line : proof.wrap_lines) {
    std::size_t begin = starts[line - 1], size = starts[line] - begin;
    EXPECT_EQ(text.substr(begin, 5), "tuck ");
    std::string dropped = text;
    dropped.erase(begin, size);
    knitout::ProofResult without = testing::replay_and_prove(dropped, c, p);
    EXPECT_TRUE(without.proven) << without.summary;
    EXPECT_EQ(without.wrap_lines.size(), 13u);
  }
}

// At 11 stitches and 49 rows per 10 cm, two of the sock heel's turns come beside one waiting
// loop: the second wraps its own stitch instead, tucking its needle on the way back, so that
// no needle of the Kniterate gathers more than 2 loops. The proof takes it for a wrap.
TEST(KnitoutShortRows, ASecondTurnBesideAWrappedLoopWrapsItsOwnStitchGoingBack) {
  std::string project = ::testing::TempDir() + "/double-wrap.yaml";
  std::ofstream(project) << fmt::format(
      "mesh: {}/samples/sock/sock.obj\ngauge: {{stitches: 11, rows: 49}}\npatterns: {{cuff: "
      "k2p2}}\nshort_rows:\n  method: sr4\n  faces: [34, 39]\n",
      SKEIN_SOURCE_DIR);
  Compilation c = compile_model(project);
  knitout::MachineProfile p = shipped_profile("kniterate");
  std::string text = testing::emit_knitout_text(c, p);
  ASSERT_TRUE(testing::replay_and_prove(text, c, p).proven);
  int back_wraps = 0;
  knitout::CourseLayout l = knitout::lay_out_pieces(c).front();  // kept: the loop reads it
  for (const knitout::Course& course : l.courses) back_wraps += course.wrap_back;
  EXPECT_EQ(back_wraps, 4);
  // "knit - b131 6" then "tuck + b131 6": the same needle, the other way.
  std::size_t at = text.find("knit - b131 6\ntuck + b131 6\n");
  ASSERT_NE(at, std::string::npos);
  knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
  std::size_t line =
      static_cast<std::size_t>(std::count(text.begin(), text.begin() + at, '\n')) + 2;
  EXPECT_NE(std::find(proof.wrap_lines.begin(), proof.wrap_lines.end(), line),
            proof.wrap_lines.end());
}

TEST(KnitoutShortRows, TheFixtureKnitsAndProvesOnEveryProfileWithATuckAtTheTurn) {
  for (StitchType turn : {T::sr4, T::sr5}) {
    Compilation c = compile_stitch_mesh(testing::short_row_mesh(turn), "short rows");
    for (const char* name : kProfiles) {
      knitout::MachineProfile p = shipped_profile(name);
      std::string text = testing::emit_knitout_text(c, p);
      EXPECT_NE(text.find(";!source: row 2 knit (short row)"), std::string::npos) << name;
      knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
      EXPECT_TRUE(proof.proven) << abbreviation(turn) << " on " << name << ": " << proof.summary;
    }
  }
}

// An sr5 makes the turn's loop itself: a tuck on the facing needle on the way back, which
// the k2tog above takes on top of the sr5's knit loop (its lean). No other wrap is made.
TEST(KnitoutShortRows, AFiveEdgedTurnTucksTheFacingNeedleOnTheWayBack) {
  Compilation c = compile_stitch_mesh(testing::short_row_mesh(T::sr5), "short rows");
  knitout::CourseLayout l = knitout::lay_out_pieces(c).front();
  for (const knitout::Course& course : l.courses) EXPECT_EQ(course.wrap, knitout::kNoWrap);
  std::string text = testing::emit_knitout_text(c, shipped_profile("generic"));
  std::size_t row2 = text.find(";!source: row 2 knit (short row)");
  std::size_t row3 = text.find(";!source: row 3", row2);
  EXPECT_EQ(text.substr(row2, row3 - row2),
            ";!source: row 2 knit (short row): faces 6..7 (right to left)\n"
            "knit - f501 1\nknit - f500 1\nknit - f499 1\ntuck + b499 1\n");
}

// A tuck after the turn that no st pulls through is no wrap: the proof names it.
TEST(KnitoutShortRows, ATurnsTuckThatNothingTakesIsNotProven) {
  Compilation c = compile_stitch_mesh(testing::short_row_mesh(T::sr4), "short rows");
  knitout::MachineProfile p = shipped_profile("generic");
  std::string text = testing::emit_knitout_text(c, p);
  ASSERT_TRUE(testing::replay_and_prove(text, c, p).proven);
  std::size_t knit = text.find(";!source: row 2 knit (short row)");
  std::size_t tuck = text.find("tuck ", knit);
  ASSERT_NE(tuck, std::string::npos);
  std::size_t end = text.find('\n', tuck);
  std::string line = text.substr(tuck, end - tuck);  // "tuck - f498 1": moved to an empty needle
  std::string moved = line.substr(0, 8) + "100" + line.substr(line.rfind(' '));
  text.replace(tuck, end - tuck, moved);
  knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
  EXPECT_FALSE(proof.proven);
  EXPECT_NE(proof.summary.find("the turn's tuck"), std::string::npos) << proof.summary;
}

// Random sheets with pairs of short rows (sr4 or sr5 turns) and random knits and purls: each
// proves on every profile.
TEST(KnitoutRandomized, ShortRowSheetsProveOnEveryProfile) {
  std::mt19937_64 rng(77);
  int proven = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::uint32_t width = 3 + static_cast<std::uint32_t>(rng() % 30);
    std::uint32_t rows = 1 + static_cast<std::uint32_t>(rng() % 15);
    Compilation c = compile_stitch_mesh(short_row_sheet(width, rows, rng()), "short-row sheet");
    ASSERT_TRUE(c.knittability.knittable);
    for (const char* name : kProfiles) {
      knitout::MachineProfile p = shipped_profile(name);
      std::string text = testing::emit_knitout_text(c, p);
      knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
      EXPECT_TRUE(proof.proven) << "trial " << trial << " on " << name << ": " << proof.summary;
      proven += proof.proven;
    }
  }
  EXPECT_EQ(proven, 180);
}

TEST(KnitoutShortRows, ShapingInsideAShortRowProvesOnEveryProfile) {
  struct Case {
    const char *letters, *name;
    long short_rows;
  };
  for (auto [letters, name, short_rows] : {Case{testing::kShapedShortRowTube, "tube.st", 2},
                                           Case{testing::kShapedShortRowSheet, "sheet.st", 4}}) {
    Compilation c = testing::compile_letters(letters, name);
    ASSERT_TRUE(c.knittability.knittable) << name;
    knitout::CourseLayout l = knitout::lay_out_pieces(c).front();
    auto partial = std::count_if(l.courses.begin(), l.courses.end(),
                                 [](const knitout::Course& course) { return course.partial; });
    EXPECT_EQ(partial, short_rows) << name;
    for (const char* profile : kProfiles) {
      knitout::MachineProfile p = shipped_profile(profile);
      knitout::ProofResult proof =
          testing::replay_and_prove(testing::emit_knitout_text(c, p), c, p);
      EXPECT_TRUE(proof.proven) << name << " on " << profile << ": " << proof.summary;
    }
  }
}

// The sheet's kfb at f502, in a short row from the right edge: the loops of its row below it
// (f501, f500) and the four waiting beyond its turn (f496..f499) move one needle left, through
// the back bed, before it is knit; its second loop gets f501, and the turn wraps f498. They go
// over first at rack 1 and in at rack 0, where the kfb's split is knit: as many rack changes as
// out at rack 0 and over at rack -1 (then back to 0 for the split), and the tie goes to the plan
// that leaves the machine at rack 0.
TEST(KnitoutShortRows, AKfbInAShortRowMovesTheWaitingLoopsToMakeRoom) {
  std::string text = testing::emit_knitout_text(
      testing::compile_letters(testing::kShapedShortRowSheet, "sheet.st"),
      shipped_profile("generic"));
  std::size_t row4 = text.find(";!source: row 4 transfers");
  std::size_t row5 = text.find(";!source: row 5", row4);
  EXPECT_EQ(text.substr(row4, row5 - row4),
            ";!source: row 4 transfers: lines 25..28 (right to left)\n"
            "rack 1\nxfer f501 b500\nxfer f500 b499\nxfer f496 b495\nxfer f497 b496\n"
            "xfer f498 b497\nxfer f499 b498\nrack 0\nxfer b500 f500\nxfer b499 f499\n"
            "xfer b495 f495\nxfer b496 f496\nxfer b497 f497\nxfer b498 f498\n"
            ";!source: row 4 knit (short row): lines 25..28 (right to left)\n"
            "knit - f503 1\nsplit - f502 b502 1\nknit - b502 1\nknit - f500 1\n"
            "knit - f499 1\ntuck - f498 1\n");
}

// An 8-needle bed filled by an 8-wide sheet: a short row's kfb would move the loops waiting
// left of it off the bed's left end, which is refused in words.
TEST(KnitoutShortRows, MakingRoomOffTheBedIsRefusedInWords) {
  std::string text = read_file(testing::source_path("machine_profiles/generic.yaml"));
  text.replace(text.find("needles: 1000"), 13, "needles: 8");
  std::string path = ::testing::TempDir() + "/eight-needles.yaml";
  std::ofstream(path) << text;
  Compilation c = testing::compile_letters("ssssssss|kkkkkkkk|kkkkkkkk|kikk|kkdk|kkkkkkkk|eeeeeeee",
                                           "sheet.st");
  try {
    testing::emit_knitout_text(c, knitout::read_machine_profile(path));
    ADD_FAILURE() << "not refused";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "sheet.st: making room for a short row's shaping moves the loop of line 17 (k) off "
              "the bed's left end (generic has needles 0..7)");
  }
}

// A short row turns beside a loop that a k2tog then takes: the turn's wrap would make 3 loops
// on the k2tog's needle, which kniterate (2 per needle) cannot hold. There the turn is left bare
// (no tuck over the waiting loop) and the file is proven all the same (the model has no
// wraps); on swg091n2, which holds 3, the turn is wrapped.
TEST(KnitoutShortRows, AWrapTheNeedleCannotHoldIsLeftOut) {
  const char* letters = "ssssss|kkkkkk|kkk|kkk|kkdkk|eeeee";
  for (const char* profile : {"kniterate", "swg091n2"}) {
    auto [c, p, text] = testing::emit_letters(letters, "bare-turn.st", profile);
    std::size_t from = text.find("row 3 knit (short row)"), to = text.find(";!source", from);
    bool wrapped = text.substr(from, to - from).find("\ntuck ") != std::string::npos;
    EXPECT_EQ(wrapped, p.max_loops_per_needle >= 3) << profile << "\n" << text;
    knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
    EXPECT_TRUE(proof.proven) << profile << ": " << proof.summary;
  }
}

// A lopsided tube's bind-off, starting at a turn, goes from the back's left end (b273) to the
// front's (f266), 7 needles apart: more than swg091n2's transfers stretch (4), so the chain's
// loop hops over f269 and b267, needles the half-gauge layout leaves empty there.
TEST(KnitoutShortRows, ABindOffBetweenFarLeftEndsHopsFromBedToBed) {
  auto [c, p, text] = testing::emit_letters(testing::kLeftFoldHopTube, "hop.st", "swg091n2");
  EXPECT_NE(text.find("knit - b273 3\nrack -4\nxfer b273 f269\nrack 2\nxfer f269 b267\nrack -1\n"
                      "xfer b267 f266\nknit + f266 3\n"),
            std::string::npos);
  knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
  EXPECT_TRUE(proof.proven) << proof.summary;
}

// A random stitch graph with shaping inside short rows: a tube (rounds, and pairs of short rows
// from the round's start that turn back past it, then a round from that turn) or a sheet
// (rows, some of which turn before the edge). Every row keeps at least 4 loops on the needles.
std::string random_shaped_short_rows(std::mt19937_64& rng, bool tube) {
  std::size_t n = 6 + rng() % 10;
  std::string letters(n, 's');
  std::size_t yarn = n;  // the loops left of the yarn (a sheet's)
  auto row = [&](std::size_t loops) {
    std::size_t made = 0;
    letters += testing::random_run(rng, loops, made);
    return made;
  };
  for (int r = 0, rows = 3 + static_cast<int>(rng() % 6); r < rows; ++r) {
    if (tube) {
      n = row(n);  // a round
      if (n < 4) return random_shaped_short_rows(rng, tube);
      if (rng() % 2 == 0) continue;
      std::size_t forward = 1 + rng() % (n - 1), made = row(forward);
      std::size_t back = 1 + rng() % (n - forward + made - 1);  // back past the round's start
      letters += '|';
      std::size_t back_made = row(back);
      letters += '|';
      n = n - forward + made - back + back_made;
      n = row(n);  // a round from the turn
      if (n < 4) return random_shaped_short_rows(rng, tube);
      continue;
    }
    bool rightward = yarn == 0;
    std::size_t edge = rightward ? n : yarn, loops = rng() % 3 ? edge : 1 + rng() % edge;
    letters += '|';
    std::size_t made = row(loops);
    n = n - loops + made;
    yarn = rightward ? made : yarn - loops;
    if (loops == edge) continue;
    letters += '|';  // a short row: back over what it made, on to the other edge
    std::size_t back = rightward ? yarn : n - yarn, back_made = row(back);
    n = n - back + back_made;
    yarn = rightward ? 0 : n;
    if (n < 4) return random_shaped_short_rows(rng, tube);
  }
  if (!tube) letters += '|';
  letters += std::string(n, 'e');
  return letters;
}

TEST(KnitoutRandomized, ShapingInsideShortRowsProvesOrIsRefusedInWords) {
  std::mt19937_64 rng(2019);
  int proven = 0, refused = 0;
  for (int trial = 0; trial < 60; ++trial)
    testing::prove_or_refuse_gathering(random_shaped_short_rows(rng, trial % 2), proven, refused);
  std::cout << "shaped short rows: " << proven << " proven, " << refused << " refused\n";
  // 2026-12-03: 131 proven, 49 refused (124 / 56 before a wrap the needle has no room for was
  // left out).
  EXPECT_GE(proven, 131);
}

// Emits and proves `c` on each shipped profile; a profile too narrow for it must refuse it for
// its needles (counted in `refused`). Returns how many proved.
int prove_on_every_profile_it_fits(const Compilation& c, const std::string& name, int& refused) {
  int proven = 0;
  for (const char* profile : kProfiles) {
    knitout::MachineProfile p = shipped_profile(profile);
    std::string text;
    try {
      text = testing::emit_knitout_text(c, p);
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(" needles"), std::string::npos)
          << name << " on " << profile << ": " << e.what();
      ++refused;
      continue;
    }
    knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
    EXPECT_TRUE(proof.proven) << name << " on " << profile << ": " << proof.summary;
    proven += proof.proven;
  }
  return proven;
}

// Socks of random sizes from `skein new sock` (tubes with a short-row heel and a shaped toe):
// each proves on every profile it fits and is refused for its width on the others.
TEST(KnitoutRandomized, SocksOfRandomSizesProveOnEveryProfileTheyFit) {
  std::mt19937_64 rng(19);
  std::string dir = ::testing::TempDir();
  int proven = 0, too_wide = 0;
  for (int trial = 0; trial < 10; ++trial) {
    ShapeSize size;
    size.circumference = 12 + static_cast<double>(rng() % 130);
    size.length = 6 + static_cast<double>(rng() % 12);
    std::string name = fmt::format("sock{}", trial);
    std::string project = write_shape(make_shape("sock", size, name), dir + "/" + name);
    Compilation c = compile_model(project);
    ASSERT_TRUE(c.knittability.knittable) << project;
    proven += prove_on_every_profile_it_fits(c, name, too_wide);
  }
  EXPECT_GT(proven, 12);
  EXPECT_GT(too_wide, 0);
}

// The short-row wedge (a sheet with increases) and the sock (a tube with a heel and a toe) at
// random gauges, turning at sr4 or sr5 faces: each proves on every profile it fits. An sr5's
// turn loop is knit together with its own by a decrease in the next short row, in place.
TEST(KnitoutRandomized, ShortRowProjectsAtRandomGaugesProveOnEveryProfileTheyFit) {
  std::mt19937_64 rng(31);
  std::string dir = ::testing::TempDir();
  int proven = 0, refused = 0;
  for (int trial = 0; trial < 40; ++trial) {
    bool sock = trial % 2;
    std::string sample = sock ? "sock" : "short-row-wedge";
    std::string project = fmt::format("{}/random-{}.yaml", dir, trial);
    std::ofstream(project) << fmt::format(
        "mesh: {}/samples/{}/{}.obj\ngauge: {{stitches: {}, rows: {}}}\n{}short_rows:\n  "
        "method: {}\n{}",
        SKEIN_SOURCE_DIR, sample, sample, 12 + rng() % 30, 16 + rng() % 30,
        sock ? "patterns: {cuff: k2p2}\n" : "", rng() % 2 ? "sr5" : "sr4",
        sock ? "  faces: [34, 39]\n" : "");
    Compilation c = compile_model(project);
    ASSERT_TRUE(c.knittability.knittable) << project;
    proven += prove_on_every_profile_it_fits(c, project, refused);
  }
  std::cout << "knitout short-row projects: " << proven << " proven, " << refused << " refused\n";
  EXPECT_GT(proven, 100);
}

}  // namespace
}  // namespace skein
