#include "hand/pattern_document.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace skein::hand {
namespace {

constexpr std::uint32_t kLongestBlock = 8;  // rows in one repeated block
constexpr const char* kDash = "\u2014";     // before a stitch count
constexpr const char* kRange = "\u2013";    // between row numbers
constexpr double kCircularNeedleCm = 40;    // the shortest common circular needle

std::string with_commas(std::uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

// "1 st", "12 sts".
std::string sts(std::uint32_t n) {
  return fmt::format("{} st{}", n, n == 1 ? "" : "s");
}

// A piece whose last row went to holders for the pieces that work it: no st to fasten off.
bool parted_between_pieces(const PatternSection& sec) {
  return sec.last_row_held() || (!sec.holdings.empty() && sec.holdings.back().of_row);
}

std::string cm_and_inches(double cm) {
  return fmt::format("{:.0f} cm ({:.1f} in)", cm, cm / 2.54);
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

std::string title_of(const std::string& source) {
  std::string title = std::filesystem::path(source).stem().string();
  bool start = true;
  for (char& ch : title) {
    if (ch == '-' || ch == '_') ch = ' ';
    if (start) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    start = ch == ' ';
  }
  return title.empty() ? "Pattern" : title;
}

// What the pattern calls piece `number` (1-based): "Thumb", "Leg 2", "Piece 3".
const std::string& piece_name(const HandPattern& p, std::uint32_t number) {
  return p.piece_names[number - 1];
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
      return fmt::format(
          "Put the {} of holder {} on a {}spare needle, the {} st of its last {} "
          "at the tip.",
          sts(p.count), p.holder, p.second_spare ? "second " : "", p.from_last ? "last" : "first",
          last_course(spare, p.holder));
    bool cast_on = p.chain || spare.first_row == spare.end_row;
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
    return std::any_of(held.begin(), held.end(),
                       [&](const PatternSection::Holding& h) { return h.after_row == row; });
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
    if (start.holder && p_.sections[section_].in_round && !holds_a_flat_row(start.holder))
      return fmt::format(
          "Join a new yarn to the {} of holder {}, the {} st slipped to it at the tip{}.",
          sts(start.count), start.holder, start.from_last ? "last" : "first",
          start.at ? fmt::format("; the rnd begins at its st {}", start.at) : "");
    if (start.holder)
      return fmt::format(
          "Join a new yarn to the {} of holder {}, the {} st of its last {} at the tip.",
          sts(start.count), start.holder, start.from_last ? "last" : "first",
          last_course(spare, start.holder));
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

// What the front matter needs to know about the whole pattern.
struct Totals {
  bool flat = false, round = false, joins = false;
  bool partial_bind_off = false;   // a row binds off some of its sts
  bool spare_needles = false;      // a piece waits on one
  bool second_spare = false;       // rows take sts from two spare needles at once
  bool provisional = false;        // a provisional cast-on
  bool picks_up = false;           // a piece starts on loops picked up along an edge
  bool picks_up_into_rnd = false;  // loops picked up along an edge go into a rnd
  bool joins_flat_piece = false;   // a flat piece is joined in the rnd in the middle of its work
  std::uint32_t holders = 0;
  std::uint32_t widest = 0, narrowest_round = 0;
  std::vector<bool> used = std::vector<bool>(kHandOpCount, false);
};

Totals totals_of(const HandPattern& p) {
  Totals t;
  t.narrowest_round = ~0u;
  for (const PatternSection& s : p.sections) {
    t.joins = t.joins || s.joins;
    t.spare_needles = t.spare_needles || s.left_live || s.provisional || !s.holdings.empty();
    t.provisional = t.provisional || s.provisional || s.row_chain > 0;
    for (const PatternSection::Placement& placed : s.placements) {
      t.picks_up_into_rnd = t.picks_up_into_rnd || placed.edge.has_value();
      t.second_spare = t.second_spare || placed.second_spare;
    }
    t.picks_up = t.picks_up || s.picks_up.has_value();
    for (const PatternSection::Holding& h : s.holdings) t.holders = std::max(t.holders, h.holder);
    if (s.joins) continue;
    (s.in_round ? t.round : t.flat) = true;
    t.flat = t.flat || s.joined_in_rnd_at;
    t.joins_flat_piece = t.joins_flat_piece || s.joined_in_rnd_at;
    t.widest = std::max(t.widest, s.cast_on);
    if (s.in_round) t.narrowest_round = std::min(t.narrowest_round, s.cast_on);
  }
  for (const PatternRow& r : p.rows) {
    auto ops = p.ops_of(r);
    t.partial_bind_off = t.partial_bind_off || (!r.bind_off && std::find(ops.begin(), ops.end(),
                                                                         HandOp::bo) != ops.end());
    t.widest = std::max(t.widest, r.sts_after);
    if (r.round && !r.bind_off) t.narrowest_round = std::min(t.narrowest_round, r.sts_after);
  }
  for (HandOp op : p.ops) t.used[static_cast<std::size_t>(op)] = true;
  return t;
}

class FrontMatter {
 public:
  FrontMatter(const HandPattern& p, const Gauge& gauge, const std::vector<InstructionLine>& lines)
      : p_(p), gauge_(gauge), t_(totals_of(p)) {
    for (const InstructionLine& l : lines) text_ += l.label + " " + l.text + "\n";
  }

  std::vector<FrontSection> sections() const {
    return {{"Finished measurements", measurements()},
            {"Yarn", yarn()},
            {"Needles and notions", needles()},
            {"Gauge", {gauge_text()}},
            {"Abbreviations", abbreviations()},
            {"Techniques", techniques()},
            {"Notes", notes()}};
  }

 private:
  double width_cm(std::uint32_t sts) const { return sts * 10.0 / gauge_.sts_per_10cm; }
  double length_cm(std::uint32_t rows) const { return rows * 10.0 / gauge_.rows_per_10cm; }

  std::vector<std::string> measurements() const {
    std::vector<std::string> items;
    for (const PatternSection& s : p_.sections) {
      if (s.joins || (s.resumed && s.first_row == s.end_row)) continue;  // nothing to measure
      std::uint32_t widest = s.cast_on, rows = 0, short_rows = 0, rnds = 0;
      for (std::uint32_t r = s.first_row; r < s.end_row; ++r) {
        widest = std::max(widest, p_.rows[r].sts_after);
        ++(p_.rows[r].partial ? short_rows : rows);
        rnds += !p_.rows[r].partial && p_.rows[r].round;
      }
      std::string piece = p_.sections.size() > 1 ? fmt::format("{}{}: ", piece_name(p_, s.piece),
                                                               s.resumed ? " (taken up again)" : "")
                                                 : "";
      std::string width = fmt::format("{}{}: {}, {} sts at the widest.", piece,
                                      s.in_round ? "Circumference" : "Width",
                                      cm_and_inches(width_cm(widest)), widest);
      const char* unit = rnds == 0 ? "rows" : rnds == rows ? "rnds" : "rows and rnds";
      items.push_back(width + " " + height(s, rows, short_rows, s.in_round ? unit : "rows"));
    }
    return items;
  }

  // Short rows add length to part of the piece only; a piece of a cast-on alone (along a
  // split) has no height.
  std::string height(const PatternSection& s, std::uint32_t rows, std::uint32_t short_rows,
                     const char* unit) const {
    if (rows == 0 && short_rows == 0) return "A cast-on only: no rows of its own.";
    if (rows == 0)
      return fmt::format("{} short rows (worked on part of the sts), no whole {}.", short_rows,
                         s.in_round ? "rnds" : "rows");
    std::string extra = short_rows ? fmt::format(", plus {} short rows", short_rows) : "";
    return fmt::format("{}: {}, {} {}{}.", s.in_round ? "Height" : "Length",
                       cm_and_inches(length_cm(rows)), rows, unit, extra);
  }

  // "9 stitch holders (or lengths of waste yarn), numbered 1 to 9", or one.
  static std::string holders_text(std::uint32_t holders) {
    if (holders == 1) return "1 stitch holder (or a length of waste yarn).";
    return fmt::format("{} stitch holders (or lengths of waste yarn), numbered 1 to {}.", holders,
                       holders);
  }

  // One line per yarn piece; a piece taken up again goes on with the same yarn.
  std::vector<std::string> yarn() const {
    std::vector<std::uint64_t> stitches(p_.sections.size() + 1, 0);
    for (const PatternSection& s : p_.sections) stitches[s.piece] += s.stitches;
    std::vector<std::string> items;
    for (const PatternSection& s : p_.sections) {
      if (s.resumed) continue;
      double metres = std::ceil(stitches[s.piece] * gauge_.yarn_cm_per_stitch() / 100 + 0.4);
      items.push_back(fmt::format(
          "{}About {:.0f} m ({:.0f} yd) of {}-weight yarn, estimated from its {} sts at the "
          "gauge below, with 20 cm tails at each end.",
          p_.sections.size() > 1
              ? fmt::format("{} (yarn {}): ", piece_name(p_, s.piece), s.yarn + 1)
              : "",
          metres, std::ceil(metres / 0.9144), weight_text(), with_commas(stitches[s.piece])));
    }
    return items;
  }

  std::vector<std::string> needles() const {
    std::vector<std::string> items;
    if (t_.flat)
      items.push_back(needle_text() +
                      " needles: straight, or a circular needle worked back and forth.");
    if (t_.round) {
      auto fits = static_cast<std::uint32_t>(kCircularNeedleCm * gauge_.sts_per_10cm / 10);
      if (t_.widest >= fits)
        items.push_back(
            fmt::format("{} circular needle, 40 cm (16 in) long, for rounds of {} sts or more.",
                        needle_text(), fits));
      if (t_.narrowest_round < fits)
        items.push_back(
            fmt::format("{} double-pointed needles, or a long circular needle for magic loop, "
                        "for rounds of fewer than {} sts.",
                        needle_text(), fits));
    }
    if (p_.markers == 1)
      items.push_back(t_.round ? "1 stitch marker for the beginning of the round."
                               : "1 stitch marker.");
    else if (p_.markers > 1)
      items.push_back(fmt::format("{} stitch markers{}.", p_.markers,
                                  t_.round ? ", one of them in another colour for the beginning "
                                             "of the round"
                                           : ""));
    if (t_.spare_needles)
      items.push_back("A spare needle (or stitch holder) for each piece left to wait on one.");
    if (t_.second_spare)
      items.push_back("A second spare needle, for rows that take sts from two at once.");
    if (t_.holders > 0) items.push_back(holders_text(t_.holders));
    if (t_.joins) items.push_back("A third needle for the three-needle bind-off.");
    items.push_back("Tapestry needle for weaving in ends.");
    return items;
  }

  std::string gauge_text() const {
    std::string gauge = fmt::format(
        "{} sts and {} rows = 10 cm (4 in) in stockinette stitch with {}-weight yarn on {} needles",
        decimal(gauge_.sts_per_10cm), decimal(gauge_.rows_per_10cm), weight_text(), needle_text());
    return fmt::format(
        "{}{}. Knit a swatch and change needle size to match it.", gauge,
        gauge_.assumed ? ". The model does not say its gauge: the measurements and yarn amounts "
                         "assume this one, skein's default"
                       : ", the project's gauge: the measurements and yarn amounts assume it");
  }

  // "4.5 mm (US 7)": the US size where the metric size is a standard one.
  std::string needle_text() const {
    constexpr std::pair<double, const char*> kUsSizes[] = {
        {2, "0"},   {2.25, "1"},   {2.75, "2"}, {3.25, "3"}, {3.5, "4"},    {3.75, "5"}, {4, "6"},
        {4.5, "7"}, {5, "8"},      {5.5, "9"},  {6, "10"},   {6.5, "10.5"}, {8, "11"},   {9, "13"},
        {10, "15"}, {12.75, "17"}, {15, "19"},  {19, "35"},  {25, "50"}};
    for (auto [mm, us] : kUsSizes)
      if (std::abs(gauge_.needle_mm - mm) < 0.01)
        return fmt::format("{} mm (US {})", decimal(mm), us);
    return fmt::format("{} mm", decimal(gauge_.needle_mm));
  }

  // "DK", "super bulky": as a yarn label writes the weight.
  std::string weight_text() const {
    if (gauge_.yarn_weight == "dk") return "DK";
    std::string text = gauge_.yarn_weight;
    std::replace(text.begin(), text.end(), '-', ' ');
    return text;
  }

  // 22 -> "22", 22.5 -> "22.5", 2.75 -> "2.75": to a hundredth, no trailing zeros.
  static std::string decimal(double value) {
    std::string text = fmt::format("{:.2f}", value);
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
    return text;
  }

  bool uses(HandOp op) const { return t_.used[static_cast<std::size_t>(op)]; }

  // The first instruction sentence that starts with `start`, without its count and period.
  std::string first_sentence(std::string_view start) const {
    std::size_t at = text_.find(start);
    if (at == std::string::npos) return "";
    std::size_t end = std::min(text_.find(".", at), text_.find(kDash, at) - 1);
    return text_.substr(at, end - at);
  }
  bool says(std::string_view words) const { return text_.find(words) != std::string::npos; }

  // A tube parted into legs: the sts of one leg gathered on a holder from two rnds, then worked
  // in the rnd with a new yarn or the yarn carried on from the other leg.
  std::string held_sts_in_the_rnd_technique() const {
    std::string text;
    if (std::any_of(p_.sections.begin(), p_.sections.end(), parted_between_pieces))
      text +=
          " \"Slip sts 1\u20138 of Row 57 to holder 7, ...\" parts the sts a row left on the "
          "needle between the pieces that work them: it counts them in the order the row "
          "worked them, the first st worked being st 1.";
    if (says(" sts of the row, the "))
      text +=
          " On a flat piece \"after the first 7 sts of the row\" counts the sts the next row "
          "works first, from the tip of the needle that holds them (the last st just worked is "
          "st 1): slide the placed sts onto that needle after them, the st named first next to "
          "them, so that the row goes on into them.";
    if (says(" on it)"))
      text +=
          " \"(after the 1 st on it)\" slips the sts onto the holder after those it already "
          "holds, so they wait in the order they are worked.";
    if (says("slipped to it at the tip. Pm and join"))
      text +=
          " To work a holder's sts in the rnd, slide them onto the needle(s) with the st "
          "named at the tip of the left needle, place the BOR marker and work that st first.";
    if (says("; the rnd begins at its st "))
      text +=
          " \"The rnd begins at its st 6\": count the holder's sts in the order they were "
          "slipped to it; slide them round the needle(s), keeping that order, until st 6 is at "
          "the tip of the left needle (the sts before it come after the other end), place the "
          "BOR marker and work st 6 first.";
    if (says("Do not fasten off: carry the yarn"))
      text +=
          " \"Do not fasten off: carry the yarn to\" them: after binding off, pull the yarn "
          "through the last loop without cutting it and work the held sts with it, leaving a "
          "strand from the bind-off to the first of them.";
    return text;
  }

  std::vector<std::string> abbreviations() const {
    std::vector<std::string> items;
    for (auto op = HandOp::k; op <= HandOp::slip_back;
         op = static_cast<HandOp>(static_cast<int>(op) + 1))
      if (uses(op) || (op == HandOp::pm && says("Pm ")))
        items.push_back(fmt::format("**{}**: {}", info(op).abbreviation, info(op).meaning));
    auto word = [&](bool used, const char* abbr, const char* meaning) {
      if (used) items.push_back(fmt::format("**{}**: {}", abbr, meaning));
    };
    word(t_.round, "BOR", "beginning of round");
    word(says(" m,") || says(" m.") || says(" m "), "m", "marker");
    word(says("rep") || says("Rep "), "rep", "repeat");
    word(says("Rnd"), "rnd(s)", "round(s)");
    word(says("(RS)") || says("(WS)"), "RS / WS", "right side / wrong side of the work");
    word(true, "st(s)", "stitch(es)");
    return items;
  }

  std::vector<std::string> techniques() const {
    std::vector<std::string> items = {fmt::format(
        "**Cast on** with the long-tail method (any cast-on that makes one loop per stitch will "
        "do). The cast-on is not counted: {} is the first worked after it.",
        t_.flat && t_.round ? "Row 1 (or Rnd 1)"
        : t_.flat           ? "Row 1"
                            : "Rnd 1")};
    if (t_.flat)
      items.push_back(
          "**Working flat:** at the end of every row, turn the work; the next row "
          "starts with the last stitch just worked.");
    if (t_.round)
      items.push_back(
          "**Joining in the round:** spread the cast-on stitches around the needle(s) "
          "with the cast-on edge untwisted, place the BOR marker and knit the first "
          "cast-on stitch with the working yarn. The marker then sits at the start of "
          "every round: slip it as you come to it.");
    if (p_.ws_rounds)
      items.push_back(
          "**Rounds worked with the WS facing** (\"Rnd 30 (WS)\"): the tube is worked inside "
          "out, around in the usual direction with the WS facing you (the wrong side of the "
          "piece shows outside); a st that shows as a knit on the RS is purled. When such rnds "
          "follow rows that end with the WS facing, go on around without turning.");
    if (p_.short_rows) items.push_back(short_rows_technique());
    if (t_.provisional)
      items.push_back(
          "**Provisional cast-on** (a cast-on along a split): with waste yarn crochet a chain a "
          "few sts longer than needed; with the working yarn pick up and knit 1 st through the "
          "back bump of each chain st. The sts on the needle are one side of the split; where "
          "the pattern works \"the loops of its chain\", unzip the waste yarn and put the live "
          "loops on a needle: they are the other side. In the middle of a row (\"CO 3 sts with "
          "a provisional cast-on\") pick up and knit the sts through the chain onto the right "
          "needle and go on with the row.");
    if (t_.picks_up)
      items.push_back(
          "**Picking up along an edge:** with the RS facing and a new yarn, put the outer loop "
          "of the edge st of each row named onto the needle, one row after the other (the loops "
          "are not knit: the next row works them, starting with the last one picked up).");
    if (t_.picks_up_into_rnd)
      items.push_back(fmt::format(
          "**Picking up onto the needle of a rnd** (\"..., onto the needle after the first 18 sts "
          "of the rnd\"): with the {} facing and no new yarn, put the outer loop of the edge st "
          "of each row named on the needle at that place, one row after the other (the loops "
          "are not knit: the rnd works them in the order picked up).",
          p_.ws_rounds ? "side the rnd is worked from (the WS in a rnd labelled (WS))" : "RS"));
    if (t_.joins_flat_piece)
      items.push_back(
          "**Joining a flat piece in the round** (after rows worked flat): once the last row's "
          "sts are slipped to a holder, place the BOR marker where the yarn is, put the sts the "
          "pattern picks up and places next on the needle after it, in order, and work the next "
          "rnd over them (and any sts the rows left) with the yarn still attached at the end of "
          "the last row (after \"do not turn\", without turning the work): starting with the "
          "first st put on, it joins them into a tube.");
    if (t_.holders > 0)
      items.push_back(
          "**Holders:** \"Slip sts 10\u201318 of the rnd to holder 1\" counts the sts from the "
          "BOR marker, as they are before any is slipped, and moves them in order to holder 1; "
          "they wait there until the pattern places them on the needle, puts them on a spare "
          "needle (for \"sl1 from spare\") or binds them off. \"Place\" puts a holder's sts (a "
          "spare needle's, a chain's loops) on the needle where it says, the st it names "
          "first." +
          held_sts_in_the_rnd_technique());
    if (uses(HandOp::slip_back)) items.push_back(decreasing_across_a_gap_technique());
    if (t_.joins)
      items.push_back(
          "**Three-needle bind-off:** hold the two needles parallel, tips to the right; insert "
          "the third needle knitwise into the first st of the front needle and then the first st "
          "of the back needle, knit them together; *knit the next pair together the same way, "
          "pass the first st on the right needle over the second; rep from * until all pairs "
          "are worked; cut the yarn and pull it through the last loop.");
    if (uses(HandOp::tnbo))
      items.push_back(
          "**Three-needle bind-off in a row** (\"3-needle BO 3 sts\"): hold the spare needle "
          "named behind the left needle, parallel to it. *Knit the first st of the left needle "
          "together with the first st of the back needle; if there is a st before it on the "
          "right needle, pass that one over it; rep from * as many times as said. Work the next "
          "st as the pattern says and pass the last pair over it: it is the first st of what "
          "follows (as when binding off part of a row; where nothing follows, the pattern "
          "fastens off the last st). With more than one needle held, bind off from them in the "
          "order they were held.");
    if (uses(HandOp::bo))
      items.push_back(
          "**Binding off (BO):** work 2 sts as they appear, *pass the first st on the "
          "right needle over the second; work 1 more st; rep from * until 1 st "
          "remains, removing any markers as you come to them; cut the yarn and pull it "
          "through that last loop (fasten off).");
    if (t_.partial_bind_off)
      items.push_back(
          "**Binding off part of a row** (\"BO 8 sts, k40\"): bind off 8 sts as above without "
          "cutting the yarn; the st left on the right needle is the first st of what follows "
          "(the first of the 40).");
    return items;
  }

  // Like a heel turn: the rows of a narrow band take one st of the sts waiting beside it at
  // each end.
  static std::string decreasing_across_a_gap_technique() {
    return "**Decreasing across a gap** (as in turning a heel): a row that ends with a decrease "
           "works its last st together with the first st beyond it on the left needle (past the "
           "end of the left needle, around the needle's cable to the far end of the right one). "
           "A row that begins with \"sl1 back\" slips the st at the tip of the right needle (in "
           "the rnd, the last st before the gap) back to the left needle and works it together "
           "with the row's first st. A row that starts at the beginning of the rnd removes the "
           "BOR marker first (rm); the next rnd places it anew (pm), where the yarn is. Until "
           "then, sts \"of the rnd\" (to slip, place or pick up) count from there.";
  }

  // The method the project chose, and how its turns are resolved later.
  std::string short_rows_technique() const {
    if (uses(HandOp::sl1yo)) return tuck_turn_technique();
    if (p_.turns == TurnMethod::wrap_and_turn)
      return "**Short rows (wrap and turn):** a row that ends in w&t stops there: bring the yarn "
             "between the needles, slip the next st purlwise, take the yarn back between the "
             "needles, slip the st back to the left needle and turn the work; the next row starts "
             "with the st worked last. The sts beyond wait on the needle. When a later row comes "
             "to a wrapped st, lift the wrap onto the left needle and work it together with the "
             "st: kw to knit them, pw to purl them." +
             std::string(wraps_a_wrapped_st() ? wrapping_a_wrapped_st() : "");
    return "**Short rows (German short rows):** a row that ends in \"turn\" stops there: turn the "
           "work; the sts beyond wait on the needle. When the next row begins with DS, bring the "
           "yarn to the front, slip the first st (the one worked last) purlwise and pull the yarn "
           "up over the needle to the back until the st shows two legs: a double stitch. When a "
           "later row comes to a double stitch, work its two legs together as one st: k DS to "
           "knit them, p DS to purl them.";
  }

  bool wraps_a_wrapped_st() const {
    return std::ranges::any_of(p_.rows, [](const PatternRow& r) { return r.wraps_again; });
  }

  // Heel-turn patterns' double-wrapped st: wrapped again, resolved with both its wraps.
  static const char* wrapping_a_wrapped_st() {
    return " When w&t comes to a st that is already wrapped, wrap it again as it is (do not "
           "work its wrap): it now has two wraps. kw and pw lift all of a st's wraps and work "
           "them together with the st, as one st.";
  }

  // A stitch graph's short rows (AutoKnit's) turn on a tuck, whatever the project chose.
  static std::string tuck_turn_technique() {
    return "**Short rows (turned on a tuck):** a row that ends in \"sl1yo, turn\" stops there: "
           "with the yarn in front slip the next st purlwise, take the yarn over the needle to "
           "the back (the yo lies over the st, which is not worked) and turn the work; the sts "
           "beyond wait on the needle. The next row begins with sl1: slip that st and its yo "
           "purlwise as one. When a later row comes to it, work the st and its yo together as "
           "one st: brk on the RS, brp on the WS (a decrease takes them as one of its sts). The "
           "short rows go round past the beginning of the rnd: slip the marker as you come to "
           "it; where a row says rm, remove it, and the next rnd places it anew (pm) where it "
           "begins.";
  }

  std::vector<std::string> notes() const {
    std::vector<std::string> items;
    if (says(kDash))
      items.push_back(
          fmt::format("When a {} changes the number of stitches, the count on the "
                      "needle at its end follows the dash: {} 56 sts.",
                      t_.round ? (t_.flat ? "row or rnd" : "rnd") : "row", kDash));
    if (std::string rep = first_sentence("Rep "); !rep.empty())
      items.push_back(
          fmt::format("\"{}\" works those rows again that many more times after "
                      "the first (once more in all than the number says); a stitch "
                      "count after it is the count once all the repeats are done.",
                      rep));
    if (std::string even = first_sentence("Knit every "); !even.empty())
      items.push_back(
          fmt::format("\"{}\" counts every {} from the cast-on, those already "
                      "worked included.",
                      even, t_.round ? "rnd" : "row"));
    if (p_.short_rows && t_.round)
      items.push_back(
          "In the rnd, a row that ends with a turn is a short row: it is worked back and forth "
          "over part of the rnd while the other sts wait. A rnd after short rows starts where "
          "the last one ended and goes on to the BOR marker; the row and rnd numbers count "
          "both.");
    if (p_.markers > 1)
      items.push_back(t_.round ? "Slip the markers as you come to them. The beginning-of-round "
                                 "marker is the last \"m\" of every round: \"to m\" in the last "
                                 "section of a round goes up to it."
                               : "Slip the markers as you come to them.");
    if (uses(HandOp::m1l) || uses(HandOp::m1r) || uses(HandOp::m1pl) || uses(HandOp::m1pr) ||
        uses(HandOp::yo))
      items.push_back(
          "A make-one or yarn over goes with the stitch worked just before it: \"k1, "
          "M1L\" makes 2 sts from 1.");
    if (p_.mirror)
      items.push_back(fmt::format(
          "The rounds of the model ({}) run left to right as seen from the right side; hand "
          "knitting runs right to left, so this pattern knits the model's mirror image: decreases "
          "and increases lean the other way (ssk where the model has k2tog, M1R for M1L).",
          p_.source));
    return items;
  }

  const HandPattern& p_;
  const Gauge& gauge_;
  Totals t_;
  std::string text_;  // every instruction, to see which abbreviations are used
};

}  // namespace

double Gauge::yarn_cm_per_stitch() const {
  double per_cm2 = sts_per_10cm / 10 * rows_per_10cm / 10;
  return std::sqrt(19.0 / per_cm2) * 1.1;
}

PatternDocument make_document(const HandPattern& pattern, Dialect dialect, const Gauge& gauge) {
  PatternDocument doc;
  doc.title = title_of(pattern.source);
  std::uint64_t stitches = 0;
  for (const PatternSection& s : pattern.sections) stitches += s.stitches;
  doc.subtitle = fmt::format(
      "A hand-knitting pattern written by skein from {} ({} stitches). Prove it with `skein "
      "verify` against the same model.",
      pattern.source, with_commas(stitches));
  InstructionWriter(pattern, dialect, doc.instructions).write();
  doc.front = FrontMatter(pattern, gauge, doc.instructions).sections();
  doc.finishing = {"Weave in the ends. Block lightly to the measurements."};
  return doc;
}

}  // namespace skein::hand
