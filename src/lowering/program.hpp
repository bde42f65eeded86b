// The live-loop program: the knit graph and its schedule lowered to what every knitter and
// every knitting machine holds between two courses, runs of live loops (made, not yet taken),
// and the steps that change them, in knitting order. Targets map runs onto needles, spare
// needles and holders (hand) or needle ranges of two beds (knitout); none re-derives course
// direction, rows or loop order.
//
// A run's loops are ordered as seen from the right side, wales up: left to right along a line;
// along a ring the same way round (the order a left-to-right round meets them). Order follows
// from yarn order alone: a course meets its run's loops forward when its direction (from the
// input) is left to right, backward otherwise, and leaves its new loops in their place, each
// stitch's by slot.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "knitgraph/knit_graph.hpp"
#include "knitgraph/yarn_pieces.hpp"
#include "mesh/handles.hpp"
#include "schedule/schedule.hpp"

namespace skein {

struct RunTag {};
using RunId = Handle<RunTag>;
struct StepTag {};
using StepId = Handle<StepTag>;

enum class RunShape : std::uint8_t { line, ring };
const char* run_shape_name(RunShape shape);

struct Run {
  RunShape shape = RunShape::line;
  std::uint32_t yarn = 0;  // the piece that last worked it
  StepId made_by;          // the step that started it
};

enum class StepKind : std::uint8_t {
  cast_on,                // stitches that take no loop start a run (or two, along a split)
  course,                 // a row, round or short row over a segment of one run, in place
  bind_off,               // a course that leaves no loop (all or part of its run)
  three_needle_bind_off,  // a course that also takes a second run's loops, one with each st
  split,                  // a segment of a run becomes a run of its own
  join,                   // runs taken up in one course become one run, in the order met
  reverse,                // a run cast on across a split takes the order of the side that
                          // takes it: the first course to meet it backward turns it round
  hold,                   // the yarn is set aside: its next stitch waits for another's
  resume,                 // the yarn is taken up again
};
const char* step_kind_name(StepKind kind);

// The order a step walks a segment of a run: forward is the run's order.
enum class Walk : std::uint8_t { forward, backward };

// Loops a step reads from one run: `count` of them from `first` on, walking `walk`.
struct Segment {
  RunId run;
  std::uint32_t first = 0;  // a loop (index into KnitGraph::loops)
  std::uint32_t count = 0;
  Walk walk = Walk::forward;
};

// Where a loop a course makes goes.
enum class LoopPlace : std::uint8_t {
  in_run,      // the course's run, in place of the loops it took
  other_side,  // the run cast on across a split, on its other side
  along_edge,  // made across a wale edge: waits there to be picked up
};

struct PlacedLoop {
  std::uint32_t loop;
  LoopPlace place;
};

// One stitch of a course with the loops it takes and makes, each by slot (as the knit graph
// has them): `taken` and `made` count entries of Program::taken and Program::made.
struct WorkedStitch {
  StitchId stitch;
  std::uint8_t taken = 0, made = 0;
};

struct Range {
  std::uint32_t begin = 0, end = 0;
  std::uint32_t size() const { return end - begin; }
};

struct Step {
  StepKind kind = StepKind::course;
  std::uint32_t yarn = 0;
  // Courses (cast_on, course, bind_off, three_needle_bind_off):
  RowShape shape = RowShape::open;
  CourseDirection direction = CourseDirection::left_to_right;  // the input's; resolved
  Range stitches;  // into Program::stitches, in working (yarn) order
  Range reads;     // into Program::segments: the first is the run worked in place; a
                   // three-needle bind-off's second is the other needle's; a split's the part
                   // cut off; a join's the runs joined, in order
  RunId run;       // the run worked, cut off (split) or made by joining (join)
  RunShape run_shape = RunShape::line;  // `run`'s shape after the step
  bool run_ends = false;                // `run` holds no loop after the step
  RunId other;  // a cast-on across a split: the other side's run; a split of a line in its
                // middle: the run its tail becomes; a round over a ring that binds off in
                // two places (both underarms): the line after the second block (`run` is
                // the line after the first); in more places (a bag's handle openings), split
                // steps right after it cut the lines after the third block on off this one
  std::uint32_t picked_up = 0;     // loops taken along an edge (not from a run)
  StitchId waits_for = kNoStitch;  // hold: the stitch it waits for
};

// Where the lowering stopped: a course that does not meet its loops as one walk of a run
// (a crossing the vocabulary has no stitch for, or a layout no target can make room for).
struct LoweringGap {
  StitchId stitch = kNoStitch;
  std::string why;
};

struct Program {
  std::vector<Run> runs;
  std::vector<Step> steps;
  std::vector<WorkedStitch> stitches;
  std::vector<std::uint32_t> taken;  // per worked stitch, its loops by slot
  std::vector<PlacedLoop> made;      // per worked stitch, its loops by slot
  std::vector<Segment> segments;
  std::vector<std::uint32_t> worked_at;  // per stitch of the model: its index in `stitches`
  std::vector<std::uint32_t> taken_at;   // per worked stitch and one more: its first `taken`
  std::vector<std::uint32_t> made_at;    // per worked stitch and one more: its first `made`
  std::optional<LoweringGap> gap;        // set when the lowering stopped early

  bool complete() const { return !gap.has_value(); }
  const Step& operator[](StepId s) const { return steps[s.index()]; }
  const Run& operator[](RunId r) const { return runs[r.index()]; }
};

// Per loop: 1 when it is made across its maker's wale edge and waits there to be picked up (a
// loop across an expanding perpendicular edge, or one a stitch graph or test graph records as
// perpendicular without its edge). A loop across a contracting perpendicular edge is made at
// its maker's top, a live loop like any other, and taken across the taker's side.
std::vector<std::uint8_t> loops_along_edges(const KnitGraph& graph);

// Lowers a knittable model (its schedule in hand) to the live-loop program. Linear in stitches
// and loops. Never throws on a model: where a course cannot be lowered the program stops there
// and says why (Program::gap).
Program lower_to_program(const KnitGraph& graph, const YarnPieces& yarns, const Schedule& schedule);

// Replays the program on its own and checks it against the knit graph: every loop made once
// and taken once (or left live at the end, or bound off); every loop a step reads is live in
// the run it names, at the place it names; runs hold every live loop once at every step; every
// stitch is worked in exactly one course, taking and making the knit graph's loops by slot.
// Throws InternalError naming the step on the first broken rule.
void verify_program(const KnitGraph& graph, const Program& program);

// The program that knits the model's mirror image, left and right swapped: every course goes
// the other way, each stitch takes and makes its loops in the other slot order, runs lie the
// other way round; yarn order is kept. A hand knitter works rnds right to left: a model whose
// rnds mostly run left to right is knitted as its mirror image (decreases swap lean).
Program mirror_image(const KnitGraph& graph, const Program& program);

// The stitches of the rnds (closed courses) that go `direction`.
std::uint64_t stitches_in_rounds_going(const Program& program, CourseDirection direction);

// One step a line, for debugging and golden tests ("12 course R2 rnd left to right ...").
std::string program_text(const KnitGraph& graph, const Program& program);

}  // namespace skein
