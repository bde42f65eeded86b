// The knit/purl chart of a piece without shaping (ribs, textures): which pieces have one and
// what its squares are. The printable page draws it (html_writer.cpp) and the knitting page
// shows it beside the current row (targets/hand_web), both from here.
#pragma once

#include <cstdint>
#include <vector>

#include "hand/pattern_model.hpp"

namespace skein::hand {

// One row of a chart: the pattern row it charts and that row's stitches as seen from the RS,
// left to right (RS rows are worked right to left, WS rows left to right).
struct ChartRow {
  std::uint32_t row = 0;  // into HandPattern::rows
  std::vector<StitchType> cells;
};

// The chart of section `s`, its first row first (bind-off rows are not charted); empty when
// the section has none: a stitch that is not a knit or a purl, a row not as wide as the
// cast-on, knits alone or purls alone, or too large to read.
std::vector<ChartRow> chart_rows(const HandPattern& p, const PatternSection& s);

}  // namespace skein::hand
