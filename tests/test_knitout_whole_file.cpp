// The whole-file proof (targets/knitout/whole_file_proof.*): the piece proven stitch for stitch
// must also come free of everything else the file knits, off a whole border.
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

// Replayed by each rule's severity (an edited border may knit an empty needle, which generic
// allows), then proven.
knitout::ProofResult prove_lenient(const std::string& text, const Compilation& c,
                                   const knitout::MachineProfile& p) {
  knitout::Replay replay = knitout::replay_knitout(text, "out.k", p, {.strict = false});
  return knitout::prove_whole_file(replay, text, c);
}

std::string without_line(const std::string& text, const std::string& line) {
  std::size_t at = text.find(line + "\n");
  EXPECT_NE(at, std::string::npos) << line;
  return text.substr(0, at) + text.substr(at + line.size() + 1);
}

// `text` with its first `from` made `to`.
std::string edited(std::string text, const std::string& from, const std::string& to) {
  std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// The proof of an edited file fails, saying `why`.
void expect_not_proven(const knitout::ProofResult& proof, const std::string& why) {
  EXPECT_FALSE(proof.proven);
  EXPECT_NE(proof.summary.find(why), std::string::npos) << proof.summary;
}

std::string rib_swatch_on(const char* profile, Compilation& c) {
  std::filesystem::current_path(SKEIN_SOURCE_DIR);
  c = compile_model("samples/rib-swatch/rib-swatch.obj");
  return testing::emit_knitout_text(c, testing::shipped_profile(profile));
}

TEST(KnitoutWholeFile, ADrawThreadMissingANeedleLeavesThePieceOnTheWaste) {
  Compilation c;
  std::string text = swatch_on_kniterate(c);
  std::size_t draw = text.find(";!source: draw thread");
  std::size_t knit = text.find("knit ", draw);
  std::string line = text.substr(knit, text.find('\n', knit) - knit);
  knitout::ProofResult proof =
      prove_lenient(without_line(text, line), c, testing::shipped_profile("kniterate"));
  EXPECT_FALSE(proof.proven);
  EXPECT_NE(proof.summary.find("the piece does not come free"), std::string::npos) << proof.summary;
}

TEST(KnitoutWholeFile, AMissingBorderLoopIsRefused) {
  Compilation c;
  knitout::MachineProfile p = testing::shipped_profile("generic");
  std::string text = rib_swatch_on("generic", c);
  ASSERT_TRUE(prove_lenient(text, c, p).proven);
  // Without its tuck (the last of the border) the first row's stitch on f491 is pulled through
  // nothing.
  knitout::ProofResult proof = prove_lenient(without_line(text, "tuck - f491 1"), c, p);
  EXPECT_FALSE(proof.proven);
  EXPECT_NE(proof.summary.find("19 cast-on loops of the piece hang on border loops, the input "
                               "has 20 cast-on stitches"),
            std::string::npos)
      << proof.summary;
  // Inside a pass, the border's yarn skips a needle there.
  proof = prove_lenient(without_line(text, "tuck + f496 1"), c, p);
  EXPECT_FALSE(proof.proven);
  EXPECT_NE(proof.summary.find("the border it is cast on is not whole"), std::string::npos)
      << proof.summary;
}

TEST(KnitoutWholeFile, ABorderEditThatChangesTheFabricIsRefused) {
  Compilation c;
  knitout::MachineProfile p = testing::shipped_profile("swg091n2");
  std::string text = rib_swatch_on("swg091n2", c);
  ASSERT_TRUE(prove_lenient(text, c, p).proven);
  // A tuck made going the other way in the middle of its pass.
  expect_not_proven(prove_lenient(edited(text, "tuck - f276 3", "tuck + f276 3"), c, p),
                    "the border it is cast on is not whole: the loop of line 13 (carrier 3) is "
                    "made going right in the middle of a pass going the other way");
  // Part of a pass knitted over the tucks before the first row: the first row hangs on knitted
  // loops there, on tucks elsewhere.
  expect_not_proven(
      prove_lenient(
          edited(text, "releasehook 3\n", "releasehook 3\nknit - f264 3\nknit - f261 3\n"), c, p),
      "holding the cast-on is not made as");
  // Two tucks of one pass swapped.
  expect_not_proven(
      prove_lenient(edited(text, "tuck - f276 3\ntuck - f273 3", "tuck - f273 3\ntuck - f276 3"), c,
                    p),
      "out of its pass's order");
}

// A tube 8 round has a border of tuck passes one and two loops long. Edits there leave passes of
// one loop, which show no step of their own: the border's other passes say where they go on, and a
// loop made against the yarn on both sides is wrapped round its needle.
TEST(KnitoutWholeFile, ATuckPassOfOneLoopOutOfPlaceIsRefusedInANarrowPiece) {
  testing::EmittedLetters e =
      testing::emit_letters(testing::kPartedTube, "parted tube", "swg091n2");
  ASSERT_TRUE(prove_lenient(e.text, e.c, e.p).proven);
  // f272 after b269: where the pass of f268 would have gone on.
  expect_not_proven(
      prove_lenient(edited(e.text, "tuck + f272 3\ntuck - b269 3", "tuck - b269 3\ntuck + f272 3"),
                    e.c, e.p),
      "the border it is cast on is not whole: the loop of line 19 (carrier 3) is "
      "made going right where an earlier pass its way left off, after the yarn went "
      "elsewhere");
  // The middle tuck of a pass three tucks long made going the other way.
  e = testing::emit_letters(testing::kShapedShortRowTube, "short rows", "swg091n2");
  ASSERT_TRUE(prove_lenient(e.text, e.c, e.p).proven);
  expect_not_proven(prove_lenient(edited(e.text, "tuck + f268 3", "tuck - f268 3"), e.c, e.p),
                    "(carrier 3) is made going left, and the yarn comes to it and goes on from "
                    "it going right: it is wrapped in its own yarn");
}

}  // namespace
}  // namespace skein
