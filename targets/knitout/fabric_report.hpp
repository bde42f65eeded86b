// What a knitout file makes, read from the fabric the virtual v-bed knitted, without a model
// to compare it with: how many pieces, the stitches by kind, and what a knitter would want to
// hear about before spending yarn (loops dropped that unravel, loops left on the needles,
// stitches pulled through nothing, long floats, tucks that hold nothing).
#pragma once

#include <cstdint>
#include <string>

#include "knitout/vbed_simulator.hpp"

namespace skein::knitout {

struct FabricReport {
  std::uint64_t pieces = 0;  // loops joined by loops pulled through them or by yarn
  std::uint64_t knits = 0;   // knit loops made on the front bed (knit seen from the front)
  std::uint64_t purls = 0;   // ... on the back bed
  std::uint64_t tucks = 0, splits = 0;
  std::uint64_t decreases = 0;        // loops pulled through two or more loops at once
  std::uint64_t through_nothing = 0;  // knit or split loops pulled through no loop
  std::uint64_t unravelling = 0;      // loops dropped while nothing was pulled through them
  std::uint64_t left_on_needles = 0;  // loops still on the needles at the end
  std::uint64_t long_floats = 0;      // yarn between two loops longer than max_float
  std::uint64_t idle_tucks = 0;       // tucks that nothing was pulled through (dropped or left)
};

FabricReport fabric_report(const Replay& replay);

// A few lines for people.
std::string fabric_summary(const FabricReport& report, const MachineProfile& profile);

}  // namespace skein::knitout
