// Legs joining into a body (trousers knit up from the hems): the second leg is a tube cast on
// beside the first, turned so that the arc the body takes goes round its far fold; the body is
// knit over both legs' outer arcs while the crotch waits, and the crotch is closed by a
// three-needle bind-off. Proven by the virtual v-bed, or refused by name before writing.
#include <gtest/gtest.h>

#include <algorithm>

#include "common/error.hpp"
#include "knitout/course_layout.hpp"
#include "labeling/shapes.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

Compilation small_trousers() {
  return testing::compile_new_shape("trousers", {40, 0, 12}, "extra");
}

TEST(KnitoutLegsJoining, TheSecondLegIsCastOnBesideTheFirstInOneLayout) {
  Compilation c = small_trousers();
  ASSERT_TRUE(c.knittability.knittable);
  std::vector<knitout::CourseLayout> layouts = knitout::lay_out_pieces(c);
  ASSERT_EQ(layouts.size(), 1u);  // both legs, the body and the crotch share the bed
  const knitout::CourseLayout& l = layouts[0];
  EXPECT_TRUE(l.tube);
  auto beside = std::count_if(l.courses.begin(), l.courses.end(), [](const knitout::Course& k) {
    return k.cast_on && k.beside != knitout::Beside::none;
  });
  EXPECT_EQ(beside, 1);
}

TEST(KnitoutLegsJoining, TrousersAreProvenOrRefusedByName) {
  Compilation c = small_trousers();
  for (const char* profile : {"generic", "swg091n2", "kniterate"}) {
    knitout::MachineProfile p = testing::shipped_profile(profile);
    std::string text;
    try {
      text = testing::emit_knitout_text(c, p);
    } catch (const UnsupportedError& e) {
      // The crotch's three-needle bind-off gathers 3 loops on a needle; kniterate holds 2.
      EXPECT_EQ(std::string(profile), "kniterate") << e.what();
      EXPECT_NE(std::string(e.what()).find("loops on one needle"), std::string::npos) << e.what();
      continue;
    }
    knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
    EXPECT_TRUE(proof.proven) << profile << ": " << proof.summary;
  }
}

}  // namespace
}  // namespace skein
