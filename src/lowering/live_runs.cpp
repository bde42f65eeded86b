#include "lowering/live_runs.hpp"

#include "common/error.hpp"

namespace skein {

LiveRuns::LiveRuns(const KnitGraph& g)
    : next_(g.loops.size(), kNoLoop),
      prev_(g.loops.size(), kNoLoop),
      run_of_(g.loops.size()),
      edge_(g.loops.size(), 0) {}

std::uint32_t LiveRuns::walk_end(const Segment& seg) const {
  std::uint32_t loop = seg.first;
  for (std::uint32_t i = 1; i < seg.count; ++i)
    loop = seg.walk == Walk::forward ? next_[loop] : prev_[loop];
  return loop;
}

void LiveRuns::start(RunId id, std::span<const std::uint32_t> loops, RunShape shape) {
  if (runs_.size() <= id.index()) runs_.resize(id.index() + 1);
  State& r = runs_[id.index()];
  r = State{loops.empty() ? kNoLoop : loops.front(), static_cast<std::uint32_t>(loops.size()),
            shape};
  std::uint32_t last = kNoLoop;
  for (std::uint32_t loop : loops) {
    edge_[loop] = 0;
    run_of_[loop] = id;
    prev_[loop] = last;
    if (last != kNoLoop) next_[last] = loop;
    last = loop;
  }
  if (last == kNoLoop) return;
  next_[last] = kNoLoop;
  if (shape == RunShape::ring) close_ring(id, loops.front(), last);
}

void LiveRuns::close_ring(RunId r, std::uint32_t first, std::uint32_t last) {
  next_[last] = first;
  prev_[first] = last;
  runs_[r.index()].shape = RunShape::ring;
}

bool LiveRuns::leaves_tail(const Segment& seg) const {
  const State& r = runs_[seg.run.index()];
  return r.shape == RunShape::line && prev_[seg.first] != kNoLoop &&
         next_[walk_end(seg)] != kNoLoop;
}

void LiveRuns::relabel(std::uint32_t from, std::uint32_t count, RunId r) {
  for (std::uint32_t loop = from, i = 0; i < count; ++i, loop = next_[loop]) run_of_[loop] = r;
}

void LiveRuns::replace(const Segment& seg, std::span<const std::uint32_t> loops, RowShape course,
                       RunId tail) {
  SKEIN_ASSERT(seg.walk == Walk::forward, "segments are replaced in run order");
  if (tail.valid() && runs_.size() <= tail.index()) runs_.resize(tail.index() + 1);
  State& r = runs_[seg.run.index()];
  std::uint32_t first = seg.first, last = walk_end(seg);
  bool whole = seg.count == r.size;
  std::uint32_t before = whole ? kNoLoop : prev_[first], after = whole ? kNoLoop : next_[last];
  bool had_head = whole;
  for (std::uint32_t loop = first, i = 0; i < seg.count; ++i, loop = next_[loop]) {
    had_head |= loop == r.head;
    run_of_[loop] = RunId();
  }
  r.size -= seg.count;
  if (!loops.empty()) {
    std::uint32_t link = before;
    for (std::uint32_t loop : loops) {
      edge_[loop] = 0;
      run_of_[loop] = seg.run;
      prev_[loop] = link;
      if (link != kNoLoop) next_[link] = loop;
      link = loop;
    }
    next_[loops.back()] = after;
    if (after != kNoLoop) prev_[after] = loops.back();
    r.size += static_cast<std::uint32_t>(loops.size());
    if (had_head) r.head = loops.front();
    if (!whole) return;
    bool ring =
        course == RowShape::closed || (course == RowShape::short_row && r.shape == RunShape::ring);
    r.shape = ring ? RunShape::ring : RunShape::line;
    if (ring) close_ring(seg.run, loops.front(), loops.back());
    return;
  }
  if (whole) {
    r.head = kNoLoop;
    return;
  }
  if (r.shape == RunShape::ring) {  // the ring opens where the segment was
    r.shape = RunShape::line;
    r.head = after;
    next_[before] = kNoLoop;
    prev_[after] = kNoLoop;
    return;
  }
  if (before != kNoLoop) next_[before] = kNoLoop;
  if (after != kNoLoop) prev_[after] = kNoLoop;
  if (before == kNoLoop) {
    r.head = after;
  } else if (after != kNoLoop) {  // the tail beyond the segment becomes a run of its own
    SKEIN_ASSERT(tail.valid(), "a run for the tail of a line cut in its middle");
    std::uint32_t count = 0;
    for (std::uint32_t loop = after; loop != kNoLoop; loop = next_[loop]) ++count;
    runs_[tail.index()] = State{after, count, RunShape::line};
    relabel(after, count, tail);
    r.size -= count;
  }
}

void LiveRuns::cut(const Segment& seg, RunId id, RunId tail) {
  std::vector<std::uint32_t> loops;
  loops.reserve(seg.count);
  for (std::uint32_t loop = seg.first, i = 0; i < seg.count; ++i, loop = next_[loop])
    loops.push_back(loop);
  replace(seg, {}, RowShape::short_row, tail);
  start(id, loops, RunShape::line);
}

void LiveRuns::open_at(RunId r, std::uint32_t first) {
  State& s = runs_[r.index()];
  if (s.shape != RunShape::ring) return;
  std::uint32_t last = prev_[first];
  next_[last] = kNoLoop;
  prev_[first] = kNoLoop;
  s.head = first;
  s.shape = RunShape::line;
}

void LiveRuns::close(RunId r) {
  State& s = runs_[r.index()];
  if (s.shape == RunShape::ring || s.size == 0) return;
  std::uint32_t last = s.head;
  while (next_[last] != kNoLoop) last = next_[last];
  close_ring(r, s.head, last);
}

void LiveRuns::reverse(RunId r) {
  State& s = runs_[r.index()];
  if (s.size == 0) return;
  std::uint32_t loop = s.head, last = s.head;
  for (std::uint32_t i = 0; i < s.size; ++i) {
    std::uint32_t next = next_[loop];
    std::swap(next_[loop], prev_[loop]);
    last = loop;
    loop = next;
  }
  if (s.shape == RunShape::line) s.head = last;
}

void LiveRuns::append(RunId a, RunId b) {
  State &x = runs_[a.index()], &y = runs_[b.index()];
  SKEIN_ASSERT(x.shape == RunShape::line && y.shape == RunShape::line, "lines are appended");
  if (y.size == 0) return;
  relabel(y.head, y.size, a);
  if (x.size == 0) {
    x.head = y.head;
  } else {
    std::uint32_t last = x.head;
    while (next_[last] != kNoLoop) last = next_[last];
    next_[last] = y.head;
    prev_[y.head] = last;
  }
  x.size += y.size;
  y = State{};
}

}  // namespace skein
