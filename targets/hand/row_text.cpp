#include "hand/row_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <vector>

namespace skein::hand {
namespace {

constexpr std::uint32_t kLongestUnit = 24;  // tokens in one repeated unit
constexpr std::uint32_t kShortRun = 4;      // shorter plain runs keep their count
constexpr std::int32_t kCountableRest = 8;  // "to last N sts" only while N is easy to see

bool puts_on_left_needle(HandOp op) {
  return op == HandOp::from_spare || op == HandOp::from_spare_behind ||
         op == HandOp::from_second_spare || op == HandOp::from_second_spare_behind ||
         op == HandOp::slip_back;
}

// A run of one plain stitch ("k12") or of bind-offs ("BO 8 sts"), or one other operation.
struct Token {
  HandOp op;
  std::uint32_t count;
  bool operator==(const Token&) const = default;
  // Loops taken off the left needle, less the st a slip onto it puts there first (from a
  // spare needle, or back from the right needle): "sl1 from spare, ssk" takes one st of its own.
  std::int32_t takes() const {
    return (info(op).takes - static_cast<std::int32_t>(puts_on_left_needle(op))) *
           static_cast<std::int32_t>(count);
  }
};

std::vector<Token> tokens_of(std::span<const HandOp> ops) {
  std::vector<Token> tokens;
  for (HandOp op : ops) {
    bool runs = is_plain(op) || op == HandOp::bo || is_cast_on_in_row(op) || op == HandOp::tnbo;
    if (runs && !tokens.empty() && tokens.back().op == op)
      ++tokens.back().count;
    else
      tokens.push_back({op, 1});
  }
  return tokens;
}

// What a row is made of after compression: one token, or a unit of tokens worked several
// times.
struct Item {
  std::uint32_t begin = 0, length = 1;  // tokens
  std::uint32_t count = 1;              // times the unit is worked
  std::int32_t takes = 0;               // loops it takes in all (less those slipped there)
  bool until = false;  // written as "to end" / "to last N sts" / "to m" instead of a count
  bool repeat() const { return count > 1; }
};

// Greedy left to right: at each token the unit whose repeats cover the most tokens; a single
// token when nothing repeats.
std::vector<Item> items_of(const std::vector<Token>& t) {
  std::vector<Item> items;
  const auto n = static_cast<std::uint32_t>(t.size());
  for (std::uint32_t i = 0; i < n;) {
    Item best{i, 1, 1};
    std::uint32_t best_cover = 1;
    for (std::uint32_t len = 1; len <= kLongestUnit && i + 2 * len <= n; ++len) {
      // The unit repeats as far as each token equals the one a unit before it.
      std::uint32_t j = i + len;
      while (j < n && t[j] == t[j - len]) ++j;
      std::uint32_t span = j - i;
      if (span < 2 * len || span <= best_cover) continue;  // no repeat, or no better
      std::uint32_t count = span / len;
      if (count * len > best_cover) {
        best = {i, len, count};
        best_cover = count * len;
      }
    }
    for (std::uint32_t k = 0; k < best.length; ++k) best.takes += t[i + k].takes();
    best.takes *= static_cast<std::int32_t>(best.count);
    items.push_back(best);
    i += best_cover;
  }
  return items;
}

std::string token_text(const Token& t) {
  std::string_view abbr = info(t.op).abbreviation;
  if (t.op == HandOp::bo || t.op == HandOp::tnbo)
    return fmt::format("{} {} st{}", abbr, t.count, t.count == 1 ? "" : "s");
  if (is_cast_on_in_row(t.op))
    return fmt::format("CO {} st{} with a {} cast-on", t.count, t.count == 1 ? "" : "s",
                       t.op == HandOp::co ? "backward-loop" : "provisional");
  return is_plain(t.op) ? fmt::format("{}{}", abbr, t.count) : std::string(abbr);
}

std::string unit_text(const std::vector<Token>& t, const Item& item) {
  std::string out;
  for (std::uint32_t k = item.begin; k < item.begin + item.length; ++k)
    out += (out.empty() ? "" : ", ") + token_text(t[k]);
  return out;
}

std::string sts(std::uint32_t n) {
  return n == 1 ? "st" : fmt::format("{} sts", n);
}

// Where an "until" item stops: the end of the row or the next marker, `rest` sts before it.
std::string until_text(std::int32_t rest, bool marker) {
  if (marker)
    return rest == 0 ? "to m" : fmt::format("to {} st{} before m", rest, rest == 1 ? "" : "s");
  return rest == 0 ? "to end" : fmt::format("to last {}", sts(static_cast<std::uint32_t>(rest)));
}

// Gives the "until" form to the one repeat of a stretch, or else to its last long plain run,
// when what follows it is short enough to count at a glance.
void choose_until(std::vector<Item>& items, const std::vector<Token>& t, std::uint32_t short_run) {
  std::int32_t rest = 0;
  auto repeats =
      std::count_if(items.begin(), items.end(), [](const Item& i) { return i.repeat(); });
  for (auto it = items.rbegin(); it != items.rend() && rest <= kCountableRest; ++it) {
    if (it->repeat()) {
      it->until = repeats == 1;
      return;
    }
    if (repeats == 0 && is_plain(t[it->begin].op) && t[it->begin].count >= short_run) {
      it->until = true;
      return;
    }
    rest += it->takes;
  }
}

// Before a marker every run goes "to m": rows shaped between markers then read the same
// whatever the width ("k to 2 sts before m, ssk"). A short row turns before the end of the
// needle, so its last stretch keeps its counts.
std::string stretch_text(std::span<const HandOp> ops, bool before_marker, Dialect dialect) {
  std::vector<Token> tokens = tokens_of(ops);
  std::vector<Item> items = items_of(tokens);
  bool turns = !ops.empty() && ends_row(ops.back());
  if (before_marker || !turns) choose_until(items, tokens, before_marker ? 1 : kShortRun);
  std::string out;
  std::int32_t rest = 0;
  for (const Item& item : items) rest += item.takes;
  for (const Item& item : items) {
    rest -= item.takes;
    if (!out.empty()) out += ", ";
    const Token& first = tokens[item.begin];
    if (!item.repeat()) {
      out += item.until ? fmt::format("{} {}", info(first.op).abbreviation,
                                      until_text(rest, before_marker))
                        : token_text(first);
    } else if (!item.until) {
      out += fmt::format("[{}] {} times", unit_text(tokens, item), item.count);
    } else if (dialect == Dialect::knitspeak && rest == 0 && !before_marker) {
      out += fmt::format("*{}, repeat from *", unit_text(tokens, item));
    } else {
      out += fmt::format("*{}{} {}", unit_text(tokens, item),
                         dialect == Dialect::knitspeak ? ", repeat from *" : "; rep from *",
                         until_text(rest, before_marker));
    }
  }
  return out;
}

void capitalise(std::string& text) {
  std::size_t i = text.find_first_not_of("*[");
  if (i != std::string::npos)
    text[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[i])));
}

}  // namespace

std::optional<RowRepeat> whole_row_repeat(std::span<const HandOp> ops) {
  // The shortest period from the prefix function (Knuth-Morris-Pratt): linear.
  const std::size_t n = ops.size();
  if (n < 2) return std::nullopt;
  std::vector<std::uint32_t> border(n, 0);
  for (std::size_t i = 1; i < n; ++i) {
    std::uint32_t b = border[i - 1];
    while (b > 0 && ops[i] != ops[b]) b = border[b - 1];
    border[i] = b + (ops[i] == ops[b] ? 1 : 0);
  }
  std::size_t period = n - border[n - 1];
  if (period == n || n % period != 0) return std::nullopt;
  return RowRepeat{static_cast<std::uint32_t>(period), static_cast<std::uint32_t>(n / period)};
}

std::string row_instructions(std::span<const HandOp> ops, Dialect dialect, bool end_is_marker) {
  auto is = [&](HandOp want) { return [want](HandOp op) { return op == want; }; };
  if (!ops.empty() && std::all_of(ops.begin(), ops.end(), is(HandOp::bo))) return "BO all sts";
  // Plain rows slip the markers they meet.
  auto plain = std::find_if_not(ops.begin(), ops.end(), is(HandOp::sm));
  if (plain != ops.end() && is_plain(*plain) && std::all_of(ops.begin(), ops.end(), [&](HandOp op) {
        return op == *plain || op == HandOp::sm;
      }))
    return *plain == HandOp::k ? "Knit" : "Purl";
  // Stretches end at the markers met on the left needle: their runs and repeats go "to m". In
  // the round the beginning-of-round marker ends the last one.
  std::vector<std::string> stretches;
  std::vector<HandOp> markers;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= ops.size(); ++i) {
    if (i < ops.size() && ops[i] != HandOp::sm && ops[i] != HandOp::rm) continue;
    bool marker = i < ops.size() || (end_is_marker && !markers.empty());
    stretches.push_back(stretch_text(ops.subspan(start, i - start), marker, dialect));
    if (i < ops.size()) markers.push_back(ops[i]);
    start = i + 1;
  }
  std::string out;
  // A stretch with a repeat of its own keeps the star: the sections then repeat in brackets.
  if (end_is_marker && !markers.empty() && !stretches[0].empty() &&
      stretches[0].find('*') == std::string::npos &&
      std::all_of(markers.begin(), markers.end(), is(HandOp::sm)) &&
      std::all_of(stretches.begin(), stretches.end(),
                  [&](const std::string& s) { return s == stretches[0]; })) {
    out = fmt::format("*{}, sm{}", stretches[0],
                      dialect == Dialect::knitspeak ? ", repeat from *" : "; rep from * to end");
  } else {
    // Equal sections in a row read "[K to 3 sts before m, s2kp, sm] 2 times".
    for (std::size_t k = 0; k < stretches.size();) {
      std::size_t same = 1;
      while (k + same < markers.size() && markers[k] == HandOp::sm &&
             markers[k + same] == HandOp::sm && !stretches[k].empty() &&
             stretches[k + same] == stretches[k])
        ++same;
      std::string part = stretches[k];
      if (k < markers.size())
        part += (part.empty() ? "" : ", ") + std::string(info(markers[k]).abbreviation);
      if (same > 1) part = fmt::format("[{}] {} times", part, same);
      if (!part.empty()) out += (out.empty() ? "" : ", ") + part;
      k += same;
    }
  }
  capitalise(out);
  return out;
}

}  // namespace skein::hand
