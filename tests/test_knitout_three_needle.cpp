// The three-needle bind-off (3nbo) on a v-bed: the second needle's loop of each pair lands on
// the first's needle, each needle is knit (the st takes both loops) and the chain goes on as
// the chain bind-off's does, each link pulled through the one before. Proven by the virtual
// v-bed; what the target cannot bring face to face is refused by name.
#include <gtest/gtest.h>

#include <string>

#include "fixtures.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

using testing::shipped_profile;

// The hand tests' folded tube (6 sts in the rnd, a rnd, 3 pairs bound off with a new yarn),
// its 3nbo sts ordered as the mismatch transform extrudes them: along their loops.
Compilation folded_tube() {
  KnitGraph g = testing::folded_tube_graph();
  for (StitchId s = 0; s < g.size(); ++s)
    if (g.type[s] == StitchType::tnbo) g.direction[s] = CourseDirection::along_its_loops;
  return compile_knit_graph(std::move(g), "folded tube");
}

// A tube of 6 folded in half: its back half's loops land on the front's facing needles (one
// transfer each at rack -1), and a new yarn chains them off, three links, each knit on a needle
// holding both loops and the link before.
TEST(KnitoutThreeNeedle, AFoldedTubeIsChainedOffAcrossItsHalves) {
  Compilation c = folded_tube();
  ASSERT_TRUE(c.knittability.knittable);
  for (const char* profile : {"generic", "swg091n2"}) {
    knitout::MachineProfile p = shipped_profile(profile);
    std::string text = testing::emit_knitout_text(c, p);
    knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
    EXPECT_TRUE(proof.proven) << profile << ": " << proof.summary << "\n" << text;
  }
  std::string text = testing::emit_knitout_text(c, shipped_profile("generic"));
  EXPECT_EQ(testing::section(text, ";!source: row 3 transfers", ";!source: tag"),
            ";!source: row 3 transfers: faces 13..15 (right to left)\n"
            "rack -1\nxfer b501 f500\nxfer b499 f498\nxfer b497 f496\n"
            ";!source: carrier 2 comes in for yarn piece 2\nin 2\nmiss + f496 2\n"
            ";!source: row 3 bind-off: faces 13..15 (right to left)\n"
            "knit - f500 2\nxfer f500 b501\nrack -3\nxfer b501 f498\nknit - f498 2\n"
            "xfer f498 b501\nrack -5\nxfer b501 f496\nknit - f496 2\n");
}

// kniterate holds 2 loops a needle: a needle with both loops and the chain's is refused.
TEST(KnitoutThreeNeedle, ANeedleOfBothLoopsAndTheChainMustFitTheProfile) {
  try {
    testing::emit_knitout_text(folded_tube(), shipped_profile("kniterate"));
    ADD_FAILURE() << "emitted";
  } catch (const UnsupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("would gather 3 loops on one needle"), std::string::npos)
        << e.what();
  }
}

// The proof's chain: each link is pulled through its two loops and the link before. Knit
// without moving the chain on (each st through its two loops only, the old model), the file
// is not the model.
TEST(KnitoutThreeNeedle, TheProofWantsEachLinkThroughTheOneBefore) {
  Compilation c = folded_tube();
  knitout::MachineProfile p = shipped_profile("generic");
  std::string text = testing::emit_knitout_text(c, p);
  // A link's two transfers (the racks stay: the next link's transfers need them).
  for (auto [out, in] : {std::pair("xfer f500 b501\n", "xfer b501 f498\n"),
                         std::pair("xfer f498 b501\n", "xfer b501 f496\n")}) {
    std::string unchained = text;
    for (std::string xfer : {out, in}) {
      std::size_t at = unchained.find(xfer);
      ASSERT_NE(at, std::string::npos) << xfer;
      unchained.erase(at, xfer.size());
    }
    knitout::ProofResult proof = testing::replay_and_prove(unchained, c, p);
    EXPECT_FALSE(proof.proven) << unchained;
    EXPECT_NE(proof.summary.find("the bind-off chain"), std::string::npos) << proof.summary;
  }
}

// Two pieces each knit on their own and then bound off together (two sheets; a sheet that
// binds off part of a row with a piece knit first and left on the bed, then goes on): the
// piece cast on later is cast on beside the other and both wait knit on the bed until the
// chain takes a loop of each. Proven on generic; on swg091n2 a sheet's loops lie further
// apart than one transfer moves them (with the sheet's loops between), and kniterate's needles
// hold 2 loops, fewer than both loops and the chain's: refused by name.
TEST(KnitoutThreeNeedle, PiecesKnitApartAreBoundOffTogether) {
  for (auto [mesh, name] : {std::pair{testing::join_mesh(), "join"},
                            std::pair{testing::mid_row_join_mesh(), "mid-row join"}}) {
    Compilation c = compile_stitch_mesh(mesh, name);
    ASSERT_TRUE(c.knittability.knittable) << name;
    for (const char* profile : {"generic", "swg091n2", "kniterate"}) {
      std::string why = testing::prove_unless_refused(c, shipped_profile(profile), name);
      if (why.empty()) continue;
      EXPECT_NE(std::string(profile), "generic") << name << ": " << why;
      const char* expected =
          std::string(profile) == "kniterate" ? "loops on one needle" : "further than";
      EXPECT_NE(why.find(expected), std::string::npos) << name << " on " << profile << ": " << why;
    }
  }
}

}  // namespace
}  // namespace skein
