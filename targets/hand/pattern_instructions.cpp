// The instructions of a pattern document: each section's setup, rows and blocks of rows that
// repeat, holds, placements and finishing.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <unordered_map>

#include "hand/pattern_wording.hpp"

namespace skein::hand::document {
namespace {

constexpr std::uint32_t kLongestBlock = 8;  // rows in one repeated block
constexpr const char* kRange = "\u2013";    // between row numbers

// "1 st", "12 sts".
std::string sts(std::uint32_t n) {
  return fmt::format("{} st{}", n, n == 1 ? "" : "s");
}

// "once more", "twice more", "five more times", "12 more times".
std::string more_times(std::uint32_t n) {
  constexpr std::array<const char*, 11> kWords = {"",    "",      "",      "three", "four", "five",
                                                  "six", "seven", "eight", "nine",  "ten"};
  if (n == 1) return "once more";
  if (n == 2) return "twice more";
  if (n < kWords.size()) return fmt::format("{} more times", kWords[n]);
  return fmt::format("{} more times", n);
}

constexpr const char* kJoinInTheRnd =
    "Pm and join to work in the rnd: the sts picked up and placed below go on the needle after "
    "the marker, in order.";

// Writes the rows of each section, finding blocks of rows that repeat.
class InstructionWriter {
 public:
  InstructionWriter(const HandPattern& p, Dialect dialect, std::vector<InstructionLine>& out)
      : p_(p), dialect_(dialect), out_(out) {
    texts_.reserve(p.rows.size());
    for (const PatternRow& r : p.rows)
      texts_.push_back(row_instructions(p.ops_of(r), dialect, r.round));
  }

  void write() {
    for (std::uint32_t s = 0; s < p_.sections.size(); ++s) {
      const PatternSection& sec = p_.sections[s];
      if (only_pauses(sec)) continue;
      section_ = s;
      if (p_.sections.size() > 1)
        add(InstructionLine::Kind::heading, "",
            fmt::format("{} (yarn {}){}{}", piece_name(p_, sec.piece), sec.yarn + 1,
                        sec.resumed ? taken_up_for(sec) : "",
                        sec.joins ? ": three-needle bind-off" : ""));
      // A join with a new yarn is a piece of its own; with a piece's yarn it ends that piece.
      std::size_t body = out_.size();
      if (!sec.joins || sec.own_yarn) add(InstructionLine::Kind::setup, "", setup_text(sec));
      write_rows(sec.first_row, sec.end_row);
      if (sec.joins) add(InstructionLine::Kind::finish, "", three_needle_text(sec));
      add(InstructionLine::Kind::finish, "", finish_text(sec));
      if (p_.sections.size() > 1 && !sec.resumed && !sec.joins)
        write_once(body, piece_name(p_, sec.piece));
    }
  }

 private:
  bool knitspeak() const { return dialect_ == Dialect::knitspeak; }

  std::string setup_text(const PatternSection& sec) const {
    return first_setup_text(sec) + hold_text(sec, sec.first_row);
  }

  // Sts held behind for a row in the middle of the work, on a line of their own before it.
  void write_holds_before(std::uint32_t row) {
    std::string text = hold_text(p_.sections[section_], row);
    if (!text.empty()) add(InstructionLine::Kind::setup, "", text.substr(1));
  }

  bool hold_before(std::uint32_t row) const {
    const auto& holds = p_.sections[section_].holds;
    return std::any_of(holds.begin(), holds.end(),
                       [&](const PatternSection::Hold& h) { return h.before_row == row; });
  }

  // ", taken up again", and what for where it works another part of the garment than the one
  // it is named after: "Palm (yarn 1), taken up again for the thumb".
  std::string taken_up_for(const PatternSection& sec) const {
    if (sec.part.empty() || piece_name(p_, sec.piece).starts_with(sec.part))
      return ", taken up again";
    std::string part = sec.part;
    part[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(part[0])));
    return ", taken up again for the " + part;
  }

  // " Hold the 3 sts of Piece 2 behind the needle, the first st of its last row at the tip."
  std::string hold_text(const PatternSection& sec, std::uint32_t row) const {
    std::string text;
    for (const PatternSection::Hold& h : sec.holds)
      if (h.before_row == row)
        text += fmt::format(
            " Hold the {} of {} behind the needle, the {} st of its last {} at the tip.",
            sts(h.count),
            h.holder ? fmt::format("holder {}", h.holder)
                     : piece_name(p_, p_.sections[h.section].piece),
            h.from_last ? "last" : "first", last_course(p_.sections[h.section], h.holder));
    return text;
  }

  std::string first_setup_text(const PatternSection& sec) const {
    if (sec.resumed) return take_up_text(sec);
    if (sec.starts_from) return join_spare_text(*sec.starts_from) + join_round_text(sec);
    if (sec.picks_up) return pick_up_text(*sec.picks_up, sec.cast_on) + join_round_text(sec);
    std::string held = holdings_text(sec.first_row - 1, sec.cast_on);  // parts of the cast-on
    return fmt::format("Cast on {}{}.", sts(sec.cast_on),
                       sec.provisional ? " with a provisional cast-on" : "") +
           join_round_text(sec) + (held.empty() ? "" : " " + held);
  }

  // " Pm and join to work in the rnd, being careful not to twist." after the cast-on (or the
  // new yarn joined to another piece's sts) of a piece worked in the rnd from its first row (a
  // flat piece joined in the rnd later says so before its first rnd).
  // A piece taken up and set aside again with nothing worked or moved in between ("Take up
  // Body again. Leave the 96 sts on the needle and set the yarn aside."): not worth a heading.
  static bool only_pauses(const PatternSection& sec) {
    return sec.resumed && sec.set_aside && sec.first_row == sec.end_row && !sec.joins &&
           sec.placements.empty() && sec.holdings.empty() && sec.carries.empty() &&
           sec.holds.empty() && !sec.starts_from && !sec.picks_up && sec.row_chain == 0 &&
           !sec.joined_in_rnd_at;
  }

  std::string join_round_text(const PatternSection& sec) const {
    if (!sec.in_round || sec.joined_in_rnd_at) return "";
    return fmt::format(" Pm and join to work in the rnd{}, being careful not to twist.",
                       starts_inside_out(sec) ? " with the WS facing (the tube inside out)" : "");
  }

  bool starts_inside_out(const PatternSection& sec) const {
    return sec.first_row < sec.end_row && p_.rows[sec.first_row].round &&
           p_.rows[sec.first_row].side == Side::ws;
  }

  std::string three_needle_text(const PatternSection& sec) const {
    if (sec.fold) return folded_needle_text(sec, *sec.fold);
    return fmt::format(
        "Three-needle bind-off: hold the pieces with RS together: {} in front, {}; {} behind, "
        "{} (slide the sts to the other end of a needle if need be); with {} yarn bind off "
        "all {} pairs.",
        joined_needle(sec, 0), needle_tip_text(sec, 0, " needle"), joined_needle(sec, 1),
        needle_tip_text(sec, 1, ""), sec.own_yarn ? "its" : "a new", sec.pairs);
  }

  // "the first st of its last row at the needle tip", or, a needle begun in the middle of a
  // piece's last rnd: "st 21 of its last rnd at the tip, going up round the needle".
  std::string needle_tip_text(const PatternSection& sec, int side, const char* needle) const {
    if (sec.tips[side] == 0)
      return fmt::format("the {} st of its last row at the{} tip",
                         sec.from_last[side] ? "last" : "first", needle);
    const PatternSection& spare = p_.sections[side == 0 ? sec.front : sec.back];
    return fmt::format("st {} of its last {} at the{} tip, going {} round the needle",
                       sec.tips[side], last_course(spare, sec.holders[side]), needle,
                       sec.from_last[side] ? "down" : "up");
  }

  // "Piece 1", or "holder 3" where the sts wait on one.
  std::string joined_needle(const PatternSection& sec, int side) const {
    if (sec.holders[side] != 0) return fmt::format("holder {}", sec.holders[side]);
    return piece_name(p_, p_.sections[side == 0 ? sec.front : sec.back].piece);
  }

  // "Three-needle bind-off: fold the 42 sts of Piece 4 in half with RS together (count them
  // round the needle from the first st of its last row): sts 35 down to 15 in front, sts 36 up
  // to 14 behind; with a new yarn bind off all 21 pairs."
  std::string folded_needle_text(const PatternSection& sec, const PatternSection::Fold& f) const {
    auto run = [&](int side) {
      std::uint32_t steps = sec.pairs - 1, n = f.sts;
      std::uint32_t end = f.down[side] ? (f.tip[side] - 1 + n - steps % n) % n + 1
                                       : (f.tip[side] - 1 + steps) % n + 1;
      return fmt::format("sts {} {} to {}", f.tip[side], f.down[side] ? "down" : "up", end);
    };
    const PatternSection& held = p_.sections[sec.front];
    bool rnd = held.end_row > held.first_row && p_.rows[held.end_row - 1].round;
    return fmt::format(
        "{}Three-needle bind-off: fold the {} sts of {} in half with RS together (count them "
        "round the needle from the first st of its last {}): {} in front, {} behind; with a "
        "new yarn bind off all {} pairs.",
        held_sts_text(f, piece_name(p_, held.piece), rnd), f.sts, piece_name(p_, held.piece),
        rnd ? "rnd" : "row", run(0), run(1), sec.pairs);
  }

  // "Place the 7 sts of holder 1 on the spare needle of Piece 4 after its st 13 (count round
  // the needle from the first st of its last row), the last st slipped first — 42 sts. "
  static std::string held_sts_text(const PatternSection::Fold& f, const std::string& piece,
                                   bool rnd) {
    if (f.holder == 0) return "";
    return fmt::format(
        "Place the {} sts of holder {} on the spare needle of {} after its st {} (count "
        "round the needle from the first st of its last {}), the {} st slipped first {} {} "
        "sts. ",
        f.held, f.holder, piece, f.after, rnd ? "rnd" : "row", f.held_from_last ? "last" : "first",
        kDash, f.sts);
  }

  // "Take up Piece 1 again with its yarn. Place the 58 sts of Piece 2 on the needle at the
  // beginning of the rnd, the first st of its last rnd first."
  std::string take_up_text(const PatternSection& sec) const {
    std::string text = fmt::format("Take up {} again with its yarn.", piece_name(p_, sec.piece));
    if (sec.first_row > 0)  // the sts of its flap another piece works, slipped as it is taken up
      if (std::string held = holdings_text(sec.first_row - 1, set_aside_with(sec)); !held.empty())
        text.append(" ").append(held);
    if (sec.joined_in_rnd_at == sec.first_row) text.append(" ").append(kJoinInTheRnd);
    for (const std::string& placed : placement_texts_before(sec.first_row))
      text.append(" ").append(placed);
    return with_count_after_placements(text, sec.first_row);
  }

  // The sts a piece taken up again was set aside with.
  std::uint32_t set_aside_with(const PatternSection& taken_up) const {
    std::uint32_t sts = 0;
    for (std::uint32_t s = 0; s < section_; ++s)
      if (p_.sections[s].piece == taken_up.piece) sts = p_.sections[s].live_at_end;
    return sts;
  }

  // What is placed before `row`: holders put on a spare needle first, as they add no st to the
  // rnd, so that the count can follow the last sentence.
  std::vector<std::string> placement_texts_before(std::uint32_t row) const {
    std::vector<std::string> texts;
    for (bool to_spare : {true, false})
      for (const PatternSection::Placement& p : p_.sections[section_].placements)
        if (p.before_row == row && p.to_spare == to_spare) texts.push_back(placement_text(p));
    return texts;
  }

  // Is the section worked in the rnd at the row (a flat piece joined in the rnd only from its
  // first rnd on)?
  bool in_the_rnd_before(std::uint32_t row) const {
    const PatternSection& sec = p_.sections[section_];
    return sec.in_round && (!sec.joined_in_rnd_at || row >= *sec.joined_in_rnd_at);
  }

  // "Place the 9 loops of Piece 3's chain on the needle after the first 9 sts of the rnd, the
  // first st cast on first." A piece worked in the rnd is placed from the st its rnd works
  // first: "..., st 16 of its last rnd first."
  std::string placement_text(const PatternSection::Placement& p) const {
    const PatternSection& spare = p_.sections[p.section];
    // On a flat piece: counted from the tip of the needle its next row works.
    const char* along = in_the_rnd_before(p.before_row) ? "rnd" : "row";
    std::string where = p.after == 0
                            ? fmt::format("at the beginning of the {}", along)
                            : fmt::format("after the first {} of the {}", sts(p.after), along);
    if (p.edge)  // "Pick up 10 sts along ..., onto the needle after the first 18 sts of the rnd."
      return fmt::format("{}, onto the needle {}.", pick_up_words(*p.edge, p.count), where);
    if (p.to_spare)
      return fmt::format("Put the {} of holder {} on a {}spare needle, the {} st {} at the tip.",
                         sts(p.count), p.holder, p.second_spare ? "second " : "",
                         p.from_last ? "last" : "first", held_end_words(spare, p.holder));
    bool cast_on = p.chain || spare.first_row == spare.end_row || cast_on_onto(p.holder);
    std::string which =
        cast_on ? "cast on" : fmt::format("of its last {}", last_course(spare, p.holder));
    std::string from =
        p.holder != 0 ? fmt::format("holder {}", p.holder)
                      : fmt::format("{}{}", piece_name(p_, spare.piece), p.chain ? "'s chain" : "");
    std::string first = p.start != 0
                            ? fmt::format("st {} {}", p.start, which)
                            : fmt::format("the {} st {}", p.from_last ? "last" : "first", which);
    return fmt::format("Place the {} {}{} of {} on the needle {}, {} first.", p.count,
                       p.chain ? "loop" : "st", p.count == 1 ? "" : "s", from, where, first);
  }

  // "Slip sts 10–18 of the rnd to holder 1, sts 19–27 to holder 2 and sts 28–36 to holder 3."
  void write_holdings_after(std::uint32_t row) {
    if (write_flat_row_held_after(row)) return;
    std::string text = holdings_text(row, p_.rows[row].sts_after);
    if (!text.empty()) add(InstructionLine::Kind::setup, "", text);
  }

  // The holdings after `row` (a row of the section, or the one before a piece is taken up), with
  // what then stays of the `on_needle` sts.
  std::string holdings_text(std::uint32_t row, std::uint32_t on_needle) const {
    std::vector<std::string> runs;
    std::uint32_t held = 0;
    for (const PatternSection::Holding& h : p_.sections[section_].holdings) {
      if (h.after_row != row) continue;
      if (h.flat_row)  // a piece taken up again to be joined in the rnd
        return flat_row_held_text(h, h.of_number, on_needle - std::min(on_needle, h.count));
      held += h.count;
      std::string of =
          h.of_cast_on ? " of the cast-on"
          : h.of_row   ? fmt::format(" of Row {}", h.of_number ? h.of_number : p_.rows[row].number)
                       : " of the rnd";
      runs.push_back(fmt::format("{}{} to holder {}{}", held_sts_text(h), runs.empty() ? of : "",
                                 h.holder, onto_text(h)));
    }
    if (runs.empty()) return "";
    std::string text = "Slip " + runs.front();
    for (std::size_t i = 1; i < runs.size(); ++i)
      text.append(i + 1 == runs.size() ? " and " : ", ").append(runs[i]);
    if (on_needle == held) return text + ".";  // a row parted between other pieces
    return fmt::format("{} {} {}.", text, kDash, sts(on_needle - held));
  }

  // A flat piece's last row, before the piece is joined in the rnd.
  bool write_flat_row_held_after(std::uint32_t row) {
    for (const PatternSection::Holding& h : p_.sections[section_].holdings)
      if (h.after_row == row && h.flat_row) {
        add(InstructionLine::Kind::setup, "",
            flat_row_held_text(h, p_.rows[row].number, p_.rows[row].sts_after - h.count));
        return true;
      }
    return false;
  }

  // "Slip the 35 sts of Row 33 to holder 3 — 7 sts." (`left`: the sts that stay on the needle).
  std::string flat_row_held_text(const PatternSection::Holding& h, std::uint32_t number,
                                 std::uint32_t left) const {
    return fmt::format("Slip the {} of {} {} to holder {}{}.", sts(h.count),
                       rows_word(false, false), number, h.holder,
                       left ? fmt::format(" {} {}", kDash, sts(left)) : "");
  }

  // Before the first rnd of a flat piece joined in the rnd, its last row then on a holder.
  void write_join_in_the_rnd_before(std::uint32_t row) {
    if (p_.sections[section_].joined_in_rnd_at != row) return;
    add(InstructionLine::Kind::setup, "", kJoinInTheRnd);
  }

  // "sts 10–18", or "st 26".
  std::string held_sts_text(const PatternSection::Holding& h) const {
    if (h.count == 1) return fmt::format("st {}", h.first);
    return fmt::format("sts {}{}{}", h.first, knitspeak() ? "-" : kRange, h.first + h.count - 1);
  }

  // " (after the 1 st on it)": sts that go on a holder already holding some.
  static std::string onto_text(const PatternSection::Holding& h) {
    return h.onto ? fmt::format(" (after the {} on it)", sts(h.onto)) : "";
  }

  bool holding_after(std::uint32_t row) const {
    const auto& held = p_.sections[section_].holdings;
    const auto& cast = p_.sections[section_].casts_on_aside;
    return std::any_of(held.begin(), held.end(),
                       [&](const PatternSection::Holding& h) { return h.after_row == row; }) ||
           std::any_of(cast.begin(), cast.end(),
                       [&](const PatternSection::CastOnAside& c) { return c.after_row == row; });
  }

  // "With the working yarn, cast on 4 sts with a provisional cast-on onto holder 5."
  void write_casts_on_aside_after(std::uint32_t row) {
    for (const PatternSection::CastOnAside& c : p_.sections[section_].casts_on_aside)
      if (c.after_row == row)
        add(InstructionLine::Kind::setup, "",
            fmt::format("With the working yarn, cast on {}{} onto holder {}.", sts(c.count),
                        c.provisional ? " with a provisional cast-on" : "", c.holder));
  }

  // Placements into a rnd in the middle of a piece's work, written before the rnd; the last
  // says how many sts the rnd then has.
  void write_placements_before(std::uint32_t row) {
    std::vector<std::string> texts = placement_texts_before(row);
    if (texts.empty()) return;
    texts.back() = with_count_after_placements(texts.back(), row);
    for (std::string& text : texts) add(InstructionLine::Kind::setup, "", std::move(text));
  }

  // "… first — 36 sts.": the count on the needle once the sts placed before `row` are there
  // (a holder put on a spare needle adds none).
  std::string with_count_after_placements(std::string text, std::uint32_t row) const {
    const auto& placed = p_.sections[section_].placements;
    bool adds = std::any_of(placed.begin(), placed.end(), [&](const PatternSection::Placement& p) {
      return p.before_row == row && !p.to_spare;
    });
    if (!adds || text.empty() || text.back() != '.') return text;
    text.pop_back();
    return fmt::format("{} {} {} sts.", text, kDash, p_.rows[row].sts_before);
  }

  bool placement_before(std::uint32_t row) const {
    const auto& placed = p_.sections[section_].placements;
    return std::any_of(placed.begin(), placed.end(),
                       [&](const PatternSection::Placement& p) { return p.before_row == row; });
  }

  // "Pick up 3 sts along the right edge of Piece 1, one in each row from Row 2 down to the
  // cast-on."
  std::string pick_up_text(const PatternSection::PickUp& p, std::uint32_t count) const {
    return pick_up_words(p, count) + ".";
  }

  std::string pick_up_words(const PatternSection::PickUp& p, std::uint32_t count) const {
    auto row = [](std::uint32_t n) {
      return n == 0 ? std::string("the cast-on") : fmt::format("Row {}", n);
    };
    return fmt::format("Pick up {} along the {} edge of {}, one in each row from {} {} to {}",
                       sts(count), p.right ? "right" : "left", edge_owner(p), row(p.from_row),
                       p.from_row <= p.to_row ? "up" : "down", row(p.to_row));
  }

  // A gusset's edges are the flap's, rows of the piece being worked (of a flat piece joined in
  // the rnd, this piece's).
  std::string edge_owner(const PatternSection::PickUp& p) const {
    const PatternSection& worked = p_.sections[section_];
    std::uint32_t piece = p_.sections[p.section].piece;
    if (piece != worked.piece) return piece_name(p_, piece);
    return worked.joined_in_rnd_at ? "this piece" : "the flap";
  }

  // Does the holder hold the sts of a flat piece's last row (slipped before it was joined in
  // the rnd)?
  // "rnd" or "row": the course whose first (or last) st names the end of a holder's sts, or
  // of a piece's on its spare needle.
  const char* last_course(const PatternSection& spare, std::uint32_t holder) const {
    if (holder != 0) return spare.in_round && !holds_a_flat_row(holder) ? "rnd" : "row";
    bool rnd = spare.end_row > spare.first_row ? p_.rows[spare.end_row - 1].round : spare.in_round;
    return rnd ? "rnd" : "row";
  }

  // "of its last row", or "cast on" for a holder the working yarn cast sts on onto.
  std::string held_end_words(const PatternSection& spare, std::uint32_t holder) const {
    if (cast_on_onto(holder)) return "cast on";
    return fmt::format("of its last {}", last_course(spare, holder));
  }

  bool cast_on_onto(std::uint32_t holder) const {
    for (const PatternSection& sec : p_.sections)
      for (const PatternSection::CastOnAside& c : sec.casts_on_aside)
        if (c.holder == holder && holder != 0) return true;
    return false;
  }

  bool holds_a_flat_row(std::uint32_t holder) const {
    for (const PatternSection& sec : p_.sections)
      for (const PatternSection::Holding& h : sec.holdings)
        if (h.holder == holder && holder != 0) return h.flat_row || h.of_row;
    return false;
  }

  // "Join a new yarn to the 3 loops of Piece 1's chain, the first st cast on at the tip." A
  // holder of sts from two rnds names the st by the order they were slipped; one of a flat
  // row's, by its row.
  std::string join_spare_text(const PatternSection::Start& start) const {
    const PatternSection& spare = p_.sections[start.section];
    if (start.holder && p_.sections[section_].in_round && !holds_a_flat_row(start.holder) &&
        !cast_on_onto(start.holder))
      return fmt::format(
          "Join a new yarn to the {} of holder {}, the {} st slipped to it at the tip{}.",
          sts(start.count), start.holder, start.from_last ? "last" : "first",
          start.at ? fmt::format("; the rnd begins at its st {}", start.at) : "");
    if (start.holder)
      return fmt::format("Join a new yarn to the {} of holder {}, the {} st {} at the tip.",
                         sts(start.count), start.holder, start.from_last ? "last" : "first",
                         held_end_words(spare, start.holder));
    return fmt::format("Join a new yarn to the {} {} of {}{}, the {} st cast on at the tip.",
                       start.count, start.chain ? "loops" : "sts", piece_name(p_, spare.piece),
                       start.chain ? "'s chain" : "", start.from_last ? "last" : "first");
  }

  std::string finish_text(const PatternSection& sec) const {
    if (sec.set_aside)
      return fmt::format("Leave the {} on the needle and set the yarn aside (do not cut it).",
                         sts(sec.live_at_end));
    if (sec.left_live && sec.live_at_end != 0)
      return fmt::format("Leave the {} on a spare needle and cut the yarn.", sts(sec.live_at_end));
    bool bound_off = sec.end_row > sec.first_row && p_.rows[sec.end_row - 1].bind_off;
    if (parted_between_pieces(sec) && !bound_off) return "Cut the yarn.";
    return "Fasten off.";
  }

  std::string rows_word(bool round, bool plural) const {
    if (knitspeak()) return std::string(round ? "Round" : "Row") + (plural ? "s" : "");
    return std::string(round ? "Rnd" : "Row") + (plural ? "s" : "");
  }

  std::string label(const PatternRow& r) const {
    std::string word = rows_word(r.round, false);
    if (r.round && r.side == Side::rs) return fmt::format("{} {}", word, r.number);
    return fmt::format("{} {} ({})", word, r.number, side_name(r.side));
  }

  // None left (a row that binds off its last sts with held ones): the fasten-off says so.
  static std::string count_after(std::uint32_t before, std::uint32_t after) {
    return before == after || after == 0 ? "" : fmt::format(" {} {}", kDash, sts(after));
  }

  // The longest-covering block of rows starting at `i` that repeats, as (rows, times).
  std::pair<std::uint32_t, std::uint32_t> best_block(std::uint32_t i, std::uint32_t end) const {
    std::pair<std::uint32_t, std::uint32_t> best{1, 1};
    for (std::uint32_t period = 1; period <= kLongestBlock && i + 2 * period <= end; ++period) {
      std::uint32_t times = 1;
      while (i + (times + 1) * period <= end && block_repeats(i, i + times * period, period))
        ++times;
      if (times >= 2 && times * period > best.first * best.second) best = {period, times};
    }
    return best;
  }

  bool block_repeats(std::uint32_t a, std::uint32_t b, std::uint32_t period) const {
    for (std::uint32_t k = 0; k < period; ++k) {
      const PatternRow &x = p_.rows[a + k], &y = p_.rows[b + k];
      if (x.bind_off || y.bind_off || x.round != p_.rows[a].round || y.round != x.round ||
          texts_[a + k] != texts_[b + k])
        return false;
    }
    return true;
  }

  // Rows are written in runs between the placements that come before some of them.
  void write_rows(std::uint32_t first, std::uint32_t end) {
    for (std::uint32_t i = first; i < end;) {
      std::uint32_t stop = i + 1;
      while (stop < end && !placement_before(stop) && !holding_after(stop - 1) &&
             !hold_before(stop) && !carry_before(stop))
        ++stop;
      write_carry_before(i);
      // A piece taken up again places its first ones as it is taken up.
      if (i != first || !p_.sections[section_].resumed) {
        write_join_in_the_rnd_before(i);
        write_placements_before(i);
      }
      if (i != first) write_holds_before(i);
      write_row_run(first, i, stop);
      write_holdings_after(stop - 1);
      write_casts_on_aside_after(stop - 1);
      i = stop;
    }
  }

  const PatternSection::CarryOn* carry_before(std::uint32_t row) const {
    for (const PatternSection::CarryOn& c : p_.sections[section_].carries)
      if (c.before_row == row) return &c;
    return nullptr;
  }

  // The yarn goes on from a bind-off to a holder's sts (a tube's second leg).
  void write_carry_before(std::uint32_t row) {
    const PatternSection::CarryOn* c = carry_before(row);
    if (!c) return;
    add(InstructionLine::Kind::setup, "",
        fmt::format("Do not fasten off: carry the yarn to the {} of holder {}, the {} st slipped "
                    "to it at the tip. Pm and join to work in the rnd.",
                    sts(c->count), c->holder, c->from_last ? "last" : "first"));
  }

  void write_row_run(std::uint32_t first, std::uint32_t from, std::uint32_t end) {
    for (std::uint32_t i = from; i < end;) {
      auto [period, times] = best_block(i, end);
      std::uint32_t last = i + period * times - 1;
      const PatternRow& r = p_.rows[i];
      // The first row of a piece keeps its label: it says which side is the RS (a rnd worked
      // with the WS facing says WS).
      bool sided = (!r.round || r.side == Side::ws) && i == first;
      if (times > 1 && period == 1 && (texts_[i] == "Knit" || texts_[i] == "Purl") &&
          !knitspeak() && !sided) {
        add(InstructionLine::Kind::repeat, "", work_even_text(r, p_.rows[last], i));
      } else {
        for (std::uint32_t k = 0; k < period; ++k) row_line(i + k);
        if (times > 1) repeat_line(i, period, times);
      }
      i = last + 1;
    }
  }

  // "Knit every rnd until 24 rnds in all"; after short rows, or rows among the rnds, which the
  // numbers count too (also before the piece was set aside), "Knit every rnd through Rnd 105".
  std::string work_even_text(const PatternRow& r, const PatternRow& last, std::uint32_t i) const {
    const char* every = r.round ? "rnd" : "row";
    if (numbers_count_other_rows(r, i))
      return fmt::format("{} every {} through {} {}.", texts_[i], every, rows_word(r.round, false),
                         last.number);
    return fmt::format("{} every {} until {} {} in all.", texts_[i], every, last.number,
                       r.round ? "rnds" : "rows");
  }

  bool numbers_count_other_rows(const PatternRow& r, std::uint32_t i) const {
    std::uint32_t piece = p_.sections[section_].piece;
    for (const PatternSection& sec : p_.sections)
      for (std::uint32_t k = sec.first_row; sec.piece == piece && k < std::min(sec.end_row, i); ++k)
        if (p_.rows[k].short_row || p_.rows[k].round != r.round) return true;
    return false;
  }

  void row_line(std::uint32_t i) {
    const PatternRow& r = p_.rows[i];
    std::string text = texts_[i];
    if (r.bind_off && i > p_.sections[section_].first_row && knits_and_purls(p_.rows[i - 1]))
      text += " in patt";
    else if (!r.bind_off)
      text += count_after(r.sts_before, r.sts_after);
    add(InstructionLine::Kind::row, label(r), text + ".");
  }

  // Does the row show both knits and purls on the side facing the knitter?
  bool knits_and_purls(const PatternRow& r) const {
    auto ops = p_.ops_of(r);
    return std::find(ops.begin(), ops.end(), HandOp::k) != ops.end() &&
           std::find(ops.begin(), ops.end(), HandOp::p) != ops.end();
  }

  void repeat_line(std::uint32_t i, std::uint32_t period, std::uint32_t times) {
    const PatternRow &a = p_.rows[i], &b = p_.rows[i + period - 1];
    std::uint32_t last = i + period * times - 1;
    std::string rows = period == 1 ? fmt::format("{} {}", rows_word(a.round, false), a.number)
                                   : fmt::format("{} {}{}{}", rows_word(a.round, true), a.number,
                                                 knitspeak() ? "-" : kRange, b.number);
    std::string verb = knitspeak() ? "Repeat" : "Rep";
    add(InstructionLine::Kind::repeat, "",
        fmt::format("{} {} {}{}.", verb, rows, more_times(times - 1),
                    count_after(b.sts_after, p_.rows[last].sts_after)));
  }

  void add(InstructionLine::Kind kind, std::string label, std::string text) {
    out_.push_back({kind, std::move(label), std::move(text), section_});
  }

  // A piece worked word for word as one before it (the second sleeve) says so instead:
  // "Work as Sleeve 1."
  void write_once(std::size_t body, const std::string& name) {
    std::string words;
    for (std::size_t i = body; i < out_.size(); ++i)
      words +=
          fmt::format("{}\n{}\n{}\n", static_cast<int>(out_[i].kind), out_[i].label, out_[i].text);
    auto [same, first] = worked_before_.try_emplace(std::move(words), name);
    if (first) return;
    out_.resize(body);
    add(InstructionLine::Kind::setup, "", fmt::format("Work as {}.", same->second));
  }

  const HandPattern& p_;
  Dialect dialect_;
  std::vector<InstructionLine>& out_;
  std::vector<std::string> texts_;  // per pattern row, without label and count
  std::uint32_t section_ = 0;
  std::unordered_map<std::string, std::string> worked_before_;  // a piece's words: its name
};

}  // namespace

std::vector<InstructionLine> instructions(const HandPattern& p, Dialect dialect) {
  std::vector<InstructionLine> lines;
  InstructionWriter(p, dialect, lines).write();
  return lines;
}

}  // namespace skein::hand::document
