// The needle simulator's instructions and stitches: repeats, each op on the needles, short-row
// turns, slipped and made sts.
#include "hand/needle_simulator.hpp"

#include <algorithm>

namespace skein::hand::sim {

void NeedleSimulator::run_nodes(const Program& p, std::uint32_t begin, std::uint32_t end) {
  for (std::uint32_t i = begin; i < end; ++i) run_node(p, p.nodes[i]);
}

void NeedleSimulator::count_work() {
  if (++work_ > max_work_)
    fail(
        fmt::format("the pattern works more than {} sts and instructions, skein's limit "
                    "(docs/formats.md, \"Limits\")",
                    max_work_));
}

void NeedleSimulator::run_node(const Program& p, const Node& n) {
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
          while (slips && !pc_.left.empty() && is_marker_entry(pc_.left.back())) apply(HandOp::sm);
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

std::optional<std::uint32_t> NeedleSimulator::fixed_takes(const Program& p, std::uint32_t begin,
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

std::uint32_t NeedleSimulator::remaining(const Until& u, std::string_view what) const {
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

std::uint32_t NeedleSimulator::whole_repeats(const Until& u, std::uint32_t takes,
                                             std::string_view what) const {
  std::uint32_t left = remaining(u, what);
  if (left == 0) return 0;
  if (takes == 0) fail(fmt::format("{} works no sts, so it never ends", what));
  if (left % takes != 0)
    fail(fmt::format("{}: {} to go, not a whole number of repeats of {}", what, sts(left),
                     sts(takes)));
  return left / takes;
}

void NeedleSimulator::apply(HandOp op) {
  count_work();
  if (row_ended_)
    fail(
        fmt::format("{} after the turn: the row ends where the work turns", info(op).abbreviation));
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
    case HandOp::co:
      cast_on_in_row(op == HandOp::provisional_co);
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

void NeedleSimulator::three_needle_bind_off_st() {
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

void NeedleSimulator::wrap_and_turn() {
  std::uint32_t loop = pc_.right.back();
  std::uint32_t slipped = fab().taken.back();
  pc_.right.pop_back();
  turn_mark_[loop] = kWrapped;
  wraps_[loop] = (turn_mark_[slipped] == kWrapped ? wraps_[slipped] : 0) + 1;
  push_left(loop);
  row_ended_ = true;
}

void NeedleSimulator::push_left(std::uint32_t loop) {
  pc_.left.push_back(loop);
  to_marker_.resize(pc_.left.size());
  marker_ahead_.resize(pc_.left.size());
  std::size_t i = pc_.left.size() - 1;
  to_marker_[i] = (i ? to_marker_[i - 1] : 0) + 1;
  marker_ahead_[i] = i && marker_ahead_[i - 1];
  ++left_loops_;
}

void NeedleSimulator::slip_from_spare(bool behind) {
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

void NeedleSimulator::slip_from_second_spare(bool behind) {
  if (spare_for_rows_[1].empty()) fail("sl1 from 2nd spare: no sts wait on a second spare needle");
  slip_onto_left_needle(spare_for_rows_[1], behind, "sl1 from 2nd spare");
}

void NeedleSimulator::slip_onto_left_needle(std::vector<std::uint32_t>& spare, bool behind,
                                            const char* what) {
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

void NeedleSimulator::slip_back() {
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

bool NeedleSimulator::bor_just_slipped() const {
  return position_ == 0 && !pc_.right.empty() && pc_.right.back() == pc_.bor;
}

void NeedleSimulator::place_marker() {
  std::uint32_t marker = new_marker();
  pc_.right.push_back(marker);
  if (row_round_ && pc_.bor == kNone && position_ == 0) pc_.bor = marker;
}

void NeedleSimulator::double_stitch() {
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

void NeedleSimulator::mark_st_with_yo(HandOp op) {
  if (op == HandOp::sl1yo) turn_mark_[pc_.right.back()] = kWithYo;
  if (op == HandOp::sl1) turn_mark_[pc_.right.back()] = turn_mark_[fab().taken.back()];
}

void NeedleSimulator::check_turn_loop(HandOp op, std::uint32_t loop) const {
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

std::string NeedleSimulator::wrapped(std::uint32_t loop) const {
  return wraps_[loop] == 1 ? "wrapped" : fmt::format("wrapped ({} wraps)", wraps_[loop]);
}

void NeedleSimulator::with_yo_or_not(HandOp op, std::uint32_t loop) const {
  if (turn_mark_[loop] == kWithYo)
    fail(fmt::format("{}: the next st has a yo over it (sl1yo): work it with {}",
                     info(op).abbreviation, facing_ == Side::rs ? "brk" : "brp"));
  fail(fmt::format("{}: the next st has no yo over it", info(op).abbreviation));
}

void NeedleSimulator::remove_bor() {
  auto at = std::find(pc_.right.begin(), pc_.right.end(), pc_.bor);
  if (at != pc_.right.end()) pc_.right.erase(at);
  pc_.bor = kNone;
}

void NeedleSimulator::stitch(HandOp op) {
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

void NeedleSimulator::make_one(HandOp op) {
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

void NeedleSimulator::adopt(std::uint32_t x, HandOp op, std::uint32_t loop) {
  Fabric& f = fab();
  bool single_knit =
      f.type[x] == StitchType::k && f.taken_first[x + 1] - f.taken_first[x] == 1 && f.made[x] <= 1;
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

void NeedleSimulator::wrong_side(HandOp op) const {
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

std::uint32_t NeedleSimulator::new_stitch(StitchType type) {
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

std::uint32_t NeedleSimulator::new_loop(std::uint32_t maker) {
  Fabric& f = fab();
  auto loop = static_cast<std::uint32_t>(f.loop_maker.size());
  f.loop_maker.push_back(maker);
  turn_mark_.push_back(kPlainLoop);
  wraps_.push_back(0);
  f.loop_picked.push_back(0);
  f.loop_index.push_back(maker == kNone ? 0 : f.made[maker]++);
  return loop;
}

}  // namespace skein::hand::sim
