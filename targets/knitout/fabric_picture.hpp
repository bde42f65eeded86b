// The fabric a knitout file makes, drawn as SVG so that a user can look at what a foreign file
// knits: each loop a dot at its needle (across) and its height in the fabric (up: one above the
// highest loop it was pulled through; a loop pulled through nothing, a tuck, sits at the height
// of the yarn's previous loop), loops on the front bed dark, on the back bed light, tucks as
// rings, loops that unravel red; grey lines join each loop to the loops it was pulled through
// (the wales), coloured lines follow each yarn from loop to loop. Linear in the loops.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <vector>

#include "knitout/vbed_simulator.hpp"

namespace skein::knitout {

// Each loop's height in the fabric: one above the highest loop it was pulled through; a loop
// pulled through nothing sits at the height of its yarn piece's previous loop.
std::vector<std::uint32_t> loop_heights(const Fabric& fabric);

void write_fabric_svg(const Replay& replay, const std::string& title, std::ostream& out);

}  // namespace skein::knitout
