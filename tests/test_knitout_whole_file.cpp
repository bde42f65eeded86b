// The whole-file proof (targets/knitout/whole_file_proof.*): the piece proven stitch for stitch
// must also come free of everything else the file knits.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "test_knitout_util.hpp"

namespace skein {
namespace {

std::string swatch_on_kniterate(Compilation& c) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  c = compile_model("samples/rib-swatch/rib-swatch.obj");
  return testing::emit_knitout_text(c, testing::shipped_profile("kniterate"));
}

TEST(KnitoutWholeFile, TheSwatchComesFreeOfItsWasteByItsDrawThread) {
  Compilation c;
  std::string text = swatch_on_kniterate(c);
  knitout::ProofResult proof =
      testing::replay_and_prove(text, c, testing::shipped_profile("kniterate"));
  ASSERT_TRUE(proof.proven) << proof.summary;
  EXPECT_NE(proof.summary.find("it comes free of everything else in the file"), std::string::npos);
}

TEST(KnitoutWholeFile, WithoutItsDrawThreadThePieceIsCaughtInTheWaste) {
  Compilation c;
  // The draw thread's knits are its only ops with carrier 2: without them the first row is
  // knit straight onto the waste section's last row.
  std::string text =
      std::regex_replace(swatch_on_kniterate(c), std::regex("knit \\+ f\\d+ 2\n"), "");
  text = std::regex_replace(text, std::regex("in 2\nout 2\n"), "");
  knitout::ProofResult proof =
      testing::replay_and_prove(text, c, testing::shipped_profile("kniterate"));
  EXPECT_FALSE(proof.proven);
  EXPECT_NE(proof.summary.find("the piece does not come free: the loop of line"), std::string::npos)
      << proof.summary;
  EXPECT_NE(proof.summary.find("(carrier 1), which is knitted into itself"), std::string::npos)
      << proof.summary;
}

TEST(KnitoutWholeFile, APieceLoopCaughtInAnotherYarnIsRefused) {
  Compilation c;
  std::string text = swatch_on_kniterate(c);
  // Before the tag, the waste carrier comes back and knits through the bind-off's last loop,
  // which the tag then knits through: the piece hangs from a loop of another yarn.
  std::size_t tag = text.find(";!source: tag");
  ASSERT_NE(tag, std::string::npos);
  std::size_t knit = text.find("knit + f", tag);
  std::string needle = text.substr(knit + 7, text.find(' ', knit + 7) - knit - 7);
  text.insert(tag, "in 1\nknit + " + needle + " 1\nout 1\n");
  knitout::ProofResult proof =
      testing::replay_and_prove(text, c, testing::shipped_profile("kniterate"));
  EXPECT_FALSE(proof.proven);
  EXPECT_NE(proof.summary.find("(carrier 1), which is not the piece's yarn"), std::string::npos)
      << proof.summary;
}

}  // namespace
}  // namespace skein
