#include "knitout/fabric_report.hpp"

#include <fmt/format.h>

#include <memory>
#include <numeric>
#include <vector>

namespace skein::knitout {
namespace {

// Pieces are the connected parts of the fabric: union-find over the loops.
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
  std::uint64_t count() {
    std::uint64_t n = 0;
    for (LoopId l = 0; l < size_; ++l) n += root(l) == l;
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

}  // namespace

FabricReport fabric_report(const Replay& replay) {
  const Fabric& f = replay.fabric;
  FabricReport r;
  Pieces pieces(f.loops.size());
  for (LoopId l = 0; l < f.loops.size(); ++l) {
    const FabricLoop& loop = f.loops[l];
    for (LoopId parent : f.parents_of(l)) pieces.join(l, parent);
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
    if (loop.parent_count >= 2) ++r.decreases;
    r.unravelling += loop.dropped;
  }
  // The yarn joins consecutive loops of one yarn piece.
  for (const std::vector<LoopId>& along : f.by_carrier)
    for (std::size_t i = 1; i < along.size(); ++i)
      if (f.loops[along[i]].piece == f.loops[along[i - 1]].piece)
        pieces.join(along[i - 1], along[i]);
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
