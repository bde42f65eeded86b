// The runs of live loops while the lowering walks the schedule: per loop its run and its
// neighbours along it (a doubly linked list per run, closed on itself for a ring), so that a
// course replaces the loops it takes in time linear in what it takes and makes.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "knitgraph/knit_graph.hpp"
#include "lowering/program.hpp"

namespace skein {

inline constexpr std::uint32_t kNoLoop = 0xffffffffu;

class LiveRuns {
 public:
  explicit LiveRuns(const KnitGraph& g);

  RunId run_of(std::uint32_t loop) const { return run_of_[loop]; }
  std::uint32_t next(std::uint32_t loop) const { return next_[loop]; }
  std::uint32_t prev(std::uint32_t loop) const { return prev_[loop]; }
  bool along_edge(std::uint32_t loop) const { return edge_[loop]; }
  // True when `b` comes straight after `a` in a's run.
  bool follows(std::uint32_t b, std::uint32_t a) const {
    return run_of_[a].valid() && next_[a] == b && run_of_[b] == run_of_[a];
  }
  std::uint32_t size(RunId r) const { return runs_[r.index()].size; }
  RunShape shape(RunId r) const { return runs_[r.index()].shape; }
  // A line's first loop (a ring's: where it was closed).
  std::uint32_t head(RunId r) const { return runs_[r.index()].head; }
  // The loop a segment's walk ends on.
  std::uint32_t walk_end(const Segment& seg) const;

  void lay_along_edge(std::uint32_t loop) { edge_[loop] = 1; }
  // Starts run `id` (numbered as the program numbers them) with `loops` in order.
  void start(RunId id, std::span<const std::uint32_t> loops, RunShape shape);
  // Would taking the forward segment `seg` with nothing in its place leave loops on both
  // sides of it in a line (the tail then becomes a run of its own)?
  bool leaves_tail(const Segment& seg) const;
  // Puts `loops` in place of the forward segment. A course over a whole run decides its shape
  // (`course`: a round makes a ring, a row a line, a short row keeps it); a ring that loses a
  // segment to nothing opens there; a line's tail beyond such a segment moves to `tail`.
  void replace(const Segment& seg, std::span<const std::uint32_t> loops, RowShape course,
               RunId tail = {});
  // The forward segment becomes run `id`, a line (the rest as replace() leaves it).
  void cut(const Segment& seg, RunId id, RunId tail);
  // Opens a ring at `first` (it becomes a line starting there).
  void open_at(RunId r, std::uint32_t first);
  // Turns run `r` round: its loops in the opposite order.
  void reverse(RunId r);
  // Appends line `b` to line `a`; b ends.
  void append(RunId a, RunId b);

 private:
  struct State {
    std::uint32_t head = kNoLoop, size = 0;
    RunShape shape = RunShape::line;
  };
  void relabel(std::uint32_t from, std::uint32_t count, RunId r);
  void close_ring(RunId r, std::uint32_t first, std::uint32_t last);

  std::vector<std::uint32_t> next_, prev_;  // per loop, along its run (kNoLoop: a line's end)
  std::vector<RunId> run_of_;               // per loop: invalid unless live in a run
  std::vector<std::uint8_t> edge_;          // per loop: made along an edge, not yet picked up
  std::vector<State> runs_;
};

}  // namespace skein
