// The needle simulator's piece steps: cast on, pick up, join a yarn or a spare needle, set a
// piece aside and take it up again, fasten off.
#include "hand/needle_simulator.hpp"

#include <algorithm>

namespace skein::hand::sim {

void NeedleSimulator::cast_on(std::uint32_t n, bool provisional) {
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

void NeedleSimulator::cast_on_st(bool provisional) {
  std::uint32_t x = new_stitch(provisional ? StitchType::sco : StitchType::co);
  fab().taken_first.push_back(static_cast<std::uint32_t>(fab().taken.size()));
  pc_.right.push_back(new_loop(x));
  if (provisional) spare_needles_[{pc_.number, kChain}].push_back(new_loop(x));
}

void NeedleSimulator::cast_on_aside(const Step& s) {
  if (!active_ || in_row_) fail("With the working yarn, cast on: no yarn is being worked");
  if (s.count == 0) fail("With the working yarn, cast on: no sts to cast on");
  if (holders_.contains(s.number))
    fail(fmt::format("With the working yarn, cast on onto holder {}: it already holds {}", s.number,
                     sts(static_cast<std::uint32_t>(holders_[s.number].size()))));
  if (s.provisional && spare_needles_.contains({pc_.number, kChain}))
    fail(
        fmt::format("With the working yarn, cast on with a provisional cast-on: Piece {} "
                    "already has a chain (one per piece)",
                    pc_.number));
  // The sts cast on are a cast-on of their own in the fabric, the yarn going on into them.
  const std::uint32_t row = row_, position = position_;
  const Side facing = facing_;
  fab().rows.push_back({s.line, 0, 0, false, Side::rs});
  fab().rows.back().aside = true;
  row_ = static_cast<std::uint32_t>(fab().rows.size() - 1);
  position_ = 0;
  next_link_ = pc_.turn_before ? YarnLink::turn : YarnLink::shift;
  std::vector<std::uint32_t>& held = holders_[s.number];
  for (std::uint32_t i = 0; i < s.count; ++i) {
    facing_ = s.provisional ? Side::ws : Side::rs;  // the needle's loop first, seen from the RS
    std::uint32_t x = new_stitch(s.provisional ? StitchType::sco : StitchType::co);
    fab().taken_first.push_back(static_cast<std::uint32_t>(fab().taken.size()));
    held.push_back(new_loop(x));
    if (s.provisional) spare_needles_[{pc_.number, kChain}].push_back(new_loop(x));
  }
  row_ = row;
  position_ = position;
  facing_ = facing;
  pc_.cast_on_aside = true;  // the next row goes on along from the last st cast on
}

void NeedleSimulator::cast_on_in_row(bool provisional) {
  Side facing = facing_;
  if (provisional) facing_ = Side::ws;
  cast_on_st(provisional);
  facing_ = facing;
  ++pc_.live;
  row_last_stitch_ = pc_.last_stitch;
  last_make_.reset();
}

void NeedleSimulator::pick_up(const Step& given) {
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

Step NeedleSimulator::along_the_flap(Step s) const {
  if (s.number != 0) return s;
  if (!active_ || !s.into_rnd)
    fail("Pick up along the flap: only onto the needle of the piece worked, into its rnd");
  s.number = pc_.number;
  return s;
}

void NeedleSimulator::pick_up_into_rnd(const Step& s, const std::vector<std::uint32_t>& rows) {
  if (!active_ || !pc_.joined || !s.round)
    fail(fmt::format("Pick up along Piece {} onto the needle: only into a piece worked in the rnd",
                     s.number));
  std::vector<std::uint32_t> loops;
  for (std::uint32_t i = 0; i < s.count; ++i) {
    std::uint32_t n = s.from_row <= s.to_row ? s.from_row + i : s.from_row - i;
    loops.push_back(pick_up_loop(rows, n, s.provisional));
  }
  insert_into_rnd(loops, s.last, fmt::format("Pick up along Piece {}", s.number));
}

std::vector<std::uint32_t> NeedleSimulator::rows_of_piece(std::uint32_t piece) const {
  std::vector<std::uint32_t> rows;
  for (std::uint32_t r = 0; r < out_.fabric.rows.size(); ++r) {
    const Fabric::RowWorked& w = out_.fabric.rows[r];
    if (w.piece != piece || w.join || w.aside) continue;
    if (rows.size() <= w.number) rows.resize(w.number + 1, kNone);
    rows[w.number] = r;
  }
  return rows;
}

std::uint32_t NeedleSimulator::pick_up_loop(const std::vector<std::uint32_t>& rows, std::uint32_t n,
                                            bool right) {
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

void NeedleSimulator::join_spare(const Step& s) {
  if (active_ && pc_.live > 0)
    fail(
        fmt::format("Join a new yarn: the piece before still has {} on the needle", sts(pc_.live)));
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

void NeedleSimulator::begin_at_holder_st(std::vector<std::uint32_t>& loops, const Step& s) const {
  if (s.from_row == 0) return;
  if (s.from_row > loops.size())
    fail(fmt::format("Join a new yarn: holder {} has no st {}", s.number, s.from_row));
  std::size_t tip = s.from_last[0] ? loops.size() - s.from_row : s.from_row - 1;
  std::rotate(loops.begin(), loops.begin() + static_cast<std::ptrdiff_t>(tip), loops.end());
}

void NeedleSimulator::start_piece() {
  active_ = true;
  facing_ = Side::rs;
  fab().piece_first.push_back(fab().size());
  pc_ = Piece{};
  pc_.number = static_cast<std::uint32_t>(fab().piece_first.size());
  position_ = 0;
  next_link_ = YarnLink::course;
}

void NeedleSimulator::carry_on(const Step& s) {
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

void NeedleSimulator::join(const Step& s) {
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

void NeedleSimulator::join_flat_piece(const Step& s) {
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

void NeedleSimulator::fasten_off() {
  if (!active_) fail("Fasten off: no yarn is being worked");
  if (pc_.live > 0)
    fail(fmt::format("Fasten off: {} still on the needle; bind them off first", sts(pc_.live)));
  active_ = false;
}

void NeedleSimulator::check_live(std::uint32_t n, const char* what) const {
  if (!active_) fail(fmt::format("{}: no piece is being worked", what));
  if (n != pc_.live)
    fail(fmt::format("{}: the pattern says {}, but {} on the needle", what, sts(n),
                     pc_.live == 1 ? "1 st is" : fmt::format("{} sts are", pc_.live)));
}

void NeedleSimulator::check_printed_count(const Step& s, const char* what) {
  if (!s.sts) return;
  ++out_.counts_checked;
  check_live(*s.sts, what);
}

void NeedleSimulator::set_aside(std::uint32_t n) {
  check_live(n, "Leave the sts");
  set_aside_[pc_.number] = std::move(pc_);
  active_ = false;
}

void NeedleSimulator::take_up(std::uint32_t number) {
  if (active_ && pc_.live > 0)
    fail(fmt::format("Take up Piece {}: the piece before still has {} on the needle", number,
                     sts(pc_.live)));
  auto at = set_aside_.find(number);
  if (at == set_aside_.end()) fail(fmt::format("Take up Piece {}: it was not set aside", number));
  pc_ = std::move(at->second);
  set_aside_.erase(at);
  active_ = true;
}

}  // namespace skein::hand::sim
