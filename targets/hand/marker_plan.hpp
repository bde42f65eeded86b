// Stitch markers between the sections of rows shaped alike (the wedges of a crown): placed on
// the row before the first shaped row, slipped on every row after, so that the rows read
// "*K to 2 sts before m, ssk, sm; rep from * to end" whatever their width and repeat as a
// block (paper §5.1: repeat until a marker rather than count).
#pragma once

#include <optional>
#include <vector>

#include "hand/pattern_model.hpp"

namespace skein::hand {

// Rewrites the rows of each section with pm / sm / rm where a group of at least two shaped
// rows, each the same unit worked the same number of times, keeps its sections aligned.
void place_section_markers(HandPattern& pattern);

// Gives each row with new operations (`rewritten[r]`) those, the others keeping theirs.
void rewrite_rows(HandPattern& pattern,
                  const std::vector<std::optional<std::vector<HandOp>>>& rewritten);

}  // namespace skein::hand
