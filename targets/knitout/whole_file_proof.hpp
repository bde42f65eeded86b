// The proof of a whole knitout file against its input: the piece is there stitch for stitch
// (fabric_proof.hpp), and what the file knits around it lets it go. Every loop the piece is
// pulled through that is not its own (its own cast-on border stays with it) belongs to a yarn
// that comes out when pulled, a draw thread: one course, none of its loops pulled through
// another of its loops; and no loop of the piece is caught in a loop of any other yarn (a loop
// of the piece's own yarn after it, its tag, may hang from it). So pulling the draw thread frees
// the piece from the waste section, and nothing else holds it.
#pragma once

#include <string_view>

#include "driver/pipeline.hpp"
#include "knitout/fabric_proof.hpp"

namespace skein::knitout {

ProofResult prove_whole_file(const Replay& replay, std::string_view text, const Compilation& input);

}  // namespace skein::knitout
