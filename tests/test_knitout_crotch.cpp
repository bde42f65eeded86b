// A cast-on along a split (a crotch): a tube parts into two branches round its two folds, the
// crotch's sco sts cast on between them (with extra yarn, or the yarn of the round that parts
// it), each branch knit where its loops wait. Proven by the virtual v-bed, or refused by name
// before writing.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <iostream>
#include <map>

#include "common/atomic_file.hpp"
#include "knitout/course_layout.hpp"
#include "labeling/shapes.hpp"
#include "random_garments.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

using testing::shipped_profile;

// Shorts from `skein new` (small: the crotch fits every profile), with the yarn the project
// picks for the crotch.
Compilation small_shorts(const std::string& yarn) {
  return testing::compile_new_shape("shorts", {40, 0, 6}, yarn);
}

// The crotch is one course of its own, between the body's last round and the first leg's.
TEST(KnitoutCrotch, TheCrotchIsACourseOfItsOwnThatClosesTheFirstLeg) {
  Compilation c = small_shorts("extra");
  knitout::CourseLayout l = knitout::lay_out_pieces(c).front();
  auto crotch = std::find_if(l.courses.begin(), l.courses.end(),
                             [](const knitout::Course& k) { return k.along_split; });
  ASSERT_NE(crotch, l.courses.end());
  EXPECT_NE(crotch->arc_end, knitout::kNoWrap);
  EXPECT_NE(crotch->arc_start, knitout::kNoWrap);
  for (std::uint32_t i = crotch->begin; i < crotch->end; ++i)
    EXPECT_EQ(c.knit.type[l.order[i]], StitchType::sco);
  EXPECT_TRUE((crotch + 1)->partial) << "the first leg is knit while the second's loops wait";
}

// Each crotch st tucks two loops on the front, one beside each leg; those of the sts on the back
// half are then moved to the back at rack 0.
TEST(KnitoutCrotch, EachCrotchStTucksALoopForEachLeg) {
  Compilation c = small_shorts("extra");
  std::string text = testing::emit_knitout_text(c, shipped_profile("generic"));
  std::size_t from = text.find("cast-on along a split:");
  ASSERT_NE(from, std::string::npos);
  std::string ops = text.substr(from, text.find(";!source", from + 1) - from);
  std::size_t tucks = 0, xfers = 0;
  for (std::size_t at = ops.find("\ntuck "); at != std::string::npos;
       at = ops.find("\ntuck ", at + 1)) {
    ++tucks;
    EXPECT_EQ(ops[at + 8], 'f') << "every crotch loop is made on the front";
  }
  for (std::size_t at = ops.find("\nxfer f"); at != std::string::npos;
       at = ops.find("\nxfer f", at + 1))
    ++xfers;
  std::uint32_t sts = 0;
  for (StitchId s = 0; s < c.knit.size(); ++s) sts += c.knit.type[s] == StitchType::sco;
  EXPECT_EQ(tucks, 2 * sts);
  EXPECT_EQ(xfers, 2 * (sts / 2)) << "the second half's loops go to the back";
}

TEST(KnitoutCrotch, ShortsAreProvenOnEveryProfileWithExtraOrOwnYarn) {
  for (const char* yarn : {"extra", "own"}) {
    Compilation c = small_shorts(yarn);
    for (const char* profile : {"generic", "swg091n2", "kniterate"}) {
      knitout::MachineProfile p = shipped_profile(profile);
      knitout::ProofResult proof =
          testing::replay_and_prove(testing::emit_knitout_text(c, p), c, p);
      EXPECT_TRUE(proof.proven) << yarn << " yarn on " << profile << ": " << proof.summary;
    }
  }
}

// A random tube (maybe bent by short rows) parted at random places into two branches that each
// go round one of its folds (3 to 5 of its ring's 8 sides each), each branch a random length,
// maybe closed by a crown; random size, gauge, stitch pattern and yarn for the crotch.
testing::RandomGarment random_parted_tube(testing::Dice& dice, int trial) {
  testing::Garment g;
  double radius = dice.real(12, 60) / (2 * testing::kPi);
  testing::Trunk trunk = testing::random_trunk(g, dice, radius);
  auto first = static_cast<std::uint32_t>(dice.integer(1, 3));
  auto last = static_cast<std::uint32_t>(dice.integer(5, 7));
  Vec3 c = g.draft.centre(trunk.top);
  Vec3 side = unit({trunk.axis.y, -trunk.axis.x, 0});
  Vec3 crotch = moved(moved(c, trunk.axis, radius * 0.3), side, dice.real(-0.2, 0.2) * radius);
  auto [one, two] = fork(g.draft, trunk.top, first, last, crotch);
  double share = static_cast<double>(last - first) / 8;
  testing::random_limb(g, dice, one, unit(moved(trunk.axis, side, 0.15)), radius * share, "one");
  testing::random_limb(g, dice, two, unit(moved(trunk.axis, side, -0.15)), radius * (1 - share),
                       "two");
  g.starts = {fmt::format("{{vertex: {}}}", trunk.bottom[0] + 1)};
  std::string dir = ::testing::TempDir(), name = fmt::format("parted{}", trial);
  std::string project = fmt::format("{}/{}.yaml", dir, name);
  std::string text = testing::project_text(g, dice, name);
  write_file_atomically(dir + "/" + name + ".obj",
                        [&](std::ostream& out) { write_coarse_mesh(g.draft.finish(name), out); });
  write_file_atomically(project, [&](std::ostream& out) { out << text; });
  return {project, text, fmt::format("sides {}..{}", first, last)};
}

// The spec's test: every random parted tube whose crotch the target writes is proven; what it
// cannot write yet it refuses by name before writing.
TEST(KnitoutCrotch, RandomPartedTubesAreProvenOrRefusedByName) {
  const char* const profiles[] = {"generic", "swg091n2", "kniterate"};
  testing::Dice dice(1515);
  int proven = 0, refused = 0, unknittable = 0, crotches = 0;
  std::map<std::string, int> refusals;
  for (int trial = 0; trial < 80; ++trial) {
    testing::RandomGarment g = random_parted_tube(dice, trial);
    SCOPED_TRACE(fmt::format("trial {}: {} ({})\n{}", trial, g.project, g.structure, g.text));
    Compilation c;
    try {
      c = compile_model(g.project);
    } catch (const Error&) {
      ++unknittable;
      continue;
    }
    if (!c.knittability.knittable) {
      ++unknittable;
      continue;
    }
    bool has_crotch = false;
    for (StitchId s = 0; s < c.knit.size(); ++s) has_crotch |= c.knit.type[s] == StitchType::sco;
    crotches += has_crotch;
    knitout::MachineProfile p = shipped_profile(profiles[dice.integer(0, 2)]);
    std::string text;
    try {
      text = testing::emit_knitout_text(c, p);
    } catch (const UnsupportedError& e) {
      ++refused, ++refusals[testing::refusal_kind(e.what())];
      continue;
    }
    knitout::ProofResult proof = testing::replay_and_prove(text, c, p);
    EXPECT_TRUE(proof.proven) << p.name << ": " << proof.summary;
    proven += proof.proven;
  }
  std::cout << fmt::format(
      "80 random parted tubes ({} with a crotch): {} proven, {} refused by name, {} not "
      "knittable\n",
      crotches, proven, refused, unknittable);
  for (const auto& [why, n] : refusals) std::cout << "  " << n << " " << why << "\n";
  EXPECT_GT(crotches, 20);
  // 2026-12-03: 52 proven, 2 refused, 26 not knittable (44 / 10 before a decrease across a
  // fold of a branch was knit; of the draw before bent tubes knit from their branches were
  // labelled 38 / 4 / 38, 34 / 8 before that decrease and 29 / 13 before a branch on one bed
  // rolled).
  EXPECT_GE(proven, 52);
}

}  // namespace
}  // namespace skein
