// A thumb: a tube parts into two branches where one of them (the thumb) lies on one bed of the
// tube as laid out. The emitter rolls the tube round its needles first, so that a fold runs
// through the thumb's middle; the crotch then closes both branches as tubes, as it does legs.
// Proven by the virtual v-bed, or refused by name before writing.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <iostream>
#include <map>
#include <sstream>

#include "random_garments.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

using testing::shipped_profile;

// A mitten from `skein new` (small: it fits every profile), with the yarn the project picks for
// the crotch.
Compilation small_mitten(const std::string& yarn) {
  return testing::compile_new_shape("mitten", {16, 0, 14}, yarn);
}

// The lines of the file's roll: from its note to the next note.
std::vector<std::string> roll_lines(const std::string& text) {
  std::size_t from = text.find("the tube rolled");
  if (from == std::string::npos) return {};
  std::istringstream in(text.substr(from, text.find(";!source", from + 1) - from));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(KnitoutThumb, AMittenIsProvenOnEveryProfileWithExtraOrOwnYarn) {
  for (const char* yarn : {"extra", "own"}) {
    Compilation c = small_mitten(yarn);
    for (const char* profile : {"generic", "swg091n2", "kniterate"}) {
      knitout::MachineProfile p = shipped_profile(profile);
      std::string text = testing::emit_knitout_text(c, p);
      EXPECT_FALSE(roll_lines(text).empty()) << yarn << " on " << profile << ": no roll";
      knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
      EXPECT_TRUE(proof.proven) << yarn << " yarn on " << profile << ": " << proof.summary;
    }
  }
}

// `skein new glove` at its default size (a thumb and four fingers parting from the palm, each
// crotch a cast-on along a split): proven on every profile; prints passes, transfers, racks.
TEST(KnitoutThumb, AGloveIsProvenOnEveryProfile) {
  Compilation c = testing::compile_new_shape("glove", {}, "extra");
  for (const char* profile : {"generic", "swg091n2", "kniterate"}) {
    knitout::MachineProfile p = shipped_profile(profile);
    std::string text = testing::emit_knitout_text(c, p);
    knitout::Replay replay = knitout::replay_knitout(text, "glove.k", p);
    const knitout::ShopStats& st = replay.stats;
    std::cout << fmt::format("glove on {}: {} passes, {} transfers, {} rack changes\n", profile,
                             st.stitch_passes + st.transfer_passes, st.transfers, st.racks);
    knitout::ProofResult proof = knitout::prove_whole_file(replay, text, c);
    EXPECT_TRUE(proof.proven) << "glove on " << profile << ": " << proof.summary;
  }
}

// The roll moves every loop of the tube the same way round; no transfer of it stretches
// further than the profile allows (the v-bed would refuse the file), and the judge, which never
// sees the generator's plan, finds a roll with one transfer left out.
TEST(KnitoutThumb, TheRollMovesEveryLoopAndTheJudgeFindsOneLeftOut) {
  Compilation c = small_mitten("extra");
  knitout::MachineProfile p = shipped_profile("swg091n2");
  std::string text = testing::emit_knitout_text(c, p);
  std::vector<std::string> roll = roll_lines(text);
  std::size_t xfers = 0, racks = 0;
  std::string dropped;
  for (const std::string& line : roll) {
    xfers += line.rfind("xfer ", 0) == 0;
    racks += line.rfind("rack ", 0) == 0;
    if (dropped.empty() && line.rfind("xfer b", 0) == 0) dropped = line;
  }
  std::cout << fmt::format("mitten's roll on {}: {} transfers, {} rack changes\n", p.name, xfers,
                           racks);
  EXPECT_GT(xfers, 0u);
  ASSERT_FALSE(dropped.empty());
  std::size_t at = text.find(dropped + "\n", text.find("the tube rolled"));
  ASSERT_NE(at, std::string::npos);
  std::string mutated = text;
  mutated.erase(at, dropped.size() + 1);
  bool proven = false;
  try {
    proven = testing::replay_and_prove(mutated, c, p).proven;
  } catch (const Error&) {  // an operation the v-bed refuses is a refusal too
  }
  EXPECT_FALSE(proven) << "the roll without " << dropped << " was proven";
}

// The random garments' trees whose small branch parts from the trunk (a thumb), at random
// sizes, gauges, patterns, bends, crowns and crotch yarns, each on all three profiles: every one
// is proven, or refused by name before writing (a bed too narrow for it).
TEST(KnitoutThumb, RandomThumbsPartingAreProvenOnEveryProfile) {
  std::map<std::string, int> refusals;
  testing::Tally tally =
      testing::tally_random_garments(300, [&](const Compilation& c, testing::Dice& dice) {
        dice.real(0, 3);  // the random garments test's roll for its profile: the same garments
        testing::Verdict v;
        bool crotch = false;
        for (StitchId s = 0; s < c.knit.size(); ++s) crotch |= c.knit.type[s] == StitchType::sco;
        if (!crotch) return v;
        for (const char* profile : {"generic", "swg091n2", "kniterate"}) {
          std::string why = testing::prove_unless_refused(c, shipped_profile(profile), "a thumb");
          if (why.empty()) continue;
          v.refusal = why;
          ++refusals[testing::refusal_kind(why)];
        }
        v.proven = v.refusal.empty();
        return v;
      });
  int proven = 0, refused = 0;
  for (const auto& [structure, n] : tally.by_structure)
    if (structure.find("thumb parting") != std::string::npos) proven += n[0], refused += n[1];
  std::cout << fmt::format(
      "random thumbs parting, each on 3 profiles: {} proven on all, {} refused on one or more\n",
      proven, refused);
  for (const auto& [why, n] : refusals) std::cout << "  " << n << " " << why << "\n";
  EXPECT_GE(proven, 50);
}

}  // namespace
}  // namespace skein
