// The pattern document written out: markdown, a self-contained printable HTML page (with an
// SVG schematic per piece and a chart where the stitches form a pattern), or the rows alone in
// Stitch-Maps' KnitSpeak.
#pragma once

#include <iosfwd>

#include "hand/pattern_document.hpp"
#include "hand/pattern_model.hpp"

namespace skein::hand {

void write_markdown(const PatternDocument& doc, std::ostream& out);
void write_html(const PatternDocument& doc, const HandPattern& pattern, const Gauge& gauge,
                std::ostream& out);
void write_knitspeak(const PatternDocument& doc, std::ostream& out);

}  // namespace skein::hand
