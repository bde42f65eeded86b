#include "knitout/vbed_rules.hpp"

#include <fmt/format.h>

#include <array>

namespace skein::knitout {
namespace {

using enum Severity;
using S = RuleSource;

// clang-format off
constexpr std::array<RuleInfo, static_cast<std::size_t>(Rule::count)> kRules{{
    {Rule::carriers_line, "carriers-line", S::back_end, error,
     "the back end accepts one ;;Carriers: line (knitout-to-dat: 1 2 3 4 5 6 7 8 9 10, knitout-to-kcode: 1 2 3 4 5 6); a profile without a back end takes the file's"},
    {Rule::machine_header, "machine-header", S::profile, warning,
     "the file names another machine than the one it is replayed on (only with --machine)"},
    {Rule::gauge_header, "gauge-header", S::profile, warning,
     "the file's ;;Gauge: is not the profile's: the fabric comes out another size"},
    {Rule::width_header, "width-header", S::back_end, error,
     "knitout-to-dat lays the design out on ;;Width: needles, which the bed must have"},
    {Rule::needle_off_bed, "needle-off-bed", S::back_end, note,
     "the back ends read any integer needle (-?[0-9]+) and place the design by ;;Position:; only --strict holds needles to 0..needles-1"},
    {Rule::needle_span, "needle-span", S::machine, error,
     "the needles used must fit on the bed"},
    {Rule::no_sliders, "no-sliders", S::machine, error,
     "the machine has no sliders (fs, bs)"},
    {Rule::loops_per_needle, "loops-per-needle", S::back_end, warning,
     "knitout-to-dat warns past 4 loops on a needle: they may not knit off"},
    {Rule::needle_overfull, "needle-overfull", S::virtual_bed, error,
     "the v-bed holds at most 15 loops on a needle; no machine knits more"},
    {Rule::knit_empty_needle, "knit-empty-needle", S::spec, note,
     "knitting an empty needle forms a loop held by nothing below it (a cast-on); the back ends warn"},
    {Rule::carrier_not_in, "carrier-not-in", S::spec, error,
     "a carrier knits only between its in (or inhook) and its out (knitout-to-dat, knitout-to-kcode: 'using a carrier that isn't active')"},
    {Rule::carrier_already_in, "carrier-already-in", S::back_end, error,
     "'Can't bring in carrier -- it is already active'"},
    {Rule::first_use_set, "first-use-set", S::back_end, error,
     "'first use of carriers doesn't match in info': carriers brought in together are first used together"},
    {Rule::first_pass_direction, "first-pass-direction", S::simulator, warning,
     "the yarn comes in from the hook's side (SWG: the right, so the first pass goes -; Kniterate: the left, +)"},
    {Rule::no_hook, "no-hook", S::back_end, note,
     "the machine has no yarn-inserting hook; its back end knits inhook as in and outhook as out"},
    {Rule::hook_busy, "hook-busy", S::back_end, error,
     "the hook holds one yarn at a time: releasehook it before the next inhook or outhook"},
    {Rule::hook_blocks, "hook-blocks", S::simulator, warning,
     "until releasehook, the hook stands beside the first stitch of its yarn and blocks the needles beyond it"},
    {Rule::releasehook_mismatch, "releasehook-mismatch", S::back_end, error,
     "'Can't releasehook ... hook currently holds ...': releasehook names what the hook holds"},
    {Rule::releasehook_early, "releasehook-early", S::back_end, error,
     "the hook releases a yarn only after it made a stitch (the release pass goes where it last stitched)"},
    {Rule::out_not_in, "out-not-in", S::back_end, error,
     "'Can't bring out carrier -- it isn't yet active'"},
    {Rule::out_without_stitch, "out-without-stitch", S::back_end, error,
     "'Can't bring out carrier -- it hasn't yet stitched'"},
    {Rule::out_while_hooked, "out-while-hooked", S::back_end, error,
     "'Can't out carriers, hook release pending': releasehook first"},
    {Rule::carrier_left_in, "carrier-left-in", S::simulator, warning,
     "a carrier still in at the end stays threaded to the fabric: it is cut by hand"},
    {Rule::rack_limit, "rack-limit", S::profile, warning,
     "beyond the profile's racking limit (swg091n2: 4, as Hofmann's simulator; knitout-to-dat allows 8)"},
    {Rule::rack_fraction, "rack-fraction", S::back_end, error,
     "knitout-to-dat: 'rackings must be an integer or an integer + 0.25'; Kniterate racks by halves"},
    {Rule::transfer_misaligned, "transfer-misaligned", S::spec, error,
     "xfer and split move a loop to the needle that faces it at the current rack"},
    {Rule::transfer_same_bed, "transfer-same-bed", S::spec, error,
     "xfer and split move loops between the front and the back bed"},
    {Rule::transfer_slider_slider, "transfer-slider-slider", S::machine, error,
     "a slider hands its loops only to a needle"},
    {Rule::transfer_stretch, "transfer-stretch", S::profile, warning,
     "a transfer at a wide rack stretches the loop across that many needles"},
    {Rule::split_from_slider, "split-from-slider", S::back_end, error,
     "a slider cannot knit, so it cannot split"},
    {Rule::stitch_on_slider, "stitch-on-slider", S::machine, error,
     "sliders only hold loops moved there: they do not knit, tuck or miss"},
    {Rule::miss_without_carriers, "miss-without-carriers", S::spec, error,
     "miss moves carriers: without one it does nothing (knitout-to-dat: 'it makes no sense to miss with no yarns')"},
}};
// clang-format on

constexpr bool table_in_order() {
  for (std::size_t i = 0; i < kRules.size(); ++i)
    if (static_cast<std::size_t>(kRules[i].rule) != i) return false;
  return true;
}
static_assert(table_in_order(), "kRules lists the rules in the order of enum Rule");

}  // namespace

const char* severity_name(Severity s) {
  switch (s) {
    case error:
      return "error";
    case warning:
      return "warning";
    case note:
      return "note";
    case off:
      return "off";
  }
  return "?";
}

const RuleInfo& rule_info(Rule rule) {
  return kRules[static_cast<std::size_t>(rule)];
}

std::span<const RuleInfo> all_rules() {
  return kRules;
}

Severity rule_severity(Rule rule, const MachineProfile& p, bool strict) {
  if (rule == Rule::knit_empty_needle) return strict && p.knit_empty_needle_is_error ? error : note;
  if (strict) return error;
  bool machine_choice =
      rule == Rule::carriers_line || rule == Rule::no_hook || rule == Rule::first_pass_direction;
  if (machine_choice && p.back_end.empty()) return off;
  return rule_info(rule).severity;
}

std::string source_name(RuleSource source, const MachineProfile& p) {
  switch (source) {
    case S::spec:
      return "knitout spec";
    case S::back_end:
      return p.back_end.empty() ? "the back ends" : p.back_end;
    case S::simulator:
      return "Hofmann's SWG091N2 simulator";
    case S::machine:
      return fmt::format("the {} machine", p.name);
    case S::profile:
      return fmt::format("profile {}", p.name);
    case S::virtual_bed:
      return "the v-bed";
  }
  return "?";
}

std::string finding_line(const Finding& f, const MachineProfile& p) {
  const RuleInfo& info = rule_info(f.rule);
  return fmt::format("{}: {}{} [{}: {}]{}", severity_name(f.severity),
                     f.line ? fmt::format("line {}: ", f.line) : "", f.message, info.name,
                     source_name(info.source, p),
                     f.count > 1 ? fmt::format(" ({} times)", f.count) : "");
}

}  // namespace skein::knitout
