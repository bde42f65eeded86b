#include "hand/needle_sim.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>

namespace skein::hand {

std::uint8_t Fabric::rs_slot(std::uint32_t loop) const {
  std::uint32_t maker = loop_maker[loop];
  bool left = picked_from[maker] == kLeftEdge;
  if (loop_picked[loop]) return left ? 0 : static_cast<std::uint8_t>(made[maker] - 1);
  auto worked = static_cast<std::uint8_t>(made[maker] - (picked_from[maker] != kNoEdge));
  std::uint8_t slot = facing[maker] == Side::rs
                          ? static_cast<std::uint8_t>(worked - 1 - loop_index[loop])
                          : loop_index[loop];
  return static_cast<std::uint8_t>(slot + left);
}

std::vector<std::uint32_t> Fabric::rs_taken(std::uint32_t stitch) const {
  std::vector<std::uint32_t> loops(taken.begin() + taken_first[stitch],
                                   taken.begin() + taken_first[stitch + 1]);
  // Facing the RS the knitter works right to left: the first loop taken is the rightmost.
  if (facing[stitch] == Side::rs) std::reverse(loops.begin(), loops.end());
  return loops;
}

std::string Fabric::row_label(std::uint32_t r) const {
  const RowWorked& w = rows[r];
  if (w.join) return "Three-needle bind-off";
  if (w.number == 0) return "Cast on";
  std::string word = w.round ? "Rnd" : "Row";
  std::string label = w.round ? fmt::format("Rnd {}", w.number)
                              : fmt::format("Row {} ({})", w.number, side_name(w.side));
  if (w.repeat_of) label += fmt::format(", {} {} again", word, w.repeat_of);
  return label;
}

std::string Fabric::describe(std::uint32_t s) const {
  return fmt::format("{}, st {} ({})", row_label(row[s]), position[s], abbreviation(type[s]));
}

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr std::uint32_t kMarkerBit = 0x80000000u;  // needle entries: a loop, or a marker

bool is_marker_entry(std::uint32_t entry) {
  return entry & kMarkerBit;
}

std::string sts(std::uint32_t n) {
  return fmt::format("{} st{}", n, n == 1 ? "" : "s");
}

// An impossible step: where, and why.
struct StepFailure {
  std::string message;
};

class NeedleSimulator {
 public:
  NeedleSimulator(const Script& script, const std::string& file, std::uint64_t max_work)
      : script_(script), file_(file), max_work_(max_work) {
    work_even_.resize(2);
    for (HandOp op : {HandOp::k, HandOp::p}) {
      Program& p = work_even_[op == HandOp::k ? 0 : 1];
      p.nodes.push_back({Node::Kind::op, op, 1, {Until::Kind::end, 0}});
      p.top_end = 1;
    }
  }

  Replay run() && {
    const Step* step = nullptr;
    try {
      for (const Step& s : script_.steps) {
        step = &s;
        do_step(s);
      }
      finish();
    } catch (const StepFailure& f) {
      out_.ok = false;
      out_.failure = step ? fmt::format("{}:{}: {}", file_, step->line, f.message)
                          : fmt::format("{}: {}", file_, f.message);
    }
    return std::move(out_);
  }

 private:
  Fabric& fab() { return out_.fabric; }

  [[noreturn]] void fail(const std::string& why) const {
    throw StepFailure{in_row_ ? fmt::format("{}: {}", out_.fabric.row_label(row_), why) : why};
  }

  void do_step(const Step& s) {
    switch (s.kind) {
      case Step::Kind::piece:
        if (s.number != 0 && s.number != fab().piece_first.size() + 1 &&
            !set_aside_.contains(s.number))
          fail(fmt::format("Piece {} comes next (or one set aside), not Piece {}",
                           fab().piece_first.size() + 1, s.number));
        break;
      case Step::Kind::cast_on:
        cast_on(s.count, s.provisional);
        break;
      case Step::Kind::carry_on:
        carry_on(s);
        break;
      case Step::Kind::join_spare:
        join_spare(s);
        break;
      case Step::Kind::pick_up:
        pick_up(s);
        check_printed_count(s, "Pick up");
        break;
      case Step::Kind::join_round:
        join(s);
        break;
      case Step::Kind::row:
        work_rows(s);
        break;
      case Step::Kind::repeat_rows:
        repeat_rows(s);
        break;
      case Step::Kind::work_even:
        work_even(s);
        break;
      case Step::Kind::fasten_off:
        fasten_off();
        break;
      case Step::Kind::leave:
        leave(s.count);
        break;
      case Step::Kind::set_aside:
        set_aside(s.count);
        break;
      case Step::Kind::take_up:
        take_up(s.number);
        break;
      case Step::Kind::place:
        place(s);
        check_printed_count(s, "Place the sts");
        break;
      case Step::Kind::three_needle_bind_off:
        three_needle_bind_off(s);
        break;
      case Step::Kind::hold_behind:
        hold_behind(s);
        break;
      case Step::Kind::hold:
        hold(s);
        check_printed_count(s, "Slip sts to holders");
        break;
      case Step::Kind::hold_all:
        hold_all(s);
        break;
      case Step::Kind::place_on_spare:
        place_on_spare_needle(s);
        break;
      case Step::Kind::to_spare:
        put_on_spare_needle(s);
        break;
    }
  }

  // --- pieces -------------------------------------------------------------------------------

  // A provisional cast-on makes each st with two loops (a cast-on along a split): one on the
  // needle, one in the waste-yarn chain, which waits on a spare needle for the other side.
  void cast_on(std::uint32_t n, bool provisional) {
    if (active_ && pc_.live > 0)
      fail(fmt::format("Cast on: the piece before still has {} on the needle", sts(pc_.live)));
    if (n == 0) fail("Cast on: no sts to cast on");
    start_piece();
    fab().rows.push_back({0, 0, 0, false, Side::rs});
    row_ = static_cast<std::uint32_t>(fab().rows.size() - 1);
    facing_ = provisional ? Side::ws : Side::rs;  // the needle's loop first, seen from the RS
    for (std::uint32_t i = 0; i < n; ++i) cast_on_st(provisional);
    pc_.live = n;
  }

  // One st cast on onto the right needle; a provisional one also makes the loop of its
  // waste-yarn chain, which waits on a spare needle for the other side of the split.
  void cast_on_st(bool provisional) {
    std::uint32_t x = new_stitch(provisional ? StitchType::sco : StitchType::co);
    fab().taken_first.push_back(static_cast<std::uint32_t>(fab().taken.size()));
    pc_.right.push_back(new_loop(x));
    if (provisional) spare_needles_[{pc_.number, kChain}].push_back(new_loop(x));
  }

  // "CO 3 sts with a provisional cast-on" in the middle of a row: as a provisional cast-on of
  // its own, the needle's loop first seen from the RS; the chain joins the piece's chain.
  void provisional_cast_on_in_row() {
    Side facing = facing_;
    facing_ = Side::ws;
    cast_on_st(true);
    facing_ = facing;
    ++pc_.live;
    row_last_stitch_ = pc_.last_stitch;
    last_make_.reset();
  }

  // A new piece worked from loops picked up along an edge of a finished piece, one in each
  // of its rows: the loop of the st at that edge, the last one picked up at the needle tip.
  void pick_up(const Step& given) {
    Step s = along_the_flap(given);
    if (!s.into_rnd && active_ && pc_.live > 0)
      fail(fmt::format("Pick up: the piece before still has {} on the needle", sts(pc_.live)));
    std::vector<std::uint32_t> rows = rows_of_piece(s.number);
    std::uint32_t low = std::min(s.from_row, s.to_row), high = std::max(s.from_row, s.to_row);
    for (std::uint32_t n : {low, high})
      if (n >= rows.size() || rows[n] == kNone)
        fail(fmt::format("Pick up: Piece {} has no {}", s.number,
                         n == 0 ? std::string("cast-on") : fmt::format("Row {}", n)));
    if (high - low + 1 != s.count)
      fail(fmt::format("Pick up: the pattern says {}, but there are {} rows from {} to {}",
                       sts(s.count), high - low + 1, low, high));
    if (s.into_rnd) return pick_up_into_rnd(s, rows);
    start_piece();
    fab().rows.push_back({0, 0, 0, false, Side::rs});
    row_ = static_cast<std::uint32_t>(fab().rows.size() - 1);
    for (std::uint32_t i = 0; i < s.count; ++i) {
      std::uint32_t n = s.from_row <= s.to_row ? s.from_row + i : s.from_row - i;
      pc_.right.push_back(pick_up_loop(rows, n, s.provisional));
    }
    pc_.live = s.count;
  }

  // "... along the left edge of the flap": the piece on the needle, picked up into its rnd (a
  // gusset).
  Step along_the_flap(Step s) const {
    if (s.number != 0) return s;
    if (!active_ || !s.into_rnd)
      fail("Pick up along the flap: only onto the needle of the piece worked, into its rnd");
    s.number = pc_.number;
    return s;
  }

  // Loops picked up along another piece's edge go into the rnd of the piece worked, the first
  // picked up worked first; counted as "Place" counts.
  void pick_up_into_rnd(const Step& s, const std::vector<std::uint32_t>& rows) {
    if (!active_ || !pc_.joined || !s.round)
      fail(fmt::format(
          "Pick up along Piece {} onto the needle: only into a piece worked in the rnd", s.number));
    std::vector<std::uint32_t> loops;
    for (std::uint32_t i = 0; i < s.count; ++i) {
      std::uint32_t n = s.from_row <= s.to_row ? s.from_row + i : s.from_row - i;
      loops.push_back(pick_up_loop(rows, n, s.provisional));
    }
    insert_into_rnd(loops, s.last, fmt::format("Pick up along Piece {}", s.number));
  }

  // Per row number of a piece (0: its cast-on), the row worked (kNone: none with stitches).
  std::vector<std::uint32_t> rows_of_piece(std::uint32_t piece) const {
    std::vector<std::uint32_t> rows;
    for (std::uint32_t r = 0; r < out_.fabric.rows.size(); ++r) {
      const Fabric::RowWorked& w = out_.fabric.rows[r];
      if (w.piece != piece || w.join) continue;
      if (rows.size() <= w.number) rows.resize(w.number + 1, kNone);
      rows[w.number] = r;
    }
    return rows;
  }

  // The loop picked up at the right (or left) edge of a row, seen from the RS: a row worked
  // with the RS facing starts at the right; a cast-on ends where the next row starts.
  std::uint32_t pick_up_loop(const std::vector<std::uint32_t>& rows, std::uint32_t n, bool right) {
    if (n >= rows.size() || rows[n] == kNone)  // a row between the two named
      fail(fmt::format("Pick up: Row {} worked no st to pick up from", n));
    Fabric& f = fab();
    const Fabric::RowWorked& row = f.rows[rows[n]];
    Side side =
        n == 0 && rows.size() > 1 && rows[1] != kNone ? other(f.rows[rows[1]].side) : row.side;
    bool first = (side == Side::rs) == right;
    std::uint32_t x = first ? row.first : row.last;
    if (f.picked_from[x] != Fabric::kNoEdge)
      fail(fmt::format("Pick up: {} already gave a st", f.describe(x)));
    std::uint32_t loop = new_loop(x);
    f.loop_picked[loop] = 1;
    f.picked_from[x] = right ? Fabric::kRightEdge : Fabric::kLeftEdge;
    return loop;
  }

  // A new piece worked from a spare needle's sts with a new yarn.
  void join_spare(const Step& s) {
    if (active_ && pc_.live > 0)
      fail(fmt::format("Join a new yarn: the piece before still has {} on the needle",
                       sts(pc_.live)));
    std::vector<std::uint32_t> loops =
        s.holder[0] ? held(s.number, s.from_last[0], "Join a new yarn")
                    : spare_needle(s.number, s.from_last[0], "Join a new yarn", s.provisional);
    if (loops.size() != s.count)
      fail(fmt::format("Join a new yarn: the pattern says {}, but the {} holds {}", sts(s.count),
                       s.holder[0] ? "holder" : "needle", loops.size()));
    begin_at_holder_st(loops, s);
    if (s.holder[0])
      holders_.erase(s.number);
    else
      spare_needles_.erase({s.number, s.provisional ? kChain : kNeedle});
    start_piece();
    fab().rows.push_back({0, 0, 0, false, Side::rs});
    row_ = static_cast<std::uint32_t>(fab().rows.size() - 1);
    pc_.right.assign(loops.rbegin(), loops.rend());
    pc_.live = s.count;
    pc_.joined_to_sts = true;
  }

  // "; the rnd begins at its st 6": the holder's sts (tip first) go round from its 6th
  // slipped, the way the st named at the tip says.
  void begin_at_holder_st(std::vector<std::uint32_t>& loops, const Step& s) const {
    if (s.from_row == 0) return;
    if (s.from_row > loops.size())
      fail(fmt::format("Join a new yarn: holder {} has no st {}", s.number, s.from_row));
    std::size_t tip = s.from_last[0] ? loops.size() - s.from_row : s.from_row - 1;
    std::rotate(loops.begin(), loops.begin() + static_cast<std::ptrdiff_t>(tip), loops.end());
  }

  // A new piece with its own yarn and needles.
  // A flat piece's first row works the cast-on from its last st (turn_before).
  void start_piece() {
    active_ = true;
    facing_ = Side::rs;
    fab().piece_first.push_back(fab().size());
    pc_ = Piece{};
    pc_.number = static_cast<std::uint32_t>(fab().piece_first.size());
    position_ = 0;
    next_link_ = YarnLink::course;
  }

  // "Do not fasten off: carry the yarn to the sts of holder 1": every st bound off, the yarn
  // goes on to a holder's sts (joined in the rnd next); the rows count on.
  void carry_on(const Step& s) {
    if (!active_) fail("Carry the yarn: no yarn is being worked");
    if (pc_.live > 0)
      fail(fmt::format("Carry the yarn to holder {}: {} still on the needle; bind them off first",
                       s.number, sts(pc_.live)));
    std::vector<std::uint32_t> loops = held(s.number, s.from_last[0], "Carry the yarn");
    if (loops.size() != s.count)
      fail(fmt::format("Carry the yarn: the pattern says {}, but the holder holds {}", sts(s.count),
                       loops.size()));
    holders_.erase(s.number);
    pc_.left.clear();
    pc_.right.assign(loops.rbegin(), loops.rend());
    pc_.live = s.count;
    pc_.joined = false;
    pc_.joined_to_sts = pc_.carried = true;
    pc_.bor = kNone;
  }

  // Before a piece's first row, or after its yarn is carried to held sts; or a flat piece in
  // the middle of its work.
  void join(const Step& s) {
    if (active_ && pc_.next_number != 1 && !pc_.joined && !pc_.carried) return join_flat_piece(s);
    if (!active_ || (pc_.next_number != 1 && !pc_.carried) || pc_.joined)
      fail(
          "Join to work in the rnd: only before a piece's first row, or after the yarn is carried "
          "to held sts");
    pc_.carried = false;
    pc_.joined = true;
    // The first rnd starts with the first st cast on, or with the st at the tip of the sts a
    // yarn was joined to.
    if (pc_.joined_to_sts) std::reverse(pc_.right.begin(), pc_.right.end());
    pc_.turn_before = false;
    pc_.place_bor = s.marker;
  }

  // A flat piece joined to work in the rnd in the middle of its work: its last row's sts were
  // slipped to a holder; the BOR marker goes where the yarn is (the tip of the right needle),
  // and the sts picked up and placed next go in after it.
  void join_flat_piece(const Step& s) {
    auto of_last_row = [&](std::uint32_t entry) { return made_by_last_row(entry); };
    if (std::any_of(pc_.right.begin(), pc_.right.end(), of_last_row) ||
        std::any_of(pc_.left.begin(), pc_.left.end(), of_last_row))
      fail(fmt::format(
          "Join to work in the rnd: the sts of Row {} are still on the needle (slip them to a "
          "holder first: the rnd is made of the sts picked up and placed, and those left)",
          pc_.next_number - 1));
    if (!s.marker)
      fail("Join to work in the rnd: pm for the beginning of the rnd first (where the yarn is)");
    pc_.joined = true;
    pc_.right.push_back(pc_.bor = new_marker());
  }

  void fasten_off() {
    if (!active_) fail("Fasten off: no yarn is being worked");
    if (pc_.live > 0)
      fail(fmt::format("Fasten off: {} still on the needle; bind them off first", sts(pc_.live)));
    active_ = false;
  }

  void check_live(std::uint32_t n, const char* what) const {
    if (!active_) fail(fmt::format("{}: no piece is being worked", what));
    if (n != pc_.live)
      fail(fmt::format("{}: the pattern says {}, but {} on the needle", what, sts(n),
                       pc_.live == 1 ? "1 st is" : fmt::format("{} sts are", pc_.live)));
  }

  // A count printed after a sentence that changes what is on the needle ("— 36 sts").
  void check_printed_count(const Step& s, const char* what) {
    if (!s.sts) return;
    ++out_.counts_checked;
    check_live(*s.sts, what);
  }

  // The piece waits, sts and yarn, until it is taken up again.
  void set_aside(std::uint32_t n) {
    check_live(n, "Leave the sts");
    set_aside_[pc_.number] = std::move(pc_);
    active_ = false;
  }

  void take_up(std::uint32_t number) {
    if (active_ && pc_.live > 0)
      fail(fmt::format("Take up Piece {}: the piece before still has {} on the needle", number,
                       sts(pc_.live)));
    auto at = set_aside_.find(number);
    if (at == set_aside_.end()) fail(fmt::format("Take up Piece {}: it was not set aside", number));
    pc_ = std::move(at->second);
    set_aside_.erase(at);
    active_ = true;
  }

  // The sts of a spare needle join the rnd of the piece being worked, after the first `last`
  // sts from the beginning of the rnd (or, when a row across a gap removed its marker, from
  // where the next rnd starts).
  void place(const Step& s) {
    if (active_ && !pc_.joined && !s.round) return place_into_row(s);
    if (!active_ || !pc_.joined || !s.round)
      fail(fmt::format("Place the sts of Piece {}: only into a piece worked in the rnd{}", s.number,
                       active_ && !s.round ? " (count them 'of the rnd')" : ""));
    insert_into_rnd(sts_to_place(s), s.last, placing(s));
    release_placed(s);
  }

  static std::string placing(const Step& s) {
    return fmt::format("Place the sts of {} {}", s.holder[0] ? "holder" : "Piece", s.number);
  }

  // The sts a "Place" sentence takes from a holder, a spare needle or a chain, from the one it
  // names first; as many as it says.
  std::vector<std::uint32_t> sts_to_place(const Step& s) const {
    std::vector<std::uint32_t> placed =
        s.holder[0] ? held(s.number, s.from_last[0], "Place the sts")
                    : spare_needle(s.number, s.from_last[0], "Place the sts", s.provisional);
    start_at(placed, s);
    if (placed.size() != s.count)
      fail(fmt::format("{}: the pattern says {}, but {} holds {}", placing(s), sts(s.count),
                       s.holder[0]     ? "it"
                       : s.provisional ? "its chain"
                                       : "its needle",
                       placed.size()));
    return placed;
  }

  void release_placed(const Step& s) {
    if (s.holder[0])
      holders_.erase(s.number);
    else
      spare_needles_.erase({s.number, s.provisional ? kChain : kNeedle});
  }

  // On a flat piece the next row works them after the first `last` sts of the needle it works
  // (counted from its tip), the first placed next (the teapot's top, taken up on a chain).
  void place_into_row(const Step& s) {
    std::vector<std::uint32_t> placed = sts_to_place(s);
    std::vector<std::uint32_t>& next_row = pc_.turn_before ? pc_.right : pc_.left;
    auto at = next_row.end();
    for (std::uint32_t before = 0; before < s.last; --at) {
      if (at == next_row.begin())
        fail(fmt::format("{}: the row has only {}", placing(s), sts(before)));
      before += !is_marker_entry(*(at - 1));
    }
    next_row.insert(at, placed.rbegin(), placed.rend());
    pc_.live += s.count;
    release_placed(s);
  }

  // A holder's sts go back on a piece's spare needle (before it is folded), after its st
  // `last` counted round from the first st of its last row.
  void place_on_spare_needle(const Step& s) {
    std::string what = fmt::format("Place the sts of holder {}", s.number);
    std::vector<std::uint32_t> placed = held(s.number, s.from_last[0], what.c_str());
    if (placed.size() != s.count)
      fail(fmt::format("{}: the pattern says {}, but it holds {}", what, sts(s.count),
                       placed.size()));
    std::vector<std::uint32_t> ring = spare_needle(s.to_row, false, what.c_str());
    if (s.last > ring.size())
      fail(fmt::format("{}: the spare needle of Piece {} has no st {}", what, s.to_row, s.last));
    ring.insert(ring.begin() + s.last, placed.begin(), placed.end());
    if (s.sts && (++out_.counts_checked, *s.sts != ring.size()))
      fail(fmt::format("{}: the pattern says {}, but the spare needle holds {}", what, sts(*s.sts),
                       ring.size()));
    spare_needles_[{s.to_row, kNeedle}] = ring;
    holders_.erase(s.number);
  }

  // "..., st 16 of its last rnd first": the placed sts go round from that one.
  void start_at(std::vector<std::uint32_t>& placed, const Step& s) const {
    if (s.from_row > placed.size())
      fail(fmt::format("Place the sts of Piece {}: its needle holds no st {}", s.number,
                       s.from_row));
    if (s.from_row > 0) std::rotate(placed.begin(), placed.begin() + s.from_row - 1, placed.end());
  }

  // The loops go into the rnd after its first `after` sts, from the beginning-of-round marker.
  void insert_into_rnd(const std::vector<std::uint32_t>& loops, std::uint32_t after,
                       const std::string& what) {
    std::vector<std::uint32_t> ring = ring_from_bor();
    if (after > ring.size())
      fail(fmt::format("{}: the rnd has only {}", what,
                       sts(static_cast<std::uint32_t>(ring.size()))));
    ring.insert(ring.begin() + after, loops.begin(), loops.end());
    lay_out_from_bor(ring);
    pc_.live += static_cast<std::uint32_t>(loops.size());
  }

  // The loops of the rnd, the beginning-of-round marker first, go on the right needle, so that
  // the next rnd starts at the marker; after a row that turned, on the left one, where the turn
  // still to come puts them on the right.
  void lay_out_from_bor(const std::vector<std::uint32_t>& ring) {
    std::vector<std::uint32_t>& needle = pc_.turn_before ? pc_.left : pc_.right;
    needle.clear();
    if (pc_.bor != kNone) needle.push_back(pc_.bor);
    needle.insert(needle.end(), ring.begin(), ring.end());
    (pc_.turn_before ? pc_.right : pc_.left).clear();
  }

  // A holder's sts go on the spare needle that "sl1 from spare" takes from.
  // (Where two wait at once, the second goes on a second spare needle.)
  void put_on_spare_needle(const Step& s) {
    std::vector<std::uint32_t>& spare = spare_for_rows_[s.last];
    if (!spare.empty())
      fail(
          fmt::format("Put the sts of holder {} on a {}spare needle: the {}spare needle still "
                      "holds {}",
                      s.number, s.last ? "second " : "", s.last ? "second " : "",
                      sts(static_cast<std::uint32_t>(spare.size()))));
    std::vector<std::uint32_t> loops = held(s.number, s.from_last[0], "Put the sts");
    if (loops.size() != s.count)
      fail(fmt::format("Put the sts of holder {}: the pattern says {}, but it holds {}", s.number,
                       sts(s.count), loops.size()));
    holders_.erase(s.number);
    spare = std::move(loops);
  }

  // Sts A–B of the rnd, counted from the beginning-of-round marker, go to a holder of their
  // own (the reader gives the runs of one sentence last first, so the counts stay true).
  void hold(const Step& s) {
    if (s.of_row || s.of_cast_on) return hold_run_of_row(s);
    if (!active_ || !pc_.joined)
      fail(fmt::format("Slip sts to holder {}: only from a piece worked in the rnd", s.number));
    if (s.onto) check_held_before(s);
    if (!s.onto && holders_.contains(s.number))
      fail(fmt::format("Slip sts to holder {}: it already holds sts", s.number));
    if (s.from_row == 0) fail(fmt::format("Slip sts to holder {}: the sts count from 1", s.number));
    std::vector<std::uint32_t> ring = ring_from_bor();
    if (s.to_row > ring.size())
      fail(fmt::format("Slip sts {}\u2013{} to holder {}: the rnd has only {}", s.from_row,
                       s.to_row, s.number, sts(static_cast<std::uint32_t>(ring.size()))));
    auto first = ring.begin() + (s.from_row - 1), end = ring.begin() + s.to_row;
    holders_[s.number].insert(holders_[s.number].end(), first, end);
    ring.erase(first, end);
    lay_out_from_bor(ring);
    pc_.live -= s.to_row - s.from_row + 1;
  }

  // "Slip sts 1–8 of Row 57 to holder 7": a run of the sts the last row left on the needle,
  // counted in the order it worked them (the reader gives the runs last first, so the counts
  // stay true); the others stay. "Of the cast-on": of a piece only cast on, as cast on.
  void hold_run_of_row(const Step& s) {
    std::string what =
        fmt::format("Slip sts {}\u2013{} of {} to holder {}", s.from_row, s.to_row,
                    s.of_cast_on ? "the cast-on" : fmt::format("Row {}", s.of_row), s.number);
    if (!active_) fail(what + ": no piece is on the needle");
    if (holders_.contains(s.number)) fail(what + ": it already holds sts");
    if (s.of_row >= pc_.next_number)
      fail(fmt::format("{}: the last row worked is Row {}", what, pc_.next_number - 1));
    // An earlier row's sts left on the needle (a piece set aside after rows on others) count
    // as the last row's do.
    std::vector<std::uint32_t> row;
    for (const std::vector<std::uint32_t>* needle : {&pc_.right, &pc_.left})
      std::copy_if(needle->begin(), needle->end(), std::back_inserter(row),
                   [&](std::uint32_t entry) { return made_by_row(entry, s.of_row); });
    if (s.from_row == 0 || s.to_row > row.size())
      fail(fmt::format("{}: the {} left {} on the needle", what, s.of_cast_on ? "cast-on" : "row",
                       sts(static_cast<std::uint32_t>(row.size()))));
    std::vector<std::uint32_t> run(row.begin() + (s.from_row - 1), row.begin() + s.to_row);
    for (std::vector<std::uint32_t>* needle : {&pc_.right, &pc_.left})
      std::erase_if(*needle, [&](std::uint32_t entry) {
        return std::find(run.begin(), run.end(), entry) != run.end();
      });
    holders_[s.number] = std::move(run);
    pc_.live -= s.to_row - s.from_row + 1;
  }

  // "(after the 1 st on it)": the holder must hold that many sts.
  void check_held_before(const Step& s) const {
    auto at = holders_.find(s.number);
    auto held = static_cast<std::uint32_t>(at == holders_.end() ? 0 : at->second.size());
    if (held != s.count)
      fail(fmt::format("Slip sts to holder {} after the {} on it: it holds {}", s.number,
                       sts(s.count), held == 0 ? "no sts" : sts(held)));
  }

  // "Slip the 35 sts of Row 33 to holder 3": the sts a flat piece's last row left on the needle,
  // in the order it worked them (before the piece is joined in the rnd); the others stay.
  void hold_all(const Step& s) {
    std::string what = fmt::format("Slip the sts of Row {} to holder {}", s.from_row, s.number);
    if (!active_ || pc_.joined)
      fail(what + ": only from a piece worked flat (in the rnd, say which sts)");
    if (holders_.contains(s.number)) fail(what + ": it already holds sts");
    if (s.from_row + 1 != pc_.next_number)
      fail(fmt::format("{}: the last row worked is Row {}", what, pc_.next_number - 1));
    std::vector<std::uint32_t> held = sts_of_row_off_the_needle(s.from_row);
    if (held.size() != s.count)
      fail(fmt::format("{}: the pattern says {}, but the row left {} on the needle", what,
                       sts(s.count), sts(static_cast<std::uint32_t>(held.size()))));
    pc_.live -= s.count;
    holders_[s.number] = std::move(held);
    check_printed_count(s, "Slip the sts to holder");
  }

  // The loops the piece's row `number` (its last) made that are on the needles, in the order
  // it made them; taken off. (Another piece's rows may have come since: a piece taken up.)
  std::vector<std::uint32_t> sts_of_row_off_the_needle(std::uint32_t number) {
    std::vector<std::uint32_t> off;
    auto of_last_row = [&](std::uint32_t entry) { return made_by_row(entry, number); };
    for (std::vector<std::uint32_t>* needle : {&pc_.right, &pc_.left}) {
      std::copy_if(needle->begin(), needle->end(), std::back_inserter(off), of_last_row);
      std::erase_if(*needle, of_last_row);
    }
    return off;
  }

  // Made by Row `number` of the piece being worked.
  bool made_by_row(std::uint32_t entry, std::uint32_t number) {
    if (is_marker_entry(entry)) return false;
    const Fabric::RowWorked& r = fab().rows[fab().row[fab().loop_maker[entry]]];
    return r.piece == pc_.number && r.number == number;
  }

  bool made_by_last_row(std::uint32_t entry) {
    return !is_marker_entry(entry) && fab().row[fab().loop_maker[entry]] == row_;
  }

  // A holder's sts from the needle tip: the first or the last st of the run slipped to it.
  std::vector<std::uint32_t> held(std::uint32_t holder, bool from_last, const char* what) const {
    auto at = holders_.find(holder);
    if (at == holders_.end()) fail(fmt::format("{}: holder {} holds no sts", what, holder));
    std::vector<std::uint32_t> loops = at->second;
    if (from_last) std::reverse(loops.begin(), loops.end());
    return loops;
  }

  // The loops around the needle from the beginning-of-round marker on (markers left out).
  // A turn still to come (after a row that turned) swaps the needles first.
  std::vector<std::uint32_t> ring_from_bor() const {
    const std::vector<std::uint32_t>& ahead = pc_.turn_before ? pc_.right : pc_.left;
    const std::vector<std::uint32_t>& behind = pc_.turn_before ? pc_.left : pc_.right;
    std::vector<std::uint32_t> ring(ahead.rbegin(), ahead.rend());
    ring.insert(ring.end(), behind.begin(), behind.end());
    auto at = std::find(ring.begin(), ring.end(), pc_.bor);
    std::rotate(ring.begin(), at, ring.end());
    std::erase_if(ring, is_marker_entry);
    return ring;
  }

  // The piece's live sts wait on a spare needle, in the order its last row worked them (in
  // the rnd, after a row that turned, going on round the needle with those it left).
  void leave(std::uint32_t n) {
    check_live(n, "Leave the sts");
    std::vector<std::uint32_t>& spare = spare_needles_[{pc_.number, kNeedle}];
    for (std::uint32_t entry : pc_.right)
      if (!is_marker_entry(entry)) spare.push_back(entry);
    for (auto at = pc_.left.rbegin(); at != pc_.left.rend(); ++at)
      if (!is_marker_entry(*at)) spare.push_back(*at);
    start_at_last_row(spare);
    pc_.right.clear();
    pc_.left.clear();
    active_ = false;
    pc_.live = 0;
  }

  // After a row that turned in the rnd the right needle holds sts of earlier rows behind those
  // it worked: the ring starts at the row's first st.
  void start_at_last_row(std::vector<std::uint32_t>& ring) {
    const Fabric::RowWorked& last = fab().rows[row_];
    if (!pc_.joined || last.round || last.first == kNoStitch) return;
    auto at = std::find_if(ring.begin(), ring.end(), [&](std::uint32_t loop) {
      return fab().loop_maker[loop] == last.first;
    });
    if (at != ring.end()) std::rotate(ring.begin(), at, ring.end());
  }

  // Pairs the sts of two spare needles, each from the end the pattern puts at the tip, and
  // binds them off with a new yarn.
  // With its own yarn the front piece is the one being worked: its needle is the front one.
  void three_needle_bind_off(const Step& s) {
    if (s.fold) return folded_bind_off(s);
    std::uint32_t front = s.number, back = s.last, pairs = s.count;
    if (s.own_yarn && (!active_ || pc_.number != front))
      fail(fmt::format("three-needle bind-off with its yarn: Piece {} is not being worked", front));
    if (s.own_yarn)
      leave(pc_.live);
    else if (active_ && pc_.live > 0)
      fail(fmt::format("three-needle bind-off: the piece before still has {} on the needle",
                       sts(pc_.live)));
    auto needle = [&](int side) {
      std::uint32_t n = side == 0 ? front : back;
      bool from_last = s.from_last[side] && s.tip[side] == 0;
      std::vector<std::uint32_t> sts = s.holder[side]
                                           ? held(n, from_last, "three-needle bind-off")
                                           : spare_needle(n, from_last, "three-needle bind-off");
      if (s.tip[side] == 0) return sts;
      return round_from(sts, s.tip[side], s.from_last[side],
                        fmt::format("{} {}", s.holder[side] ? "holder" : "Piece", n));
    };
    std::vector<std::uint32_t> f = needle(0), b = needle(1);
    if (f.size() != b.size())
      fail(fmt::format("three-needle bind-off: {} on front needle, {} on back", sts(f.size()),
                       b.size()));
    if (f.size() != pairs)
      fail(fmt::format("three-needle bind-off: the pattern says {} pairs, but the needles hold {}",
                       pairs, f.size()));
    if (s.own_yarn) {
      // The yarn turns from the front piece's last row when its last st is at the tip; with
      // its first st there, the yarn goes on round from the end of its last rnd into it.
      bool round = pc_.joined;
      active_ = true;
      next_link_ = !s.from_last[0] && round ? YarnLink::shift : YarnLink::turn;
    } else {
      start_piece();
    }
    bind_off_pairs(f, b);
    for (int side : {0, 1}) {
      std::uint32_t n = side == 0 ? front : back;
      if (s.holder[side])
        holders_.erase(n);
      else
        spare_needles_.erase({n, kNeedle});
    }
  }

  // A needle's sts from st `tip` (1-based) at the tip, the others following round the needle,
  // down (towards st 1) or up.
  std::vector<std::uint32_t> round_from(const std::vector<std::uint32_t>& sts, std::uint32_t tip,
                                        bool down, const std::string& whose) const {
    auto n = static_cast<std::uint32_t>(sts.size());
    if (tip > n) fail(fmt::format("three-needle bind-off: {} has no st {}", whose, tip));
    std::vector<std::uint32_t> run;
    for (std::uint32_t i = 0; i < n; ++i)
      run.push_back(sts[down ? (tip - 1 + n - i) % n : (tip - 1 + i) % n]);
    return run;
  }

  void bind_off_pairs(const std::vector<std::uint32_t>& f, const std::vector<std::uint32_t>& b) {
    fab().rows.push_back({0, 0, 0, false, Side::ws, true});
    row_ = static_cast<std::uint32_t>(fab().rows.size() - 1);
    facing_ = Side::ws;  // the front piece shows its WS: its loop is taken first
    for (std::size_t i = 0; i < f.size(); ++i) {
      new_stitch(StitchType::tnbo);
      fab().taken.push_back(f[i]);
      fab().taken.push_back(b[i]);
      fab().taken_first.push_back(static_cast<std::uint32_t>(fab().taken.size()));
    }
  }

  // One piece's spare needle folded in half, counted round from the first st of its last row:
  // each needle's run goes from its tip, down or up (round past either end), with a new yarn.
  void folded_bind_off(const Step& s) {
    if (active_ && pc_.live > 0)
      fail(fmt::format("three-needle bind-off: the piece before still has {} on the needle",
                       sts(pc_.live)));
    std::vector<std::uint32_t> ring = spare_needle(s.number, false, "three-needle bind-off");
    if (ring.size() != s.last)
      fail(fmt::format("three-needle bind-off: the pattern folds {}, but Piece {} has {}",
                       sts(s.last), s.number, sts(static_cast<std::uint32_t>(ring.size()))));
    if (2 * s.count != ring.size())
      fail(fmt::format("three-needle bind-off: {} pairs do not fold {} in half", s.count,
                       sts(s.last)));
    std::vector<std::uint32_t> f = folded_run(s, 0, ring), b = folded_run(s, 1, ring);
    std::vector<std::uint32_t> all(f);
    all.insert(all.end(), b.begin(), b.end());
    std::sort(all.begin(), all.end());
    if (std::adjacent_find(all.begin(), all.end()) != all.end())
      fail("three-needle bind-off: the front and back needles share sts");
    start_piece();
    bind_off_pairs(f, b);
    spare_needles_.erase({s.number, kNeedle});
  }

  std::vector<std::uint32_t> folded_run(const Step& s, int side,
                                        const std::vector<std::uint32_t>& ring) const {
    auto n = static_cast<std::uint32_t>(ring.size());
    if (s.tip[side] < 1 || s.tip[side] > n)
      fail(fmt::format("three-needle bind-off: Piece {} has no st {}", s.number, s.tip[side]));
    std::vector<std::uint32_t> run;
    std::uint32_t at = s.tip[side] - 1;
    for (std::uint32_t i = 0; i < s.count; ++i) {
      run.push_back(ring[at]);
      if (i + 1 < s.count) at = s.from_last[side] ? (at + n - 1) % n : (at + 1) % n;
    }
    if (at + 1 != s.end[side])
      fail(fmt::format("three-needle bind-off: {} sts from st {} {} end at st {}, not {}", s.count,
                       s.tip[side], s.from_last[side] ? "down" : "up", at + 1, s.end[side]));
    return run;
  }

  // The sts from the needle tip: the first or the last st of the piece's last row.
  // A spare needle held behind the work for "3-needle BO" in the rows that follow, from the
  // end the sentence names.
  void hold_behind(const Step& s) {
    if (!active_) fail(fmt::format("Hold the sts of Piece {}: no piece is being worked", s.number));
    const char* what = s.holder[0] ? "holder" : "Piece";
    std::vector<std::uint32_t> sts_held =
        s.holder[0] ? held(s.number, s.from_last[0], "Hold the sts")
                    : spare_needle(s.number, s.from_last[0], "Hold the sts");
    if (sts_held.size() != s.count)
      fail(fmt::format("Hold the sts of {} {}: the pattern says {}, but its needle holds {}", what,
                       s.number, sts(s.count), sts_held.size()));
    held_behind_.insert(held_behind_.end(), sts_held.begin(), sts_held.end());
    if (s.holder[0])
      holders_.erase(s.number);
    else
      spare_needles_.erase({s.number, kNeedle});
  }

  std::vector<std::uint32_t> spare_needle(std::uint32_t piece, bool from_last, const char* what,
                                          bool chain = false) const {
    auto at = spare_needles_.find({piece, chain ? kChain : kNeedle});
    if (at == spare_needles_.end())
      fail(fmt::format("{}: {} of Piece {} {} not waiting on a spare needle", what,
                       chain ? "the chain" : "the sts", piece, chain ? "is" : "are"));
    std::vector<std::uint32_t> loops = at->second;
    if (from_last) std::reverse(loops.begin(), loops.end());
    return loops;
  }

  void finish() {
    if (fab().piece_first.empty()) throw StepFailure{"the pattern casts nothing on"};
    if (!set_aside_.empty())
      throw StepFailure{
          fmt::format("Piece {} is set aside and never taken up again", set_aside_.begin()->first)};
    if (!spare_needles_.empty())
      throw StepFailure{
          fmt::format("the {} of Piece {} {} left on a spare needle, never worked",
                      spare_needles_.begin()->first.second == kChain ? "chain" : "sts",
                      spare_needles_.begin()->first.first,
                      spare_needles_.begin()->first.second == kChain ? "is" : "are")};
    for (const std::vector<std::uint32_t>& spare : spare_for_rows_)
      if (!spare.empty())
        throw StepFailure{fmt::format("{} left on the spare needle, never worked",
                                      sts(static_cast<std::uint32_t>(spare.size())))};
    if (!holders_.empty())
      throw StepFailure{fmt::format("the sts of holder {} are left on it, never worked",
                                    holders_.begin()->first)};
    if (active_ && pc_.live > 0)
      throw StepFailure{fmt::format("the pattern ends with {} still on the needle", sts(pc_.live))};
  }

  // --- rows ---------------------------------------------------------------------------------

  void check_kind(bool round_label, const char* what) const {
    if (!active_)
      throw StepFailure{
          set_aside_.empty()
              ? fmt::format("{}: no sts are on the needle (cast on first)", what)
              : fmt::format("{}: no sts are on the needle (take up Piece {} again first)", what,
                            set_aside_.begin()->first)};
    // Joined work has rnds, and rows where it turns (short rows).
    if (round_label && !pc_.joined)
      throw StepFailure{fmt::format(
          "{}: the work is flat (never joined in the rnd), so it has rows, not rnds", what)};
  }

  void work_rows(const Step& s) {
    check_kind(s.round, s.round ? "Rnd" : "Row");
    if (s.number != pc_.next_number)
      throw StepFailure{fmt::format("{} {} comes next, not {} {}", s.round ? "Rnd" : "Row",
                                    pc_.next_number, s.round ? "Rnd" : "Row", s.number)};
    for (std::uint32_t n = s.number; n <= s.last; ++n) {
      if (pc_.defined.size() <= n) pc_.defined.resize(n + 1, kNone);
      pc_.defined[n] = s.program;
      work_row(script_.programs[s.program], s.round, 0, n == s.number ? label_of(s) : std::nullopt,
               s.line);
    }
    check_count(s);
  }

  void repeat_rows(const Step& s) {
    std::string what =
        s.number == s.last
            ? fmt::format("Rep {} {}", s.round ? "Rnd" : "Row", s.number)
            : fmt::format("Rep {} {}\u2013{}", s.round ? "Rnds" : "Rows", s.number, s.last);
    check_kind(s.round, what.c_str());
    for (std::uint32_t n = s.number; n <= s.last; ++n)
      if (n >= pc_.defined.size() || pc_.defined[n] == kNone)
        throw StepFailure{
            fmt::format("{}: {} {} is not written out above", what, s.round ? "Rnd" : "Row", n)};
    if (s.last + 1 != pc_.next_number)
      throw StepFailure{fmt::format("{}: the rows to repeat must be the last ones worked ({} {})",
                                    what, s.round ? "Rnd" : "Row", pc_.next_number - 1)};
    for (std::uint32_t t = 0; t < s.count; ++t)
      for (std::uint32_t n = s.number; n <= s.last; ++n) {
        std::uint32_t number = pc_.next_number;
        if (pc_.defined.size() <= number) pc_.defined.resize(number + 1, kNone);
        pc_.defined[number] = pc_.defined[n];
        work_row(script_.programs[pc_.defined[n]], s.round, n, std::nullopt, s.line);
      }
    check_count(s);
  }

  void work_even(const Step& s) {
    check_kind(s.round, s.round ? "every rnd" : "every row");
    if (s.count < pc_.next_number)
      throw StepFailure{fmt::format("until {} {} in all: {} are already worked", s.count,
                                    s.round ? "rnds" : "rows", pc_.next_number - 1)};
    std::uint32_t program = s.op == HandOp::k ? 0 : 1;
    while (pc_.next_number <= s.count)
      work_row(work_even_[program], s.round, 0, std::nullopt, s.line);
  }

  void check_count(const Step& s) {
    if (!s.sts) return;
    ++out_.counts_checked;
    if (*s.sts != pc_.live)
      throw StepFailure{fmt::format(
          "{}: the pattern says {}, but {} on the needle", fab().row_label(row_), sts(*s.sts),
          pc_.live == 1 ? "1 st is" : fmt::format("{} sts are", pc_.live))};
  }

  // The side a written row says faces the knitter. A rnd without (WS) is worked with the RS
  // facing; a flat row without a side follows from the turns.
  static std::optional<Side> label_of(const Step& s) {
    return s.round ? s.side.value_or(Side::rs) : s.side;
  }

  // A row turns the work first when the one before ended at a turn (every flat row does);
  // after a rnd, or a row that did not turn, the work goes on in the same direction. The first
  // row of a piece says which side faces (a rnd (WS): the tube is worked inside out).
  Side facing_of(std::optional<Side> label) const {
    if (!pc_.last_side) return label.value_or(Side::rs);
    return pc_.turn_before ? other(*pc_.last_side) : *pc_.last_side;
  }

  void work_row(const Program& p, bool round, std::uint32_t repeat_of, std::optional<Side> label,
                std::size_t line) {
    Side facing = facing_of(label);
    fab().rows.push_back({line, pc_.next_number, repeat_of, round, facing});
    row_ = static_cast<std::uint32_t>(fab().rows.size() - 1);
    in_row_ = true;
    row_round_ = round;
    if (round && label == Side::rs && facing == Side::ws)
      fail(
          "the WS faces you (the work was turned): a rnd worked with the WS facing is "
          "labelled (WS)");
    if (label && *label != facing)
      fail(fmt::format("labelled {}, but the {} faces you: {}", side_name(*label),
                       side_name(facing),
                       !pc_.turn_before ? "the work was not turned"
                       : !pc_.joined    ? "every row turns the work"
                                        : "the work was turned"));
    begin_row(facing);
    run_nodes(p, p.top_begin, p.top_end);
    end_row();
    in_row_ = false;
    pc_.last_side = facing;
    ++pc_.next_number;
    ++(round ? out_.rounds : out_.rows);
  }

  void begin_row(Side facing) {
    facing_ = facing;
    position_ = 0;
    row_last_stitch_ = kNone;
    row_ended_ = not_turned_ = false;
    pending_.clear();
    last_make_ = std::nullopt;
    next_link_ = pc_.turn_before ? YarnLink::turn : YarnLink::shift;
    if (pc_.turn_before) pc_.left.swap(pc_.right);
    if (row_round_)
      gather_round();
    else if (!pc_.turn_before)
      slip_bor_if_next();
    place_bor_before_first_row();
    index_left_needle();
  }

  // "Pm and join to work in the rnd" before a row (a short row first): the marker goes where
  // the row begins, as before a first rnd.
  void place_bor_before_first_row() {
    if (row_round_ || !pc_.place_bor) return;
    pc_.right.push_back(pc_.bor = new_marker());
    pc_.place_bor = false;
  }

  // A row that goes on from the end of a rnd starts, like a rnd, by slipping the marker.
  void slip_bor_if_next() {
    wrap_around();
    if (pc_.left.empty() || pc_.left.back() != pc_.bor) return;
    pc_.right.push_back(pc_.bor);
    pc_.left.pop_back();
  }

  // A rnd runs from here to the beginning-of-round marker (all the way round when the marker
  // is next: it is slipped): the loops before the marker go on the left needle, the marker
  // and the rest behind.
  void gather_round() {
    std::vector<std::uint32_t> ring(pc_.left.rbegin(), pc_.left.rend());  // from here onwards
    ring.insert(ring.end(), pc_.right.begin(), pc_.right.end());
    auto at = std::find(ring.begin(), ring.end(), pc_.bor);
    if (pc_.place_bor || at == ring.end()) {
      pc_.left.assign(ring.rbegin(), ring.rend());
      pc_.right.clear();
      if (pc_.place_bor) pc_.right.push_back(pc_.bor = new_marker());
      pc_.place_bor = false;
      return;
    }
    if (at == ring.begin()) {
      std::rotate(ring.begin(), ring.begin() + 1, ring.end());
      at = ring.end() - 1;
    }
    pc_.left.assign(std::make_reverse_iterator(at), ring.rend());
    pc_.right.assign(at, ring.end());
  }

  // In the rnd the needle has no end: a row that turns goes on past the last st on the left
  // needle to the first on the right one.
  void wrap_around() {
    if (!pc_.joined || row_round_ || !pc_.left.empty()) return;
    pc_.left.assign(pc_.right.rbegin(), pc_.right.rend());
    pc_.right.clear();
    index_left_needle();
  }

  // ... and a row that turns goes "to m" round to a marker beyond the last st on the left
  // needle (the BOR marker a stitch graph's short rows pass): the right needle's sts follow
  // the left needle's there.
  void look_round_for_marker() {
    bool beyond = std::any_of(pc_.right.begin(), pc_.right.end(), is_marker_entry);
    if (!pc_.joined || row_round_ || marker_ahead() || !beyond) return;
    pc_.left.insert(pc_.left.begin(), pc_.right.rbegin(), pc_.right.rend());
    pc_.right.clear();
    index_left_needle();
  }

  // ... and a row that turns may work the last st of the left needle together with the first
  // of the right one's far end (a decrease across a gap, on the other side of the needle).
  void reach_around(std::uint32_t takes) {
    if (!pc_.joined || row_round_ || left_loops_ >= takes || pc_.left.empty()) return;
    std::size_t moved = 0;
    while (left_loops_ + moved < takes && moved < pc_.right.size() &&
           !is_marker_entry(pc_.right[moved]))
      ++moved;
    pc_.left.insert(pc_.left.begin(), pc_.right.rend() - static_cast<std::ptrdiff_t>(moved),
                    pc_.right.rend());
    pc_.right.erase(pc_.right.begin(), pc_.right.begin() + static_cast<std::ptrdiff_t>(moved));
    index_left_needle();
  }

  void end_row() {
    const char* what = row_round_ ? "rnd" : "row";
    if (!row_ended_ && pc_.joined && !row_round_)
      fail("a row worked in the rnd ends where the work turns: end it with w&t or turn");
    if (!row_ended_ && left_loops_ > 0)
      fail(fmt::format("{} left unworked at the end of the {}", sts(left_loops_), what));
    if (!row_ended_ && !pc_.left.empty())
      fail(fmt::format("a marker is left at the end of the {}: slip it (sm) or remove it (rm)",
                       what));
    if (!held_behind_.empty())
      fail(fmt::format("{} held behind the needle left unworked at the end of the {}",
                       sts(static_cast<std::uint32_t>(held_behind_.size())), what));
    if (!pending_.empty())
      fail(fmt::format("{} with no st worked in the {} to go with it",
                       info(pending_.front().op).abbreviation, what));
    if (!row_round_ && last_make_ && *last_make_ != HandOp::yo)
      fail(fmt::format("{} at the end of a row: there is no strand after the last st to lift",
                       info(*last_make_).abbreviation));
    pc_.turn_before = (row_ended_ || !pc_.joined) && !not_turned_;
  }

  // For each place on the left needle, the loops from there to the next marker (the tip is at
  // the back), and whether a marker comes at all: "to m" in constant time.
  void index_left_needle() {
    to_marker_.resize(pc_.left.size());
    marker_ahead_.resize(pc_.left.size());
    left_loops_ = 0;
    for (std::size_t i = 0; i < pc_.left.size(); ++i) {
      bool marker = is_marker_entry(pc_.left[i]);
      to_marker_[i] = marker ? 0 : (i ? to_marker_[i - 1] : 0) + 1;
      marker_ahead_[i] = marker || (i && marker_ahead_[i - 1]);
      left_loops_ += !marker;
    }
  }

  std::uint32_t loops_to_marker() const {
    return pc_.left.empty() ? 0 : to_marker_[pc_.left.size() - 1];
  }
  // In the round the beginning-of-round marker ends the round: it counts as the last marker.
  bool end_is_marker() const { return row_round_ && pc_.bor != kNone; }
  bool marker_ahead() const {
    return (!pc_.left.empty() && marker_ahead_[pc_.left.size() - 1]) || end_is_marker();
  }

  // --- instructions -------------------------------------------------------------------------

  void run_nodes(const Program& p, std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t i = begin; i < end; ++i) run_node(p, p.nodes[i]);
  }

  // Every instruction and st worked counts against the work limit, so that repeats inside
  // repeats cannot run for minutes: each loop below works at least one of them per turn.
  void count_work() {
    if (++work_ > max_work_)
      fail(
          fmt::format("the pattern works more than {} sts and instructions, skein's limit "
                      "(docs/formats.md, \"Limits\")",
                      max_work_));
  }

  void run_node(const Program& p, const Node& n) {
    count_work();
    if (n.until.kind == Until::Kind::marker || n.until.kind == Until::Kind::before_marker)
      look_round_for_marker();
    switch (n.kind) {
      case Node::Kind::bind_off_all:
        while (!pc_.left.empty()) {
          if (is_marker_entry(pc_.left.back()))
            pc_.left.pop_back();  // binding off removes markers
          else
            apply(HandOp::bo);
        }
        return;
      case Node::Kind::op:
        if (n.until.kind == Until::Kind::count) {
          for (std::uint32_t t = 0; t < n.times; ++t) apply(n.op);
        } else {
          // "k to end" slips the markers it meets; "k to m" stops at the first.
          bool slips = n.until.kind == Until::Kind::end || n.until.kind == Until::Kind::last;
          std::uint32_t times = whole_repeats(n.until, info(n.op).takes, info(n.op).abbreviation);
          for (std::uint32_t t = 0; t < times; ++t) {
            while (slips && !pc_.left.empty() && is_marker_entry(pc_.left.back()))
              apply(HandOp::sm);
            apply(n.op);
          }
          while (n.until.kind == Until::Kind::end && !pc_.left.empty()) apply(HandOp::sm);
        }
        return;
      case Node::Kind::group:
        if (n.until.kind == Until::Kind::count) {
          for (std::uint32_t t = 0; t < n.times; ++t) run_nodes(p, n.first_child, n.end_child);
        } else if (auto takes = fixed_takes(p, n.first_child, n.end_child)) {
          std::uint32_t times = whole_repeats(n.until, *takes, "the repeat");
          for (std::uint32_t t = 0; t < times; ++t) run_nodes(p, n.first_child, n.end_child);
        } else {
          while (remaining(n.until, "the repeat") > 0) {
            std::uint32_t before = left_loops_;
            run_nodes(p, n.first_child, n.end_child);
            if (left_loops_ == before) fail("the repeat works no sts, so it never ends");
          }
        }
        return;
    }
  }

  // Loops one working of nodes[begin, end) takes, when that does not depend on the needle.
  static std::optional<std::uint32_t> fixed_takes(const Program& p, std::uint32_t begin,
                                                  std::uint32_t end) {
    std::uint32_t total = 0;
    for (std::uint32_t i = begin; i < end; ++i) {
      const Node& n = p.nodes[i];
      if (n.kind == Node::Kind::bind_off_all || n.until.kind != Until::Kind::count)
        return std::nullopt;
      if (n.kind == Node::Kind::op) {
        total += info(n.op).takes * n.times;
      } else {
        auto inner = fixed_takes(p, n.first_child, n.end_child);
        if (!inner) return std::nullopt;
        total += *inner * n.times;
      }
    }
    return total;
  }

  // Sts between the needle tip and where `until` stops.
  std::uint32_t remaining(const Until& u, std::string_view what) const {
    switch (u.kind) {
      case Until::Kind::end:
        if (pc_.joined && !row_round_)
          fail(fmt::format("{} to end: a row worked in the rnd has no end; give the count", what));
        return left_loops_;
      case Until::Kind::last:
        if (left_loops_ < u.sts)
          fail(fmt::format("{} to last {}: only {} left", what, sts(u.sts), sts(left_loops_)));
        return left_loops_ - u.sts;
      case Until::Kind::marker:
      case Until::Kind::before_marker: {
        if (!marker_ahead()) fail(fmt::format("{} to m: no marker ahead on the left needle", what));
        std::uint32_t to_m = loops_to_marker();
        if (to_m < u.sts)
          fail(fmt::format("{} to {} before m: only {} before the marker", what, sts(u.sts),
                           sts(to_m)));
        return to_m - u.sts;
      }
      case Until::Kind::count:
        break;
    }
    return 0;
  }

  std::uint32_t whole_repeats(const Until& u, std::uint32_t takes, std::string_view what) const {
    std::uint32_t left = remaining(u, what);
    if (left == 0) return 0;
    if (takes == 0) fail(fmt::format("{} works no sts, so it never ends", what));
    if (left % takes != 0)
      fail(fmt::format("{}: {} to go, not a whole number of repeats of {}", what, sts(left),
                       sts(takes)));
    return left / takes;
  }

  void apply(HandOp op) {
    count_work();
    if (row_ended_)
      fail(fmt::format("{} after the turn: the row ends where the work turns",
                       info(op).abbreviation));
    wrap_around();
    switch (op) {
      case HandOp::turn:
        row_ended_ = true;
        return;
      case HandOp::no_turn:
        row_ended_ = not_turned_ = true;
        return;
      case HandOp::ds:
        double_stitch();
        return;
      case HandOp::from_spare:
      case HandOp::from_spare_behind:
        slip_from_spare(op == HandOp::from_spare_behind);
        return;
      case HandOp::from_second_spare:
      case HandOp::from_second_spare_behind:
        slip_from_second_spare(op == HandOp::from_second_spare_behind);
        return;
      case HandOp::provisional_co:
        provisional_cast_on_in_row();
        return;
      case HandOp::tnbo:
        three_needle_bind_off_st();
        return;
      case HandOp::slip_back:
        slip_back();
        return;
      case HandOp::pm:
        place_marker();
        return;
      case HandOp::sm:
      case HandOp::rm: {
        if (pc_.left.empty() && end_is_marker()) {  // the beginning-of-round marker
          if (op == HandOp::rm) remove_bor();
          return;
        }
        if (op == HandOp::rm && bor_just_slipped()) return remove_bor();
        if (pc_.left.empty() || !is_marker_entry(pc_.left.back()))
          fail(fmt::format("{}: the next thing on the left needle is {}, not a marker",
                           info(op).abbreviation, pc_.left.empty() ? "nothing" : "a st"));
        std::uint32_t marker = pc_.left.back();
        pc_.left.pop_back();
        if (op == HandOp::sm)
          pc_.right.push_back(marker);
        else if (marker == pc_.bor)
          pc_.bor = kNone;
        return;
      }
      default:
        break;
    }
    if (is_make_one(op))
      make_one(op);
    else
      stitch(op);
    if (op == HandOp::wt) wrap_and_turn();
  }

  // "3-needle BO": the next st and the first st held behind it knit together and bound off;
  // as in a three-needle bind-off of whole pieces, the front loop first seen from the RS.
  void three_needle_bind_off_st() {
    if (held_behind_.empty()) fail("3-needle BO: no sts are held behind the needle");
    if (loops_to_marker() == 0)
      fail(fmt::format("3-needle BO needs 1 st{}, 0 left",
                       marker_ahead() ? " before the marker" : ""));
    check_turn_loop(HandOp::tnbo, pc_.left.back());
    Side facing = facing_;
    facing_ = Side::ws;
    std::uint32_t x = new_stitch(StitchType::tnbo);
    facing_ = facing;
    fab().taken.push_back(pc_.left.back());
    fab().taken.push_back(held_behind_.front());
    fab().taken_first.push_back(static_cast<std::uint32_t>(fab().taken.size()));
    pc_.left.pop_back();
    --left_loops_;
    held_behind_.erase(held_behind_.begin());
    --pc_.live;
    row_last_stitch_ = x;
    last_make_.reset();
  }

  // w&t: the st just slipped and wrapped goes back to the left needle, and the work turns. A
  // wrapped st wrapped again keeps its wraps: it has one more.
  void wrap_and_turn() {
    std::uint32_t loop = pc_.right.back();
    std::uint32_t slipped = fab().taken.back();
    pc_.right.pop_back();
    turn_mark_[loop] = kWrapped;
    wraps_[loop] = (turn_mark_[slipped] == kWrapped ? wraps_[slipped] : 0) + 1;
    push_left(loop);
    row_ended_ = true;
  }

  // Puts a loop at the tip of the left needle, keeping its index.
  void push_left(std::uint32_t loop) {
    pc_.left.push_back(loop);
    to_marker_.resize(pc_.left.size());
    marker_ahead_.resize(pc_.left.size());
    std::size_t i = pc_.left.size() - 1;
    to_marker_[i] = (i ? to_marker_[i - 1] : 0) + 1;
    marker_ahead_[i] = i && marker_ahead_[i - 1];
    ++left_loops_;
  }

  // The next st of the one piece waiting on a spare needle (in the order its last row worked
  // them) joins the work at the tip of the left needle.
  void slip_from_spare(bool behind) {
    // The spare needle a holder was put on, or else the one piece whose sts wait on a spare
    // needle (a provisional cast-on's chain holds no sts to slip).
    bool holder = !spare_for_rows_[0].empty();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> waiting;
    for (const auto& [key, loops] : spare_needles_)
      if (key.second == kNeedle) waiting.push_back(key);
    if (!holder && waiting.size() != 1)
      fail(fmt::format("sl1 from spare: {} pieces wait on spare needles; which one is meant?",
                       waiting.size()));
    std::vector<std::uint32_t>& spare = holder ? spare_for_rows_[0] : spare_needles_[waiting[0]];
    slip_onto_left_needle(spare, behind, "sl1 from spare");
    if (spare.empty() && !holder) spare_needles_.erase(waiting[0]);
  }

  // "sl1 from 2nd spare": from the second of two holders put on spare needles.
  void slip_from_second_spare(bool behind) {
    if (spare_for_rows_[1].empty())
      fail("sl1 from 2nd spare: no sts wait on a second spare needle");
    slip_onto_left_needle(spare_for_rows_[1], behind, "sl1 from 2nd spare");
  }

  // The spare needle's next st goes to the tip of the left needle, or behind the st there.
  void slip_onto_left_needle(std::vector<std::uint32_t>& spare, bool behind, const char* what) {
    std::uint32_t first = kNone;
    if (behind) {
      if (pc_.left.empty() || is_marker_entry(pc_.left.back()))
        fail(fmt::format("{} behind: there is no st on the left needle to slip it behind", what));
      first = pc_.left.back();
      pc_.left.pop_back();
      --left_loops_;
    }
    push_left(spare.front());
    if (behind) push_left(first);
    spare.erase(spare.begin());
    ++pc_.live;
  }

  // sl1 back: the st at the tip of the right needle (in the rnd, the last st of the left
  // needle when the right one is empty: the needle has no end) goes back to the left needle.
  void slip_back() {
    bool wraps = pc_.joined && pc_.right.empty() && !pc_.left.empty();
    std::vector<std::uint32_t>& from = wraps ? pc_.left : pc_.right;
    std::uint32_t loop = wraps ? from.front() : (from.empty() ? kNone : from.back());
    if (loop == kNone || is_marker_entry(loop))
      fail(fmt::format("sl1 back: the tip of the right needle holds {}, not a st",
                       loop == kNone ? "nothing" : "a marker"));
    if (wraps) {
      from.erase(from.begin());
      index_left_needle();
    } else {
      from.pop_back();
    }
    push_left(loop);
  }

  // A row that goes on from the end of a rnd slips the beginning-of-round marker first; "rm"
  // before any st removes it (a row that works across it, as "sl1 back" does).
  bool bor_just_slipped() const {
    return position_ == 0 && !pc_.right.empty() && pc_.right.back() == pc_.bor;
  }

  // In the rnd with no beginning-of-round marker (it was removed), the first marker placed in
  // a rnd marks the new beginning.
  void place_marker() {
    std::uint32_t marker = new_marker();
    pc_.right.push_back(marker);
    if (row_round_ && pc_.bor == kNone && position_ == 0) pc_.bor = marker;
  }

  // DS: first after a turn, the st worked last before it is pulled up into a double stitch
  // and slipped.
  void double_stitch() {
    if (position_ != 0 || next_link_ != YarnLink::turn || pc_.left.empty() ||
        is_marker_entry(pc_.left.back()) || fab().loop_maker[pc_.left.back()] != pc_.last_stitch)
      fail("DS: only first in a row after a turn, on the st worked last before it");
    Fabric& f = fab();
    std::uint32_t x = pc_.last_stitch;
    bool plain = (f.type[x] == StitchType::k || f.type[x] == StitchType::p) && f.made[x] == 1 &&
                 f.taken_first[x + 1] - f.taken_first[x] == 1;
    if (!plain)
      fail(fmt::format("DS: {} is not a plain st; a double stitch is made from a k or p",
                       f.describe(x)));
    f.type[x] = StitchType::sr4;
    std::uint32_t loop = pc_.left.back();
    pc_.left.pop_back();
    --left_loops_;
    turn_mark_[loop] = kDouble;
    pc_.right.push_back(loop);
  }

  // sl1yo lays a yo over the st it slips; sl1 slips a st with its yo as it is.
  void mark_st_with_yo(HandOp op) {
    if (op == HandOp::sl1yo) turn_mark_[pc_.right.back()] = kWithYo;
    if (op == HandOp::sl1) turn_mark_[pc_.right.back()] = turn_mark_[fab().taken.back()];
  }

  // A loop a short row turned at must be worked with what resolves it, and only such a loop.
  void check_turn_loop(HandOp op, std::uint32_t loop) const {
    // A st is slipped as it is; a decrease takes a st and its yo as one of its sts.
    if (op == HandOp::sl1 || (turn_mark_[loop] == kWithYo && info(op).takes > 1)) return;
    if (op == HandOp::wt && turn_mark_[loop] == kWrapped) return;  // wrapped again
    std::uint8_t needs = op == HandOp::kw || op == HandOp::pw     ? kWrapped
                         : op == HandOp::kds || op == HandOp::pds ? kDouble
                         : works_with_yo(op)                      ? kWithYo
                                                                  : kPlainLoop;
    if (turn_mark_[loop] == needs) return;
    if (turn_mark_[loop] == kWithYo || needs == kWithYo) with_yo_or_not(op, loop);
    if (needs != kPlainLoop)
      fail(fmt::format("{}: the next st is {}", info(op).abbreviation,
                       turn_mark_[loop] == kPlainLoop ? "not a short-row turn"
                       : turn_mark_[loop] == kWrapped ? "wrapped, not a double stitch"
                                                      : "a double stitch, not wrapped"));
    fail(fmt::format("{}: the next st is {}: work it with {}", info(op).abbreviation,
                     turn_mark_[loop] == kWrapped ? wrapped(loop) : "a double stitch",
                     turn_mark_[loop] == kWrapped ? (facing_ == Side::rs ? "kw" : "pw")
                                                  : (facing_ == Side::rs ? "k DS" : "p DS")));
  }

  std::string wrapped(std::uint32_t loop) const {
    return wraps_[loop] == 1 ? "wrapped" : fmt::format("wrapped ({} wraps)", wraps_[loop]);
  }

  [[noreturn]] void with_yo_or_not(HandOp op, std::uint32_t loop) const {
    if (turn_mark_[loop] == kWithYo)
      fail(fmt::format("{}: the next st has a yo over it (sl1yo): work it with {}",
                       info(op).abbreviation, facing_ == Side::rs ? "brk" : "brp"));
    fail(fmt::format("{}: the next st has no yo over it", info(op).abbreviation));
  }

  void remove_bor() {
    auto at = std::find(pc_.right.begin(), pc_.right.end(), pc_.bor);
    if (at != pc_.right.end()) pc_.right.erase(at);
    pc_.bor = kNone;
  }

  void stitch(HandOp op) {
    const HandOpInfo& oi = info(op);
    reach_around(oi.takes);
    std::uint32_t ready = loops_to_marker();
    if (ready < oi.takes)
      fail(fmt::format("{} needs {}{}, {} left", oi.abbreviation, sts(oi.takes),
                       marker_ahead() ? " before the marker" : "", ready));
    std::optional<StitchType> face = rs_face(op, facing_);
    if (!face) wrong_side(op);
    for (std::uint32_t i = 0; i < oi.takes; ++i)
      check_turn_loop(op, pc_.left[pc_.left.size() - 1 - i]);
    std::uint32_t x = new_stitch(*face);
    for (std::uint32_t i = 0; i < oi.takes; ++i) {
      fab().taken.push_back(pc_.left.back());
      pc_.left.pop_back();
    }
    left_loops_ -= oi.takes;
    fab().taken_first.push_back(static_cast<std::uint32_t>(fab().taken.size()));
    for (const Pending& p : pending_) adopt(x, p.op, p.loop);
    pending_.clear();
    for (std::uint32_t i = 0; i < oi.makes; ++i) pc_.right.push_back(new_loop(x));
    mark_st_with_yo(op);
    pc_.live = pc_.live + oi.makes - oi.takes;
    row_last_stitch_ = x;
    last_make_.reset();
  }

  // A make-one goes with the stitch just worked, or (first in a row) with the next one.
  void make_one(HandOp op) {
    if (!row_round_ && op != HandOp::yo && row_last_stitch_ == kNone)
      fail(fmt::format("{} at the start of a row: there is no strand before the first st to lift",
                       info(op).abbreviation));
    std::uint32_t loop = new_loop(kNone);
    pc_.right.push_back(loop);
    ++pc_.live;
    last_make_ = op;
    if (row_last_stitch_ == kNone)
      pending_.push_back({op, loop});
    else
      adopt(row_last_stitch_, op, loop);
  }

  void adopt(std::uint32_t x, HandOp op, std::uint32_t loop) {
    Fabric& f = fab();
    bool single_knit = f.type[x] == StitchType::k && f.taken_first[x + 1] - f.taken_first[x] == 1 &&
                       f.made[x] <= 1;
    if (!single_knit)
      fail(
          fmt::format("{} must go with a plain knit st (k on RS rows, p on WS rows); with {} it "
                      "makes a stitch the model cannot have",
                      info(op).abbreviation, f.describe(x)));
    std::optional<StitchType> face = rs_face(op, facing_);
    if (!face) wrong_side(op);
    f.type[x] = *face;
    f.loop_maker[loop] = x;
    f.loop_index[loop] = f.made[x]++;
  }

  [[noreturn]] void wrong_side(HandOp op) const {
    std::optional<StitchType> shown = rs_face(op, other(facing_));
    std::optional<Working> here = shown ? working_of(*shown, facing_) : std::nullopt;
    std::string_view alternative =
        here ? info(here->make ? *here->make : here->op).abbreviation : std::string_view("?");
    fail(
        fmt::format("{} is a {} stitch: worked with the {} facing it makes a stitch the model "
                    "cannot have (on {} rows work {})",
                    info(op).abbreviation, side_name(other(facing_)), side_name(facing_),
                    side_name(facing_), alternative));
  }

  std::uint32_t new_stitch(StitchType type) {
    Fabric& f = fab();
    auto x = static_cast<std::uint32_t>(f.type.size());
    f.type.push_back(type);
    f.facing.push_back(facing_);
    f.yarn_next.push_back(kNoStitch);
    f.yarn_link.push_back(YarnLink::none);
    f.row.push_back(row_);
    f.position.push_back(++position_);
    f.made.push_back(0);
    f.picked_from.push_back(Fabric::kNoEdge);
    Fabric::RowWorked& r = f.rows[row_];
    if (r.first == kNoStitch) {
      r.first = x;
      r.piece = pc_.number;
    }
    r.last = x;
    if (pc_.last_stitch != kNone) {
      f.yarn_next[pc_.last_stitch] = x;
      f.yarn_link[pc_.last_stitch] = next_link_;
    }
    next_link_ = YarnLink::course;
    pc_.last_stitch = x;
    return x;
  }

  std::uint32_t new_loop(std::uint32_t maker) {
    Fabric& f = fab();
    auto loop = static_cast<std::uint32_t>(f.loop_maker.size());
    f.loop_maker.push_back(maker);
    turn_mark_.push_back(kPlainLoop);
    wraps_.push_back(0);
    f.loop_picked.push_back(0);
    f.loop_index.push_back(maker == kNone ? 0 : f.made[maker]++);
    return loop;
  }

  std::uint32_t new_marker() { return kMarkerBit | markers_++; }

  struct Pending {
    HandOp op;
    std::uint32_t loop;
  };

  const Script& script_;
  const std::string& file_;
  Replay out_;
  std::vector<Program> work_even_;  // "k to end", "p to end"

  // Per piece number (1-based): the sts it left on a spare needle.
  // (and with a provisional cast-on, the loops of its chain).
  static constexpr std::uint32_t kNeedle = 0, kChain = 1;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> spare_needles_;
  std::vector<std::uint32_t> held_behind_;  // for "3-needle BO", the next at the front
  std::map<std::uint32_t, std::vector<std::uint32_t>> holders_;  // by holder number
  // Holders' sts that sl1 from spare (and sl1 from 2nd spare) take.
  std::array<std::vector<std::uint32_t>, 2> spare_for_rows_;

  // Per loop: whether a short row turned at it, and how.
  static constexpr std::uint8_t kPlainLoop = 0, kWrapped = 1, kDouble = 2, kWithYo = 3;
  std::vector<std::uint8_t> turn_mark_;
  std::vector<std::uint8_t> wraps_;  // per wrapped loop: how many times (w&t over a wrapped st)

  // The piece being worked: what a knitter sets aside with its yarn and takes up again.
  struct Piece {
    std::uint32_t number = 0;  // 1-based, in the order the pieces start
    bool joined = false, place_bor = false;
    bool turn_before = true;     // the next row starts by turning the work
    bool joined_to_sts = false;  // started by joining a yarn to another piece's sts
    bool carried = false;        // the yarn was carried to held sts, not yet joined in the rnd
    std::uint32_t bor = kNone;
    std::uint32_t next_number = 1;
    std::optional<Side> last_side;
    std::vector<std::uint32_t> defined;  // per row number: the program that worked it
    std::uint32_t live = 0;
    std::uint32_t last_stitch = kNone;       // along its yarn
    std::vector<std::uint32_t> left, right;  // the needles; tips at the back
  };
  bool active_ = false;
  Piece pc_;
  std::map<std::uint32_t, Piece> set_aside_;  // by piece number
  YarnLink next_link_ = YarnLink::course;

  // The left needle's index.
  std::vector<std::uint32_t> to_marker_;
  std::vector<std::uint8_t> marker_ahead_;
  std::uint32_t left_loops_ = 0;
  std::uint64_t work_ = 0;  // instructions and sts worked, up to max_work_
  std::uint64_t max_work_;
  std::uint32_t markers_ = 0;

  // The row being worked.
  bool in_row_ = false, row_round_ = false;
  bool row_ended_ = false;   // by w&t or turn (or "do not turn")
  bool not_turned_ = false;  // ... by "do not turn": the next row goes on the same way
  std::uint32_t row_ = 0;
  Side facing_ = Side::rs;
  std::uint32_t position_ = 0;
  std::uint32_t row_last_stitch_ = kNone;
  std::vector<Pending> pending_;
  std::optional<HandOp> last_make_;
};

}  // namespace

Replay replay(const Script& script, const std::string& file, std::uint64_t max_work) {
  return NeedleSimulator(script, file, max_work).run();
}

}  // namespace skein::hand
