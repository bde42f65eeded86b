#include "hand/pattern_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <numeric>

#include "common/error.hpp"
#include "hand/pattern_document.hpp"

namespace skein::hand {
namespace {

constexpr std::string_view kEmDash = "\u2014";
constexpr std::string_view kEnDash = "\u2013";

char lower(char ch) {
  return ch >= 'A' && ch <= 'Z' ? static_cast<char>(ch - 'A' + 'a') : ch;
}
bool is_word_char(char ch) {
  return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9');
}
bool is_space(char ch) {
  return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n';
}

bool starts_with_ci(std::string_view s, std::string_view prefix) {
  if (s.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i)
    if (lower(s[i]) != lower(prefix[i])) return false;
  return true;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::optional<std::uint32_t> number_word(std::string_view word) {
  constexpr std::array<std::string_view, 21> kWords = {
      "zero",     "one",     "two",     "three",     "four",     "five",     "six",
      "seven",    "eight",   "nine",    "ten",       "eleven",   "twelve",   "thirteen",
      "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen", "twenty"};
  for (std::size_t i = 0; i < kWords.size(); ++i)
    if (word.size() == kWords[i].size() && starts_with_ci(word, kWords[i]))
      return static_cast<std::uint32_t>(i);
  if (word.size() == 4 && starts_with_ci(word, "once")) return 1;
  if (word.size() == 5 && starts_with_ci(word, "twice")) return 2;
  return std::nullopt;
}

// A position in one sentence, with the small vocabulary of pattern text.
class Cursor {
 public:
  explicit Cursor(std::string_view text) : s_(text) {}

  bool done() {
    spaces();
    return i_ >= s_.size();
  }
  char peek() {
    spaces();
    return i_ < s_.size() ? s_[i_] : '\0';
  }
  bool eat_char(char ch) {
    if (peek() != ch) return false;
    ++i_;
    return true;
  }
  // A whole word or symbol, case-insensitive: "to" matches in "to end" but not in "tog".
  bool eat(std::string_view word) {
    spaces();
    if (!starts_with_ci(s_.substr(i_), word)) return false;
    std::size_t end = i_ + word.size();
    if (end < s_.size() && is_word_char(s_[end]) && is_word_char(word.back())) return false;
    i_ = end;
    return true;
  }
  bool eat_any(std::initializer_list<std::string_view> words) {
    for (std::string_view w : words)
      if (eat(w)) return true;
    return false;
  }
  std::string_view word() {
    spaces();
    std::size_t start = i_;
    while (i_ < s_.size() && is_word_char(s_[i_])) ++i_;
    return s_.substr(start, i_ - start);
  }
  // Digits or a number word ("five", "twice").
  std::optional<std::uint32_t> number() {
    std::size_t start = (spaces(), i_);
    std::string_view w = word();
    std::uint32_t value = 0;
    auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
    if (!w.empty() && ec == std::errc() && end == w.data() + w.size()) return value;
    if (auto n = number_word(w)) return n;
    i_ = start;
    return std::nullopt;
  }
  std::string_view rest() {
    spaces();
    return s_.substr(i_);
  }

 private:
  void spaces() {
    while (i_ < s_.size() && is_space(s_[i_])) ++i_;
  }
  std::string_view s_;
  std::size_t i_ = 0;
};

class SentenceReader {
 public:
  SentenceReader(Script& script, const std::string& file, std::size_t line_no,
                 std::string_view line)
      : script_(script), file_(file), line_no_(line_no), line_(line) {}

  void read(std::string_view sentence) {
    Cursor c(sentence);
    if (starts_with_ci(sentence, "row") || starts_with_ci(sentence, "rnd") ||
        starts_with_ci(sentence, "round"))
      return row(c);
    if (c.eat_any({"rep", "repeat"})) return repeat(c);
    if (c.eat_any({"knit", "purl"})) return work_even(sentence, c);
    if (starts_with_ci(sentence, "join a new yarn to")) {
      Cursor rest(sentence.substr(18));
      return join_spare(rest);
    }
    // "Place ... the first st cast on first" is no cast-on.
    if (c.eat("place")) return place(c);
    if (c.eat("slip")) return hold(c);
    if (c.eat("put")) return to_spare(c);
    if (std::size_t at = find_ci(sentence, "cast on"); at != std::string_view::npos)
      return cast_on(Cursor(sentence.substr(at + 7)));
    if (c.eat("co")) return cast_on(c);
    if (mentions(sentence, "join") && (mentions(sentence, "rnd") || mentions(sentence, "round"))) {
      Step step{Step::Kind::join_round, line_no_};
      step.round = true;
      step.marker = starts_with_ci(sentence, "pm");
      return add(step);
    }
    if (starts_with_ci(sentence, "do not fasten off")) {
      Cursor rest(sentence.substr(17));
      return carry_on(rest);
    }
    if (mentions(sentence, "fasten off")) return add({Step::Kind::fasten_off, line_no_});
    // A piece whose sts all went to holders ends with no st to fasten off.
    if (starts_with_ci(sentence, "cut the yarn")) return add({Step::Kind::fasten_off, line_no_});
    if (c.eat("leave")) return leave(c);
    if (c.eat("take") && c.eat("up")) return take_up(c);
    if (c.eat("pick") && c.eat("up")) return pick_up(c);
    if (c.eat("three-needle") && c.eat("bind-off")) return three_needle_bind_off(c);
    if (c.eat("hold")) return hold_behind(c);
    if (c.eat("work") && c.eat("as")) return work_as(c);
    fail(
        "expected a row ('Row 3 (RS): ...', 'Rnd 5: ...'), 'Cast on N sts', 'Pm and join to "
        "work in the rnd', 'Rep Rows 3\u20134 N more times', 'Knit every rnd until N rnds in "
        "all', 'Leave the N sts on a spare needle', 'Three-needle bind-off: ...' or 'Fasten off'",
        sentence);
  }

 private:
  [[noreturn]] void fail(const std::string& expected, std::string_view found) const {
    throw ParseError(file_, line_no_, std::string(line_),
                     fmt::format("{}, found '{}'", expected, found));
  }

  static std::size_t find_ci(std::string_view s, std::string_view what) {
    for (std::size_t i = 0; i + what.size() <= s.size(); ++i)
      if (starts_with_ci(s.substr(i), what)) return i;
    return std::string_view::npos;
  }
  static bool mentions(std::string_view s, std::string_view what) {
    return find_ci(s, what) != std::string_view::npos;
  }

  void add(Step step) { script_.steps.push_back(step); }

  // A number, refused beyond kMaxPatternNumber: no garment needs more sts, rows or repeats,
  // and a simulator working them would run for minutes.
  std::optional<std::uint32_t> number(Cursor& c) {
    std::optional<std::uint32_t> n = c.number();
    if (n && *n > kMaxPatternNumber) too_big(*n);
    return n;
  }
  [[noreturn]] void too_big(std::uint64_t n) const {
    throw ParseError(file_, line_no_, std::string(line_),
                     fmt::format("expected a number of at most {} (docs/formats.md, \"Limits\"), "
                                 "found {}",
                                 kMaxPatternNumber, n));
  }

  std::uint32_t need_number(Cursor& c, const char* what) {
    if (auto n = number(c)) return *n;
    fail(fmt::format("expected {}", what), c.rest());
  }

  // "12 sts" (or "1 st"): the number, then the word.
  std::uint32_t need_sts(Cursor& c, const char* what) {
    std::uint32_t n = need_number(c, what);
    need(c.eat_any({"sts", "st"}), c, "'sts' after the number");
    return n;
  }

  void need(bool ok, Cursor& c, const char* expected) {
    if (!ok) fail(fmt::format("expected {}", expected), c.rest());
  }

  // "Cast on 12 sts", "Cast on 12 sts with a provisional cast-on".
  void cast_on(Cursor c) {
    Step step{Step::Kind::cast_on, line_no_};
    step.count = need_sts(c, "the number of sts to cast on");
    if (c.eat("with")) {
      need_words(c, {"a", "provisional", "cast-on"}, "'with a provisional cast-on'");
      step.provisional = true;
    }
    add(step);
  }

  // "Pick up 3 sts along the right edge of Piece 1, one in each row from Row 2 down to the
  // cast-on".
  void pick_up(Cursor& c) {
    Step step{Step::Kind::pick_up, line_no_};
    step.count = need_number(c, "the number of sts to pick up");
    need_words(c, {"sts", "along", "the"}, "'sts along the right (or left) edge'");
    step.provisional = c.eat("right");
    need(step.provisional || c.eat("left"), c, "'right' or 'left'");
    need_words(c, {"edge", "of"}, "'edge of Piece N' (or 'of the flap', 'of this piece')");
    if (c.eat("the")) {
      need(c.eat("flap"), c, "'the flap'");  // number 0: the piece on the needle
    } else if (c.eat("this")) {
      need(c.eat("piece"), c, "'this piece'");  // a flat piece joined in the rnd: the same
    } else {
      step.number = need_piece(c, "'Piece N' or a piece's name (or 'the flap')");
    }
    need_words(c, {",", "one", "in", "each", "row", "from"}, "', one in each row from'");
    step.from_row = row_of_piece(c);
    need(c.eat_any({"up", "down"}), c, "'up' or 'down'");
    need(c.eat("to"), c, "'to'");
    step.to_row = row_of_piece(c);
    if (c.eat_char(',')) {
      need_words(c, {"onto", "the", "needle"}, "', onto the needle'");
      step.into_rnd = true;
      step.last = where_on_the_needle(c, step);
    }
    end_with_count(c, step);
    add(step);
  }

  // The end of a sentence that may print the count on the needle after it: "— 36 sts".
  void end_with_count(Cursor& c, Step& step) {
    std::string_view rest = c.rest();
    step.sts = printed_count(rest);
    if (!trim(rest).empty()) fail("expected the end of the sentence", rest);
  }

  // "at the beginning of the rnd" (0) or "after the first 18 sts of the rnd" (step.round); on
  // a flat piece "after the first 7 sts of the row" (counted from the tip of the needle the
  // next row works).
  std::uint32_t where_on_the_needle(Cursor& c, Step& step) {
    std::uint32_t after = 0;
    if (c.eat("after")) {
      need_words(c, {"the", "first"}, "'after the first N sts'");
      after = need_number(c, "how many sts come before them");
      need(c.eat_any({"sts", "st"}), c, "'sts'");
    } else {
      need_words(c, {"at", "the", "beginning"}, "'at the beginning' or 'after the first N sts'");
    }
    need_words(c, {"of", "the"}, "'of the rnd' or 'of the row'");
    step.round = c.eat("rnd");
    need(step.round || c.eat("row"), c, "'of the rnd' or 'of the row'");
    return after;
  }

  // "Put the 10 sts (the 1 st) of holder 2 on a [second] spare needle, the first st of its last
  // rnd at the tip".
  void to_spare(Cursor& c) {
    Step step{Step::Kind::to_spare, line_no_};
    c.eat("the");
    step.count = need_number(c, "the number of sts");
    need(c.eat("sts") || (step.count == 1 && c.eat("st")), c, "'sts of holder N'");
    need_words(c, {"of", "holder"}, "'sts of holder N'");
    step.number = need_number(c, "a holder number");
    need(c.eat("on") && c.eat("a"), c, "'on a spare needle' or 'on a second spare needle'");
    step.last = c.eat("second") ? 1 : 0;
    need_words(c, {"spare", "needle", ",", "the"}, "'spare needle, the'");
    step.from_last[0] = c.eat("last");
    need(step.from_last[0] || c.eat("first"), c, "'first' or 'last'");
    need_words(c, {"st", "of", "its", "last"}, "'st of its last rnd'");
    need(c.eat_any({"rnd", "row"}), c, "'rnd' or 'row'");
    need_words(c, {"at", "the", "tip"}, "'at the tip'");
    need(c.done(), c, "the end of the sentence");
    add(step);
  }

  // "Work as Sleeve 1": the steps of that piece's first section again, for this piece.
  void work_as(Cursor& c) {
    std::uint32_t piece = need_piece(c, "'Work as Piece N' (or a piece's name)");
    auto is_heading = [](const Step& s) { return s.kind == Step::Kind::piece; };
    auto& steps = script_.steps;
    auto from = std::find_if(steps.begin(), steps.end(),
                             [&](const Step& s) { return is_heading(s) && s.number == piece; });
    auto current = std::find_if(steps.rbegin(), steps.rend(), is_heading);  // this piece's
    if (from == steps.end() || current == steps.rend() || from >= current.base() - 1)
      fail("'Work as' a piece written before this one",
           piece <= script_.piece_names.size() && !script_.piece_names[piece - 1].empty()
               ? script_.piece_names[piece - 1]
               : fmt::format("Piece {}", piece));
    auto to = std::find_if(from + 1, steps.end(), is_heading);
    std::vector<Step> again(from + 1, to);
    for (Step& s : again) s.line = line_no_;
    steps.insert(steps.end(), again.begin(), again.end());
  }

  // "Piece 2", or the name a heading gave the piece ("Thumb", "Leg 2"): its number.
  std::uint32_t need_piece(Cursor& c, const char* expected) {
    if (c.eat("piece")) return need_number(c, "a piece number");
    std::vector<std::uint32_t> longest_first(script_.piece_names.size());
    std::iota(longest_first.begin(), longest_first.end(), 0u);
    std::stable_sort(longest_first.begin(), longest_first.end(),
                     [&](std::uint32_t a, std::uint32_t b) {
                       return script_.piece_names[a].size() > script_.piece_names[b].size();
                     });
    for (std::uint32_t i : longest_first)
      if (!script_.piece_names[i].empty() && c.eat(script_.piece_names[i])) return i + 1;
    need(false, c, expected);
    return 0;
  }

  // "the cast-on" (0) or "Row 7".
  std::uint32_t row_of_piece(Cursor& c) {
    if (c.eat("the") && c.eat("cast-on")) return 0;
    need(c.eat("row"), c, "'the cast-on' or 'Row N'");
    return need_number(c, "a row number");
  }

  // "the 3 sts of Piece 1", "the 7 sts of holder 2", "the 1 st of holder 3" or "the 3 loops
  // of Piece 1's chain".
  void whose_sts(Cursor& c, Step& step, const char* count) {
    c.eat("the");
    step.count = need_number(c, count);
    step.provisional = c.eat("loops") || (step.count == 1 && c.eat("loop"));
    need(step.provisional || c.eat("sts") || (step.count == 1 && c.eat("st")), c,
         "'sts' or 'loops'");
    need(c.eat("of"), c, "'of Piece N' or 'of holder N'");
    step.holder[0] = !step.provisional && c.eat("holder");
    step.number = step.holder[0]
                      ? need_number(c, "a holder number")
                      : need_piece(c, "'of Piece N', of a piece's name or 'of holder N'");
    if (step.provisional) need_words(c, {"'", "s", "chain"}, "'s chain' after the piece");
  }

  // "Join a new yarn to the 3 sts of Piece 1 (or: the 3 loops of Piece 1's chain), the first
  // st cast on at the tip".
  void join_spare(Cursor& c) { add(sts_at_the_tip(c, {Step::Kind::join_spare, line_no_})); }

  // "Do not fasten off: carry the yarn to the 9 sts of holder 1, the first st slipped to it at
  // the tip".
  void carry_on(Cursor& c) {
    need_words(c, {":", "carry", "the", "yarn", "to"},
               "': carry the yarn to the N sts of holder N'");
    Step step = sts_at_the_tip(c, {Step::Kind::carry_on, line_no_});
    if (!step.holder[0]) fail("expected the sts of a holder", c.rest());
    add(step);
  }

  // "the 3 sts of Piece 1, the first st cast on at the tip" (or "the 13 sts of holder 1, the
  // first st of its last rnd (or: slipped to it) at the tip").
  Step sts_at_the_tip(Cursor& c, Step step) {
    whose_sts(c, step, "the number of sts");
    need_words(c, {",", "the"}, "', the first (or last) st cast on'");
    step.from_last[0] = c.eat("last");
    need(step.from_last[0] || c.eat("first"), c, "'first' or 'last'");
    need(c.eat("st"), c, "'st cast on at the tip' or 'st of its last rnd at the tip'");
    if (step.holder[0] && c.eat("slipped")) {
      need_words(c, {"to", "it"}, "'slipped to it'");
    } else if (step.holder[0]) {
      need_words(c, {"of", "its", "last"}, "'of its last rnd' or 'slipped to it'");
      need(c.eat_any({"rnd", "row"}), c, "'rnd' or 'row'");
    } else {
      need_words(c, {"cast", "on"}, "'st cast on at the tip'");
    }
    need_words(c, {"at", "the", "tip"}, "'at the tip'");
    // "; the rnd begins at its st 6": a holder's sts in the rnd, begun in their middle.
    if (step.holder[0] && c.eat(";")) {
      need_words(c, {"the", "rnd", "begins", "at", "its", "st"}, "'the rnd begins at its st N'");
      step.from_row = need_number(c, "the st of the holder the rnd begins at");
    }
    need(c.done(), c, "the end of the sentence");
    return step;
  }

  // "Leave the 16 sts on a spare needle and cut the yarn", "Leave the 96 sts on the needle and
  // set the yarn aside (do not cut it)".
  void leave(Cursor& c) {
    Step step{Step::Kind::leave, line_no_};
    c.eat("the");
    step.count = need_number(c, "the number of sts left on the needle");
    need(c.eat_any({"sts", "st"}) && c.eat("on"), c, "'sts on'");
    if (c.eat("the")) {
      step.kind = Step::Kind::set_aside;
      need_words(c, {"needle", "and", "set", "the", "yarn", "aside"},
                 "'the needle and set the yarn aside'");
      if (c.eat_char('(')) need_words(c, {"do", "not", "cut", "it", ")"}, "'(do not cut it)'");
    } else {
      need_words(c, {"a", "spare", "needle", "and", "cut", "the", "yarn"},
                 "'a spare needle and cut the yarn' or 'the needle and set the yarn aside'");
    }
    need(c.done(), c, "the end of the sentence");
    add(step);
  }

  // "Take up Piece 1 again with its yarn".
  void take_up(Cursor& c) {
    Step step{Step::Kind::take_up, line_no_};
    step.number = need_piece(c, "'Take up Piece N again' (or a piece's name)");
    need_words(c, {"again", "with", "its", "yarn"}, "'again with its yarn'");
    need(c.done(), c, "the end of the sentence");
    add(step);
  }

  // "Place the 58 sts of Piece 2 (or: the 9 loops of Piece 3's chain) on the needle at the
  // beginning of the rnd (or: after the first 106 sts of the rnd), the first st of its last
  // rnd (or: the first st cast on; st 16 of its last rnd) first".
  void place(Cursor& c) {
    Step step{Step::Kind::place, line_no_};
    whose_sts(c, step, "the number of sts to place");
    need_words(c, {"on", "the"}, "'on the needle'");
    if (step.holder[0] && c.eat("spare")) return place_on_spare_needle(c, step);
    need(c.eat("needle"), c, "'on the needle' or 'on the spare needle of Piece N'");
    step.last = where_on_the_needle(c, step);
    need(c.eat_char(','), c, "', the first (or last) st' or ', st N'");
    if (c.eat("st")) {
      step.from_row = need_number(c, "the st placed first");
      need_words(c, {"of", "its", "last"}, "'st N of its last rnd'");
      need(c.eat_any({"rnd", "row"}), c, "'rnd' or 'row'");
    } else {
      place_first_or_last(c, step);
    }
    need(c.eat("first"), c, "'first'");
    end_with_count(c, step);
    add(step);
  }

  // "... on the spare needle of Piece 4 after its st 13 (count round the needle from the first
  // st of its last row), the last st slipped first — 42 sts" (before a fold).
  void place_on_spare_needle(Cursor& c, Step& step) {
    step.kind = Step::Kind::place_on_spare;
    need_words(c, {"needle", "of"}, "'the spare needle of Piece N'");
    step.to_row = need_piece(c, "'the spare needle of Piece N' (or of a piece's name)");
    need_words(c, {"after", "its", "st"}, "'after its st N'");
    step.last = need_number(c, "the st the held sts go after");
    need(c.eat_char('('), c, "'(count round the needle from the first st of its last row)'");
    need_words(
        c, {"count", "round", "the", "needle", "from", "the", "first", "st", "of", "its", "last"},
        "'count round the needle from the first st of its last row'");
    need(c.eat_any({"rnd", "row"}) && c.eat_char(')') && c.eat_char(','), c, "'row),'");
    need(c.eat("the"), c, "'the first (or last) st slipped first'");
    step.from_last[0] = c.eat("last");
    need(step.from_last[0] || c.eat("first"), c, "'first' or 'last'");
    need_words(c, {"st", "slipped", "first"}, "'st slipped first'");
    end_with_count(c, step);
    add(step);
  }

  // "the first (or last) st of its last rnd" or "the first (or last) st cast on".
  void place_first_or_last(Cursor& c, Step& step) {
    need(c.eat("the"), c, "'the first (or last) st'");
    step.from_last[0] = c.eat("last");
    need(step.from_last[0] || c.eat("first"), c, "'first' or 'last'");
    need(c.eat("st"), c, "'st of its last rnd' or 'st cast on'");
    if (c.eat("cast")) {
      need(c.eat("on"), c, "'st cast on'");
    } else {
      need_words(c, {"of", "its", "last"}, "'st of its last rnd' or 'st cast on'");
      need(c.eat_any({"rnd", "row"}), c, "'rnd' or 'row'");
    }
  }

  // "Slip sts 10–18 of the rnd to holder 1, sts 19–27 to holder 2 and sts 28–36 to holder 3":
  // the sts are counted in the rnd as it is before any is slipped, so the last run goes first.
  void hold(Cursor& c) {
    if (c.eat("the")) return hold_all(c);
    std::vector<Step> runs;
    do {
      Step step{Step::Kind::hold, line_no_};
      bool one = c.eat("st");
      need(one || c.eat("sts"), c, "'sts A–B' or 'st A'");
      step.from_row = need_number(c, "the first st to hold");
      if (!one) need(c.eat(kEnDash) || c.eat("-"), c, "'–' between the first and the last st");
      step.to_row = one ? step.from_row : need_number(c, "the last st to hold");
      if (step.to_row < step.from_row) fail("expected the sts in increasing order", c.rest());
      if (runs.empty()) of_the_rnd_row_or_cast_on(c, step);
      step.of_row = runs.empty() ? step.of_row : runs.front().of_row;
      step.of_cast_on = runs.empty() ? step.of_cast_on : runs.front().of_cast_on;
      need_words(c, {"to", "holder"}, "'to holder N'");
      step.number = need_number(c, "a holder number");
      if (c.eat_char('(')) onto_held_sts(c, step);
      runs.push_back(step);
    } while (c.eat_char(',') || c.eat("and"));
    end_with_count(c, runs.front());  // checked once the last run (given first) is slipped
    for (auto run = runs.rbegin(); run != runs.rend(); ++run) add(*run);
  }

  // "of the rnd", "of Row 57" (the row's number) or "of the cast-on".
  void of_the_rnd_row_or_cast_on(Cursor& c, Step& step) {
    const char* expected = "'of the rnd', 'of Row N' or 'of the cast-on'";
    need(c.eat("of"), c, expected);
    if (c.eat("row")) {
      step.of_row = need_number(c, "a row number");
      return;
    }
    need(c.eat("the"), c, expected);
    step.of_cast_on = c.eat("cast-on");
    need(step.of_cast_on || c.eat("rnd"), c, expected);
  }

  // "(after the 1 st on it)": the sts go on a holder after those it holds.
  void onto_held_sts(Cursor& c, Step& step) {
    need_words(c, {"after", "the"}, "'(after the N sts on it)'");
    step.onto = true;
    step.count = need_number(c, "the number of sts on the holder");
    need(c.eat_any({"st", "sts"}), c, "'sts on it)'");
    need_words(c, {"on", "it", ")"}, "'on it)'");
  }

  // "Slip the 35 sts of Row 33 to holder 3 — 7 sts": a flat piece's last row, before the piece
  // is joined in the rnd.
  void hold_all(Cursor& c) {
    Step step{Step::Kind::hold_all, line_no_};
    step.count = need_number(c, "the number of sts to hold");
    need(c.eat_any({"sts", "st"}), c, "'sts'");
    need_words(c, {"of", "row"}, "'of Row N'");
    step.from_row = need_number(c, "a row number");
    need_words(c, {"to", "holder"}, "'to holder N'");
    step.number = need_number(c, "a holder number");
    end_with_count(c, step);
    add(step);
  }

  void need_words(Cursor& c, std::initializer_list<std::string_view> words, const char* expected) {
    for (std::string_view w : words) need(w.size() == 1 ? c.eat_char(w[0]) : c.eat(w), c, expected);
  }

  // "Three-needle bind-off: hold the pieces with RS together: Piece 1 in front, the first st of
  // its last row at the needle tip; Piece 2 behind, the last st of its last row at the tip
  // (slide the sts to the other end of a needle if need be); with a new yarn bind off all 6
  // pairs".
  void three_needle_bind_off(Cursor& c) {
    Step step{Step::Kind::three_needle_bind_off, line_no_};
    need(c.eat_char(':'), c, "':'");
    if (c.eat("fold")) {
      folded_needle(c, step);
    } else {
      need_words(c, {"hold", "the", "pieces", "with", "RS", "together", ":"},
                 "': hold the pieces with RS together:' or ': fold the N sts'");
      step.number = needle_end(c, {"in", "front"}, step.from_last[0], step.holder[0], &step.tip[0]);
      need(c.eat_char(';'), c, "';' after the front piece");
      step.last = needle_end(c, {"behind"}, step.from_last[1], step.holder[1], &step.tip[1]);
      if (c.eat_char('('))
        while (!c.done() && !c.eat_char(')')) c.eat_char(c.peek());
    }
    need_words(c, {";", "with"}, "'; with a new yarn' or '; with its yarn'");
    step.own_yarn = c.eat("its");
    if (!step.own_yarn) need_words(c, {"a", "new"}, "'a new yarn' or 'its yarn'");
    need_words(c, {"yarn", "bind", "off", "all"}, "'yarn bind off all N pairs'");
    step.count = need_number(c, "the number of pairs");
    need(c.eat_any({"pairs", "pair"}) && c.done(), c, "'pairs' and the end of the sentence");
    add(step);
  }

  // "... fold the 42 sts of Piece 4 in half with RS together (count them round the needle from
  // the first st of its last row): sts 35 down to 15 in front, sts 36 up to 14 behind".
  void folded_needle(Cursor& c, Step& step) {
    step.fold = true;
    c.eat("the");
    step.last = need_number(c, "the number of sts folded");
    need_words(c, {"sts", "of"}, "'sts of Piece N'");
    step.number = need_piece(c, "'sts of Piece N' (or of a piece's name)");
    need_words(c,
               {"in", "half", "with", "RS", "together", "(", "count", "them", "round", "the",
                "needle", "from", "the", "first", "st", "of", "its", "last"},
               "'in half with RS together (count them round the needle from the first st of its "
               "last rnd)'");
    need(c.eat_any({"rnd", "row"}) && c.eat_char(')') && c.eat_char(':'), c,
         "'rnd):' or 'row):' before the needles' sts");
    folded_run(c, step, 0, {"in", "front"});
    need(c.eat_char(','), c, "',' after the front needle's sts");
    folded_run(c, step, 1, {"behind"});
  }

  // "sts 35 down to 15 in front".
  void folded_run(Cursor& c, Step& step, int side, std::initializer_list<std::string_view> where) {
    need(c.eat("sts"), c, "'sts A down (or up) to B'");
    step.tip[side] = need_number(c, "the st at the needle tip");
    step.from_last[side] = c.eat("down");
    need((step.from_last[side] || c.eat("up")) && c.eat("to"), c, "'down to' or 'up to'");
    step.end[side] = need_number(c, "the last st of the needle");
    need_words(c, where, "'in front' or 'behind'");
  }

  // "Piece 1 (or: holder 3) in front, the first st of its last row at the needle tip": the
  // piece's (or holder's) number. Where `tip` is given, the needle may begin in the middle:
  // "..., st 21 of its last rnd at the tip, going up (down) round the needle".
  std::uint32_t needle_end(Cursor& c, std::initializer_list<std::string_view> where,
                           bool& from_last, bool& holder, std::uint32_t* tip = nullptr) {
    holder = c.eat("holder");
    std::uint32_t piece = holder ? need_number(c, "a holder number")
                                 : need_piece(c, "'Piece N', a piece's name or 'holder N'");
    need_words(c, where, "'in front' or 'behind' after the piece");
    need(c.eat_char(','), c, "', the first (or last) st of its last row'");
    bool middle = tip && c.eat("st");
    if (middle) {
      *tip = need_number(c, "the st at the tip");
      need(*tip > 0, c, "a st number from 1");
    } else {
      need(c.eat("the"), c, "', the first (or last) st of its last row'");
      from_last = c.eat("last");
      need(from_last || c.eat("first"), c, "'first' or 'last'");
      need(c.eat("st"), c, "'st of its last row (or rnd)'");
    }
    need_words(c, {"of", "its", "last"}, "'st of its last row (or rnd)'");
    need(c.eat("row") || c.eat("rnd"), c, "'row' or 'rnd'");
    need_words(c, {"at", "the"}, "'at the tip'");
    c.eat("needle");
    need(c.eat("tip"), c, "'tip'");
    if (middle) {
      need_words(c, {",", "going"}, "', going up (or down) round the needle'");
      from_last = c.eat("down");
      need((from_last || c.eat("up")) && c.eat("round") && c.eat("the") && c.eat("needle"), c,
           "'up round the needle' or 'down round the needle'");
    }
    return piece;
  }

  // "Hold the 3 sts of Piece 2 behind the needle, the first st of its last row at the tip":
  // for "3-needle BO" in the next row.
  void hold_behind(Cursor& c) {
    Step step{Step::Kind::hold_behind, line_no_};
    c.eat("the");
    step.count = need_number(c, "the number of sts to hold");
    need_words(c, {"sts", "of"}, "'sts of Piece N'");
    step.number = needle_end(c, {"behind", "the", "needle"}, step.from_last[0], step.holder[0]);
    need(c.done(), c, "the end of the sentence");
    add(step);
  }

  // "Row 3 (RS): ...", "Rnds 2–16: ...".
  void row(Cursor& c) {
    Step step{Step::Kind::row, line_no_};
    std::string_view word = c.word();
    step.round = starts_with_ci(word, "rnd") || starts_with_ci(word, "round");
    row_range(c, step);
    if (c.eat_char('(')) {
      if (c.eat("RS"))
        step.side = Side::rs;
      else if (c.eat("WS"))
        step.side = Side::ws;
      else
        fail("expected (RS) or (WS)", c.rest());
      need(c.eat_char(')'), c, "')' after the side");
    }
    need(c.eat_char(':'), c, "':' after the row label");
    std::string_view text = c.rest();
    step.sts = printed_count(text);
    step.program = static_cast<std::uint32_t>(script_.programs.size());
    script_.programs.push_back(program(text));
    add(step);
  }

  void row_range(Cursor& c, Step& step) {
    step.number = step.last = need_number(c, "a row number");
    if (c.eat(kEnDash) || c.eat("-") || c.eat("to"))
      step.last = need_number(c, "the last row number");
    if (step.last < step.number) fail("expected the rows in increasing order", c.rest());
  }

  // "Rep Rows 3–4 five more times — 40 sts", "Repeat rows 3-4 5 more times".
  void repeat(Cursor& c) {
    Step step{Step::Kind::repeat_rows, line_no_};
    std::string_view word = c.word();
    if (!starts_with_ci(word, "row") && !starts_with_ci(word, "rnd") &&
        !starts_with_ci(word, "round"))
      fail("expected 'Rows' or 'Rnds' after 'Rep'", word);
    step.round = !starts_with_ci(word, "row");
    row_range(c, step);
    step.count = need_number(c, "how many more times");
    need(c.eat("more"), c, "'more' (as in 'twice more', 'five more times')");
    c.eat_any({"times", "time"});
    std::string_view rest = c.rest();
    step.sts = printed_count(rest);
    if (!trim(rest).empty()) fail("expected the end of the sentence", rest);
    add(step);
  }

  // "Knit every rnd until 24 rnds in all", "Knit every rnd through Rnd 105".
  void work_even(std::string_view sentence, Cursor& c) {
    Step step{Step::Kind::work_even, line_no_};
    step.op = starts_with_ci(sentence, "knit") ? HandOp::k : HandOp::p;
    need(c.eat("every"), c, "'every rnd' or 'every row'");
    std::string_view word = c.word();
    step.round = starts_with_ci(word, "rnd") || starts_with_ci(word, "round");
    if (c.eat("through")) {  // "Knit every rnd through Rnd 105": up to that row number
      c.word();
      step.count = need_number(c, "the last row or rnd number");
    } else {
      need(c.eat("until"), c, "'until N rnds in all' or 'through Rnd N'");
      step.count = need_number(c, "how many rows or rnds in all");
      c.word();
      need(c.eat("in") && c.eat("all"), c, "'in all'");
    }
    need(c.done(), c, "the end of the sentence");
    add(step);
  }

  // Strips "— 56 sts" (or "(56 sts)") from the end of `text`.
  std::optional<std::uint32_t> printed_count(std::string_view& text) {
    std::size_t at = text.rfind(kEmDash);
    std::size_t skip = kEmDash.size();
    if (at == std::string_view::npos && (at = text.rfind("--")) != std::string_view::npos) skip = 2;
    if (at == std::string_view::npos && !text.empty() && text.back() == ')' &&
        (at = text.rfind('(')) != std::string_view::npos)
      skip = 1;
    if (at == std::string_view::npos) return std::nullopt;
    Cursor c(text.substr(at + skip));
    std::uint32_t n = need_number(c, "a stitch count after the dash");
    need(c.eat_any({"sts", "st"}), c, "'sts' after the stitch count");
    c.eat_char(')');
    need(c.done(), c, "the end of the row after the stitch count");
    text = trim(text.substr(0, at));
    return n;
  }

  Program program(std::string_view text) {
    Program p;
    Cursor c(text);
    std::vector<Node> top = items(c, p);
    if (!c.done()) fail("expected ',' between instructions, or the end of the row", c.rest());
    if (top.empty()) fail("expected instructions after the row label", text);
    p.top_begin = static_cast<std::uint32_t>(p.nodes.size());
    p.nodes.insert(p.nodes.end(), top.begin(), top.end());
    p.top_end = static_cast<std::uint32_t>(p.nodes.size());
    return p;
  }

  static bool at_rep_from(Cursor& c) {
    std::string_view rest = c.rest();
    return starts_with_ci(rest, "rep from") || starts_with_ci(rest, "repeat from");
  }

  // Items up to the end, a ']', a ';' or a "rep from *".
  std::vector<Node> items(Cursor& c, Program& p) {
    std::vector<Node> out;
    for (;;) {
      char next = c.peek();
      if (next == '\0' || next == ']' || next == ';' || at_rep_from(c)) return out;
      out.push_back(item(c, p));
      if (!c.eat_char(',')) return out;
    }
  }

  // Groups nest by recursion: the depth is bounded so that no row can exhaust the stack.
  Node item(Cursor& c, Program& p) {
    if (c.peek() != '*' && c.peek() != '[') return operation(c);
    if (++depth_ > kMaxPatternNesting)
      fail(fmt::format("expected repeats nested at most {} deep (docs/formats.md, \"Limits\")",
                       kMaxPatternNesting),
           c.rest().substr(0, 40));
    bool starred = c.eat_char('*');
    if (!starred) c.eat_char('[');
    Node g = starred ? star(c, p) : bracket(c, p);
    --depth_;
    return g;
  }

  Node group(std::vector<Node> body, Program& p, Cursor& c) {
    if (body.empty()) fail("expected instructions to repeat", c.rest());
    Node g;
    g.kind = Node::Kind::group;
    g.first_child = static_cast<std::uint32_t>(p.nodes.size());
    p.nodes.insert(p.nodes.end(), body.begin(), body.end());
    g.end_child = static_cast<std::uint32_t>(p.nodes.size());
    return g;
  }

  // "*k2, p2; rep from * to last 2 sts" or KnitSpeak's "*k2, p2, repeat from *".
  Node star(Cursor& c, Program& p) {
    Node g = group(items(c, p), p, c);
    c.eat_char(';');
    need(c.eat_any({"rep", "repeat"}) && c.eat("from") && c.eat_char('*'), c, "'; rep from *'");
    if (c.eat("to")) {
      g.until = until(c);
    } else if (auto n = number(c)) {
      need(c.eat("more"), c, "'more times' after the number");
      c.eat_any({"times", "time"});
      g.times = *n + 1;
    } else {
      g.until.kind = Until::Kind::end;  // KnitSpeak: "repeat from *" alone
    }
    return g;
  }

  // "[k6, k2tog] 8 times".
  Node bracket(Cursor& c, Program& p) {
    Node g = group(items(c, p), p, c);
    need(c.eat_char(']'), c, "']' closing the repeat");
    std::optional<std::uint32_t> n = number(c);
    if (!n) fail("expected how many times after ']'", c.rest());
    c.eat_any({"times", "time"});
    g.times = *n;
    return g;
  }

  // After "to": "end", "m", "last N sts", "N sts before m".
  Until until(Cursor& c) {
    Until u;
    if (c.eat("end")) {
      u.kind = Until::Kind::end;
    } else if (c.eat("m")) {
      u.kind = Until::Kind::marker;
    } else if (c.eat("last")) {
      u.kind = Until::Kind::last;
      u.sts = number(c).value_or(1);
      need(c.eat_any({"sts", "st"}), c, "'sts' in 'to last N sts'");
    } else if (auto n = number(c)) {
      u.kind = Until::Kind::before_marker;
      u.sts = *n;
      need(c.eat_any({"sts", "st"}) && c.eat("before") && c.eat("m"), c, "'N sts before m'");
    } else {
      fail("expected 'to end', 'to m', 'to last N sts' or 'to N sts before m'", c.rest());
    }
    return u;
  }

  Node operation(Cursor& c) {
    Node n;
    if (c.eat("w&t")) {  // not a word: '&' would end it
      n.op = HandOp::wt;
      return n;
    }
    if (c.eat("3-needle")) return three_needle_bind_off_sts(c);  // '-' would end a word
    if (c.eat("do")) {
      need(c.eat("not") && c.eat("turn"), c, "'do not turn'");
      n.op = HandOp::no_turn;
      return n;
    }
    if (c.eat("sl1")) {
      if (c.eat("back")) {
        n.op = HandOp::slip_back;
        return n;
      }
      if (!c.eat("from")) {
        n.op = HandOp::sl1;
        return n;
      }
      bool second = c.eat("2nd");
      need(c.eat("spare"), c, "'sl1 from spare' or 'sl1 from 2nd spare'");
      bool behind = c.eat("behind");
      n.op = second ? (behind ? HandOp::from_second_spare_behind : HandOp::from_second_spare)
                    : (behind ? HandOp::from_spare_behind : HandOp::from_spare);
      return n;
    }
    std::string_view w = c.word();
    if (starts_with_ci(w, "bo") && w.size() == 2) return bind_off(c);
    if (starts_with_ci(w, "co") && w.size() == 2) return provisional_cast_on(c);
    if ((w.size() == 4 && (starts_with_ci(w, "knit") || starts_with_ci(w, "purl")))) {
      n.op = lower(w[0]) == 'k' ? HandOp::k : HandOp::p;
      n.until.kind = Until::Kind::end;
      if (c.eat("to")) n.until = until(c);
      return n;
    }
    if (auto op = hand_op_from(w)) {
      n.op = *op;
      if (is_plain(*op) && c.eat("DS")) n.op = *op == HandOp::k ? HandOp::kds : HandOp::pds;
      if (c.eat("to")) n.until = until(c);
      return n;
    }
    if (w.size() > 1 && (lower(w[0]) == 'k' || lower(w[0]) == 'p')) {
      std::uint32_t count = 0;
      auto [end, ec] = std::from_chars(w.data() + 1, w.data() + w.size(), count);
      if (ec == std::errc() && end == w.data() + w.size()) {
        if (count > kMaxPatternNumber) too_big(count);
        n.op = lower(w[0]) == 'k' ? HandOp::k : HandOp::p;
        n.times = count;
        return n;
      }
    }
    fail(
        "expected a stitch (k, p, k2tog, ssk, M1L, yo, w&t, k DS, ...), a marker (pm, sm, rm), "
        "'*' or '['",
        w.empty() ? c.rest() : w);
  }

  // "BO all sts", "BO rem 8 sts", "BO 5 sts".
  Node bind_off(Cursor& c) {
    Node n;
    n.op = HandOp::bo;
    if (c.eat("all")) {
      need(c.eat_any({"sts", "st"}), c, "'BO all sts'");
      c.eat_any({"knitwise", "purlwise", "in patt", "in pattern"});
      n.kind = Node::Kind::bind_off_all;
      return n;
    }
    c.eat("rem");
    n.times = need_sts(c, "how many sts to bind off");
    return n;
  }

  // "3-needle BO 3 sts": each with the next st held behind.
  Node three_needle_bind_off_sts(Cursor& c) {
    Node n;
    n.op = HandOp::tnbo;
    need(c.eat("BO"), c, "'3-needle BO N sts'");
    n.times = need_sts(c, "how many sts to bind off");
    return n;
  }

  // "CO 3 sts with a provisional cast-on": onto the right needle, in the middle of a row.
  Node provisional_cast_on(Cursor& c) {
    Node n;
    n.op = HandOp::provisional_co;
    n.times = need_sts(c, "how many sts to cast on");
    need_words(c, {"with", "a", "provisional", "cast-on"}, "'with a provisional cast-on'");
    return n;
  }

  Script& script_;
  const std::string& file_;
  std::size_t line_no_;
  std::string_view line_;
  std::uint32_t depth_ = 0;  // groups open around the item being read
};

// The part of the text a knitter follows: under "## Instructions" up to the next "## "
// heading, or everything when there is no such heading (KnitSpeak rows).
std::pair<std::size_t, std::size_t> instructions_region(
    const std::vector<std::string_view>& lines) {
  std::string heading = std::string("## ") + kInstructionsHeading;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (!starts_with_ci(trim(lines[i]), heading)) continue;
    std::size_t end = i + 1;
    while (end < lines.size() && !(trim(lines[end]).starts_with("## "))) ++end;
    return {i + 1, end};
  }
  return {0, lines.size()};
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  for (std::size_t pos = 0; pos <= text.size();) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    lines.push_back(text.substr(pos, end - pos));
    pos = end + 1;
  }
  return lines;
}

// Removes markdown emphasis: "**Row 3 (RS):** K to end." reads "Row 3 (RS): K to end.".
std::string plain(std::string_view line) {
  std::string out;
  out.reserve(line.size());
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line.compare(i, 2, "**") == 0) {
      ++i;
      continue;
    }
    out += line[i];
  }
  return out;
}

// "Thumb" in the heading "Thumb (yarn 2), taken up again"; empty for other lines.
std::optional<std::string_view> piece_name(std::string_view line) {
  std::size_t at = line.find(" (yarn ");
  if (at == 0 || at == std::string_view::npos ||
      line.substr(0, at).find_first_of(":.,") != std::string_view::npos)
    return std::nullopt;
  std::string_view rest = line.substr(at + 7);
  std::size_t digits = rest.find_first_not_of("0123456789");
  if (digits == 0 || digits == std::string_view::npos || rest[digits] != ')') return std::nullopt;
  return line.substr(0, at);
}

// The number of the piece a heading names: the one it had, or the next.
std::uint32_t number_piece(Script& script, std::string_view name) {
  for (std::size_t i = 0; i < script.piece_names.size(); ++i)
    if (script.piece_names[i].size() == name.size() && starts_with_ci(script.piece_names[i], name))
      return static_cast<std::uint32_t>(i + 1);
  script.piece_names.emplace_back(name);
  return static_cast<std::uint32_t>(script.piece_names.size());
}

void read_line(Script& script, const std::string& file, std::size_t line_no, std::string_view raw) {
  std::string_view line = trim(raw);
  if (line.empty()) return;
  if (line.front() == '#' || starts_with_ci(line, "piece ") || piece_name(line)) {
    // "### Piece 3 (yarn 3)": the number is checked, the rest is a title. "### Thumb (yarn 2)":
    // a name, numbered in the order the headings first give it.
    Step step{Step::Kind::piece, line_no};
    std::size_t start = line.find_first_not_of("# ");  // none in a heading of '#' alone
    std::string_view title =
        start == std::string_view::npos ? std::string_view() : line.substr(start);
    Cursor c(title);
    if (c.eat("piece"))
      step.number = c.number().value_or(0);
    else if (std::optional<std::string_view> name = piece_name(title))
      step.number = number_piece(script, *name);
    if (step.number != 0 && script.piece_names.size() < step.number)
      script.piece_names.resize(step.number);
    script.steps.push_back(step);
    return;
  }
  std::string text = plain(line);
  SentenceReader reader(script, file, line_no, raw);
  std::string_view rest = text;
  while (!trim(rest).empty()) {
    std::size_t end = rest.find(". ");
    std::string_view sentence = end == std::string_view::npos ? rest : rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 2);
    sentence = trim(sentence);
    if (!sentence.empty() && sentence.back() == '.') sentence.remove_suffix(1);
    if (!sentence.empty()) reader.read(sentence);
  }
}

std::string decoded_entities(std::string_view text) {
  constexpr std::array<std::pair<std::string_view, std::string_view>, 8> kEntities = {{
      {"&amp;", "&"},
      {"&lt;", "<"},
      {"&gt;", ">"},
      {"&quot;", "\""},
      {"&#39;", "'"},
      {"&nbsp;", " "},
      {"&mdash;", "\u2014"},
      {"&ndash;", "\u2013"},
  }};
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    bool replaced = false;
    if (text[i] == '&')
      for (auto [entity, ch] : kEntities)
        if (text.compare(i, entity.size(), entity) == 0) {
          out += ch;
          i += entity.size();
          replaced = true;
          break;
        }
    if (!replaced) out += text[i++];
  }
  return out;
}

}  // namespace

Script read_pattern(std::string_view text, const std::string& file) {
  Script script;
  std::vector<std::string_view> lines = split_lines(text);
  auto [begin, end] = instructions_region(lines);
  for (std::size_t i = begin; i < end; ++i) read_line(script, file, i + 1, lines[i]);
  return script;
}

std::string html_to_text(std::string_view html) {
  std::string out;
  bool hidden = false;  // inside <style>, <script> or <figure>
  for (std::string_view line : split_lines(html)) {
    std::string_view t = trim(line);
    bool opens = t.starts_with("<style") || t.starts_with("<script") || t.starts_with("<figure");
    bool closes = t.find("</style>") != std::string_view::npos ||
                  t.find("</script>") != std::string_view::npos ||
                  t.find("</figure>") != std::string_view::npos;
    if (opens) hidden = true;
    if (hidden) {
      hidden = !closes;
      out += '\n';
      continue;
    }
    if (t.starts_with("<h1")) out += "# ";
    if (t.starts_with("<h2")) out += "## ";
    if (t.starts_with("<h3")) out += "### ";
    std::string stripped;
    bool in_tag = false;
    for (char ch : line) {
      if (ch == '<')
        in_tag = true;
      else if (ch == '>')
        in_tag = false;
      else if (!in_tag)
        stripped += ch;
    }
    out += decoded_entities(stripped);
    out += '\n';
  }
  if (!out.empty()) out.pop_back();
  return out;
}

}  // namespace skein::hand
