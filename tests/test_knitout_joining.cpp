// Flaps joined into one sheet on the bed: each flap is cast on by a yarn of its own beside the
// loops already there (on the side from which the joining row takes it, one empty needle
// between), knit in place, and its yarn goes out leaving its loops; the row that joins them
// first closes the gap by transfers, then knits across both. Proven by the virtual v-bed on
// every profile; tubes joined on the bed are refused by name.
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "knitout/course_layout.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

using testing::shipped_profile;

// Two flaps of 4 (the second cast on right of the first by a yarn of its own), joined by a
// row from the right, then bound off. The first is placed so that both fit centred: f495..498,
// the second f500..503.
const char* const kJoinedFlaps = "ssss|kkkk|kkkk/ssss|kkkk|kkkk|kkkkkkkk|eeeeeeee";

TEST(KnitoutJoining, TheSecondFlapIsCastOnBesideTheFirstAndTheJoinClosesTheGap) {
  auto [c, p, text] = testing::emit_letters(kJoinedFlaps, "flaps.st", "generic");
  std::vector<knitout::CourseLayout> layouts = knitout::lay_out_pieces(c);
  ASSERT_EQ(layouts.size(), 1u);
  EXPECT_EQ(layouts[0].courses[3].beside, knitout::Beside::right);
  EXPECT_EQ(testing::section(text, ";!source: row 3 knit", ";!source: row 5"),
            ";!source: row 3 knit: lines 9..12 (left to right)\n"
            "knit + f495 1\nknit + f496 1\nknit + f497 1\nknit + f498 1\n"
            ";!source: carrier 1 goes out: yarn piece 1's loops wait for another yarn\nout 1\n"
            ";!source: cast-on border: alternating tucks\nin 2\n"
            "tuck + f500 2\ntuck + f502 2\ntuck - f503 2\ntuck - f501 2\n"
            ";!source: row 4 knit: lines 13..16 (left to right)\n"
            "knit + f500 2\nknit + f501 2\nknit + f502 2\nknit + f503 2\n");
  EXPECT_EQ(testing::section(text, ";!source: row 7 transfers", ";!source: row 8"),
            ";!source: row 7 transfers: lines 25..32 (right to left)\n"
            "xfer f498 b498\nxfer f497 b497\nxfer f496 b496\nxfer f495 b495\nrack 1\n"
            "xfer b498 f499\nxfer b497 f498\nxfer b496 f497\nxfer b495 f496\n"
            ";!source: row 7 knit: lines 25..32 (right to left)\n"
            "knit - f503 2\nknit - f502 2\nknit - f501 2\nknit - f500 2\n"
            "knit - f499 2\nknit - f498 2\nknit - f497 2\nknit - f496 2\n");
  for (const char* profile : {"generic", "swg091n2", "kniterate"}) {
    knitout::MachineProfile on = shipped_profile(profile);
    knitout::ProofResult proof =
        testing::replay_and_prove(testing::emit_knitout_text(c, on), c, on);
    EXPECT_TRUE(proof.proven) << profile << ": " << proof.summary;
  }
}

// Without the transfers that close the gap, the joining row knits the empty needle between the
// flaps (f499): the replay refuses it.
TEST(KnitoutJoining, TheJoiningRowNeedsTheGapClosed) {
  auto [c, p, text] = testing::emit_letters(kJoinedFlaps, "flaps.st", "generic");
  std::size_t from = text.find(";!source: row 7 transfers");
  std::size_t to = text.find(";!source: row 7 knit", from);
  ASSERT_NE(from, std::string::npos);
  try {
    testing::replay_and_prove(text.erase(from, to - from), c, p);
    ADD_FAILURE() << "replayed";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("knit on f499, which holds no loop"), std::string::npos)
        << e.what();
  }
}

// Two flaps of `n` stitches, two rows each, joined by a row from the right.
std::string joined_flaps_of(std::size_t n) {
  std::string flap = std::string(n, 's') + "|" + std::string(n, 'k') + "|" + std::string(n, 'k');
  return flap + "/" + flap + "|" + std::string(n, 'k') + "|" + std::string(2 * n, 'k') + "|" +
         std::string(2 * n, 'e');
}

// The first flap is placed where both fit side by side: two flaps of 120 on kniterate's 252
// needles (the first centred alone would leave the second 66 needles too few). Two of 126 need
// 253 with the needle between them: refused in words before anything is written.
TEST(KnitoutJoining, FlapsSideBySideFitTheBedOrAreRefusedInWords) {
  knitout::MachineProfile p = shipped_profile("kniterate");
  std::string letters = joined_flaps_of(120);
  Compilation c = testing::compile_letters(letters.c_str(), "wide.st");
  EXPECT_TRUE(testing::replay_and_prove(testing::emit_knitout_text(c, p), c, p).proven);
  letters = joined_flaps_of(126);
  Compilation wider = testing::compile_letters(letters.c_str(), "wider.st");
  try {
    testing::emit_knitout_text(wider, p);
    ADD_FAILURE() << "written";
  } catch (const UnsupportedError& e) {
    EXPECT_EQ(std::string(e.what()),
              "wider.st needs 253 needles for its pieces cast on side by side (from line 1 "
              "(co)), kniterate has 252");
  }
}

// Two random flaps with random shaping (the second cast on where the first's yarn ended: left
// or right of it), an even number of rows on the second so that its yarn ends outside, then
// rows across both and the bind-off.
std::string random_joined_flaps(std::mt19937_64& rng) {
  std::string letters;
  auto rows = [&](std::size_t& loops, std::uint64_t count) {
    for (std::uint64_t r = 0; r < count; ++r) {
      std::size_t made = 0;
      letters += '|';
      letters += testing::random_run(rng, loops, made);
      loops = made;
    }
  };
  std::size_t first = 2 + rng() % 8, second = 2 + rng() % 8;
  letters += std::string(first, 's');
  rows(first, 1 + rng() % 4);
  letters += '/';
  letters.append(second, 's');
  rows(second, 2 * (rng() % 3));
  if (first < 2 || second < 2) return random_joined_flaps(rng);
  std::size_t both = first + second;
  rows(both, 1 + rng() % 3);
  if (both < 2) return random_joined_flaps(rng);
  letters += '|';
  return letters.append(both, 'e');
}

TEST(KnitoutRandomized, JoinedFlapsProveOrAreRefusedInWords) {
  std::mt19937_64 rng(1515);
  int proven = 0, refused = 0;
  for (int trial = 0; trial < 60; ++trial)
    testing::prove_or_refuse_gathering(random_joined_flaps(rng), proven, refused);
  std::cout << "joined flaps: " << proven << " proven, " << refused << " refused\n";
  EXPECT_GT(proven, 120);
}

}  // namespace
}  // namespace skein
