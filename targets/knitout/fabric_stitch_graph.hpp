// The fabric a knitout file makes, written as an AutoKnit stitch graph (`.st`, which
// `skein check` and `skein compile` read), so that a user can check what a foreign file knits.
// A walk over the v-bed's fabric, linear in its loops:
// - a loop pulled through loops is a stitch taking them: `k` (one; `p`, skein's own letter,
//   when it is a purl seen from the right side: made on a sheet's back bed, or on a tube's bed
//   other than that of its half's pass), `d` (two; more become a chain of `d`s, as `.st` has no
//   wider decrease), `s` (none: a cast-on);
// - a tuck lies over the loop under it on its needle: a `t` taking that loop, which the stitch
//   knit through both then takes (a tuck made on an empty needle is a loop through nothing,
//   even once moved onto loops);
// - the tucks a yarn piece starts with on empty needles are its cast-on's border: not written,
//   the loops knit through them are the cast-on `s` stitches;
// - two loops pulled through one loop one after the other along the yarn (a split and a knit),
//   or a loop through nothing beside a knit along the yarn (a yarn-over, a make-1), are one
//   increase `i`; loops through nothing that follow each other are cast-on `s` stitches (a
//   crotch's cast-on along a split, knit on after a leg's round), none of them an increase;
// - a loop pulled through its yarn's previous loop and another (a bind-off's chain) does not
//   take the previous loop: the chain is the yarn; a loop nothing takes ends its wale (`e`);
// - a loop dropped while nothing held it unravels, and with it the cord it ends (a tag: loops
//   each pulled through their yarn's previous loop alone): none of them is written; the loops
//   a dropped row was pulled through end their wales there.
// `yarn` is the yarn piece (one per in/inhook), `dir` the way round: the pass direction on a
// sheet; on a tube (a piece whose loops are mostly pulled through loops made two passes before,
// a round below, rather than in the pass before, a row below) the front half's + and the back
// half's - are the same way round, a loop's half being that of the pass it is made in, whichever
// bed it is on (a rib's purl is knit on the other bed in its half's pass). A pass's half is told
// by its direction (the front half's being the way most loops of wales cast on on the front bed
// go), the other way after the yarn turns back (a pass pulled through the pass before it) an odd
// number of times: a heel's short row that goes on round the fold. x is the needle, y the loop's
// height, z 0 front, 1 back.
#pragma once

#include <iosfwd>
#include <vector>

#include "knitout/vbed_simulator.hpp"

namespace skein::knitout {

// `border`, when given (per loop), marks loops a proof found to be a piece's cast-on border in
// its own yarn (its tucks; on a tube with one needle the way its first pass goes, also the loop
// knit over them to bring the yarn round, which the proof counts): like the leading tucks, not
// written; the loops knit through them are the cast-on.
// Throws Error when nothing of the fabric stays (every loop unravels).
// `purled_decreases`, when given, is set per line written: whether it is a decrease knit as a
// purl (a p2tog), which `.st` writes as `d`, having no letter for it.
void write_fabric_stitch_graph(const Replay& replay, const std::string& file, std::ostream& out,
                               const std::vector<bool>* border = nullptr,
                               std::vector<bool>* purled_decreases = nullptr);

}  // namespace skein::knitout
