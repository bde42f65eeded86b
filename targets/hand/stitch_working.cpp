#include "hand/stitch_working.hpp"

#include <fmt/format.h>

#include "common/error.hpp"

namespace skein::hand {
namespace {

using T = StitchType;

[[noreturn]] void unsupported(const std::string& what) {
  throw UnsupportedError(fmt::format("hand target: {}", what));
}

// A knitter works a DS or a wrap as one st with its st: an sr5's two loops must go into one
// decrease above it that takes no other loop.
void check_sr5_knit_together(const KnitGraph& g, StitchId s) {
  StitchId above = taker_of_both_sr5_loops(g, s);
  if (above != kNoStitch && knits_an_sr5_as_one(g, above)) return;
  unsupported(fmt::format(
      "{} is an sr5 whose two loops (its st's and the turn's) are not knit together by one "
      "k2tog, ssk or p2tog above it, as a knitter works a double stitch or a wrap with its "
      "st; make it an sr4",
      g.describe(s)));
}

// brk / brp: a plain st that works a st and its yo as one (a decrease takes the two as one
// of its sts, as brioche patterns count them).
HandOp with_its_yo(HandOp op) {
  if (!is_plain(op)) return op;
  return op == HandOp::k ? HandOp::brk : HandOp::brp;
}

// The st a short row turns at. Turning again at the st the last short row turned at, the
// row works its double stitch as one first, or wraps the wrapped st again (heel-turn patterns
// do: the st then has two wraps, and kw / pw later work both with it).
HandOp turning_op(const KnitGraph& g, StitchId s, Side side, TurnMethod turns, bool& wraps_again) {
  HandOp plain = side == Side::rs ? HandOp::k : HandOp::p;
  if (turns == TurnMethod::wrap_and_turn) {
    wraps_again = works_a_turn(g, s);
    return HandOp::wt;
  }
  return works_a_turn(g, s) ? resolving(g, plain, s, turns) : plain;
}

}  // namespace

void check_stitch_types(const KnitGraph& g) {
  for (StitchId s = 0; s < g.size(); ++s) {
    if (g.type[s] == T::sr5) check_sr5_knit_together(g, s);
    if (worked_by(g.type[s], by_hand)) continue;
    unsupported(fmt::format("{} is a {} ({}), which hand patterns do not cover yet", g.describe(s),
                            info(g.type[s]).name, abbreviation(g.type[s])));
  }
}

bool works_a_turn(const KnitGraph& g, StitchId s) {
  for (std::uint32_t l : g.loops_taken_by(s))
    if (g.loops[l].maker != kNoStitch && worked_by_hand(g, g.loops[l].maker) == T::sr4) return true;
  return false;
}

HandOp resolving(const KnitGraph& g, HandOp plain, StitchId s, TurnMethod turns) {
  if (!is_plain(plain))
    unsupported(
        fmt::format("{} works the loop a short row turned at as a {}; hand patterns "
                    "resolve a turn with a plain k or p only",
                    g.describe(s), info(plain).abbreviation));
  bool knit = plain == HandOp::k;
  if (turns == TurnMethod::wrap_and_turn) return knit ? HandOp::kw : HandOp::pw;
  return knit ? HandOp::kds : HandOp::pds;
}

bool works_a_st_with_its_yo(const KnitGraph& g, StitchId s) {
  if (g.type[s] == T::sl) return false;
  for (std::uint32_t l : g.loops_taken_by(s)) {
    StitchId maker = g.loops[l].maker;
    while (maker != kNoStitch && g.type[maker] == T::sl)
      maker = g.loops[g.loops_taken_by(maker)[0]].maker;
    if (maker != kNoStitch && g.type[maker] == T::tuck) return true;
  }
  return false;
}

void append_stitch_ops(const KnitGraph& g, StitchId s, Side side, bool mirror, TurnMethod turns,
                       std::vector<HandOp>& ops, bool& wraps_again) {
  T type = worked_by_hand(g, s);
  if (type == T::sr4) return ops.push_back(turning_op(g, s, side, turns, wraps_again));
  std::optional<Working> w = working_of(mirror ? mirrored(type) : type, side);
  SKEIN_ASSERT(w.has_value(), "every supported stitch type has a hand working");
  HandOp op = works_a_turn(g, s) ? resolving(g, w->op, s, turns) : w->op;
  ops.push_back(works_a_st_with_its_yo(g, s) ? with_its_yo(op) : op);
  if (w->make) ops.push_back(*w->make);
}

void check_make_one_has_a_strand(const KnitGraph& g, StitchId last) {
  if (g.type[last] == T::m1l || g.type[last] == T::m1r)
    unsupported(
        fmt::format("{} is a make-one worked last in its row, where there is no strand "
                    "to lift; make it kfb, or move it one stitch in",
                    g.describe(last)));
}

}  // namespace skein::hand
