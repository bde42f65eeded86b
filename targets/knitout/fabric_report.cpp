#include "knitout/fabric_report.hpp"

#include <fmt/format.h>

#include <bit>
#include <memory>
#include <numeric>
#include <vector>

namespace skein::knitout {
namespace {

// Pieces are the connected parts of the fabric: union-find over the loops, in the order they
// were made. Every join links the larger root under the smaller, so a loop is a root exactly
// when nothing was linked over it: counting the pieces needs no search.
class Pieces {
 public:
  // Not value-initialised: iota writes each entry once (zeroing them first cost a pass over
  // 4 MB a million loops).
  explicit Pieces(std::size_t loops) : parent_(new LoopId[loops]), size_(loops) {
    std::iota(parent_.get(), parent_.get() + loops, LoopId{0});
  }
  void join(LoopId a, LoopId b) {
    a = root(a);
    b = root(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
  std::uint64_t count() const {
    std::uint64_t n = 0;
    for (LoopId l = 0; l < size_; ++l) n += parent_[l] == l;
    return n;
  }

 private:
  LoopId root(LoopId l) {
    while (parent_[l] != l) l = parent_[l] = parent_[parent_[l]];  // path halving
    return l;
  }
  std::unique_ptr<LoopId[]> parent_;
  std::size_t size_;
};

// A decrease gathers the loops of two stitches or more; a tuck knitted off together with the
// loop it sits on (a tuck stitch) is one stitch's.
bool is_decrease(const Fabric& f, LoopId l) {
  if (f.loops[l].parent_count < 2) return false;
  int stitches = 0;
  for (LoopId p : f.parents_of(l)) stitches += f.loops[p].made_by != OpCode::tuck;
  return stitches >= 2;
}

}  // namespace

FabricReport fabric_report(const Replay& replay) {
  const Fabric& f = replay.fabric;
  FabricReport r;
  Pieces pieces(f.loops.size());
  // Per carrier, its last loop so far: the yarn joins consecutive loops of one yarn piece.
  std::vector<LoopId> last(f.by_carrier.size(), kNoLoop);
  for (LoopId l = 0; l < f.loops.size(); ++l) {
    const FabricLoop& loop = f.loops[l];
    for (LoopId parent : f.parents_of(l)) pieces.join(l, parent);
    for (CarrierMask yarn = loop.yarn; yarn; yarn &= yarn - 1) {
      LoopId& before = last[static_cast<std::size_t>(std::countr_zero(yarn))];
      if (before != kNoLoop && f.loops[before].piece == loop.piece) pieces.join(before, l);
      before = l;
    }
    switch (loop.made_by) {
      case OpCode::tuck:
        ++r.tucks;
        r.idle_tucks += loop.children == 0;
        break;
      case OpCode::split:
        ++r.splits;
        break;
      default:
        ++(loop.front ? r.knits : r.purls);
        break;
    }
    if (loop.made_by != OpCode::tuck && loop.parent_count == 0) ++r.through_nothing;
    r.decreases += is_decrease(f, l);
    r.unravelling += loop.dropped;
  }
  r.pieces = pieces.count();
  r.left_on_needles = replay.stats.loops_left;
  r.long_floats = replay.stats.long_floats;
  return r;
}

std::string fabric_summary(const FabricReport& r, const MachineProfile& p) {
  return fmt::format(
      "  fabric: {} piece{}; {} knit on the front bed, {} on the back, {} tuck, {} split ({} "
      "decreases)\n"
      "  loops dropped that unravel: {}, loops left on the needles: {}\n"
      "  stitches pulled through nothing: {}, floats longer than {} needles: {}, tucks that hold "
      "nothing: {}",
      r.pieces, r.pieces == 1 ? "" : "s", r.knits, r.purls, r.tucks, r.splits, r.decreases,
      r.unravelling, r.left_on_needles, r.through_nothing, p.max_float, r.long_floats,
      r.idle_tucks);
}

}  // namespace skein::knitout
