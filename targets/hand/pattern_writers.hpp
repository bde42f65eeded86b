// The pattern document written out: markdown, a self-contained printable HTML page (with an
// SVG schematic per piece and a chart where the stitches form a pattern), or the rows alone in
// Stitch-Maps' KnitSpeak.
#pragma once

#include <iosfwd>
#include <optional>

#include "hand/pattern_document.hpp"
#include "hand/pattern_model.hpp"
#include "render/cell_picture.hpp"

namespace skein::hand {

void write_markdown(const PatternDocument& doc, std::ostream& out);
// The model for the page's schematics, each cell labelled with the yarn piece that knits it;
// nullopt for a stitch graph (no faces to draw).
std::optional<CellPicture> picture_of_pieces(const Compilation& c);
void write_html(const PatternDocument& doc, const HandPattern& pattern, const CellPicture* picture,
                std::ostream& out);
void write_knitspeak(const PatternDocument& doc, std::ostream& out);

}  // namespace skein::hand
