// The printed pattern, independent of markup: the front matter a publisher puts first
// (measurements, yarn, needles, gauge, abbreviations used, techniques, notes), then the
// instructions in knitting order with rows repeated across ("Rep Rnds 3–4 five more times."),
// then finishing. The markdown and HTML writers only style it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hand/pattern_model.hpp"
#include "hand/row_text.hpp"

namespace skein::hand {

// The gauge every measurement, yarn amount and needle assumes: the project's, or for a model
// that does not say (a stitch mesh or stitch graph file) worsted at 20 sts and 28 rows on
// 4.5 mm needles, which the pattern says is assumed.
struct Gauge {
  double sts_per_10cm = 20;
  double rows_per_10cm = 28;
  std::string yarn_weight = "worsted";  // the Craft Yarn Council's name: "dk", "super-bulky"
  double needle_mm = 4.5;
  bool assumed = true;  // the model does not say
  // Yarn per stitch from Munden's relation for relaxed plain knitting: stitches per cm² =
  // 19 / (loop length in cm)², plus 10% for tension and joins.
  double yarn_cm_per_stitch() const;
};

struct InstructionLine {
  enum class Kind : std::uint8_t {
    heading,  // a piece or stage
    setup,    // "Cast on 64 sts. Pm and join ..."
    row,      // "Rnd 25:" + "*K6, k2tog; rep from * to end — 56 sts."
    repeat,   // "Rep Rows 3–4 five more times."
    finish,   // "Fasten off."
  };
  Kind kind;
  std::string label;  // rows only: "Row 3 (RS)", "Rnd 5"
  std::string text;   // whole sentences, ending with a period
  std::uint32_t section = 0;
};

struct FrontSection {
  std::string heading;
  std::vector<std::string> items;
};

struct PatternDocument {
  std::string title;
  std::string subtitle;
  std::vector<FrontSection> front;
  std::vector<InstructionLine> instructions;
  std::vector<std::string> finishing;
};

PatternDocument make_document(const HandPattern& pattern, Dialect dialect = Dialect::standard,
                              const Gauge& gauge = {});

// Headings the reader looks for: the instructions are everything under the first.
inline constexpr const char* kInstructionsHeading = "Instructions";
inline constexpr const char* kFinishingHeading = "Finishing";

}  // namespace skein::hand
