// The proof of a whole knitout file against its input: the piece is there stitch for stitch
// (fabric_proof.hpp), and what the file knits around it lets it go. Every loop the piece is
// pulled through that is not its own (its own cast-on border stays with it) belongs to a yarn
// that comes out when pulled, a draw thread: one course, none of its loops pulled through
// another of its loops; and no loop of the piece is caught in a loop of any other yarn (a loop
// of the piece's own yarn after it, its tag, may hang from it). So pulling the draw thread frees
// the piece from the waste section, and nothing else holds it. Its cast-on border, which comes
// off the machine with it, must be whole: each cast-on loop hangs on a border loop of its own
// (as many as the input's cast-on stitches), the loops holding the cast-on on one bed are made
// alike, every loop of a border in the piece's own yarn is a tuck through nothing or a loop
// through one loop below the piece and holds exactly one loop, and that border's yarn runs in
// passes (each the same step along, none taking up where an earlier one left off, no loop made
// against its pass, none wrapped in its yarn: made going one way while the yarn comes to it and
// goes on from it going the other). Every loop of a draw thread holds one cast-on loop.
#pragma once

#include <string_view>
#include <vector>

#include "driver/pipeline.hpp"
#include "knitout/fabric_proof.hpp"

namespace skein::knitout {

ProofResult prove_whole_file(const Replay& replay, std::string_view text, const Compilation& input);

// Per fabric loop, for a proven file: whether it is a piece's border in the piece's own yarn
// (what its yarn makes before the piece's first stitch: it comes off the machine with it).
std::vector<bool> own_yarn_border(const Replay& replay, const ProofResult& proof);

}  // namespace skein::knitout
