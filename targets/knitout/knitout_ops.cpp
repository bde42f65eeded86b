#include "knitout/knitout_ops.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>

#include "common/error.hpp"

namespace skein::knitout {
namespace {

constexpr std::string_view kMagic = ";!knitout-2";

// What a character is to the tokenizer, looked up in one table read instead of four tests.
// `end`: a comment's ';' or the '\n' that ends the line.
enum class CharKind : std::uint8_t { word, space, end };
constexpr std::array<CharKind, 256> kCharKinds = [] {
  std::array<CharKind, 256> kinds{};
  for (char c : {' ', '\t', '\r'}) kinds[static_cast<unsigned char>(c)] = CharKind::space;
  kinds[';'] = kinds['\n'] = CharKind::end;
  return kinds;
}();
CharKind kind(char c) {
  return kCharKinds[static_cast<unsigned char>(c)];
}
bool is_space(char c) {
  return kind(c) == CharKind::space;
}

// Splits the code part of a line (before any ';') into at most 8 tokens. The words are left
// uninitialised past `count`: clearing them on every line costs more than reading the line.
struct Tokens {
  struct Word {
    const char* text;
    std::size_t size;
  };
  std::array<Word, 8> words;
  int count = 0;
  bool too_many = false;
  std::string_view word(int i) const { return {words[i].text, words[i].size}; }
};
// The '\n' after the line stops every scan, so they need no test of where the line ends.
Tokens tokenize(std::string_view line) {
  Tokens t;
  const char* p = line.data();
  for (;;) {
    while (is_space(*p)) ++p;
    if (kind(*p) == CharKind::end) break;
    const char* start = p;
    while (kind(*p) == CharKind::word) ++p;
    if (t.count == 8) {
      t.too_many = true;
      break;
    }
    t.words[t.count++] = {start, static_cast<std::size_t>(p - start)};
  }
  return t;
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Up to 9 digits, so no overflow.
bool parse_digits(std::string_view s, std::int32_t& value) {
  std::int32_t v = 0;
  for (char c : s) {
    if (!is_digit(c)) return false;
    v = v * 10 + (c - '0');
  }
  value = v;
  return true;
}

// A signed or long number: kept out of line so that parse_int inlines.
[[gnu::noinline]] bool parse_signed_int(std::string_view s, std::int32_t& value) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (!s.empty() && s.size() <= 9 && s.front() != '-') return parse_digits(s, value);
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && end == s.data() + s.size();
}

// Inlined into every caller: the needles and carriers of nearly every line are a few digits.
[[gnu::always_inline]] inline bool parse_int(std::string_view s, std::int32_t& value) {
  bool plain = !s.empty() && s.size() <= 9 && is_digit(s.front());
  return plain ? parse_digits(s, value) : parse_signed_int(s, value);
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
  if (s == "+")
    d = Direction::plus;
  else if (s == "-")
    d = Direction::minus;
  else
    return false;
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
    if (frac == "")
      q += 0;
    else if (frac == "25")
      q += 1;
    else if (frac == "5")
      q += 2;
    else if (frac == "75")
      q += 3;
    else
      return false;
  }
  quarters = negative ? -q : q;
  return true;
}

bool parse_carriers(const Tokens& t, int first, const Header& h, CarrierMask& mask,
                    std::string& error) {
  mask = 0;
  for (int i = first; i < t.count; ++i) {
    std::size_t c = 0;
    std::int32_t number = 0;
    if (h.numbered && parse_int(t.word(i), number) && number >= 1 && t.word(i)[0] != '+' &&
        static_cast<std::size_t>(number) <= h.carriers.size())
      c = static_cast<std::size_t>(number - 1);
    else
      while (c < h.carriers.size() && h.carriers[c] != t.word(i)) ++c;
    if (c == h.carriers.size()) {
      error = fmt::format("carrier '{}' is not named in the ;;Carriers: header", t.word(i));
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
    case Bed::f:
      return "f";
    case Bed::b:
      return "b";
    case Bed::fs:
      return "fs";
    case Bed::bs:
      return "bs";
  }
  return "?";
}

std::string needle_name(Needle n) {
  return fmt::format("{}{}", bed_name(n.bed), n.index);
}

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
    auto fail = [&](const std::string& why) {
      throw ParseError(file, i + 1, std::string(lines[i]), why);
    };
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
      h.numbered = true;
      for (std::size_t c = 0; c < h.carriers.size(); ++c)
        h.numbered = h.numbered && h.carriers[c] == std::to_string(c + 1);
    } else if (key == "Machine") {
      h.machine = value;
    } else if (key == "Gauge") {
      char* end = nullptr;
      std::string v(value);
      double g = std::strtod(v.c_str(), &end);
      if (v.empty() || *end != '\0' || !(g > 0))
        fail("expected ;;Gauge: a number greater than zero");
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

namespace {

// Parses the words of one operation; the operation is told apart by its first letter first,
// so the common ones cost one comparison.
class OpParser {
 public:
  OpParser(const Tokens& t, const Header& h, Op& op, std::string& error)
      : t_(t), h_(h), op_(op), error_(error) {}

  bool parse() {
    std::string_view name = t_.word(0);
    switch (name.empty() ? ' ' : name[0]) {
      case 'k':
        if (name == "knit") return stitch(OpCode::knit, "knit D N CS");
        break;
      case 't':
        if (name == "tuck") return stitch(OpCode::tuck, "tuck D N CS");
        break;
      case 'm':
        if (name == "miss") return stitch(OpCode::miss, "miss D N CS");
        break;
      case 'x':
        if (name == "xfer")
          return words(3, "xfer N N2 (no carriers: split moves with yarn)") &&
                 needle(1, op_.a, "xfer N N2") && needle(2, op_.b, "xfer N N2") &&
                 set(OpCode::xfer);
        if (name.starts_with("x-")) return extension(name);
        break;
      case 'd':
        if (name == "drop") return words(2, kDrop) && needle(1, op_.a, kDrop) && set(OpCode::drop);
        break;
      case 'a':
        if (name == "amiss")
          return words(2, "amiss N") && needle(1, op_.a, "amiss N") && set(OpCode::amiss);
        break;
      case 'r':
        if (name == "rack") return words(2, "rack R") && rack();
        if (name == "releasehook") return yarn(OpCode::releasehook, name);
        break;
      case 's':
        if (name == "split") return split();
        if (name == "stitch") return stitch_size();
        break;
      case 'i':
        if (name == "in") return yarn(OpCode::in, name);
        if (name == "inhook") return yarn(OpCode::inhook, name);
        break;
      case 'o':
        if (name == "out") return yarn(OpCode::out, name);
        if (name == "outhook") return yarn(OpCode::outhook, name);
        break;
      case 'p':
        if (name == "pause") return words(1, "pause") && set(OpCode::pause);
        break;
    }
    return fail(
        fmt::format("unknown operation '{}'; expected in, inhook, releasehook, out, outhook, "
                    "knit, tuck, split, miss, drop, amiss, xfer, rack, stitch, pause or x-...",
                    name));
  }

 private:
  static constexpr const char* kDrop = "drop N (no carriers: knit drops with yarn)";

  bool fail(std::string why) {
    error_ = std::move(why);
    return false;
  }
  bool set(OpCode code) {
    op_.code = code;
    return true;
  }
  bool words(int n, const char* form) {
    return t_.count == n || fail(fmt::format("expected '{}'", form));
  }
  bool at_least(int n, const char* form) {
    return t_.count >= n || fail(fmt::format("expected '{}'", form));
  }
  bool needle(int i, Needle& n, const char* form) {
    return parse_needle(t_.word(i), n) ||
           fail(fmt::format("expected '{}': '{}' is not a needle such as f12 or bs3", form,
                            t_.word(i)));
  }
  bool direction(const char* form) {
    return parse_direction(t_.word(1), op_.dir) ||
           fail(fmt::format("expected '{}': the direction must be + or -, found '{}'", form,
                            t_.word(1)));
  }
  bool carriers(int first) { return parse_carriers(t_, first, h_, op_.carriers, error_); }

  bool stitch(OpCode code, const char* form) {
    op_.code = code;
    return at_least(3, form) && direction(form) && needle(2, op_.a, form) && carriers(3);
  }
  bool split() {
    op_.code = OpCode::split;
    const char* form = "split D N N2 CS";
    return at_least(4, form) && direction(form) && needle(2, op_.a, form) &&
           needle(3, op_.b, form) && carriers(4);
  }
  bool yarn(OpCode code, std::string_view name) {
    op_.code = code;
    if (!carriers(1)) return false;
    return op_.carriers != 0 ||
           fail(fmt::format("expected '{} CS' with at least one carrier", name));
  }
  bool rack() {
    op_.code = OpCode::rack;
    return parse_rack(t_.word(1), op_.rack_quarters) ||
           fail(fmt::format("expected 'rack R': '{}' is not a racking such as -2, 1 or 0.25",
                            t_.word(1)));
  }
  bool stitch_size() {
    op_.code = OpCode::stitch;
    std::int32_t l = 0, s = 0;
    return (t_.count == 3 && parse_int(t_.word(1), l) && parse_int(t_.word(2), s)) ||
           fail("expected 'stitch L T' with two whole numbers");
  }
  bool extension(std::string_view name) {
    op_.code = OpCode::extension;
    if (name != "x-stitch-number" && name != "x-speed-number") return true;
    std::int32_t v = 0;
    return (t_.count == 2 && parse_int(t_.word(1), v) && v >= 0) ||
           fail(fmt::format("expected '{} K' with a whole number K >= 0", name));
  }

  const Tokens& t_;
  const Header& h_;
  Op& op_;
  std::string& error_;
};

}  // namespace

bool parse_op(std::string_view line, const Header& h, Op& op, std::string& error) {
  Tokens t = tokenize(line);
  if (t.count == 0) return false;
  if (t.too_many) {
    error = "expected at most 8 words on an operation line";
    return false;
  }
  op = Op{};
  return OpParser(t, h, op, error).parse();
}

namespace {

// Reads the plain lines parse_plain_op takes, each word in place; every test fails safe (false)
// at the end of the window it may look in.
class PlainScan {
 public:
  PlainScan(std::string_view text, std::size_t pos)
      : p_(text.data() + pos), end_(p_ + std::min<std::size_t>(32, text.size() - pos)) {}
  bool word(std::string_view w) {  // `w` and one space
    if (static_cast<std::size_t>(end_ - p_) <= w.size() || std::string_view(p_, w.size()) != w ||
        p_[w.size()] != ' ')
      return false;
    p_ += w.size() + 1;
    return true;
  }
  bool number(std::int32_t& value) {  // 1 to 9 digits
    const char* first = p_;
    std::int32_t v = 0;
    while (p_ < end_ && p_ - first < 9 && is_digit(*p_)) v = v * 10 + (*p_++ - '0');
    value = v;
    return p_ > first && p_ < end_ && !is_digit(*p_);
  }
  bool needle(Needle& n) {  // on f or b, not a slider
    if (p_ >= end_ || (*p_ != 'f' && *p_ != 'b')) return false;
    n.bed = *p_++ == 'f' ? Bed::f : Bed::b;
    return number(n.index);
  }
  bool direction(Direction& d) {
    if (end_ - p_ < 2 || (*p_ != '+' && *p_ != '-') || p_[1] != ' ') return false;
    d = *p_ == '+' ? Direction::plus : Direction::minus;
    p_ += 2;
    return true;
  }
  bool then(char c) { return p_ < end_ && *p_++ == c; }
  const char* at() const { return p_; }

 private:
  const char* p_;
  const char* end_;
};

}  // namespace

bool parse_plain_op(std::string_view text, std::size_t pos, const Header& h, Op& op,
                    std::size_t& next) {
  PlainScan scan(text, pos);
  Op read;
  if (scan.word("xfer")) {
    if (!scan.needle(read.a) || !scan.then(' ') || !scan.needle(read.b) || !scan.then('\n'))
      return false;
    read.code = OpCode::xfer;
  } else {
    read.code = scan.word("knit") ? OpCode::knit : scan.word("tuck") ? OpCode::tuck : OpCode::pause;
    std::int32_t carrier = 0;
    if (read.code == OpCode::pause || !h.numbered || !scan.direction(read.dir) ||
        !scan.needle(read.a) || !scan.then(' ') || !scan.number(carrier) || !scan.then('\n') ||
        carrier < 1 || static_cast<std::size_t>(carrier) > h.carriers.size())
      return false;
    read.carriers = CarrierMask{1} << (carrier - 1);
  }
  op = read;
  next = static_cast<std::size_t>(scan.at() - text.data());
  return true;
}

std::string carrier_names(const Header& h, CarrierMask mask) {
  std::string out;
  for (std::size_t c = 0; c < h.carriers.size(); ++c)
    if (mask & (CarrierMask{1} << c)) out += (out.empty() ? "" : " ") + h.carriers[c];
  return out;
}

}  // namespace skein::knitout
