#include "hand/pattern_reader.hpp"

#include <fmt/format.h>

#include <array>

#include "common/error.hpp"
#include "hand/pattern_document.hpp"
#include "hand/pattern_sentences.hpp"

namespace skein::hand {
namespace reader {

void SentenceReader::read(std::string_view sentence) {
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
  constexpr std::string_view kWithWorkingYarn = "with the working yarn, cast on";
  if (starts_with_ci(sentence, kWithWorkingYarn))
    return cast_on(Cursor(sentence.substr(kWithWorkingYarn.size())), true);
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

void SentenceReader::fail(const std::string& expected, std::string_view found) const {
  throw ParseError(file_, line_no_, std::string(line_),
                   fmt::format("{}, found '{}'", expected, found));
}

std::size_t SentenceReader::find_ci(std::string_view s, std::string_view what) {
  for (std::size_t i = 0; i + what.size() <= s.size(); ++i)
    if (starts_with_ci(s.substr(i), what)) return i;
  return std::string_view::npos;
}

bool SentenceReader::mentions(std::string_view s, std::string_view what) {
  return find_ci(s, what) != std::string_view::npos;
}

std::optional<std::uint32_t> SentenceReader::number(Cursor& c) {
  std::optional<std::uint32_t> n = c.number();
  if (n && *n > kMaxPatternNumber) too_big(*n);
  return n;
}

void SentenceReader::too_big(std::uint64_t n) const {
  throw ParseError(file_, line_no_, std::string(line_),
                   fmt::format("expected a number of at most {} (docs/formats.md, \"Limits\"), "
                               "found {}",
                               kMaxPatternNumber, n));
}

std::uint32_t SentenceReader::need_number(Cursor& c, const char* what) {
  if (auto n = number(c)) return *n;
  fail(fmt::format("expected {}", what), c.rest());
}

std::uint32_t SentenceReader::need_sts(Cursor& c, const char* what) {
  std::uint32_t n = need_number(c, what);
  need(c.eat_any({"sts", "st"}), c, "'sts' after the number");
  return n;
}

void SentenceReader::need(bool ok, Cursor& c, const char* expected) {
  if (!ok) fail(fmt::format("expected {}", expected), c.rest());
}

}  // namespace reader

namespace {

using reader::Cursor;
using reader::SentenceReader;
using reader::starts_with_ci;
using reader::trim;

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
