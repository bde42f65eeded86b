// The wording both halves of a pattern document share (the instructions and the front matter),
// and the two halves, which make_document puts together.
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <vector>

#include "hand/pattern_document.hpp"

namespace skein::hand::document {

inline constexpr const char* kDash = "\u2014";  // before a stitch count

inline std::string with_commas(std::uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

// A piece whose last row went to holders for the pieces that work it: no st to fasten off.
inline bool parted_between_pieces(const PatternSection& sec) {
  return sec.last_row_held() || (!sec.holdings.empty() && sec.holdings.back().of_row);
}

// What the pattern calls piece `number` (1-based): "Thumb", "Leg 2", "Piece 3".
inline const std::string& piece_name(const HandPattern& p, std::uint32_t number) {
  return p.piece_names[number - 1];
}

// The instructions of every section, finding blocks of rows that repeat.
std::vector<InstructionLine> instructions(const HandPattern& p, Dialect dialect);

// The sections before the instructions: measurements, yarn, needles, gauge, abbreviations,
// techniques and notes, as `lines` (the instructions) need them.
std::vector<FrontSection> front_matter(const HandPattern& p, const Gauge& gauge,
                                       const std::vector<InstructionLine>& lines);

}  // namespace skein::hand::document
