// The virtual v-bed: replays any knitout file operation by operation on a machine profile
// (loops on every needle and slider, carriers in/hooked/parked, racking) and stops at the
// first operation that breaks a rule of knitout.md or of the profile, naming the line, the
// operation and the rule. What it knitted is kept as a fabric: every loop, the loops it was
// pulled through (in stack order, bottom first) and its place along its carrier's yarn.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "knitout/knitout_ops.hpp"
#include "knitout/machine_profile.hpp"
#include "knitout/vbed_rules.hpp"

namespace skein::knitout {

using LoopId = std::uint32_t;
inline constexpr LoopId kNoLoop = 0xffffffffu;

struct FabricLoop {
  // With one parent (most loops), the parent itself; else where its parents start in
  // Fabric::parents (a million loops' parents are not written twice).
  std::uint32_t first_parent = 0;
  std::uint8_t parent_count = 0;  // loops it was pulled through (knit, split); 0 for tuck
  std::uint8_t children = 0;      // loops later pulled through it (saturates at 255)
  OpCode made_by = OpCode::knit;  // knit, tuck or split
  // Four flags in one byte: a loop is 24 bytes, and a million of them are written once each.
  bool dropped : 1 = false;             // released by a drop while nothing was pulled through it
  bool front : 1 = true;                // made on the front bed (seen from the front: a knit)
  Direction dir : 2 = Direction::plus;  // the direction of the pass that made it
  // A tuck made on an empty needle: it lies over nothing (a cast-on's loop), even once moved
  // onto loops; else it lies over the loop under it on its needle.
  bool over_nothing : 1 = false;
  CarrierMask yarn = 0;     // the carriers that made it
  std::uint32_t piece = 0;  // yarn piece (one per in/inhook of its carrier)
  std::uint32_t line = 0;   // the knitout line that made it
  std::int32_t needle = 0;  // the needle it was made on
};

static_assert(sizeof(FabricLoop) == 24);

struct Fabric {
  std::vector<FabricLoop> loops;
  std::vector<LoopId> parents;                  // of the loops pulled through two or more
  std::vector<std::vector<LoopId>> by_carrier;  // per carrier: its loops in yarn order
  std::span<const LoopId> parents_of(LoopId l) const {
    const FabricLoop& loop = loops[l];
    if (loop.parent_count == 1) return {&loop.first_parent, 1};
    return {parents.data() + loop.first_parent, loop.parent_count};
  }
};

// What a shop wants to know about a file.
struct ShopStats {
  std::uint64_t operations = 0;
  std::uint64_t stitch_passes = 0;    // carriage passes that knit, tuck, split or miss
  std::uint64_t transfer_passes = 0;  // carriage passes that transfer or drop
  std::uint64_t knits = 0, tucks = 0, splits = 0, misses = 0, transfers = 0;
  std::uint64_t racks = 0;  // rack changes
  std::uint64_t loops_dropped = 0;
  std::uint64_t loops_left = 0;       // still on the needles after the last line
  std::uint64_t empty_knits = 0;      // knits and splits of empty needles (where allowed)
  std::uint64_t long_floats = 0;      // yarn between two loops crossing more than max_float
  std::uint64_t yarn_pieces = 0;      // in / inhook of a carrier
  std::uint64_t needles_crossed = 0;  // summed width of the passes
  std::int32_t min_needle = 0, max_needle = 0;
  double seconds = 0;  // estimated knitting time
};

struct Replay {
  Header header;
  Fabric fabric;
  ShopStats stats;
  std::vector<Finding> findings;  // the rules broken at warning or note, in the order of Rule
};

struct ReplayOptions {
  bool strict = true;  // every rule an error (skein's own output); else each rule's severity
  // Whether ;;Machine: and ;;Gauge: are checked against the profile (not when the profile is
  // the generic one standing in for a machine no profile knows).
  bool check_machine = true;
};

// The magic line and the header of `text` (throws ParseError on a bad one).
Header read_header(std::string_view text, const std::string& file);

// The profile a file is replayed on: `machine` (--machine) if given, else the shipped profile
// its ;;Machine: header names, else the generic one (and `how` says so).
struct ProfileChoice {
  MachineProfile profile;
  ReplayOptions options;
  std::string how;  // for the summary: "" (given), " (the file's ;;Machine: SWGN2)", a note
};
ProfileChoice choose_profile(std::string_view text, const std::string& file,
                             const std::string& machine, bool strict);

// Replays `text` (read from `file`) on `profile`. Throws ParseError at the first error.
Replay replay_knitout(std::string_view text, const std::string& file, const MachineProfile& profile,
                      ReplayOptions options = {});

// Several lines for people: passes, transfers, racks, drops, yarn pieces, time.
std::string shop_summary(const Replay& replay, const MachineProfile& profile);

}  // namespace skein::knitout
