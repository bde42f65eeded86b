// The pattern reader's words and sentences, shared by the files that read each kind of
// sentence (pattern_reader_*.cpp): a cursor over a sentence's words, and the reader that
// turns one line's sentences into steps of the script.
#pragma once

#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hand/pattern_reader.hpp"

namespace skein::hand::reader {

constexpr std::string_view kEmDash = "\u2014";
constexpr std::string_view kEnDash = "\u2013";

inline char lower(char ch) {
  return ch >= 'A' && ch <= 'Z' ? static_cast<char>(ch - 'A' + 'a') : ch;
}
inline bool is_word_char(char ch) {
  return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9');
}
inline bool is_space(char ch) {
  return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n';
}

inline bool starts_with_ci(std::string_view s, std::string_view prefix) {
  if (s.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i)
    if (lower(s[i]) != lower(prefix[i])) return false;
  return true;
}

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

inline std::optional<std::uint32_t> number_word(std::string_view word) {
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

  void read(std::string_view sentence);

 private:
  [[noreturn]] void fail(const std::string& expected, std::string_view found) const;

  static std::size_t find_ci(std::string_view s, std::string_view what);
  static bool mentions(std::string_view s, std::string_view what);

  void add(Step step) { script_.steps.push_back(step); }

  // A number, refused beyond kMaxPatternNumber: no garment needs more sts, rows or repeats,
  // and a simulator working them would run for minutes.
  std::optional<std::uint32_t> number(Cursor& c);
  [[noreturn]] void too_big(std::uint64_t n) const;

  std::uint32_t need_number(Cursor& c, const char* what);

  // "12 sts" (or "1 st"): the number, then the word.
  std::uint32_t need_sts(Cursor& c, const char* what);

  void need(bool ok, Cursor& c, const char* expected);

  // "Cast on 12 sts", "Cast on 12 sts with a provisional cast-on"; with the working yarn (the
  // piece's sts stay on its needle), "... onto holder 5".
  void cast_on(Cursor c, bool with_working_yarn = false);

  // "Pick up 3 sts along the right edge of Piece 1, one in each row from Row 2 down to the
  // cast-on".
  void pick_up(Cursor& c);

  // The end of a sentence that may print the count on the needle after it: "— 36 sts".
  void end_with_count(Cursor& c, Step& step);

  // "at the beginning of the rnd" (0) or "after the first 18 sts of the rnd" (step.round); on
  // a flat piece "after the first 7 sts of the row" (counted from the tip of the needle the
  // next row works).
  std::uint32_t where_on_the_needle(Cursor& c, Step& step);

  // "Put the 10 sts (the 1 st) of holder 2 on a [second] spare needle, the first st of its last
  // rnd at the tip".
  void to_spare(Cursor& c);

  // "Work as Sleeve 1": the steps of that piece's first section again, for this piece.
  void work_as(Cursor& c);

  // "Piece 2", or the name a heading gave the piece ("Thumb", "Leg 2"): its number.
  std::uint32_t need_piece(Cursor& c, const char* expected);

  // "the cast-on" (0) or "Row 7".
  std::uint32_t row_of_piece(Cursor& c);

  // "the 3 sts of Piece 1", "the 7 sts of holder 2", "the 1 st of holder 3" or "the 3 loops
  // of Piece 1's chain".
  void whose_sts(Cursor& c, Step& step, const char* count);

  // "Join a new yarn to the 3 sts of Piece 1 (or: the 3 loops of Piece 1's chain), the first
  // st cast on at the tip".
  void join_spare(Cursor& c) { add(sts_at_the_tip(c, {Step::Kind::join_spare, line_no_})); }

  // "Do not fasten off: carry the yarn to the 9 sts of holder 1, the first st slipped to it at
  // the tip".
  void carry_on(Cursor& c);

  // "the 3 sts of Piece 1, the first st cast on at the tip" (or "the 13 sts of holder 1, the
  // first st of its last rnd (or: slipped to it) at the tip").
  Step sts_at_the_tip(Cursor& c, Step step);

  // "Leave the 16 sts on a spare needle and cut the yarn", "Leave the 96 sts on the needle and
  // set the yarn aside (do not cut it)".
  void leave(Cursor& c);

  // "Take up Piece 1 again with its yarn".
  void take_up(Cursor& c);

  // "Place the 58 sts of Piece 2 (or: the 9 loops of Piece 3's chain) on the needle at the
  // beginning of the rnd (or: after the first 106 sts of the rnd), the first st of its last
  // rnd (or: the first st cast on; st 16 of its last rnd) first".
  void place(Cursor& c);

  // "... on the spare needle of Piece 4 after its st 13 (count round the needle from the first
  // st of its last row), the last st slipped first — 42 sts" (before a fold).
  void place_on_spare_needle(Cursor& c, Step& step);

  // "the first (or last) st of its last rnd" or "the first (or last) st cast on".
  void place_first_or_last(Cursor& c, Step& step);
  // "st cast on" or "st of its last rnd (row)".
  void st_cast_on_or_of_its_last_course(Cursor& c);

  // "Slip sts 10–18 of the rnd to holder 1, sts 19–27 to holder 2 and sts 28–36 to holder 3":
  // the sts are counted in the rnd as it is before any is slipped, so the last run goes first.
  void hold(Cursor& c);

  // "of the rnd", "of Row 57" (the row's number) or "of the cast-on".
  void of_the_rnd_row_or_cast_on(Cursor& c, Step& step);

  // "(after the 1 st on it)": the sts go on a holder after those it holds.
  void onto_held_sts(Cursor& c, Step& step);

  // "Slip the 35 sts of Row 33 to holder 3 — 7 sts": a flat piece's last row, before the piece
  // is joined in the rnd.
  void hold_all(Cursor& c);

  void need_words(Cursor& c, std::initializer_list<std::string_view> words, const char* expected);

  // "Three-needle bind-off: hold the pieces with RS together: Piece 1 in front, the first st of
  // its last row at the needle tip; Piece 2 behind, the last st of its last row at the tip
  // (slide the sts to the other end of a needle if need be); with a new yarn bind off all 6
  // pairs".
  void three_needle_bind_off(Cursor& c);

  // "... fold the 42 sts of Piece 4 in half with RS together (count them round the needle from
  // the first st of its last row): sts 35 down to 15 in front, sts 36 up to 14 behind".
  void folded_needle(Cursor& c, Step& step);

  // "sts 35 down to 15 in front".
  void folded_run(Cursor& c, Step& step, int side, std::initializer_list<std::string_view> where);

  // "Piece 1 (or: holder 3) in front, the first st of its last row at the needle tip": the
  // piece's (or holder's) number. Where `tip` is given, the needle may begin in the middle:
  // "..., st 21 of its last rnd at the tip, going up (down) round the needle".
  std::uint32_t needle_end(Cursor& c, std::initializer_list<std::string_view> where,
                           bool& from_last, bool& holder, std::uint32_t* tip = nullptr);

  // "Hold the 3 sts of Piece 2 behind the needle, the first st of its last row at the tip":
  // for "3-needle BO" in the next row.
  void hold_behind(Cursor& c);

  // "Row 3 (RS): ...", "Rnds 2–16: ...".
  void row(Cursor& c);

  void row_range(Cursor& c, Step& step);

  // "Rep Rows 3–4 five more times — 40 sts", "Repeat rows 3-4 5 more times".
  void repeat(Cursor& c);

  // "Knit every rnd until 24 rnds in all", "Knit every rnd through Rnd 105".
  void work_even(std::string_view sentence, Cursor& c);

  // Strips "— 56 sts" (or "(56 sts)") from the end of `text`.
  std::optional<std::uint32_t> printed_count(std::string_view& text);

  Program program(std::string_view text);

  static bool at_rep_from(Cursor& c);

  // Items up to the end, a ']', a ';' or a "rep from *".
  std::vector<Node> items(Cursor& c, Program& p);

  // Groups nest by recursion: the depth is bounded so that no row can exhaust the stack.
  Node item(Cursor& c, Program& p);

  Node group(std::vector<Node> body, Program& p, Cursor& c);

  // "*k2, p2; rep from * to last 2 sts" or KnitSpeak's "*k2, p2, repeat from *".
  Node star(Cursor& c, Program& p);

  // "[k6, k2tog] 8 times".
  Node bracket(Cursor& c, Program& p);

  // After "to": "end", "m", "last N sts", "N sts before m".
  Until until(Cursor& c);

  Node operation(Cursor& c);

  // "BO all sts", "BO rem 8 sts", "BO 5 sts".
  Node bind_off(Cursor& c);

  // "3-needle BO 3 sts": each with the next st held behind.
  Node three_needle_bind_off_sts(Cursor& c);

  // "CO 3 sts with a provisional cast-on" (or "a backward-loop cast-on"): onto the right
  // needle, in the middle of a row.
  Node cast_on_in_row(Cursor& c);

  Script& script_;
  const std::string& file_;
  std::size_t line_no_;
  std::string_view line_;
  std::uint32_t depth_ = 0;  // groups open around the item being read
};

}  // namespace skein::hand::reader
