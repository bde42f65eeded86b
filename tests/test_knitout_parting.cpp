// A bind-off of part of the work: a tube parts into two legs, the first is knit and bound off
// while the second's loops wait on their needles, then the same yarn knits the second (as
// AutoKnit's test-B does). Proven by the virtual v-bed on every profile.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <random>

#include "knitout/course_layout.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

using testing::shipped_profile;

const char* const kProfiles[] = {"swg091n2", "kniterate", "generic"};

// The short round and the first leg take part of the loops; so does the first leg's bind-off,
// after which the second leg's round takes all that is left.
TEST(KnitoutParting, TheFirstLegAndItsBindOffAreCoursesOverPartOfTheLoops) {
  knitout::CourseLayout l =
      knitout::lay_out_pieces(testing::compile_letters(testing::kPartedTube, "legs.st")).front();
  std::vector<bool> partial;
  for (const knitout::Course& course : l.courses) partial.push_back(course.partial);
  EXPECT_EQ(partial, (std::vector<bool>{false, false, true, true, true, false, false}));
}

// The first leg's chain runs round it (f500, f502, over the right fold to b503, b501), then
// drops its last loop: the yarn goes on from b501 to the second leg's loops, which waited on
// b499, b497, f496, f498. Each link along a bed goes out to the other bed at the racking the
// last one ended at (b503 out to f502 at rack -1), so each stitch racks once; the chain, and the
// course after it (one bed each way), knit at whatever racking they are at.
TEST(KnitoutParting, AMidWorkBindOffDropsItsLastLoopAndTheYarnGoesOn) {
  std::string text = testing::emit_letters(testing::kPartedTube, "legs.st", "generic").text;
  std::size_t from = text.find(";!source: row 5 bind-off");
  std::size_t to = text.find(";!source: row 7", from);
  ASSERT_NE(from, std::string::npos);
  EXPECT_EQ(text.substr(from, to - from),
            ";!source: row 5 bind-off (part of the work; the rest goes on): lines 27..30 (left "
            "to right)\n"
            "knit + f500 1\nxfer f500 b500\nrack 2\nxfer b500 f502\nknit + f502 1\n"
            "rack -1\nxfer f502 b503\nknit - b503 1\nxfer b503 f502\nrack 1\n"
            "xfer f502 b501\nknit - b501 1\ndrop b501\n"
            ";!source: row 6 knit: lines 31..34 (left to right)\n"
            "knit - b499 1\nknit - b497 1\nknit + f496 1\nknit + f498 1\n");
}

// Without the drop the loop would stay on b501 to the end of the file: the proof refuses it.
TEST(KnitoutParting, TheProofWantsTheMidWorkChainsLastLoopDropped) {
  auto [c, p, text] = testing::emit_letters(testing::kPartedTube, "legs.st", "generic");
  std::size_t drop = text.find("drop b501\n");
  ASSERT_NE(drop, std::string::npos);
  knitout::ProofResult proof = testing::replay_and_prove(text.erase(drop, 10), c, p);
  EXPECT_EQ(proof.summary,
            "NOT proven against legs.st: the bind-off before line 31 (k) leaves its last loop "
            "(line 59 (knit - b501 1)) on the needle: a bind-off of part of the work drops it");
}

// A sheet parted at a slit into two flaps, knit one after the other by one yarn: the left
// flap's rows turn beside the right flap's loops, which wait. Those turns are not short rows:
// no later row knits across the slit, so none is wrapped (a wrap would join the flaps there).
const char* const kFlaps =
    "ssssssss|"
    "kkkkkkkk|"
    "kkkk|"
    "kkkk|"
    "eeee"
    "kkkk|"
    "kkkk|"
    "eeee";

TEST(KnitoutParting, AFlapsTurnsBesideTheSlitAreNotWrapped) {
  auto [c, p, text] = testing::emit_letters(kFlaps, "flaps.st", "generic");
  EXPECT_EQ(testing::section(text, ";!source: row 3 knit", ";!source: row 4"),
            ";!source: row 3 knit (short row): lines 17..20 (left to right)\n"
            "knit + f496 1\nknit + f497 1\nknit + f498 1\nknit + f499 1\n");
  EXPECT_TRUE(testing::replay_and_prove(text, c, p).proven);
  for (const char* profile : {"swg091n2", "kniterate"}) {
    knitout::MachineProfile other = shipped_profile(profile);
    EXPECT_TRUE(testing::replay_and_prove(testing::emit_knitout_text(c, other), c, other).proven);
  }
  // A wrap over the right flap's first loop, as a short row's turn would take: the right flap's
  // first stitch pulls it through, joining the flaps at the slit. The proof refuses it.
  text.insert(text.find(";!source: row 4"), "tuck + f500 1\n");
  EXPECT_EQ(testing::replay_and_prove(text, c, p).summary,
            "NOT proven against flaps.st: the turn's tuck line 40 (tuck + f500 1) after line 20 "
            "(k) joins what the model leaves apart: line 29 (k), pulled through it, is in a row "
            "that takes no loop made since the turn");
}

TEST(KnitoutParting, PartedTubesProveOnEveryProfile) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  std::vector<std::pair<std::string, Compilation>> inputs;
  inputs.emplace_back("legs.st", testing::compile_letters(testing::kPartedTube, "legs.st"));
  inputs.emplace_back("half.st", testing::compile_letters(testing::kHalfBoundOffTube, "half.st"));
  inputs.emplace_back("test-B.st", compile_model("samples/autoknit/test-B.st"));
  for (const auto& [name, c] : inputs)
    for (const char* profile : kProfiles) {
      knitout::MachineProfile p = shipped_profile(profile);
      knitout::ProofResult proof =
          testing::replay_and_prove(testing::emit_knitout_text(c, p), c, p);
      EXPECT_TRUE(proof.proven) << name << " on " << profile << ": " << proof.summary;
    }
}

// A random tube parting into two legs: rounds with shaping, then a short round whose last
// stitches are the first leg's first round, more rounds of that leg and its bind-off, then
// rounds of what is left and the last bind-off (with `own_yarn`, a yarn of its own, which comes
// in on the loops the first leg left). Every ring keeps at least 2 loops.
std::string random_parted_tube(std::mt19937_64& rng, bool own_yarn = false) {
  std::size_t n = 6 + rng() % 10;
  std::string letters(n, 's');
  auto rounds = [&](std::size_t& loops, std::uint64_t count, const char* after) {
    for (std::uint64_t r = 0; r < count; ++r) {
      std::size_t made = 0;
      letters += testing::random_run(rng, loops, made);
      letters += after;
      loops = made;
    }
  };
  rounds(n, 1 + rng() % 3, "");
  if (n < 6) return random_parted_tube(rng, own_yarn);
  std::size_t before = rng() % (n - 4), leg = 2 + rng() % (n - before - 3), made = 0;
  letters += testing::random_run(rng, before, made) + "(";
  std::size_t rest = made + n - before - leg;
  rounds(leg, 1, ")");
  rounds(leg, rng() % 3, ")");
  if (leg < 2 || rest < 2) return random_parted_tube(rng, own_yarn);
  letters += std::string(leg, 'e');
  if (own_yarn) letters += '/';
  rounds(rest, 1 + rng() % 3, "");
  if (rest < 2) return random_parted_tube(rng, own_yarn);
  return letters + std::string(rest, 'e');
}

TEST(KnitoutRandomized, PartedTubesProveOrAreRefusedInWords) {
  std::mt19937_64 rng(2019);
  int proven = 0, refused = 0;
  for (int trial = 0; trial < 60; ++trial)
    testing::prove_or_refuse_gathering(random_parted_tube(rng), proven, refused);
  std::cout << "parted tubes: " << proven << " proven, " << refused << " refused\n";
  EXPECT_GT(proven, 100);
}

// The same with the second leg knit by a yarn of its own: two carriers on one bed, the second
// brought in on the loops the first leg left (as AutoKnit's test-C).
TEST(KnitoutRandomized, PartedTubesWithALegOfItsOwnYarnProveOrAreRefusedInWords) {
  std::mt19937_64 rng(2026);
  int proven = 0, refused = 0;
  for (int trial = 0; trial < 60; ++trial)
    testing::prove_or_refuse_gathering(random_parted_tube(rng, true), proven, refused);
  std::cout << "parted tubes, a leg of its own yarn: " << proven << " proven, " << refused
            << " refused\n";
  EXPECT_GT(proven, 100);
}

}  // namespace
}  // namespace skein
