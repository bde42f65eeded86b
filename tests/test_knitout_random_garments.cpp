// The random garments (tests/random_garments.hpp: trees of tubes that part and join, sheets
// whose flaps part or join; the hand tests' 300) through the knitout target, each on a shipped
// profile picked at random: every file written is proven by the virtual v-bed against the model, or
// the target refuses the model by name (UnsupportedError) before writing. The test prints the tally
// by structure and the refusals by reason.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <iostream>
#include <map>

#include "common/error.hpp"
#include "random_garments.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

constexpr int kModels = 300;

// Each random garment on a shipped profile picked at random: proven, or refused by name.
testing::Tally knitout_tally() {
  const char* const profiles[] = {"generic", "swg091n2", "kniterate"};
  return testing::tally_random_garments(kModels, [&](const Compilation& c, testing::Dice& dice) {
    // One roll, as the hand test's (the same garments follow).
    knitout::MachineProfile p =
        testing::shipped_profile(profiles[static_cast<int>(dice.real(0, 3))]);
    testing::Verdict v;
    std::string text;
    try {
      text = testing::emit_knitout_text(c, p);
    } catch (const UnsupportedError& e) {
      v.refusal = e.what();
      return v;
    }
    knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
    EXPECT_TRUE(proof.proven) << p.name << ": " << proof.summary;
    v.proven = proof.proven;
    return v;
  });
}

TEST(KnitoutRandomGarments, EachIsProvenOrRefusedByNameBeforeWriting) {
  testing::Tally tally = knitout_tally();
  std::cout << tally.report(kModels, " on knitout");
  // 2026-12-03: 263 proven, 37 refused, 0 not knittable (259 / 41 before a decrease across a
  // fold of a crotch's branch was knit; of the draw before bent tubes knit from their branches
  // were labelled: 257 / 33 / 10, and 254 / 36 before that decrease; 251 / 39 before a round
  // binding off some of its sts with a second needle's was knit as blocks; 241 / 49 before pieces
  // knit apart were bound off together; 232 / 58 before legs were cast on side by side; 175 / 115
  // before thumbs rolled).
  EXPECT_GE(tally.proven, 263);
}

// Every random garment on each shipped profile: proven by the v-bed, or refused by name
// (UnsupportedError) before writing; no file written unproven, no other error. Prints, per
// profile, the tally and the refusals by reason.
TEST(KnitoutRandomGarments, EachIsProvenOrRefusedOnEveryProfile) {
  const char* const profiles[] = {"generic", "swg091n2", "kniterate"};
  struct ProfileTally {
    int proven = 0, refused = 0, unproven = 0;
    std::map<std::string, int> refusals;
  };
  std::map<std::string, ProfileTally> by_profile;
  testing::tally_random_garments(kModels, [&](const Compilation& c, testing::Dice& dice) {
    dice.real(0, 3);  // the one-profile test's roll, so that the same garments follow
    for (const char* name : profiles) {
      knitout::MachineProfile p = testing::shipped_profile(name);
      ProfileTally& t = by_profile[name];
      try {
        std::string text = testing::emit_knitout_text(c, p);
        knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
        EXPECT_TRUE(proof.proven) << name << ": " << proof.summary;
        ++(proof.proven ? t.proven : t.unproven);
      } catch (const UnsupportedError& e) {
        ++t.refused, ++t.refusals[testing::refusal_kind(e.what())];
      } catch (const Error& e) {
        ADD_FAILURE() << name << ": not a refusal by name: " << e.what();
      }
    }
    return testing::Verdict{true, ""};
  });
  for (const auto& [name, t] : by_profile) {
    std::cout << fmt::format("{}: {} proven, {} refused by name, {} written unproven\n", name,
                             t.proven, t.refused, t.unproven);
    for (const auto& [reason, count] : t.refusals) std::cout << reason << " | " << count << "\n";
  }
  // 2026-12-03, of the 300 garments (all knittable): generic 289 proven, 11 refused; swg091n2
  // 286, 14; kniterate 221, 79 (its 2 loops per needle, 57). Before a decrease across a fold
  // of a crotch's branch was knit: generic 278, 22; swg091n2 276, 24; kniterate 221, 79.
  EXPECT_GE(by_profile["generic"].proven, 289);
  EXPECT_GE(by_profile["swg091n2"].proven, 286);
  EXPECT_GE(by_profile["kniterate"].proven, 221);
}

// Legs knit from their hems and joined into a body: the second leg is cast on beside the first
// (not after it is bound off), the body knit over both legs' outer arcs while the crotch waits,
// and the crotch closed by a three-needle bind-off; every file written is proven (above).
TEST(KnitoutRandomGarments, LegsJoiningAreKnitSideBySide) {
  testing::Tally tally = knitout_tally();
  int proven = 0, refused_as_waiting = 0;
  for (const auto& [structure, row] : tally.by_structure)
    if (structure.find("legs joining") != std::string::npos) proven += row[0];
  for (const auto& [reason, count] : tally.refusals)
    if (reason.find("cast on while another waits") != std::string::npos)
      refused_as_waiting += count;
  // 2026-12-02: 9 proven (4 before pieces knit apart were bound off together; 0 before: 18
  // refused as "a tube cast on while another waits").
  EXPECT_GE(proven, 9);
  EXPECT_EQ(refused_as_waiting, 0);
}

// A thumb and a hand knit from their tips, each a piece of its own, and bound off together at
// the crotch: the piece cast on later is cast on beside the other, both wait knit on the bed,
// and the bind-off's chain takes a loop of each; every file written is proven (above).
TEST(KnitoutRandomGarments, PiecesKnitApartAreBoundOffTogether) {
  testing::Tally tally = knitout_tally();
  int proven = 0, refused_as_apart = 0, refused_as_mixed = 0;
  for (const auto& [structure, row] : tally.by_structure)
    if (structure.find("thumb joining") != std::string::npos) proven += row[0];
  for (const auto& [reason, count] : tally.refusals) {
    if (reason.find("knit apart") != std::string::npos) refused_as_apart += count;
    if (reason.find("binds off only some") != std::string::npos) refused_as_mixed += count;
  }
  // 2026-12-02: 13 proven (5 before: 36 garments refused as "a three-needle bind-off of two
  // pieces knit apart", 6 as "a row that binds off only some of its sts with a second
  // needle's"). 2026-12-03: 11 of another draw (the garments drawn after the first bent tube
  // knit from its branches changed once those could be labelled).
  EXPECT_GE(proven, 11);
  EXPECT_EQ(refused_as_apart, 0);
  EXPECT_EQ(refused_as_mixed, 0);
}

}  // namespace
}  // namespace skein
