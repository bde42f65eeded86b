// Hand patterns from stitch graphs another tool made (issue 13: AutoKnit's own test models). To
// have many such graphs, skein makes them: a model compiled to knitout on the generic machine,
// the fabric the v-bed knits from that file written as an AutoKnit `.st` (`skein verify X.k
// --fabric X.st`), and that `.st` compiled to a hand pattern, which the hand simulator proves,
// or which the hand target refuses by name before writing. Every `skein new` shape and a share
// of the random garments; the tests print the refusals by reason.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "common/error.hpp"
#include "knitout/fabric_stitch_graph.hpp"
#include "random_garments.hpp"
#include "target_runner.hpp"
#include "test_knitout_util.hpp"

namespace skein {
namespace {

// The machine's fabric of `model` as a hand pattern: proven, or refused by name (the refusal
// says which stage refused: the knitout target, or the hand target).
// `cast_on_in_row` counts the proven patterns that cast on in the middle of a row or rnd.
testing::Verdict hand_pattern_of_machine_fabric(const Compilation& model, int& cast_on_in_row) {
  knitout::MachineProfile generic = testing::shipped_profile("generic");
  testing::Verdict v;
  std::string knitout_text;
  try {
    knitout_text = testing::emit_knitout_text(model, generic);
  } catch (const UnsupportedError& e) {
    v.refusal = fmt::format("knitout: {}", e.what());
    return v;
  }
  std::ostringstream st;
  knitout::write_fabric_stitch_graph(knitout::replay_knitout(knitout_text, "m.k", generic), "m.k",
                                     st);
  Compilation fabric = compile_knit_graph(parse_autoknit_st(st.str(), "m.st"), "m.st");
  EXPECT_TRUE(fabric.knittability.knittable) << "the machine's fabric";
  std::string pattern;
  try {
    pattern = testing::emit(fabric, "hand");
  } catch (const UnsupportedError& e) {
    v.refusal = e.what();
    return v;
  }
  VerifyReport proof = testing::verify(fabric, "hand", pattern);
  EXPECT_TRUE(proof.proven) << proof.summary << "\n" << pattern;
  v.proven = proof.proven;
  cast_on_in_row += v.proven && pattern.find("backward-loop cast-on") != std::string::npos;
  return v;
}

// Every `skein new` shape at its default size.
TEST(HandMachineFabric, EveryNewShapeIsProvenOrRefusedByName) {
  const std::string dir = ::testing::TempDir() + "machine-fabric-shapes";
  std::filesystem::create_directories(dir);
  std::string table = "shape | hand pattern of the machine's fabric\n";
  int proven = 0, cast_on_in_row = 0;
  for (const std::string& kind : shape_kinds()) {
    SCOPED_TRACE(kind);
    Compilation model = compile_model(write_shape(make_shape(kind, {}, kind), dir + "/" + kind));
    testing::Verdict v = hand_pattern_of_machine_fabric(model, cast_on_in_row);
    proven += v.proven;
    table += fmt::format("{} | {}\n", kind, v.proven ? "proven" : testing::refusal_kind(v.refusal));
  }
  std::cout << table << fmt::format("cast on in a row or rnd: {}\n", cast_on_in_row);
  // 2026-12-03, of 11 shapes: 5 proven (sheet, tube, hat, mitten, shorts); 3 before a cast-on
  // in the middle of a row or rnd was written (mitten, shorts: "works co, a cast-on in a course").
  EXPECT_GE(proven, 5);
}

constexpr int kModels = 300;

TEST(HandMachineFabric, RandomGarmentsAreProvenOrRefusedByName) {
  int cast_on_in_row = 0;
  testing::Tally tally =
      testing::tally_random_garments(kModels, [&](const Compilation& c, testing::Dice&) {
        return hand_pattern_of_machine_fabric(c, cast_on_in_row);
      });
  std::cout << tally.report(kModels, " through the machine's fabric to hand")
            << fmt::format("proven patterns with a cast-on in a row or rnd: {}\n", cast_on_in_row);
  // 2026-12-03: 185 proven, 111 refused by name, 4 not knittable; 77 of the proven cast on in a
  // row or rnd (a thumb's or crotch's gap, from the machine's tube cast on beside the other),
  // all refused before ("works co, a cast-on in a course": 108 proven, 188 refused); 3 of them
  // were written unproven until the reader slipped the runs of one sentence to a holder in the
  // order given (a holder taking single sts one after another: it slipped them last first).
  EXPECT_GE(tally.proven, 185);
}

}  // namespace
}  // namespace skein
