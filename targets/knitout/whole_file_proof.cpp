#include "knitout/whole_file_proof.hpp"

#include <fmt/format.h>

#include <vector>

namespace skein::knitout {
namespace {

// Yarn pieces of which some loop is pulled through another loop of the same yarn piece: they
// hold together, so pulling one does not draw it out.
std::vector<bool> knitted_pieces(const Fabric& f, std::uint32_t pieces) {
  std::vector<bool> knitted(pieces + 1, false);
  for (LoopId l = 0; l < f.loops.size(); ++l)
    for (LoopId parent : f.parents_of(l))
      if (f.loops[parent].piece == f.loops[l].piece) knitted[f.loops[l].piece] = true;
  return knitted;
}

std::string describe(const Replay& r, LoopId l) {
  const FabricLoop& loop = r.fabric.loops[l];
  return fmt::format("the loop of line {} (carrier {})", loop.line,
                     carrier_names(r.header, loop.yarn));
}

// "" when the piece comes free; else the first loop that holds it.
std::string what_holds_the_piece(const Replay& r, const ProofResult& proof) {
  const Fabric& f = r.fabric;
  std::vector<bool> mine(f.loops.size(), false), own_yarn;
  std::uint32_t pieces = 0;
  for (const FabricLoop& l : f.loops) pieces = std::max(pieces, l.piece);
  own_yarn.assign(pieces + 1, false);
  for (const ProofResult::Run& run : proof.pieces)
    for (std::size_t i = run.start; i < run.start + run.count; ++i) {
      LoopId l = f.by_carrier[run.carrier][i];
      mine[l] = true;
      own_yarn[f.loops[l].piece] = true;
    }
  std::vector<bool> knitted = knitted_pieces(f, pieces);
  for (LoopId l = 0; l < f.loops.size(); ++l)
    for (LoopId parent : f.parents_of(l)) {
      std::uint32_t held_by = f.loops[parent].piece;
      if (mine[parent] && !mine[l] && !own_yarn[f.loops[l].piece])
        return fmt::format("{} of the piece is caught in {}, which is not the piece's yarn",
                           describe(r, parent), describe(r, l));
      if (mine[l] && !mine[parent] && !own_yarn[held_by] && knitted[held_by])
        return fmt::format(
            "{} of the piece is pulled through {}, which is knitted into itself: pulling it "
            "does not free the piece",
            describe(r, l), describe(r, parent));
    }
  return "";
}

}  // namespace

ProofResult prove_whole_file(const Replay& replay, std::string_view text, const Compilation& c) {
  ProofResult proof = prove_fabric(replay, text, c);
  if (!proof.proven) return proof;
  std::string held = what_holds_the_piece(replay, proof);
  if (held.empty()) {
    proof.summary += "; it comes free of everything else in the file";
    return proof;
  }
  proof.proven = false;
  proof.summary =
      fmt::format("NOT proven against {}: the piece does not come free: {}", c.input, held);
  return proof;
}

}  // namespace skein::knitout
