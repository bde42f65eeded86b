#include "mesh/autoknit_st.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace skein {
namespace {

constexpr std::size_t kFieldCount = 10;
constexpr std::string_view kFieldNames = "yarn type dir in0 in1 out0 out1 x y z";
constexpr std::int32_t kNone = -1;  // an unused in/out slot

// AutoKnit's letters, and skein's `p`: AutoKnit knits no purls, so its format has no letter for
// one; skein writes a purl as `p` (the fabric `skein verify --fabric x.st` writes) rather than
// lose it as a `k`. The loop counts (0 in 1 out for a start, 2 in 1 out for a decrease, ...)
// are the catalogue's loops_in/loops_out of the type each letter becomes.
struct Letter {
  char letter;
  StitchType type;
};
constexpr std::array kLetters{
    Letter{'s', StitchType::co},  Letter{'e', StitchType::bo},    Letter{'k', StitchType::k},
    Letter{'p', StitchType::p},   Letter{'t', StitchType::tuck},  Letter{'m', StitchType::sl},
    Letter{'i', StitchType::kfb}, Letter{'d', StitchType::k2tog},
};

using Slots = std::array<std::int32_t, 2>;  // stitch indices or kNone, in file order

struct Links {
  Slots in;   // in0 in1: makers of the loops this stitch consumes
  Slots out;  // out0 out1: takers of the loops this stitch makes
};

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    std::size_t end = std::min(text.find('\n'), text.size());
    std::string_view line = text.substr(0, end);
    if (line.ends_with('\r')) line.remove_suffix(1);  // CRLF files
    lines.push_back(line);
    text.remove_prefix(std::min(end + 1, text.size()));
  }
  return lines;
}

// Splits a line at runs of blanks into `fields`; returns the number of fields found, which
// may exceed what `fields` holds (the rest are only counted, for the message). A plain loop:
// find_first_of would call memchr once per character.
std::size_t split_fields(std::string_view line, std::array<std::string_view, kFieldCount>& fields) {
  auto is_blank = [](char c) { return c == ' ' || c == '\t'; };
  std::size_t count = 0;
  std::size_t at = 0;
  while (true) {
    while (at < line.size() && is_blank(line[at])) ++at;
    if (at == line.size()) return count;
    std::size_t end = at;
    while (end < line.size() && !is_blank(line[end])) ++end;
    if (count < kFieldCount) fields[count] = line.substr(at, end - at);
    ++count;
    at = end;
  }
}

// from_chars over the whole field: trailing characters are an error too.
template <typename Number>
std::errc parse_whole(std::string_view field, Number& value) {
  const char* last = field.data() + field.size();
  auto [end, error] = std::from_chars(field.data(), last, value);
  return error == std::errc() && end != last ? std::errc::invalid_argument : error;
}

int occurrences(const Slots& slots, std::int32_t index) {
  return static_cast<int>(std::count(slots.begin(), slots.end(), index));
}

char letter_of(StitchType type) {
  for (const Letter& letter : kLetters)
    if (letter.type == type) return letter.letter;
  return '?';
}

// "in0 out0": the slots a stitch with these loop counts must fill (and no others).
std::string required_slots(const StitchTypeInfo& type) {
  std::string names;
  for (int i = 0; i < type.loops_in; ++i) names += fmt::format("in{} ", i);
  for (int i = 0; i < type.loops_out; ++i) names += fmt::format("out{} ", i);
  names.pop_back();  // every type has a slot
  return names;
}

class StParser {
 public:
  StParser(std::string_view text, const std::string& file_name,
           std::vector<std::array<double, 3>>* positions)
      : file_name_(file_name), lines_(split_lines(text)), positions_(positions) {}

  KnitGraph parse() {
    if (lines_.empty())
      throw ParseError(file_name_, 1, "", "expected stitch lines, found an empty file");
    allocate();
    for (StitchId s = 0; s < size(); ++s) parse_line(s);
    for (StitchId s = 0; s < size(); ++s) check_mirrored(s);
    link_yarn();
    add_loops();
    infer_rows();
    graph_.index_loops();
    return std::move(graph_);
  }

 private:
  std::uint32_t size() const { return static_cast<std::uint32_t>(lines_.size()); }

  [[noreturn]] void fail(StitchId s, std::string expected) const {
    throw ParseError(file_name_, std::size_t{s} + 1, std::string(lines_[s]), std::move(expected));
  }

  void allocate() {
    const std::uint32_t n = size();
    graph_.source_name = file_name_;
    graph_.element = "line";
    graph_.type.resize(n);
    graph_.row.resize(n);
    graph_.source.resize(n);
    graph_.yarn_next.resize(n);
    graph_.yarn_link.resize(n);
    graph_.flags.assign(n, 0);
    graph_.direction.resize(n);
    yarn_.resize(n);
    anticlockwise_.resize(n);
    links_.resize(n);
    if (positions_) positions_->assign(n, {0, 0, 0});
  }

  void parse_line(StitchId s) {
    std::array<std::string_view, kFieldCount> field;
    std::size_t count = split_fields(lines_[s], field);
    if (count != kFieldCount) {
      fail(s, fmt::format("expected {} fields: {}, found {}", kFieldCount, kFieldNames,
                          count == 0 ? "a blank line" : std::to_string(count)));
    }
    graph_.source[s] = s;
    yarn_[s] = parse_yarn(s, field[0]);
    graph_.type[s] = parse_type(s, field[1]);
    anticlockwise_[s] = parse_direction(s, field[2]);
    graph_.direction[s] = direction_of(anticlockwise_[s]);
    Links& links = links_[s];
    links.in = {parse_index(s, "in0", field[3]), parse_index(s, "in1", field[4])};
    links.out = {parse_index(s, "out0", field[5]), parse_index(s, "out1", field[6])};
    check_link_order(s);
    std::array<double, 3> at{coordinate(s, "x", field[7]), coordinate(s, "y", field[8]),
                             coordinate(s, "z", field[9])};
    if (positions_) (*positions_)[s] = at;
    check_slots_match_type(s);
  }

  std::uint32_t parse_yarn(StitchId s, std::string_view field) const {
    std::uint32_t yarn = 0;
    if (parse_whole(field, yarn) != std::errc())
      fail(s, fmt::format("expected a yarn id (a non-negative integer), found '{}'", field));
    return yarn;
  }

  StitchType parse_type(StitchId s, std::string_view field) const {
    if (field.size() == 1) {
      for (const Letter& letter : kLetters)
        if (letter.letter == field[0]) return letter.type;
    }
    fail(s, fmt::format("expected a stitch type s, e, k, p, t, m, i or d, found '{}'", field));
  }

  // The direction tells a turn (it flips) from a shift (it stays): see infer_rows.
  bool parse_direction(StitchId s, std::string_view field) const {
    if (field != "c" && field != "a")
      fail(s, fmt::format("expected dir c (clockwise) or a (anticlockwise), found '{}'", field));
    return field == "a";
  }

  // AutoKnit's dir is the way the yarn goes round the tube seen from above (wales towards the
  // viewer): anticlockwise passes the side facing a viewer in front from left to right. In
  // each stitch's frame the ins and outs count from that left.
  static CourseDirection direction_of(bool anticlockwise) {
    return anticlockwise ? CourseDirection::left_to_right : CourseDirection::right_to_left;
  }

  std::int32_t parse_index(StitchId s, std::string_view name, std::string_view field) const {
    std::int64_t index = 0;
    std::errc error = parse_whole(field, index);
    if (error == std::errc::invalid_argument)
      fail(s, fmt::format("expected {} to be an integer (a stitch index or -1), found '{}'", name,
                          field));
    if (error != std::errc() || index < kNone || index >= size())
      fail(s, fmt::format("expected {} to be -1 or a stitch index 0..{}, found {}", name,
                          size() - 1, field));
    return static_cast<std::int32_t>(index);
  }

  // Stitches are listed in construction order: a loop is made before it is consumed.
  void check_link_order(StitchId s) const {
    const Links& links = links_[s];
    const auto here = static_cast<std::int32_t>(s);
    for (std::size_t i = 0; i < 2; ++i) {
      if (links.in[i] >= here)
        fail(s, fmt::format("expected in{} to name an earlier stitch (< {}), found {}", i, s,
                            links.in[i]));
      if (links.out[i] != kNone && links.out[i] <= here)
        fail(s, fmt::format("expected out{} to name a later stitch (> {}), found {}", i, s,
                            links.out[i]));
    }
  }

  // Positions are for display (and the yarn model) only; they must still be numbers.
  double coordinate(StitchId s, std::string_view axis, std::string_view field) const {
    double value = 0;
    if (parse_whole(field, value) != std::errc())
      fail(s, fmt::format("expected {} to be a number, found '{}'", axis, field));
    return value;
  }

  // Exactly AutoKnit's check_type(): the first loops_in in-slots and the first loops_out
  // out-slots are set, the others are -1. No tolerance: AutoKnit's samples all comply (tubes
  // end in 'e' stitches, never in a knit with out0 = -1), so every loop gets a taker.
  void check_slots_match_type(StitchId s) const {
    const StitchTypeInfo& type = info(graph_.type[s]);
    const Links& links = links_[s];
    bool ok = true;
    for (std::size_t i = 0; i < 2; ++i) {
      ok = ok && (links.in[i] != kNone) == (i < type.loops_in);
      ok = ok && (links.out[i] != kNone) == (i < type.loops_out);
    }
    if (!ok) {
      fail(s,
           fmt::format("expected a '{}' stitch (loops in/out: {}/{}) to set only {}, found "
                       "in0 in1 out0 out1 = {} {} {} {}",
                       letter_of(graph_.type[s]), type.loops_in, type.loops_out,
                       required_slots(type), links.in[0], links.in[1], links.out[0], links.out[1]));
    }
  }

  // Each link is listed on both ends, as often on one as on the other (a decrease may take
  // both loops of one increase).
  void check_mirrored(StitchId s) const {
    const Links& links = links_[s];
    const auto here = static_cast<std::int32_t>(s);
    for (std::size_t i = 0; i < 2; ++i) {
      std::int32_t maker = links.in[i];
      if (maker != kNone && occurrences(links.in, maker) != occurrences(links_[maker].out, here))
        fail_unmirrored(s, fmt::format("in{}", i), maker, "out0 out1", links.in, links_[maker].out);
      std::int32_t taker = links.out[i];
      if (taker != kNone && occurrences(links.out, taker) != occurrences(links_[taker].in, here))
        fail_unmirrored(s, fmt::format("out{}", i), taker, "in0 in1", links.out, links_[taker].in);
    }
  }

  [[noreturn]] void fail_unmirrored(StitchId s, std::string_view slot, std::int32_t other,
                                    std::string_view other_slots, const Slots& here,
                                    const Slots& there) const {
    fail(s, fmt::format("{} = {} is not mirrored: expected stitch {} (line {}) to name {} {} in "
                        "its {}, found {} {}",
                        slot, other, other, other + 1, s,
                        occurrences(here, other) == 1 ? "once" : "twice", other_slots, there[0],
                        there[1]));
  }

  // AutoKnit yarns have no explicit rows: the yarn runs on while the yarn id does. Rows are
  // inferred afterwards (infer_rows), which changes the links between them.
  void link_yarn() {
    for (StitchId s = 0; s < size(); ++s) {
      bool continues = s + 1 < size() && yarn_[s + 1] == yarn_[s];
      graph_.yarn_next[s] = continues ? s + 1 : kNoStitch;
      graph_.yarn_link[s] = continues ? YarnLink::course : YarnLink::none;
    }
  }

  // Every in-link is a wale loop. AutoKnit lists a stitch's ins and outs in the order its yarn
  // meets them (its tracer swaps them for a clockwise stitch); a knit graph counts slots from
  // the left, right side facing.
  void add_loops() {
    for (StitchId s = 0; s < size(); ++s) {
      for (std::uint8_t in_slot = 0; in_slot < links_[s].in.size(); ++in_slot) {
        std::int32_t maker = links_[s].in[in_slot];
        if (maker == kNone) continue;
        auto m = static_cast<StitchId>(maker);
        std::uint8_t taker_slot = from_left(s, links_[s].in, in_slot);
        graph_.loops.push_back(
            Loop{m, s, LoopKind::wale, maker_slot(m, s, taker_slot), taker_slot});
      }
    }
  }

  std::uint8_t from_left(StitchId s, const Slots& slots, std::uint8_t slot) const {
    bool two = slots[0] != kNone && slots[1] != kNone;
    return two && !anticlockwise_[s] ? static_cast<std::uint8_t>(1 - slot) : slot;
  }

  // Does stitch s begin a row, the current one having begun at `row_start`? It does when the
  // yarn starts there, where AutoKnit's dir flips (a turn: a machine's wrap, a tuck on the
  // needle past the turn, goes the new row's way though it takes an older loop), when it takes a
  // loop made earlier in the current row (the yarn came round the tube or back along the sheet),
  // and where a bind-off ends and the yarn goes on to other sts (test-B.st's second leg). A
  // bind-off begins in the row it ends: where a helix steps up a st before it (`k1`, then the rest
  // bound off) the yarn goes on along the row, and it comes round to that st after the others.
  bool starts_row(StitchId s, StitchId row_start) const {
    if (s == 0 || graph_.yarn_next[s - 1] != s) return true;
    if (anticlockwise_[s] != anticlockwise_[s - 1]) return true;  // the yarn turned
    for (std::int32_t maker : links_[s].in)
      if (maker != kNone && static_cast<StitchId>(maker) >= row_start) return true;
    return graph_.type[s] != StitchType::bo && graph_.type[s - 1] == StitchType::bo;
  }

  // The rows a knitter sees, in one pass along the yarns (stitches are in knitting order, and
  // each row is a run of consecutive lines). Between two rows of one yarn AutoKnit's dir flips
  // at a turn (the work is turned) and stays at a shift (the yarn goes on round the tube).
  void infer_rows() {
    std::vector<std::uint32_t> piece_of_row;
    std::vector<bool> tube;          // per yarn piece: its yarn goes round at least once
    std::vector<bool> touches_turn;  // per row: it ends at a turn or begins after one
    StitchId row_start = 0;
    for (StitchId s = 0; s < size(); ++s) {
      if (starts_row(s, row_start)) {
        bool new_piece = s == 0 || graph_.yarn_next[s - 1] != s;
        bool turn = !new_piece && anticlockwise_[s] != anticlockwise_[s - 1];
        if (new_piece) tube.push_back(false);
        if (!new_piece) link_rows(s, turn);
        if (!new_piece && !turn) tube.back() = true;
        if (turn) touches_turn.back() = true;
        touches_turn.push_back(turn);
        piece_of_row.push_back(static_cast<std::uint32_t>(tube.size() - 1));
        row_start = s;
      }
      graph_.row[s] = static_cast<std::uint32_t>(touches_turn.size() - 1);
    }
    // A piece worked flat has open rows; in a tube the rows that turn, or begin after a
    // turn, are short rows, the others whole rounds.
    for (std::size_t r = 0; r < touches_turn.size(); ++r)
      graph_.row_shape.push_back(!tube[piece_of_row[r]] ? RowShape::open
                                 : touches_turn[r]      ? RowShape::short_row
                                                        : RowShape::closed);
  }

  void link_rows(StitchId s, bool turn) {
    graph_.yarn_link[s - 1] = turn ? YarnLink::turn : YarnLink::shift;
    if (!turn) graph_.flags[s] |= kShiftPathStart;
  }

  // Which of `maker`'s loops (from the left) feeds the loop `taker_slot` (from the left) of
  // `taker`: the n-th mention of the taker among the maker's outs, for the n-th mention of the
  // maker among the taker's ins, both counted from the left (a decrease taking both loops of
  // an increase takes them side by side, not crossed).
  std::uint8_t maker_slot(StitchId maker, StitchId taker, std::uint8_t taker_slot) const {
    const Slots& ins = links_[taker].in;
    int nth = 0;
    for (std::uint8_t i = 0; i < taker_slot; ++i)
      nth += ins[from_left(taker, ins, i)] == static_cast<std::int32_t>(maker);
    const Slots& outs = links_[maker].out;
    for (std::uint8_t o = 0; o < outs.size(); ++o)
      if (outs[from_left(maker, outs, o)] == static_cast<std::int32_t>(taker) && nth-- == 0)
        return o;
    SKEIN_ASSERT(false, "links are mirrored (checked while parsing)");
    return 0;
  }

  std::string file_name_;
  std::vector<std::string_view> lines_;
  std::vector<std::uint32_t> yarn_;
  std::vector<bool> anticlockwise_;  // AutoKnit's dir: a (true) or c
  std::vector<Links> links_;
  std::vector<std::array<double, 3>>* positions_;
  KnitGraph graph_;
};

}  // namespace

KnitGraph parse_autoknit_st(std::string_view text, const std::string& file_name,
                            std::vector<std::array<double, 3>>* positions) {
  return StParser(text, file_name, positions).parse();
}

KnitGraph read_autoknit_st(const std::string& path) {
  return parse_autoknit_st(read_file(path), path);
}

}  // namespace skein
