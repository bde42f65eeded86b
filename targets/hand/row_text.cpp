#include "hand/row_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <vector>

namespace skein::hand {
namespace {

constexpr std::uint32_t kLongestUnit = 24;   // tokens in one repeated unit
constexpr std::uint32_t kShortRun = 4;       // shorter plain runs keep their count
constexpr std::uint32_t kCountableRest = 8;  // "to last N sts" only while N is easy to see

// A run of one plain stitch ("k12"), or one other operation.
struct Token {
  HandOp op;
  std::uint32_t count;
  bool operator==(const Token&) const = default;
  std::uint32_t takes() const { return info(op).takes * count; }
};

std::vector<Token> tokens_of(std::span<const HandOp> ops) {
  std::vector<Token> tokens;
  for (HandOp op : ops) {
    if (is_plain(op) && !tokens.empty() && tokens.back().op == op)
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
  std::uint32_t takes = 0;              // loops it takes in all
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
    best.takes *= best.count;
    items.push_back(best);
    i += best_cover;
  }
  return items;
}

std::string token_text(const Token& t) {
  std::string_view abbr = info(t.op).abbreviation;
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
std::string until_text(std::uint32_t rest, bool marker) {
  if (marker) return rest == 0 ? "to m" : fmt::format("to {} before m", sts(rest));
  return rest == 0 ? "to end" : fmt::format("to last {}", sts(rest));
}

// Gives the "until" form to the one repeat of a stretch, or else to its last long plain run,
// when what follows it is short enough to count at a glance.
void choose_until(std::vector<Item>& items, const std::vector<Token>& t) {
  std::uint32_t rest = 0;
  auto repeats =
      std::count_if(items.begin(), items.end(), [](const Item& i) { return i.repeat(); });
  for (auto it = items.rbegin(); it != items.rend() && rest <= kCountableRest; ++it) {
    if (it->repeat()) {
      it->until = repeats == 1;
      return;
    }
    if (repeats == 0 && is_plain(t[it->begin].op) && t[it->begin].count >= kShortRun) {
      it->until = true;
      return;
    }
    rest += it->takes;
  }
}

std::string stretch_text(std::span<const HandOp> ops, bool before_marker, Dialect dialect) {
  std::vector<Token> tokens = tokens_of(ops);
  std::vector<Item> items = items_of(tokens);
  choose_until(items, tokens);
  std::string out;
  std::uint32_t rest = 0;
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

std::string row_instructions(std::span<const HandOp> ops, Dialect dialect) {
  if (!ops.empty() &&
      std::all_of(ops.begin(), ops.end(), [](HandOp op) { return op == HandOp::bo; }))
    return "BO all sts";
  if (!ops.empty() && is_plain(ops[0]) &&
      std::all_of(ops.begin(), ops.end(), [&](HandOp op) { return op == ops[0]; }))
    return ops[0] == HandOp::k ? "Knit" : "Purl";
  // Stretches end at the markers met on the left needle: their runs and repeats go "to m".
  std::string out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= ops.size(); ++i) {
    bool boundary = i == ops.size() || ops[i] == HandOp::sm || ops[i] == HandOp::rm;
    if (!boundary) continue;
    std::string stretch = stretch_text(ops.subspan(start, i - start), i < ops.size(), dialect);
    if (!stretch.empty()) out += (out.empty() ? "" : ", ") + stretch;
    if (i < ops.size()) out += (out.empty() ? "" : ", ") + std::string(info(ops[i]).abbreviation);
    start = i + 1;
  }
  capitalise(out);
  return out;
}

}  // namespace skein::hand
