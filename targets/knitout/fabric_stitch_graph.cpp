#include "knitout/fabric_stitch_graph.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <ostream>
#include <utility>
#include <vector>

#include "common/error.hpp"
#include "knitout/fabric_picture.hpp"

namespace skein::knitout {
namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// A dropped loop nothing held unravels, and the cord it ends with it (a tag knit back and forth
// on one needle): each loop below it that held nothing else and was, like the loop above it,
// pulled through its yarn's previous loop alone (at a sheet's edge a row's first loop is
// pulled through the yarn's previous loop too, but the loop under it is not: no cord). The rows
// under a dropped row stay (their wales end there): a ladder runs only when the fabric is pulled.
std::vector<bool> unravelling(const Fabric& f) {
  std::vector<LoopId> previous(f.loops.size(), kNone), last_of_piece;
  for (LoopId l = 0; l < f.loops.size(); ++l) {
    std::uint32_t piece = f.loops[l].piece;
    if (piece >= last_of_piece.size()) last_of_piece.resize(piece + 1, kNone);
    previous[l] = std::exchange(last_of_piece[piece], l);
  }
  std::vector<bool> gone(f.loops.size(), false);
  for (LoopId l = static_cast<LoopId>(f.loops.size()); l-- > 0;) {
    gone[l] = gone[l] || f.loops[l].dropped;
    if (!gone[l] || f.loops[l].parent_count != 1) continue;
    LoopId below = f.parents_of(l)[0];
    const FabricLoop& b = f.loops[below];
    bool in_cord =
        below == previous[l] && b.parent_count == 1 && f.parents_of(below)[0] == previous[below];
    if (in_cord && b.children == 1) gone[below] = true;
  }
  return gone;
}

// A stitch of the graph: the loop it makes (and an increase's second), the loops it takes.
struct Stitch {
  LoopId loop = kNone;
  LoopId second = kNone;
  std::vector<LoopId> takes;
  std::array<std::uint32_t, 2> taker{kNone, kNone};  // the stitch taking each of its loops
  bool after_taking = false;  // its yarn's previous stitch took loops (it is not a cast-on)
  std::uint32_t first_line = 0;
  std::uint32_t lines = 0;
};

struct StitchGraph {
  std::vector<Stitch> stitches;
  std::vector<std::uint32_t> stitch_of;  // per loop: the stitch that makes it (or kNone)
};

class GraphBuilder {
 public:
  GraphBuilder(const Fabric& f, const std::vector<bool>* proven_border)
      : f_(f),
        proven_border_(proven_border),
        gone_(unravelling(f)),
        takes_(f.loops.size()),
        stitch_of_(f.loops.size(), kNone),
        taken_(f.loops.size(), false) {}

  StitchGraph build() {
    for (LoopId l = 0; l < f_.loops.size(); ++l)
      if (!gone_[l] && f_.loops[l].made_by != OpCode::tuck) resolve_parents(l);
    mark_borders();
    find_cast_on_runs();
    for (LoopId l = 0; l < f_.loops.size(); ++l)
      if (!gone_[l] && !border_[l]) add_stitch(l);
    link_takers();
    return {std::move(stitches_), std::move(stitch_of_)};
  }

 private:
  // The loops `l` takes in the stitch graph: its parents, a tuck standing for the loop under
  // it, without its yarn's previous loop when that is one link of a chain. A tuck made on an
  // empty needle and moved onto loops later lies over nothing: a loop through nothing that `l`
  // takes beside them (taken by the tuck, a loop made after it would be listed before its taker).
  void resolve_parents(LoopId l) {
    std::vector<LoopId>& takes = takes_[l];
    for (LoopId parent : f_.parents_of(l)) {
      const FabricLoop& p = f_.loops[parent];
      if (p.made_by == OpCode::tuck && !p.over_nothing && !takes.empty()) {
        takes_[parent] = {takes.back()};
        takes.back() = parent;
      } else {
        takes.push_back(parent);
      }
    }
    LoopId previous = previous_in_piece(l);
    if (takes.size() >= 2 && previous != kNone) std::erase(takes, previous);
  }

  LoopId previous_in_piece(LoopId l) {
    std::uint32_t piece = f_.loops[l].piece;
    if (piece >= last_of_piece_.size()) last_of_piece_.resize(piece + 1, kNone);
    LoopId previous = last_of_piece_[piece];
    last_of_piece_[piece] = l;
    return previous;
  }

  // The tucks through nothing a yarn piece starts with, and the loops a proof found to be its
  // border: its cast-on border.
  void mark_borders() {
    border_.assign(f_.loops.size(), false);
    std::vector<bool> started;
    for (LoopId l = 0; l < f_.loops.size(); ++l) {
      if (gone_[l]) continue;
      std::uint32_t piece = f_.loops[l].piece;
      if (piece >= started.size()) started.resize(piece + 1, false);
      bool leading_tuck =
          !started[piece] && takes_[l].empty() && f_.loops[l].made_by == OpCode::tuck;
      border_[l] = leading_tuck || (proven_border_ && (*proven_border_)[l]);
      started[piece] = started[piece] || !border_[l];
      std::erase_if(takes_[l], [&](LoopId p) { return border_[p]; });
    }
  }

  // Per loop: whether the next loop its yarn makes (of those written) is pulled through
  // nothing too: two such loops in a row are a cast-on (along a split, a crotch's), not a
  // yarn-over beside a knit.
  void find_cast_on_runs() {
    before_nothing_.assign(f_.loops.size(), false);
    std::vector<std::uint8_t> next_takes_nothing;  // per piece, going back along the yarn
    for (LoopId l = static_cast<LoopId>(f_.loops.size()); l-- > 0;) {
      if (gone_[l] || border_[l]) continue;
      std::uint32_t piece = f_.loops[l].piece;
      if (piece >= next_takes_nothing.size()) next_takes_nothing.resize(piece + 1, 0);
      before_nothing_[l] = next_takes_nothing[piece];
      next_takes_nothing[piece] = takes_[l].empty();
    }
  }

  void add_stitch(LoopId l) {
    std::uint32_t piece = f_.loops[l].piece;
    if (piece >= last_stitch_.size()) last_stitch_.resize(piece + 1, kNone);
    std::uint32_t& last = last_stitch_[piece];
    if (last != kNone && joins_as_increase(stitches_[last], l)) {
      stitches_[last].second = l;
      stitch_of_[l] = last;
      return;
    }
    Stitch s;
    s.loop = l;
    s.after_taking = last != kNone && !stitches_[last].takes.empty();
    for (LoopId p : takes_[l])
      if (!taken_[p]) s.takes.push_back(p), taken_[p] = true;
    stitch_of_[l] = last = static_cast<std::uint32_t>(stitches_.size());
    stitches_.push_back(std::move(s));
  }

  // A split and a knit through one loop, or a loop through nothing beside a knit (either way
  // along the yarn; not in a cast-on, where the loops through nothing follow each other):
  // one increase.
  bool joins_as_increase(Stitch& s, LoopId l) {
    if (s.second != kNone) return false;
    const std::vector<LoopId>& mine = takes_[l];
    if (s.takes.size() == 1 && mine.size() == 1 && s.takes[0] == mine[0]) return true;
    if (s.takes.size() == 1 && mine.empty() && !takes_[s.loop].empty() && !before_nothing_[l])
      return true;
    if (s.takes.empty() && s.after_taking && mine.size() == 1 && !taken_[mine[0]] &&
        mine[0] < s.loop) {
      s.takes = {mine[0]};
      taken_[mine[0]] = true;
      return true;
    }
    return false;
  }

  void link_takers() {
    for (std::uint32_t s = 0; s < stitches_.size(); ++s)
      for (LoopId p : stitches_[s].takes) {
        Stitch& maker = stitches_[stitch_of_[p]];
        maker.taker[p == maker.loop ? 0 : 1] = s;
      }
  }

  const Fabric& f_;
  const std::vector<bool>* proven_border_;
  std::vector<bool> gone_, border_, before_nothing_;
  std::vector<std::vector<LoopId>> takes_;
  std::vector<std::uint32_t> stitch_of_;
  std::vector<bool> taken_;
  std::vector<LoopId> last_of_piece_;
  std::vector<std::uint32_t> last_stitch_;
  std::vector<Stitch> stitches_;
};

std::uint32_t out_count(const Stitch& s) {
  return s.second == kNone ? 1 : 2;
}

// A loop nothing takes ends its wale: the stitch itself is the end (`e`) when it takes one
// loop and makes one; else an `e` line follows for each loop nothing takes.
bool is_end(const Stitch& s) {
  return s.takes.size() == 1 && s.second == kNone && s.taker[0] == kNone;
}
std::uint32_t trailing_ends(const Stitch& s) {
  if (is_end(s)) return 0;
  return (s.taker[0] == kNone) + (s.second != kNone && s.taker[1] == kNone);
}
std::uint32_t chain_lines(const Stitch& s) {  // the `d`s before a decrease of 3 or more
  return s.takes.size() > 2 ? static_cast<std::uint32_t>(s.takes.size()) - 2 : 0;
}
bool skipped(const Stitch& s) {  // a loop through nothing nothing takes: it holds nothing
  return s.takes.empty() && s.second == kNone && s.taker[0] == kNone;
}

// What the passes of each yarn piece (runs of its loops going one way) knit: per piece whether
// it is a tube, and per loop whether its pass knits a tube's front half (whichever bed a rib's
// purl or a rolled stitch in it is knit on).
struct Halves {
  std::vector<bool> tube;        // per yarn piece
  std::vector<bool> front_half;  // per loop
};

class PassReader {
 public:
  explicit PassReader(const Fabric& f) : f_(f), pass_of_(f.loops.size()) {}

  Halves read() {
    std::vector<bool> wale_front(f_.loops.size());
    for (LoopId l = 0; l < f_.loops.size(); ++l) {
      const FabricLoop& loop = f_.loops[l];
      Pass& p = pass_for(l);
      // A wale stays on the half of the bed its first loop (a cast-on) was made on.
      wale_front[l] = loop.parent_count ? wale_front[f_.parents_of(l)[0]] : loop.front;
      Piece& piece = pieces_[loop.piece];
      piece.front_goes_plus += wale_front[l] == (loop.dir == Direction::plus) ? 1 : -1;
      count_beds(piece, loop);
      for (LoopId parent : f_.parents_of(l)) {
        if (f_.loops[parent].piece != loop.piece) continue;
        std::uint32_t back = p.number - passes_[pass_of_[parent]].number;
        p.onto_previous += back == 1;
        p.onto_older += back >= 2;
        piece.rounds_over_rows += (back == 2) - (back == 1);
      }
    }
    Halves h{tubes(), std::vector<bool>(f_.loops.size())};
    for (Pass& p : passes_) {
      Piece& piece = pieces_[p.piece];
      piece.reversed ^= p.previous != kNone && p.onto_previous > p.onto_older;
      bool front_way = (p.dir == Direction::plus) == (piece.front_goes_plus >= 0);
      p.on_front = front_way != piece.reversed;
    }
    for (LoopId l = 0; l < f_.loops.size(); ++l) h.front_half[l] = passes_[pass_of_[l]].on_front;
    return h;
  }

 private:
  struct Pass {
    std::uint32_t piece = 0, number = 0;  // number: its place among its piece's passes
    std::uint32_t previous = kNone;       // its piece's pass before it
    Direction dir = Direction::none;
    std::uint32_t onto_previous = 0, onto_older = 0;  // loops it pulls through, by their pass
    bool on_front = true;
  };
  struct Piece {
    std::uint32_t last_pass = kNone;
    std::int64_t rounds_over_rows = 0;
    std::int64_t front_goes_plus = 0;  // front wales' loops going + and back's going -, less
    std::array<std::uint64_t, 2> front_by_dir{0, 0};
    bool has_back = false;
    // Whether its yarn goes round the other way now: it turned back (a pass pulled through the
    // pass before it: a short row) an odd number of times. A short row that goes on round the
    // fold knits the other half going the other way.
    bool reversed = false;
  };

  Pass& pass_for(LoopId l) {
    const FabricLoop& loop = f_.loops[l];
    if (loop.piece >= pieces_.size()) pieces_.resize(loop.piece + 1);
    Piece& piece = pieces_[loop.piece];
    if (piece.last_pass == kNone || passes_[piece.last_pass].dir != loop.dir) {
      Pass p;
      p.piece = loop.piece;
      p.dir = loop.dir;
      p.previous = piece.last_pass;
      p.number = piece.last_pass == kNone ? 0 : passes_[piece.last_pass].number + 1;
      piece.last_pass = static_cast<std::uint32_t>(passes_.size());
      passes_.push_back(p);
    }
    pass_of_[l] = piece.last_pass;
    return passes_[piece.last_pass];
  }

  static void count_beds(Piece& piece, const FabricLoop& loop) {
    if (loop.made_by == OpCode::tuck) return;
    if (loop.front)
      ++piece.front_by_dir[loop.dir == Direction::plus];
    else
      piece.has_back = true;
  }

  // A piece is a tube when its yarn goes round: more of its loops are pulled through loops its
  // yarn made two passes before (the same half, a round below) than through loops of the pass
  // just before (a row knit back across a sheet), whichever beds a rib's purls are knit on. A
  // piece pulled through none of its own loops (a draw thread's one round through the waste)
  // is a tube when its front loops go one way round, the back's being there.
  std::vector<bool> tubes() const {
    std::vector<bool> tube(pieces_.size());
    for (std::size_t i = 0; i < tube.size(); ++i) {
      const Piece& p = pieces_[i];
      auto [minus, plus] = p.front_by_dir;
      bool one_way = p.has_back && std::min(minus, plus) * 4 < std::max(minus, plus);
      tube[i] = p.rounds_over_rows > 0 || (p.rounds_over_rows == 0 && one_way);
    }
    return tube;
  }

  const Fabric& f_;
  std::vector<std::uint32_t> pass_of_;  // per loop
  std::vector<Pass> passes_;
  std::vector<Piece> pieces_;
};

class StWriter {
 public:
  StWriter(const Fabric& f, StitchGraph graph, std::ostream& out)
      : f_(f),
        stitches_(std::move(graph.stitches)),
        stitch_of_(std::move(graph.stitch_of)),
        out_(out),
        height_(loop_heights(f)),
        halves_(PassReader(f).read()) {
    std::uint32_t line = 0;
    for (Stitch& s : stitches_) {
      if (s.takes.size() >= 2) order_as_met(s);
      s.first_line = line;
      s.lines = skipped(s) ? 0 : chain_lines(s) + 1 + trailing_ends(s);
      line += s.lines;
    }
    lines_ = line;
  }

  std::uint32_t lines() const { return lines_; }

  // `.st` lists a decrease's loops in the order its yarn meets them (AutoKnit's tracer, which
  // swaps them for a clockwise stitch; the reader turns them into slots from the left): the
  // order their yarn made them when the decrease goes the same way round, else the reverse. The
  // needle stacks them in the order they were moved, which is neither.
  void order_as_met(Stitch& s) const {
    auto made = [&](LoopId l) { return made_where(l); };
    std::ranges::sort(s.takes, {}, made);
    if (round_way(s.loop) != round_way(made_where(s.takes.front()))) std::ranges::reverse(s.takes);
  }

  // A tuck that stands for the loop under it (a stitch taking that loop) lies where it does.
  LoopId made_where(LoopId l) const {
    std::uint32_t t = stitch_of_[l];
    bool stands_in =
        f_.loops[l].made_by == OpCode::tuck && t != kNone && stitches_[t].takes.size() == 1;
    return stands_in ? stitches_[t].takes[0] : l;
  }

  bool round_way(LoopId l) const {
    const FabricLoop& loop = f_.loops[l];
    bool plus = loop.dir == Direction::plus;
    return halves_.tube[loop.piece] ? plus == halves_.front_half[l] : plus;
  }

  // Lines are formatted into a buffer written out in blocks: an ostream call per line costs
  // more than the formatting.
  void write(std::vector<bool>* purled_decreases) {
    purled_ = purled_decreases;
    if (purled_) purled_->assign(lines_, false);
    for (const Stitch& s : stitches_) {
      if (s.lines) write_stitch(s);
      if (buffer_.size() > (1u << 16)) flush();
    }
    flush();
  }

 private:
  std::uint32_t main_line(const Stitch& s) const { return s.first_line + chain_lines(s); }
  std::int64_t line_of(LoopId l) const { return main_line(stitches_[stitch_of_[l]]); }
  // The line of taker `t` that takes `loop` (a decrease of 3 or more takes it in its chain).
  std::int64_t taker_line(std::uint32_t t, LoopId loop) const {
    if (t == kNone) return -1;
    const Stitch& s = stitches_[t];
    if (s.takes.size() <= 2) return main_line(s);
    auto i = static_cast<std::uint32_t>(std::find(s.takes.begin(), s.takes.end(), loop) -
                                        s.takes.begin());
    return s.first_line + (i <= 1 ? 0 : i - 1);
  }

  void write_stitch(const Stitch& s) {
    const std::size_t n = s.takes.size();
    for (std::uint32_t j = 0; j < chain_lines(s); ++j) {  // d(in0, in1), d(previous, in2), ...
      std::int64_t first = j == 0 ? line_of(s.takes[0]) : s.first_line + j - 1;
      line(s, 'd', {first, line_of(s.takes[j + 1])}, {s.first_line + j + 1, -1});
    }
    std::array<std::int64_t, 2> in{-1, -1};
    if (n > 2) in = {main_line(s) - 1, line_of(s.takes[n - 1])};
    for (std::size_t i = 0; i < n && i < 2 && n <= 2; ++i) in[i] = line_of(s.takes[i]);
    std::uint32_t next_end = main_line(s) + 1;
    std::array<std::int64_t, 2> outs{-1, -1};
    for (std::uint32_t o = 0; o < out_count(s) && !is_end(s); ++o)
      outs[o] = s.taker[o] != kNone ? taker_line(s.taker[o], o ? s.second : s.loop) : next_end++;
    char type = letter(s);
    line(s, type, in, outs);
    if (purled_ && type == 'd' && is_purl(s.loop))
      std::fill_n(purled_->begin() + s.first_line, chain_lines(s) + 1, true);
    for (std::uint32_t e = main_line(s) + 1; e < s.first_line + s.lines; ++e)
      line(s, 'e', {main_line(s), -1}, {-1, -1});
  }

  char letter(const Stitch& s) const {
    if (is_end(s)) return 'e';
    if (s.takes.empty()) return 's';
    if (s.second != kNone) return 'i';
    if (s.takes.size() >= 2) return 'd';
    if (f_.loops[s.loop].made_by == OpCode::tuck) return 't';
    return is_purl(s.loop) ? 'p' : 'k';
  }

  // A loop made on the other bed than its side's: a sheet's back bed; on a tube, the bed other
  // than that of its half's pass.
  bool is_purl(LoopId l) const {
    const FabricLoop& loop = f_.loops[l];
    return loop.front != (halves_.tube[loop.piece] ? halves_.front_half[l] : true);
  }

  void line(const Stitch& s, char type, std::array<std::int64_t, 2> in,
            std::array<std::int64_t, 2> outs) {
    const FabricLoop& l = f_.loops[s.loop];
    fmt::format_to(std::back_inserter(buffer_), "{} {} {} {} {} {} {} {} {} {}\n", l.piece, type,
                   round_way(s.loop) ? 'a' : 'c', in[0], in[1], outs[0], outs[1], l.needle,
                   height_[s.loop], l.front ? 0 : 1);
  }

  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

  const Fabric& f_;
  std::vector<Stitch> stitches_;
  std::vector<std::uint32_t> stitch_of_;
  std::ostream& out_;
  fmt::memory_buffer buffer_;
  std::vector<std::uint32_t> height_;
  Halves halves_;
  std::vector<bool>* purled_ = nullptr;  // per line: a decrease knit as a purl
  std::uint32_t lines_ = 0;
};

}  // namespace

void write_fabric_stitch_graph(const Replay& replay, const std::string& file, std::ostream& out,
                               const std::vector<bool>* border,
                               std::vector<bool>* purled_decreases) {
  StWriter writer(replay.fabric, GraphBuilder(replay.fabric, border).build(), out);
  if (writer.lines() == 0)
    throw Error(
        fmt::format("{}: nothing of the fabric stays (every loop unravels or holds "
                    "nothing), so there is no stitch graph to write",
                    file));
  writer.write(purled_decreases);
}

}  // namespace skein::knitout
