// Knitout operations as typed values, and a parser for any knitout text (skein's or another
// tool's): the magic line, the ;; header and one operation per line. Spelled as in the knitout
// spec (textiles-lab/knitout, knitout.html v0.6): beds f, b, fs, bs; directions + and -.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "knitout/machine_profile.hpp"

namespace skein::knitout {

enum class Bed : std::uint8_t { f, b, fs, bs };
inline bool is_front(Bed bed) {
  return bed == Bed::f || bed == Bed::fs;
}
inline bool is_slider(Bed bed) {
  return bed == Bed::fs || bed == Bed::bs;
}
const char* bed_name(Bed bed);

struct Needle {
  Bed bed = Bed::f;
  std::int32_t index = 0;
  friend bool operator==(const Needle&, const Needle&) = default;
};
std::string needle_name(Needle n);  // "f12", "bs3"

enum class OpCode : std::uint8_t {
  in,
  inhook,
  releasehook,
  out,
  outhook,  // yarn
  knit,
  tuck,
  split,
  miss,  // with a direction and carriers
  drop,
  amiss,
  xfer,  // without carriers
  rack,
  stitch,
  pause,
  extension,  // machine state, x-... extensions
};
const char* op_name(OpCode code);

using CarrierMask = std::uint32_t;  // bit i: carrier i of the ;;Carriers: header

struct Op {
  OpCode code = OpCode::pause;
  Direction dir = Direction::none;
  Needle a, b;  // b: the destination of split/xfer
  CarrierMask carriers = 0;
  std::int32_t rack_quarters = 0;  // rack, in quarter needles
};

// The ;; header lines (each may be absent: empty).
struct Header {
  std::string machine, gauge, position, width;
  std::vector<std::string> carriers;  // ;;Carriers:, in order
  bool has_carriers = false;
  bool numbered = false;          // the carriers are exactly 1 2 ... n (a fast lookup)
  std::size_t carriers_line = 0;  // 1-based line of ;;Carriers: (0 if absent)
  std::size_t first_op_line = 0;  // the first line after the header
};

// Splits knitout text into lines without copying; line i (1-based) is lines[i-1].
std::vector<std::string_view> split_lines(std::string_view text);

// Reads the magic line and the header; throws ParseError naming the file and line.
Header parse_header(const std::vector<std::string_view>& lines, const std::string& file);

// Parses one operation line (a comment or blank line gives false with no error). On a syntax
// error, sets `error` to what was expected and returns false. The line must be followed by a
// '\n' in memory (the one that ends it in the file), or end with one.
bool parse_op(std::string_view line, const Header& header, Op& op, std::string& error);

// The commonest operation lines, "knit D N C" or "tuck D N C" with one carrier of a numbered
// ;;Carriers: header and "xfer N N2", on needles of f and b, single spaces, no comment, read in
// one scan from `pos` of `text` that also finds where the line ends (`next`: past its '\n').
// False, with nothing set, for any other line: parse_op reads it (the same Op for these lines).
bool parse_plain_op(std::string_view text, std::size_t pos, const Header& header, Op& op,
                    std::size_t& next);

// The carriers of a mask as they are written ("1 3").
std::string carrier_names(const Header& header, CarrierMask mask);

}  // namespace skein::knitout
