// The pattern reader's sentences that move sts off the needle and back, and bind off across two
// needles: place, hold, three-needle and folded bind-offs, sts held behind.
#include "hand/pattern_sentences.hpp"

namespace skein::hand::reader {

void SentenceReader::place(Cursor& c) {
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

void SentenceReader::place_on_spare_needle(Cursor& c, Step& step) {
  step.kind = Step::Kind::place_on_spare;
  need_words(c, {"needle", "of"}, "'the spare needle of Piece N'");
  step.to_row = need_piece(c, "'the spare needle of Piece N' (or of a piece's name)");
  need_words(c, {"after", "its", "st"}, "'after its st N'");
  step.last = need_number(c, "the st the held sts go after");
  need(c.eat_char('('), c, "'(count round the needle from the first st of its last row)'");
  need_words(c,
             {"count", "round", "the", "needle", "from", "the", "first", "st", "of", "its", "last"},
             "'count round the needle from the first st of its last row'");
  need(c.eat_any({"rnd", "row"}) && c.eat_char(')') && c.eat_char(','), c, "'row),'");
  need(c.eat("the"), c, "'the first (or last) st slipped first'");
  step.from_last[0] = c.eat("last");
  need(step.from_last[0] || c.eat("first"), c, "'first' or 'last'");
  need_words(c, {"st", "slipped", "first"}, "'st slipped first'");
  end_with_count(c, step);
  add(step);
}

void SentenceReader::place_first_or_last(Cursor& c, Step& step) {
  need(c.eat("the"), c, "'the first (or last) st'");
  step.from_last[0] = c.eat("last");
  need(step.from_last[0] || c.eat("first"), c, "'first' or 'last'");
  st_cast_on_or_of_its_last_course(c);
}

void SentenceReader::st_cast_on_or_of_its_last_course(Cursor& c) {
  need(c.eat("st"), c, "'st of its last rnd' or 'st cast on'");
  if (c.eat("cast")) {
    need(c.eat("on"), c, "'st cast on'");
  } else {
    need_words(c, {"of", "its", "last"}, "'st of its last rnd' or 'st cast on'");
    need(c.eat_any({"rnd", "row"}), c, "'rnd' or 'row'");
  }
}

void SentenceReader::hold(Cursor& c) {
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
  // The runs are slipped in the order given (a holder takes them onto its sts in that order),
  // each counted as the sts were before the first: those slipped before it no longer count.
  for (std::size_t i = 0; i < runs.size(); ++i) {
    std::uint32_t gone = 0;
    for (std::size_t j = 0; j < i; ++j)
      if (runs[j].to_row < runs[i].from_row) gone += runs[j].to_row - runs[j].from_row + 1;
    runs[i].from_row -= gone;
    runs[i].to_row -= gone;
  }
  end_with_count(c, runs.back());  // checked once the last run is slipped
  for (const Step& run : runs) add(run);
}

void SentenceReader::of_the_rnd_row_or_cast_on(Cursor& c, Step& step) {
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

void SentenceReader::onto_held_sts(Cursor& c, Step& step) {
  need_words(c, {"after", "the"}, "'(after the N sts on it)'");
  step.onto = true;
  step.count = need_number(c, "the number of sts on the holder");
  need(c.eat_any({"st", "sts"}), c, "'sts on it)'");
  need_words(c, {"on", "it", ")"}, "'on it)'");
}

void SentenceReader::hold_all(Cursor& c) {
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

void SentenceReader::need_words(Cursor& c, std::initializer_list<std::string_view> words,
                                const char* expected) {
  for (std::string_view w : words) need(w.size() == 1 ? c.eat_char(w[0]) : c.eat(w), c, expected);
}

void SentenceReader::three_needle_bind_off(Cursor& c) {
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

void SentenceReader::folded_needle(Cursor& c, Step& step) {
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

void SentenceReader::folded_run(Cursor& c, Step& step, int side,
                                std::initializer_list<std::string_view> where) {
  need(c.eat("sts"), c, "'sts A down (or up) to B'");
  step.tip[side] = need_number(c, "the st at the needle tip");
  step.from_last[side] = c.eat("down");
  need((step.from_last[side] || c.eat("up")) && c.eat("to"), c, "'down to' or 'up to'");
  step.end[side] = need_number(c, "the last st of the needle");
  need_words(c, where, "'in front' or 'behind'");
}

std::uint32_t SentenceReader::needle_end(Cursor& c, std::initializer_list<std::string_view> where,
                                         bool& from_last, bool& holder, std::uint32_t* tip) {
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

void SentenceReader::hold_behind(Cursor& c) {
  Step step{Step::Kind::hold_behind, line_no_};
  c.eat("the");
  step.count = need_number(c, "the number of sts to hold");
  need_words(c, {"sts", "of"}, "'sts of Piece N'");
  step.number = needle_end(c, {"behind", "the", "needle"}, step.from_last[0], step.holder[0]);
  need(c.done(), c, "the end of the sentence");
  add(step);
}

}  // namespace skein::hand::reader
