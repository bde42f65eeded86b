// The schedule IR every target consumes: one sequence of events in knitting order. Stitches
// of a yarn piece come in runs; a run ends when the next stitch must wait for another piece
// (hold) and continues later (resume). Paper §4.3, Algorithm 1.
#pragma once

#include <cstdint>
#include <vector>

#include "depgraph/dependency_graph.hpp"
#include "knitgraph/knit_graph.hpp"
#include "knitgraph/yarn_pieces.hpp"

namespace skein {

enum class EventKind : std::uint8_t {
  yarn_start,  // join a new yarn piece; `stitch` is its first stitch
  yarn_end,    // fasten off the piece after `stitch`
  row_start,   // `stitch` begins a row or round (row_shape says which)
  turn,        // turn the work before `stitch` (open and short rows)
  marker,      // place a marker before `stitch`; `marker` says why
  hold,        // put the piece aside: `stitch` waits for `waits_for`
  resume,      // take the piece up again at `stitch`
  stitch,      // work `stitch`
};

enum class MarkerKind : std::uint8_t {
  none,
  beginning_of_round,  // at a shift-path
  mismatch_begin,      // before a run of stitches beside mismatched edges
  mismatch_end,
  short_row_begin,
  short_row_end,
};
const char* marker_name(MarkerKind kind);

struct Event {
  EventKind kind;
  MarkerKind marker = MarkerKind::none;
  std::uint32_t yarn = 0;
  StitchId stitch = kNoStitch;
  StitchId waits_for = kNoStitch;  // with hold
};

struct Schedule {
  std::vector<Event> events;
  std::uint32_t stitches = 0;
  std::uint32_t holds = 0;
};

// Algorithm 1 with a stack of yarn pieces. When a piece must wait, the piece that owns the
// first stitch it waits for moves to the top, so one part is finished before the next starts.
// The graph must be acyclic (check_knittability). Deterministic.
Schedule schedule_stitches(const KnitGraph& graph, const DependencyGraph& deps,
                           const YarnPieces& pieces);

}  // namespace skein
