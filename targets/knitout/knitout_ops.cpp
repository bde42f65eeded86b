#include "knitout/knitout_ops.hpp"

#include <fmt/format.h>

#include <charconv>

#include "common/error.hpp"

namespace skein::knitout {
namespace {

constexpr std::string_view kMagic = ";!knitout-2";

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Splits the code part of a line (before any ';') into at most 8 tokens.
struct Tokens {
  std::string_view word[8];
  int count = 0;
  bool too_many = false;
};
Tokens tokenize(std::string_view line) {
  Tokens t;
  std::size_t i = 0, n = line.size();
  while (i < n) {
    while (i < n && is_space(line[i])) ++i;
    if (i >= n || line[i] == ';') break;
    std::size_t start = i;
    while (i < n && !is_space(line[i]) && line[i] != ';') ++i;
    if (t.count == 8) {
      t.too_many = true;
      break;
    }
    t.word[t.count++] = line.substr(start, i - start);
    if (i < n && line[i] == ';') break;
  }
  return t;
}

bool parse_int(std::string_view s, std::int32_t& value) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && end == s.data() + s.size();
}

bool parse_needle(std::string_view s, Needle& n) {
  std::size_t digits = 1;
  if (s.size() >= 2 && (s[1] == 's')) {
    n.bed = s[0] == 'f' ? Bed::fs : s[0] == 'b' ? Bed::bs : Bed::f;
    if (s[0] != 'f' && s[0] != 'b') return false;
    digits = 2;
  } else if (!s.empty() && (s[0] == 'f' || s[0] == 'b')) {
    n.bed = s[0] == 'f' ? Bed::f : Bed::b;
  } else {
    return false;
  }
  std::string_view number = s.substr(digits);
  if (number.empty() || number.front() == '+') return false;
  return parse_int(number, n.index);
}

bool parse_direction(std::string_view s, Direction& d) {
  if (s == "+") d = Direction::plus;
  else if (s == "-") d = Direction::minus;
  else return false;
  return true;
}

// A rack such as -2, 1.25 or 0.5, in quarter needles.
bool parse_rack(std::string_view s, std::int32_t& quarters) {
  bool negative = !s.empty() && s.front() == '-';
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) s.remove_prefix(1);
  std::size_t dot = s.find('.');
  std::int32_t whole = 0;
  std::string_view w = s.substr(0, dot);
  if (w.empty() && dot == std::string_view::npos) return false;
  if (!w.empty() && !parse_int(w, whole)) return false;
  if (w.starts_with('-') || w.starts_with('+')) return false;
  std::int32_t q = whole * 4;
  if (dot != std::string_view::npos) {
    std::string_view frac = s.substr(dot + 1);
    while (!frac.empty() && frac.back() == '0') frac.remove_suffix(1);
    if (frac == "") q += 0;
    else if (frac == "25") q += 1;
    else if (frac == "5") q += 2;
    else if (frac == "75") q += 3;
    else return false;
  }
  quarters = negative ? -q : q;
  return true;
}

bool parse_carriers(const Tokens& t, int first, const Header& h, CarrierMask& mask,
                    std::string& error) {
  mask = 0;
  for (int i = first; i < t.count; ++i) {
    std::size_t c = 0;
    while (c < h.carriers.size() && h.carriers[c] != t.word[i]) ++c;
    if (c == h.carriers.size()) {
      error = fmt::format("carrier '{}' is not named in the ;;Carriers: header", t.word[i]);
      return false;
    }
    mask |= CarrierMask{1} << c;
  }
  return true;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

}  // namespace

const char* bed_name(Bed bed) {
  switch (bed) {
    case Bed::f: return "f";
    case Bed::b: return "b";
    case Bed::fs: return "fs";
    case Bed::bs: return "bs";
  }
  return "?";
}

std::string needle_name(Needle n) { return fmt::format("{}{}", bed_name(n.bed), n.index); }

const char* op_name(OpCode code) {
  constexpr const char* kNames[] = {"in",   "inhook", "releasehook", "out",  "outhook", "knit",
                                    "tuck", "split",  "miss",        "drop", "amiss",   "xfer",
                                    "rack", "stitch", "pause",       "x-"};
  return kNames[static_cast<int>(code)];
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  lines.reserve(text.size() / 12 + 1);
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

Header parse_header(const std::vector<std::string_view>& lines, const std::string& file) {
  if (lines.empty() || trim(lines[0]) != kMagic)
    throw ParseError(file, 1, lines.empty() ? "" : std::string(lines[0]),
                     fmt::format("expected the knitout magic line '{}'", kMagic));
  Header h;
  std::size_t i = 1;
  for (; i < lines.size() && lines[i].starts_with(";;"); ++i) {
    std::string_view line = trim(lines[i]);
    std::size_t colon = line.find(": ");
    if (colon == std::string_view::npos) break;  // a comment that only looks like a header
    std::string_view key = line.substr(2, colon - 2), value = trim(line.substr(colon + 2));
    auto fail = [&](const std::string& why) { throw ParseError(file, i + 1, std::string(lines[i]), why); };
    if (key == "Carriers") {
      h.has_carriers = true;
      h.carriers_line = i + 1;
      h.carriers.clear();
      for (std::size_t s = 0; s <= value.size();) {
        std::size_t e = value.find(' ', s);
        if (e == std::string_view::npos) e = value.size();
        if (e > s) h.carriers.emplace_back(value.substr(s, e - s));
        s = e + 1;
      }
      if (h.carriers.empty() || h.carriers.size() > 32)
        fail("expected ;;Carriers: with 1 to 32 carrier names separated by spaces");
    } else if (key == "Machine") {
      h.machine = value;
    } else if (key == "Gauge") {
      char* end = nullptr;
      std::string v(value);
      double g = std::strtod(v.c_str(), &end);
      if (v.empty() || *end != '\0' || !(g > 0)) fail("expected ;;Gauge: a number greater than zero");
      h.gauge = v;
    } else if (key == "Position") {
      if (value != "Left" && value != "Center" && value != "Right" && value != "Keep")
        fail("expected ;;Position: Left, Center, Right or Keep");
      h.position = value;
    } else if (key == "Width") {
      std::int32_t w = 0;
      if (!parse_int(value, w) || w <= 0) fail("expected ;;Width: a positive whole number");
      h.width = value;
    }
    // Other headers (Yarn-N, X-...) are allowed and not interpreted.
  }
  h.first_op_line = i + 1;
  return h;
}

bool parse_op(std::string_view line, const Header& h, Op& op, std::string& error) {
  Tokens t = tokenize(line);
  if (t.count == 0) return false;
  if (t.too_many) {
    error = "expected at most 8 words on an operation line";
    return false;
  }
  std::string_view name = t.word[0];
  op = Op{};
  auto need = [&](int words, const char* form) {
    if (t.count >= words) return true;
    error = fmt::format("expected '{}'", form);
    return false;
  };
  auto exactly = [&](int words, const char* form) {
    if (t.count == words) return true;
    error = fmt::format("expected '{}'", form);
    return false;
  };
  auto needle = [&](int i, Needle& n, const char* form) {
    if (parse_needle(t.word[i], n)) return true;
    error = fmt::format("expected '{}': '{}' is not a needle such as f12 or bs3", form, t.word[i]);
    return false;
  };
  auto direction = [&](const char* form) {
    if (parse_direction(t.word[1], op.dir)) return true;
    error = fmt::format("expected '{}': the direction must be + or -, found '{}'", form, t.word[1]);
    return false;
  };
  if (name == "knit" || name == "tuck" || name == "miss") {
    op.code = name == "knit" ? OpCode::knit : name == "tuck" ? OpCode::tuck : OpCode::miss;
    const char* form = name == "knit" ? "knit D N CS" : name == "tuck" ? "tuck D N CS" : "miss D N CS";
    return need(3, form) && direction(form) && needle(2, op.a, form) &&
           parse_carriers(t, 3, h, op.carriers, error);
  }
  if (name == "split") {
    op.code = OpCode::split;
    return need(4, "split D N N2 CS") && direction("split D N N2 CS") &&
           needle(2, op.a, "split D N N2 CS") && needle(3, op.b, "split D N N2 CS") &&
           parse_carriers(t, 4, h, op.carriers, error);
  }
  if (name == "drop" || name == "amiss") {
    op.code = name == "drop" ? OpCode::drop : OpCode::amiss;
    const char* form = name == "drop" ? "drop N (no carriers: knit drops with yarn)" : "amiss N";
    return exactly(2, form) && needle(1, op.a, form);
  }
  if (name == "xfer") {
    op.code = OpCode::xfer;
    return exactly(3, "xfer N N2 (no carriers: split moves with yarn)") &&
           needle(1, op.a, "xfer N N2") && needle(2, op.b, "xfer N N2");
  }
  if (name == "in" || name == "inhook" || name == "releasehook" || name == "out" ||
      name == "outhook") {
    op.code = name == "in"            ? OpCode::in
              : name == "inhook"      ? OpCode::inhook
              : name == "releasehook" ? OpCode::releasehook
              : name == "out"         ? OpCode::out
                                      : OpCode::outhook;
    if (!parse_carriers(t, 1, h, op.carriers, error)) return false;
    if (op.carriers == 0) {
      error = fmt::format("expected '{} CS' with at least one carrier", name);
      return false;
    }
    return true;
  }
  if (name == "rack") {
    op.code = OpCode::rack;
    if (!exactly(2, "rack R")) return false;
    if (parse_rack(t.word[1], op.rack_quarters)) return true;
    error = fmt::format("expected 'rack R': '{}' is not a racking such as -2, 1 or 0.25", t.word[1]);
    return false;
  }
  if (name == "stitch") {
    op.code = OpCode::stitch;
    std::int32_t l = 0, s = 0;
    if (exactly(3, "stitch L T") && parse_int(t.word[1], l) && parse_int(t.word[2], s)) return true;
    error = "expected 'stitch L T' with two whole numbers";
    return false;
  }
  if (name == "pause") {
    op.code = OpCode::pause;
    return exactly(1, "pause");
  }
  if (name.starts_with("x-")) {
    op.code = OpCode::extension;
    if (name == "x-stitch-number" || name == "x-speed-number") {
      std::int32_t v = 0;
      if (t.count == 2 && parse_int(t.word[1], v) && v >= 0) return true;
      error = fmt::format("expected '{} K' with a whole number K >= 0", name);
      return false;
    }
    return true;
  }
  error = fmt::format("unknown operation '{}'; expected in, inhook, releasehook, out, outhook, "
                      "knit, tuck, split, miss, drop, amiss, xfer, rack, stitch, pause or x-...",
                      name);
  return false;
}

std::string carrier_names(const Header& h, CarrierMask mask) {
  std::string out;
  for (std::size_t c = 0; c < h.carriers.size(); ++c)
    if (mask & (CarrierMask{1} << c)) out += (out.empty() ? "" : " ") + h.carriers[c];
  return out;
}

}  // namespace skein::knitout
