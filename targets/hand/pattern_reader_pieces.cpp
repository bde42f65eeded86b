// The pattern reader's sentences that start, join, carry on, leave and take up pieces: cast on,
// pick up, put sts on a spare needle, work a piece as another.
#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "hand/pattern_sentences.hpp"

namespace skein::hand::reader {

void SentenceReader::cast_on(Cursor c, bool with_working_yarn) {
  Step step{Step::Kind::cast_on, line_no_};
  step.count = need_sts(c, "the number of sts to cast on");
  if (c.eat("with")) {
    need_words(c, {"a", "provisional", "cast-on"}, "'with a provisional cast-on'");
    step.provisional = true;
  }
  if (with_working_yarn) {  // "..., cast on 4 sts onto holder 5": the piece's needle stays
    step.kind = Step::Kind::cast_on_aside;
    need_words(c, {"onto", "holder"}, "'onto holder N'");
    step.number = need_number(c, "a holder number");
  }
  add(step);
}

void SentenceReader::pick_up(Cursor& c) {
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

void SentenceReader::end_with_count(Cursor& c, Step& step) {
  std::string_view rest = c.rest();
  step.sts = printed_count(rest);
  if (!trim(rest).empty()) fail("expected the end of the sentence", rest);
}

std::uint32_t SentenceReader::where_on_the_needle(Cursor& c, Step& step) {
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

void SentenceReader::to_spare(Cursor& c) {
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
  st_cast_on_or_of_its_last_course(c);
  need_words(c, {"at", "the", "tip"}, "'at the tip'");
  need(c.done(), c, "the end of the sentence");
  add(step);
}

void SentenceReader::work_as(Cursor& c) {
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

std::uint32_t SentenceReader::need_piece(Cursor& c, const char* expected) {
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

std::uint32_t SentenceReader::row_of_piece(Cursor& c) {
  if (c.eat("the") && c.eat("cast-on")) return 0;
  need(c.eat("row"), c, "'the cast-on' or 'Row N'");
  return need_number(c, "a row number");
}

void SentenceReader::whose_sts(Cursor& c, Step& step, const char* count) {
  c.eat("the");
  step.count = need_number(c, count);
  step.provisional = c.eat("loops") || (step.count == 1 && c.eat("loop"));
  need(step.provisional || c.eat("sts") || (step.count == 1 && c.eat("st")), c, "'sts' or 'loops'");
  need(c.eat("of"), c, "'of Piece N' or 'of holder N'");
  step.holder[0] = !step.provisional && c.eat("holder");
  step.number = step.holder[0] ? need_number(c, "a holder number")
                               : need_piece(c, "'of Piece N', of a piece's name or 'of holder N'");
  if (step.provisional) need_words(c, {"'", "s", "chain"}, "'s chain' after the piece");
}

void SentenceReader::carry_on(Cursor& c) {
  need_words(c, {":", "carry", "the", "yarn", "to"}, "': carry the yarn to the N sts of holder N'");
  Step step = sts_at_the_tip(c, {Step::Kind::carry_on, line_no_});
  if (!step.holder[0]) fail("expected the sts of a holder", c.rest());
  add(step);
}

Step SentenceReader::sts_at_the_tip(Cursor& c, Step step) {
  whose_sts(c, step, "the number of sts");
  need_words(c, {",", "the"}, "', the first (or last) st cast on'");
  step.from_last[0] = c.eat("last");
  need(step.from_last[0] || c.eat("first"), c, "'first' or 'last'");
  need(c.eat("st"), c, "'st cast on at the tip' or 'st of its last rnd at the tip'");
  if (step.holder[0] && c.eat("slipped")) {
    need_words(c, {"to", "it"}, "'slipped to it'");
  } else if (step.holder[0] && !c.eat("cast")) {
    need_words(c, {"of", "its", "last"}, "'of its last rnd', 'slipped to it' or 'cast on'");
    need(c.eat_any({"rnd", "row"}), c, "'rnd' or 'row'");
  } else if (step.holder[0]) {
    need(c.eat("on"), c, "'st cast on at the tip'");
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

void SentenceReader::leave(Cursor& c) {
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

void SentenceReader::take_up(Cursor& c) {
  Step step{Step::Kind::take_up, line_no_};
  step.number = need_piece(c, "'Take up Piece N again' (or a piece's name)");
  need_words(c, {"again", "with", "its", "yarn"}, "'again with its yarn'");
  need(c.done(), c, "the end of the sentence");
  add(step);
}

}  // namespace skein::hand::reader
