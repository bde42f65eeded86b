// The rules the virtual v-bed enforces, each with where it comes from and how bad breaking it
// is. A rule of the knitout specification or one a named back end (knitout-to-dat for Shima
// SWG, knitout-to-kcode for Kniterate) refuses is an error: the file cannot be knitted. A rule
// that only a profile's choice, a simulator or the machine's habits make is a warning (legal but
// likely unintended) or a note (worth knowing). With --strict (skein's own output, and
// `compile --verify`) every rule is an error: skein promises more than the back ends demand.
// docs/knitout.md has the table.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "knitout/machine_profile.hpp"

namespace skein::knitout {

// `off`: the rule does not apply on this profile (a generic v-bed has no back end to demand a
// carriers line, no hook to be blocked by).
enum class Severity : std::uint8_t { off, note, warning, error };
const char* severity_name(Severity s);

enum class RuleSource : std::uint8_t {
  spec,         // knitout.html v0.6
  back_end,     // the profile's back end (knitout-to-dat, knitout-to-kcode) refuses it
  simulator,    // Hofmann's SWG091N2 virtual knitting machine refuses it
  machine,      // the machine itself: its bed, its sliders
  profile,      // the machine profile's own limit (skein's output keeps to it)
  virtual_bed,  // what this v-bed can track
};

enum class Rule : std::uint8_t {
  carriers_line,           // the ;;Carriers: line the back end demands
  machine_header,          // ;;Machine: names another machine than the profile's
  gauge_header,            // ;;Gauge: differs from the profile's
  width_header,            // ;;Width: wider than the bed
  needle_off_bed,          // a needle numbered outside 0..needles-1 (the back end shifts it)
  needle_span,             // the needles used span more than the bed
  no_sliders,              // a slider on a machine without them
  loops_per_needle,        // more loops on one needle than the profile allows
  needle_overfull,         // more loops on one needle than the v-bed tracks (15)
  knit_empty_needle,       // knit or split of a needle holding no loop
  carrier_not_in,          // a stitch with a carrier that is not in
  carrier_already_in,      // in / inhook of a carrier that is in
  first_use_set,           // the first use of carriers is not the set brought in together
  first_pass_direction,    // the first pass after bringing a carrier in goes the wrong way
  no_hook,                 // inhook / releasehook / outhook on a machine without a hook
  hook_busy,               // inhook or outhook while the hook holds a yarn
  hook_blocks,             // a needle in the hook's way before releasehook
  releasehook_mismatch,    // releasehook of carriers the hook does not hold
  releasehook_early,       // releasehook before the carrier made a stitch
  out_not_in,              // out of a carrier that is not in
  out_without_stitch,      // out of a carrier that made no stitch
  out_while_hooked,        // out of a carrier still held by the hook
  carrier_left_in,         // a carrier still in at the end of the file
  rack_limit,              // |rack| beyond the profile's limit
  rack_fraction,           // a fractional rack the machine cannot make
  transfer_misaligned,     // xfer / split between needles that do not face each other
  transfer_same_bed,       // xfer / split within one bed
  transfer_slider_slider,  // xfer from slider to slider
  transfer_stretch,        // xfer / split at a rack beyond the profile's transfer limit
  split_from_slider,       // split starting on a slider
  stitch_on_slider,        // knit / tuck / miss / amiss on a slider
  miss_without_carriers,   // miss with no carriers
  count,
};

struct RuleInfo {
  Rule rule;
  const char* name;   // "knit-empty-needle": named in every message
  RuleSource source;  // where it comes from
  Severity severity;  // without --strict
  const char* why;    // one line for the docs table: the source's words
};

const RuleInfo& rule_info(Rule rule);
std::span<const RuleInfo> all_rules();

// What breaking `rule` costs on `profile`: the table's severity, or error under --strict, and
// adjusted where the profile decides: a profile without a back end (generic) is a v-bed with
// no carriers line to demand, a hook wherever the file uses one and no side its yarns must
// come from; knitting an empty needle is allowed on a profile that says so, even under --strict.
Severity rule_severity(Rule rule, const MachineProfile& profile, bool strict);

// A rule broken at a warning or note: its first occurrence, and how often it happened.
struct Finding {
  Rule rule = Rule::count;
  Severity severity = Severity::note;
  std::size_t line = 0;  // of the first occurrence (0: the whole file)
  std::string message;   // of the first occurrence
  std::uint64_t count = 0;
};

// "warning: line 412: rack 5 is beyond ... [rack-limit: Hofmann's simulator] (3 times)"
std::string finding_line(const Finding& f, const MachineProfile& profile);

// Where a source is, for people: "knitout-to-dat (Shima SWG)" for the profile's back end.
std::string source_name(RuleSource source, const MachineProfile& profile);

}  // namespace skein::knitout
