// The order the queued transfers are written in: as few rack changes as their needles allow
// (emitter.hpp has the state). The planners in emit_transfers.cpp, emit_roll.cpp and
// emit_split.cpp queue their moves in an order that is right; this file reorders them.
//
// An xfer reads and writes its two needles only, so two moves that share no needle may be
// swapped, and any order that keeps, per needle, the queue's order of the moves touching it
// leaves every needle as the queue's order does (a decrease's stacking order included). Within
// that, the moves are written in runs at one racking, each run one transfer pass, so passes
// fall with the rack changes. Writing every move that is ready at the machine's racking before
// changing it never costs a change (a move written early only lets others be ready sooner), so
// the one choice is which racking to change to: each one with moves ready is tried by finishing
// the queue from it with a quick rule, and the one that needs the fewest changes is taken. That
// is not always best, so the queue's own order (batch by batch, as the planners queued them) is
// counted too, and the order with fewer changes written.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <tuple>

#include "knitout/emitter.hpp"

namespace skein::knitout::emit {

namespace {

constexpr std::uint32_t kNone = ~0u;
constexpr std::int32_t kNoRack = std::numeric_limits<std::int32_t>::min();

// The queue's moves and, per move, the next move touching its `from` and its `to` needle.
struct MoveOrder {
  const std::vector<Move>& moves;
  std::vector<std::array<std::uint32_t, 2>> next;
  std::int32_t most = 0;    // the widest racking queued
  bool zero_after = false;  // the knitting after wants rack 0: a change to it counts too
  std::uint32_t end_change(std::int32_t rack) const { return zero_after && rack != 0 ? 1 : 0; }
  std::size_t slot(std::int32_t rack) const { return static_cast<std::size_t>(rack + most); }
  std::size_t slot_of(std::uint32_t move) const { return slot(rack_of(moves[move])); }
};

// How far the writing has got: per move the earlier moves it still waits for, per racking the
// moves ready and the moves not yet written.
struct Progress {
  std::vector<std::uint8_t> waits;
  std::vector<std::vector<std::uint32_t>> ready;
  std::vector<std::uint32_t> left;
  std::uint32_t written = 0;

  // Writes (into `out`, if given) every move at `rack` that is ready or gets ready meanwhile,
  // in the queue's order (a move's earlier moves come before it there).
  void run(const MoveOrder& o, std::int32_t rack, std::vector<std::uint32_t>* out) {
    std::vector<std::uint32_t>& now = ready[o.slot(rack)];
    for (std::size_t k = 0; k < now.size(); ++k)  // grows as moves at this racking get ready
      for (std::uint32_t after : o.next[now[k]])
        if (after != kNone && --waits[after] == 0) ready[o.slot_of(after)].push_back(after);
    if (out) {
      std::sort(now.begin(), now.end());
      out->insert(out->end(), now.begin(), now.end());
    }
    written += static_cast<std::uint32_t>(now.size());
    left[o.slot(rack)] -= static_cast<std::uint32_t>(now.size());
    now.clear();
  }

  // The quick rule: a racking whose moves are all ready (it is then done with), then the most
  // moves ready, then the racking nearest 0 (where most courses knit), then the lower.
  auto merit(const MoveOrder& o, std::int32_t rack) const {
    std::size_t k = o.slot(rack);
    return std::tuple(ready[k].size() == left[k], ready[k].size(), -std::abs(rack));
  }
  std::int32_t quick_pick(const MoveOrder& o) const {
    std::int32_t best = kNoRack;
    for (std::int32_t r = -o.most; r <= o.most; ++r)
      if (!ready[o.slot(r)].empty() && (best == kNoRack || merit(o, r) > merit(o, best))) best = r;
    return best;
  }
};

// The rack changes it takes to write the rest of the queue from `rack` by the quick rule.
std::uint32_t changes_from(const MoveOrder& o, Progress p, std::int32_t rack) {
  std::uint32_t changes = 0;
  for (;; ++changes) {
    p.run(o, rack, nullptr);
    if (p.written == o.moves.size()) return changes + o.end_change(rack);
    rack = p.quick_pick(o);
  }
}

// The racking to change to: the one from which the rest needs the fewest changes; of equals,
// the quick rule's pick.
std::int32_t next_rack(const MoveOrder& o, const Progress& p) {
  std::int32_t best = kNoRack;
  std::uint32_t fewest = 0;
  for (std::int32_t r = -o.most; r <= o.most; ++r) {
    if (p.ready[o.slot(r)].empty()) continue;
    std::uint32_t changes = changes_from(o, p, r);
    if (best == kNoRack || changes < fewest ||
        (changes == fewest && p.merit(o, r) > p.merit(o, best))) {
      best = r;
      fewest = changes;
    }
  }
  return best;
}

// The order of a batch's moves when written by batch: those at the racking the machine is at
// first, then by racking from furthest from 0 to nearest (where most batches after begin).
std::tuple<bool, std::int32_t, std::int32_t> batch_key(std::int32_t rack, std::int32_t now) {
  return std::tuple(rack != now, -std::abs(rack), rack);
}

}  // namespace

void Emitter::queue_moves(std::vector<Move>& moves) {
  if (moves.empty()) return;
  auto last = std::max_element(moves.begin(), moves.end(), [&](const Move& a, const Move& b) {
    return batch_key(rack_of(a), batch_rack_) < batch_key(rack_of(b), batch_rack_);
  });
  batch_rack_ = rack_of(*last);
  pending_.insert(pending_.end(), moves.begin(), moves.end());
  batch_ends_.push_back(static_cast<std::uint32_t>(pending_.size()));
  moves.clear();
}

// The queue written batch by batch, each batch grouped by racking (batch_key). The moves of a
// batch are independent of each other.
Emitter::TransferOrder Emitter::order_by_batch(bool zero_after) const {
  TransferOrder order;
  std::int32_t now = w_.racking();
  std::uint32_t begin = 0;
  for (std::uint32_t end : batch_ends_) {
    auto first = order.moves.size();
    for (std::uint32_t i = begin; i < end; ++i) order.moves.push_back(i);
    auto key = [&](std::uint32_t i) { return batch_key(rack_of(pending_[i]), now); };
    std::stable_sort(order.moves.begin() + static_cast<std::ptrdiff_t>(first), order.moves.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    for (auto k = first; k < order.moves.size(); ++k) {
      std::int32_t r = rack_of(pending_[order.moves[k]]);
      order.changes += r != now ? 1 : 0;
      now = r;
    }
    begin = end;
  }
  order.changes += zero_after && now != 0 ? 1 : 0;
  order.end = now;
  return order;
}

Emitter::TransferOrder Emitter::order_moves(bool zero_after) const {
  auto n = static_cast<std::uint32_t>(pending_.size());
  TransferOrder order;
  MoveOrder o{pending_, std::vector<std::array<std::uint32_t, 2>>(n, {kNone, kNone})};
  for (const Move& m : pending_) o.most = std::max(o.most, std::abs(rack_of(m)));
  o.zero_after = zero_after;
  Progress p{std::vector<std::uint8_t>(n, 0),
             std::vector<std::vector<std::uint32_t>>(2 * static_cast<std::size_t>(o.most) + 1),
             std::vector<std::uint32_t>(2 * static_cast<std::size_t>(o.most) + 1, 0)};
  last_on_needle_.resize(2 * static_cast<std::size_t>(p_.needles), kNone);
  for (std::uint32_t i = 0; i < n; ++i) {
    for (Place needle : {pending_[i].from, pending_[i].to}) {
      std::uint32_t& last = last_on_needle_[needle_slot(needle)];
      if (last != kNone) {
        o.next[last][pending_[last].from == needle ? 0 : 1] = i;
        ++p.waits[i];
      }
      last = i;
    }
    ++p.left[o.slot_of(i)];
    if (p.waits[i] == 0) p.ready[o.slot_of(i)].push_back(i);
  }
  for (const Move& m : pending_)
    last_on_needle_[needle_slot(m.from)] = last_on_needle_[needle_slot(m.to)] = kNone;
  std::int32_t rack = w_.racking();
  while (p.written < n) {
    if (std::abs(rack) > o.most || p.ready[o.slot(rack)].empty()) {
      rack = next_rack(o, p);
      ++order.changes;
    }
    p.run(o, rack, &order.moves);
  }
  order.changes += o.end_change(rack);
  order.end = rack;
  return order;
}

void Emitter::write_moves(const TransferOrder& order) {
  for (std::uint32_t move : order.moves) w_.xfer(at(pending_[move].from), at(pending_[move].to));
  pending_.clear();
  batch_ends_.clear();
  batch_rack_ = w_.racking();
}

// The queue's order by batch or the one with fewest rack changes (order_moves), whichever
// changes the racking less (TransferOrder::better_than); of equals, the first.
Emitter::TransferOrder Emitter::best_order(bool zero_after) const {
  TransferOrder by_batch = order_by_batch(zero_after), fewest = order_moves(zero_after);
  return fewest.better_than(by_batch) ? fewest : by_batch;
}

}  // namespace skein::knitout::emit
