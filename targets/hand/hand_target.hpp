// The `hand` target: printable hand-knitting patterns (markdown; `hand-html`, a printable page
// with a schematic and charts; `hand-knitspeak`, the rows in Stitch-Maps' KnitSpeak), and the
// hand simulator that reads such a pattern as a knitter would, works it on a model of needles,
// markers and yarn, and proves that it knits the input stitch for stitch.
#pragma once

#include <string>
#include <string_view>

#include "driver/registry.hpp"

namespace skein {

void register_hand_target(Registry& registry);

namespace hand {

struct HandPattern;

// The pattern the hand targets write for `c` with the options' settings (`short-rows`,
// `rounds`, `builder`), not yet proven: built from the lowering's live-loop program; where that
// builder refuses a structure by name and `builder` is not `program`, from the schedule.
HandPattern build_pattern(const Compilation& c, const TargetOptions& options);

// Reads, works and (with `against`) compares a pattern; what `skein verify` runs. Throws
// ParseError for text it cannot read; an impossible step or a different fabric is a report
// that is not proven.
VerifyReport verify_pattern(std::string_view text, const std::string& file,
                            const Compilation* against);

}  // namespace hand
}  // namespace skein
