// The needle simulator's bind-offs (three-needle, folded across a tube), sts held behind for
// them, and the end of the pattern.
#include "hand/needle_simulator.hpp"

#include <algorithm>

namespace skein::hand::sim {

void NeedleSimulator::three_needle_bind_off(const Step& s) {
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

std::vector<std::uint32_t> NeedleSimulator::round_from(const std::vector<std::uint32_t>& sts,
                                                       std::uint32_t tip, bool down,
                                                       const std::string& whose) const {
  auto n = static_cast<std::uint32_t>(sts.size());
  if (tip > n) fail(fmt::format("three-needle bind-off: {} has no st {}", whose, tip));
  std::vector<std::uint32_t> run;
  for (std::uint32_t i = 0; i < n; ++i)
    run.push_back(sts[down ? (tip - 1 + n - i) % n : (tip - 1 + i) % n]);
  return run;
}

void NeedleSimulator::bind_off_pairs(const std::vector<std::uint32_t>& f,
                                     const std::vector<std::uint32_t>& b) {
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

void NeedleSimulator::folded_bind_off(const Step& s) {
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

std::vector<std::uint32_t> NeedleSimulator::folded_run(
    const Step& s, int side, const std::vector<std::uint32_t>& ring) const {
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

void NeedleSimulator::hold_behind(const Step& s) {
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

std::vector<std::uint32_t> NeedleSimulator::spare_needle(std::uint32_t piece, bool from_last,
                                                         const char* what, bool chain) const {
  auto at = spare_needles_.find({piece, chain ? kChain : kNeedle});
  if (at == spare_needles_.end())
    fail(fmt::format("{}: {} of Piece {} {} not waiting on a spare needle", what,
                     chain ? "the chain" : "the sts", piece, chain ? "is" : "are"));
  std::vector<std::uint32_t> loops = at->second;
  if (from_last) std::reverse(loops.begin(), loops.end());
  return loops;
}

void NeedleSimulator::finish() {
  if (fab().piece_first.empty()) throw StepFailure{"the pattern casts nothing on"};
  if (!set_aside_.empty())
    throw StepFailure{
        fmt::format("Piece {} is set aside and never taken up again", set_aside_.begin()->first)};
  if (!spare_needles_.empty())
    throw StepFailure{fmt::format("the {} of Piece {} {} left on a spare needle, never worked",
                                  spare_needles_.begin()->first.second == kChain ? "chain" : "sts",
                                  spare_needles_.begin()->first.first,
                                  spare_needles_.begin()->first.second == kChain ? "is" : "are")};
  for (const std::vector<std::uint32_t>& spare : spare_for_rows_)
    if (!spare.empty())
      throw StepFailure{fmt::format("{} left on the spare needle, never worked",
                                    sts(static_cast<std::uint32_t>(spare.size())))};
  if (!holders_.empty())
    throw StepFailure{
        fmt::format("the sts of holder {} are left on it, never worked", holders_.begin()->first)};
  if (active_ && pc_.live > 0)
    throw StepFailure{fmt::format("the pattern ends with {} still on the needle", sts(pc_.live))};
}

}  // namespace skein::hand::sim
