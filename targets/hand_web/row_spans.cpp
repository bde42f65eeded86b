#include "hand_web/row_spans.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string>

namespace skein::hand_web {
namespace {

using hand::HandOp;

// A piece of the row's text: one token ("k8", "k to m", "ssk") or a repeat ("*...; rep from *
// to end", "[...] 3 times") of the pieces inside it.
struct Piece {
  bool repeat = false;
  HandOp op = HandOp::k;
  std::uint32_t times = 1;  // a token's count ("k8"), a repeat's ("[...] 3 times")
  bool until = false;       // "k to m", "*...; rep from * to end": as often as the ops say
  std::uint32_t begin = 0, end = 0;
  std::vector<Piece> inside;
};

constexpr std::string_view kRepFrom = "; rep from * ";

// The first `what` at bracket depth 0 in text[from, to), or npos.
std::size_t find_outside_brackets(std::string_view text, std::string_view what, std::size_t from,
                                  std::size_t to) {
  int depth = 0;
  for (std::size_t i = from; i + what.size() <= to; ++i) {
    if (text[i] == '[') ++depth;
    if (text[i] == ']') --depth;
    if (depth == 0 && text.substr(i, what.size()) == what) return i;
  }
  return std::string_view::npos;
}

std::optional<std::uint32_t> number_at(std::string_view s) {
  std::uint32_t n = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
  if (ec != std::errc{} || n == 0) return std::nullopt;
  return n;
}

// "k8", "ssk", "k to 2 sts before m", "BO 8 sts", "CO 7 sts with a provisional cast-on"
// (or "a backward-loop cast-on").
std::optional<Piece> read_token(std::string_view s, std::uint32_t at) {
  Piece p;
  p.begin = at;
  p.end = at + static_cast<std::uint32_t>(s.size());
  if (auto op = hand::hand_op_from(s)) {
    p.op = *op;
    return p;
  }
  if (std::size_t to = s.find(" to "); to != std::string_view::npos) {
    auto op = hand::hand_op_from(s.substr(0, to));
    if (!op) return std::nullopt;
    p.op = *op;
    p.until = true;
    return p;
  }
  // "BO 8 sts", "3-needle BO 1 st", "CO 7 sts with a provisional cast-on".
  if (std::size_t st = s.find(" st"); st != std::string_view::npos) {
    std::size_t space = s.rfind(' ', st - 1);
    if (space == std::string_view::npos) return std::nullopt;
    auto count = number_at(s.substr(space + 1, st - space - 1));
    std::string_view word = s.substr(0, space);
    bool backward_loop = s.find("backward-loop") != std::string_view::npos;
    auto op = word != "CO"    ? hand::hand_op_from(word)
              : backward_loop ? std::optional(HandOp::co)
                              : std::optional(HandOp::provisional_co);
    if (!count || !op) return std::nullopt;
    p.op = *op;
    p.times = *count;
    return p;
  }
  // "k12": a plain run.
  std::size_t digits = s.find_last_not_of("0123456789") + 1;
  if (digits == 0 || digits == s.size()) return std::nullopt;
  auto op = hand::hand_op_from(s.substr(0, digits));
  auto count = number_at(s.substr(digits));
  if (!op || !count) return std::nullopt;
  p.op = *op;
  p.times = *count;
  return p;
}

std::optional<std::vector<Piece>> read_pieces(std::string_view text, std::size_t from,
                                              std::size_t to);

// "*UNIT; rep from * to end" from `from` (at the star): the repeat and where it ends.
std::optional<Piece> read_star(std::string_view text, std::size_t from, std::size_t to) {
  std::size_t rep = find_outside_brackets(text, kRepFrom, from, to);
  if (rep == std::string_view::npos) return std::nullopt;
  auto unit = read_pieces(text, from + 1, rep);
  if (!unit) return std::nullopt;
  std::size_t end = find_outside_brackets(text, ", ", rep + kRepFrom.size(), to);
  Piece p;
  p.repeat = p.until = true;
  p.begin = static_cast<std::uint32_t>(from);
  p.end = static_cast<std::uint32_t>(std::min(end, to));
  p.inside = std::move(*unit);
  return p;
}

// "[UNIT] 3 times" from `from` (at the bracket).
std::optional<Piece> read_bracket(std::string_view text, std::size_t from, std::size_t to) {
  int depth = 0;
  std::size_t close = from;
  for (; close < to; ++close) {
    depth += text[close] == '[' ? 1 : text[close] == ']' ? -1 : 0;
    if (depth == 0) break;
  }
  constexpr std::string_view kTimes = " times";
  std::size_t times = text.find(kTimes, close);
  if (close >= to || times == std::string_view::npos || times + kTimes.size() > to)
    return std::nullopt;
  auto count = number_at(text.substr(close + 2, times - close - 2));
  auto unit = read_pieces(text, from + 1, close);
  if (!count || !unit || text[close + 1] != ' ') return std::nullopt;
  Piece p;
  p.repeat = true;
  p.times = *count;
  p.begin = static_cast<std::uint32_t>(from);
  p.end = static_cast<std::uint32_t>(times + kTimes.size());
  p.inside = std::move(*unit);
  return p;
}

std::optional<std::vector<Piece>> read_pieces(std::string_view text, std::size_t from,
                                              std::size_t to) {
  std::vector<Piece> pieces;
  for (std::size_t i = from; i < to;) {
    std::optional<Piece> p;
    if (text[i] == '*') {
      p = read_star(text, i, to);
    } else if (text[i] == '[') {
      p = read_bracket(text, i, to);
    } else {
      std::size_t end = std::min(find_outside_brackets(text, ", ", i, to), to);
      p = read_token(text.substr(i, end - i), static_cast<std::uint32_t>(i));
    }
    if (!p) return std::nullopt;
    i = p->end;
    pieces.push_back(std::move(*p));
    if (i == to) break;
    if (text.substr(i, 2) != ", ") return std::nullopt;
    i += 2;
  }
  return pieces;
}

// Reads the pieces against the operations, left to right: a token takes its operation `times`
// times (an "until" token as long as the operations go on with it), a repeat its unit as often
// as it says (an "until" repeat as long as the whole unit matches).
class Matcher {
 public:
  Matcher(std::span<const HandOp> ops) : ops_(ops), spans_(ops.size()) {}

  bool all(const std::vector<Piece>& pieces) {
    std::vector<std::uint32_t> own;
    return sequence(pieces, own) && at_ == ops_.size();
  }
  std::vector<OpSpan> spans() && { return std::move(spans_); }

 private:
  // `own`: the operations matched here outside any inner repeat (their repeat is the caller's).
  bool sequence(const std::vector<Piece>& pieces, std::vector<std::uint32_t>& own) {
    for (const Piece& p : pieces)
      if (!(p.repeat ? repeat(p) : token(p, own))) return false;
    return true;
  }

  bool token(const Piece& p, std::vector<std::uint32_t>& own) {
    // The beginning-of-round marker ends the row: "*..., sm; rep from * to end" slips it
    // only in the text, not in the operations.
    if (p.op == HandOp::sm && at_ == ops_.size()) return true;
    std::uint32_t n = 0;
    for (; at_ < ops_.size() && ops_[at_] == p.op && (p.until || n < p.times); ++n, ++at_) {
      spans_[at_] = {p.begin, p.end, 0, 0};
      own.push_back(static_cast<std::uint32_t>(at_));
    }
    return p.until || n == p.times;
  }

  bool repeat(const Piece& p) {
    std::uint32_t times = 0;
    std::vector<std::uint32_t> own, round;
    while (p.until || times < p.times) {
      std::size_t start = at_;
      round.clear();
      if (!sequence(p.inside, round) || at_ == start) {
        at_ = start;
        if (!p.until) return false;
        break;
      }
      ++times;
      for (std::uint32_t op : round) spans_[op].repeat = times;
      own.insert(own.end(), round.begin(), round.end());
    }
    for (std::uint32_t op : own) spans_[op].repeats = times;
    return times > 0;
  }

  std::span<const HandOp> ops_;
  std::size_t at_ = 0;
  std::vector<OpSpan> spans_;
};

bool whole_row_word(std::string_view text) {
  return text == "Knit" || text == "Purl" || text.starts_with("BO all sts");
}

}  // namespace

std::optional<std::vector<OpSpan>> op_spans(std::string_view text, std::span<const HandOp> ops) {
  if (whole_row_word(text))
    return std::vector<OpSpan>(ops.size(), {0, static_cast<std::uint32_t>(text.size()), 0, 0});
  auto pieces = read_pieces(text, 0, text.size());
  if (!pieces) return std::nullopt;
  Matcher m(ops);
  if (!m.all(*pieces)) return std::nullopt;
  return std::move(m).spans();
}

}  // namespace skein::hand_web
