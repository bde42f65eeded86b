#include "schedule/schedule.hpp"

#include <boost/range/iterator_range.hpp>

#include "common/error.hpp"

namespace skein {

const char* marker_name(MarkerKind kind) {
  switch (kind) {
    case MarkerKind::none:
      return "none";
    case MarkerKind::beginning_of_round:
      return "bor";
    case MarkerKind::mismatch_begin:
      return "mismatch-begin";
    case MarkerKind::mismatch_end:
      return "mismatch-end";
    case MarkerKind::short_row_begin:
      return "short-row-begin";
    case MarkerKind::short_row_end:
      return "short-row-end";
  }
  return "?";
}

namespace {

constexpr std::uint32_t kNone = kNoStitch;

// The waiting yarn pieces, top first, as an intrusive doubly linked list so a piece can move
// to the top in constant time.
class PieceStack {
 public:
  explicit PieceStack(std::uint32_t pieces)
      : above_(pieces, kNone), below_(pieces, kNone), in_(pieces, 0) {}
  bool empty() const { return top_ == kNone; }
  bool contains(std::uint32_t p) const { return in_[p]; }
  std::uint32_t top() const { return top_; }
  std::uint32_t below(std::uint32_t p) const { return below_[p]; }
  void push(std::uint32_t p) {
    below_[p] = top_;
    above_[p] = kNone;
    if (top_ != kNone) above_[top_] = p;
    top_ = p;
    in_[p] = 1;
  }
  void remove(std::uint32_t p) {
    if (above_[p] != kNone)
      below_[above_[p]] = below_[p];
    else
      top_ = below_[p];
    if (below_[p] != kNone) above_[below_[p]] = above_[p];
    in_[p] = 0;
  }
  void move_to_top(std::uint32_t p) {
    remove(p);
    push(p);
  }

 private:
  std::vector<std::uint32_t> above_, below_;
  std::vector<std::uint8_t> in_;
  std::uint32_t top_ = kNone;
};

class Scheduler {
 public:
  Scheduler(const KnitGraph& g, const DependencyGraph& deps, const YarnPieces& pieces)
      : g_(g),
        deps_(deps),
        pieces_(pieces),
        waiting_(g.size()),
        at_(pieces.size()),
        started_(pieces.size(), 0),
        done_(g.size(), 0),
        stack_(pieces.size()) {
    for (StitchId s = 0; s < g.size(); ++s)
      waiting_[s] = static_cast<std::uint32_t>(in_degree(s, deps));
    for (std::uint32_t p = pieces.size(); p-- > 0;) {
      at_[p] = pieces.first[p];
      stack_.push(p);  // piece 0 ends on top: knitting starts with the first piece
    }
    out_.events.reserve(g.size() + g.size() / 8 + 16);
  }

  Schedule run() && {
    while (!stack_.empty()) knit_run(next_ready_piece());
    SKEIN_ASSERT(out_.stitches == g_.size(), "every stitch scheduled once");
    return std::move(out_);
  }

 private:
  std::uint32_t next_ready_piece() const {
    for (std::uint32_t p = stack_.top(); p != kNone; p = stack_.below(p))
      if (waiting_[at_[p]] == 0) return p;
    SKEIN_ASSERT(false, "an acyclic dependency graph always has a ready piece");
    return kNone;
  }

  void emit(EventKind kind, std::uint32_t piece, StitchId s, MarkerKind marker = MarkerKind::none,
            StitchId waits_for = kNoStitch) {
    out_.events.push_back({kind, marker, piece, s, waits_for});
  }

  // Knits along the piece's yarn until it ends or its next stitch must wait.
  void knit_run(std::uint32_t piece) {
    stack_.remove(piece);
    StitchId s = at_[piece];
    if (started_[piece]) {
      emit(EventKind::resume, piece, s);
    } else {
      started_[piece] = 1;
      emit(EventKind::yarn_start, piece, s);
      emit(EventKind::row_start, piece, s);
    }
    for (;;) {
      knit(piece, s);
      StitchId next = g_.yarn_next[s];
      if (next == kNoStitch) {
        emit(EventKind::yarn_end, piece, s);
        return;
      }
      announce_link(piece, s, next);
      s = next;
      if (waiting_[s] != 0) {
        hold(piece, s);
        return;
      }
    }
  }

  void knit(std::uint32_t piece, StitchId s) {
    emit(EventKind::stitch, piece, s);
    done_[s] = 1;
    ++out_.stitches;
    for (auto e : boost::make_iterator_range(out_edges(s, deps_))) --waiting_[target(e, deps_)];
  }

  // Row starts, turns and the markers the paper asks for (§5.1) between `s` and `next`.
  void announce_link(std::uint32_t piece, StitchId s, StitchId next) {
    switch (g_.yarn_link[s]) {
      case YarnLink::shift:
        emit(EventKind::row_start, piece, next);
        emit(EventKind::marker, piece, next, MarkerKind::beginning_of_round);
        break;
      case YarnLink::turn:
        emit(EventKind::turn, piece, next);
        emit(EventKind::row_start, piece, next);
        break;
      case YarnLink::course:
      case YarnLink::none:
        break;
    }
    mark_region(piece, s, next, kBesideMismatch, MarkerKind::mismatch_begin,
                MarkerKind::mismatch_end);
    mark_region(piece, s, next, kShortRowEnd, MarkerKind::short_row_begin,
                MarkerKind::short_row_end);
  }

  void mark_region(std::uint32_t piece, StitchId s, StitchId next, std::uint8_t flag,
                   MarkerKind begin, MarkerKind end) {
    bool was = g_.flags[s] & flag, is = g_.flags[next] & flag;
    if (was != is) emit(EventKind::marker, piece, next, is ? begin : end);
  }

  void hold(std::uint32_t piece, StitchId s) {
    StitchId blocker = first_unknit_dependency(s);
    emit(EventKind::hold, piece, s, MarkerKind::none, blocker);
    ++out_.holds;
    at_[piece] = s;
    stack_.push(piece);
    std::uint32_t owner = pieces_.piece_of[blocker];
    if (stack_.contains(owner)) stack_.move_to_top(owner);
  }

  StitchId first_unknit_dependency(StitchId s) const {
    for (auto e : boost::make_iterator_range(in_edges(s, deps_))) {
      StitchId before = static_cast<StitchId>(source(e, deps_));
      if (!knitted(before)) return before;
    }
    SKEIN_ASSERT(false, "a waiting stitch has an unknit dependency");
    return kNoStitch;
  }

  bool knitted(StitchId s) const { return done_[s]; }

  const KnitGraph& g_;
  const DependencyGraph& deps_;
  const YarnPieces& pieces_;
  std::vector<std::uint32_t> waiting_;  // unknit dependencies per stitch
  std::vector<StitchId> at_;            // per piece: the next stitch to knit
  std::vector<std::uint8_t> started_;
  std::vector<std::uint8_t> done_;
  PieceStack stack_;
  Schedule out_;
};

}  // namespace

Schedule schedule_stitches(const KnitGraph& g, const DependencyGraph& deps,
                           const YarnPieces& pieces) {
  return Scheduler(g, deps, pieces).run();
}

}  // namespace skein
