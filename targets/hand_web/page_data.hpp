// What the knitting page shows, built in C++ and embedded in the page: the proven pattern's
// rows (their printed text), and per stitch in the lowering's program order (the order the
// page steps through) the model stitch, the row of the pattern that works it, its place there
// and the token of the row's text that names it; the stitches' cells in 3D and the yarn.
//
// The bridge from the text to the model is the hand simulator's: it works the pattern and
// knits a fabric, which the judge pairs with the model stitch for stitch along each yarn. The
// page uses that pairing, so what it highlights is what the proof compared.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hand/pattern_model.hpp"

namespace skein {
struct Compilation;
}

namespace skein::hand_web {

inline constexpr std::uint32_t kNone = 0xffffffffu;

struct PageRow {
  std::string heading;  // the piece or stage it belongs to ("Piece 2 (yarn 2)"), or ""
  std::string label;    // "Rnd 27, Rnd 25 again", "Cast on"
  std::string text;     // the instruction line as printed (markup removed)
  std::string said_by;  // the line that said to work it, when not `text` ("Rep Rnds 25–26 ...")
  std::uint32_t stitches = 0;
  std::uint32_t piece = 0;  // 1-based
  // The chart of its piece it is a row of (into PageData::charts; kNone: none) and which row.
  std::uint32_t chart = kNone, chart_row = 0;
};

// A piece's knit/purl chart, as the printable page draws it (hand/chart.hpp).
struct PageChart {
  // Per chart row, its first row first: per square, left to right as seen from the RS, 'k' (a
  // blank square: k on RS rows, p on WS rows) or 'p' (a dot).
  std::vector<std::string> cells;
  std::vector<std::uint32_t> number;   // per chart row: its number in the piece
  std::vector<std::uint8_t> leftward;  // per chart row: worked from its last square to its first
};

// Per stitch in program order.
struct PageStitch {
  std::uint32_t stitch = 0;    // model stitch
  std::uint32_t step = 0;      // its step in the program (kNone: past where the lowering stopped)
  std::uint32_t row = 0;       // into PageData::rows
  std::uint32_t position = 0;  // 1-based, in the order its row works its stitches
  // The token of the row's text that names it, [begin, end) in PageRow::text (kNone: the whole
  // line; in UTF-16 code units, as the page's script counts), and the time round its repeat
  // (1-based; 0: in no repeat) of how many.
  std::uint32_t begin = kNone, end = kNone;
  std::uint32_t repeat = 0, repeats = 0;
  bool marker = false;  // the pattern places or slips a marker just before it
};

struct PageData {
  std::string title;
  std::string source;   // the input, as given
  std::string pattern;  // the proven pattern (markdown), whole
  std::string proof;    // the hand simulator's summary
  std::string note;     // where the order is not the program's (the lowering stopped early)
  std::vector<PageRow> rows;
  std::vector<PageChart> charts;
  std::vector<PageStitch> order;  // program order
  // Per model stitch its cell's corners (4 × xyz, counter-clockwise from the bottom left, the
  // right side facing); empty when the model has no positions.
  std::vector<std::array<float, 12>> cells;
  std::vector<std::uint32_t> yarn;        // pairs of model stitches joined by the yarn
  std::vector<std::uint32_t> yarn_piece;  // per model stitch: its yarn piece
  std::string key;                        // a hash of the pattern and the order
};

// Builds the page's data from a knittable compilation, its hand pattern as `--target hand`
// writes it (markdown) and the pattern model that text was written from: proves the text with
// the hand simulator and maps its rows onto the program. Throws UnsupportedError when the pattern
// is not proven (nothing is written then).
PageData build_page_data(const Compilation& c, const std::string& pattern,
                         const hand::HandPattern& written);

}  // namespace skein::hand_web
