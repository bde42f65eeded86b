// The pattern reader's rows and rnds: their labels and ranges, repeats, and the instructions of
// a row (items, groups, repeats to a point, each operation).
#include <fmt/format.h>

#include <charconv>

#include "hand/pattern_sentences.hpp"

namespace skein::hand::reader {

void SentenceReader::row(Cursor& c) {
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

void SentenceReader::row_range(Cursor& c, Step& step) {
  step.number = step.last = need_number(c, "a row number");
  if (c.eat(kEnDash) || c.eat("-") || c.eat("to"))
    step.last = need_number(c, "the last row number");
  if (step.last < step.number) fail("expected the rows in increasing order", c.rest());
}

void SentenceReader::repeat(Cursor& c) {
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

void SentenceReader::work_even(std::string_view sentence, Cursor& c) {
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

std::optional<std::uint32_t> SentenceReader::printed_count(std::string_view& text) {
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

Program SentenceReader::program(std::string_view text) {
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

bool SentenceReader::at_rep_from(Cursor& c) {
  std::string_view rest = c.rest();
  return starts_with_ci(rest, "rep from") || starts_with_ci(rest, "repeat from");
}

std::vector<Node> SentenceReader::items(Cursor& c, Program& p) {
  std::vector<Node> out;
  for (;;) {
    char next = c.peek();
    if (next == '\0' || next == ']' || next == ';' || at_rep_from(c)) return out;
    out.push_back(item(c, p));
    if (!c.eat_char(',')) return out;
  }
}

Node SentenceReader::item(Cursor& c, Program& p) {
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

Node SentenceReader::group(std::vector<Node> body, Program& p, Cursor& c) {
  if (body.empty()) fail("expected instructions to repeat", c.rest());
  Node g;
  g.kind = Node::Kind::group;
  g.first_child = static_cast<std::uint32_t>(p.nodes.size());
  p.nodes.insert(p.nodes.end(), body.begin(), body.end());
  g.end_child = static_cast<std::uint32_t>(p.nodes.size());
  return g;
}

Node SentenceReader::star(Cursor& c, Program& p) {
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

Node SentenceReader::bracket(Cursor& c, Program& p) {
  Node g = group(items(c, p), p, c);
  need(c.eat_char(']'), c, "']' closing the repeat");
  std::optional<std::uint32_t> n = number(c);
  if (!n) fail("expected how many times after ']'", c.rest());
  c.eat_any({"times", "time"});
  g.times = *n;
  return g;
}

Until SentenceReader::until(Cursor& c) {
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

Node SentenceReader::operation(Cursor& c) {
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
  if (starts_with_ci(w, "co") && w.size() == 2) return cast_on_in_row(c);
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

Node SentenceReader::bind_off(Cursor& c) {
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

Node SentenceReader::three_needle_bind_off_sts(Cursor& c) {
  Node n;
  n.op = HandOp::tnbo;
  need(c.eat("BO"), c, "'3-needle BO N sts'");
  n.times = need_sts(c, "how many sts to bind off");
  return n;
}

Node SentenceReader::cast_on_in_row(Cursor& c) {
  Node n;
  n.times = need_sts(c, "how many sts to cast on");
  need_words(c, {"with", "a"}, "'with a provisional cast-on' or 'with a backward-loop cast-on'");
  bool backward_loop = c.eat("backward-loop");
  need(backward_loop || c.eat("provisional"), c,
       "'with a provisional cast-on' or 'with a backward-loop cast-on'");
  need(c.eat("cast-on"), c, "'cast-on'");
  n.op = backward_loop ? HandOp::co : HandOp::provisional_co;
  return n;
}

}  // namespace skein::hand::reader
