// The knitout target's course layout, inside: the class that follows the live-loop program
// step by step into layouts (course_layout.hpp says what it gives), and the checks on the
// knit graph and on each layout. Its work is split by job: course_layout.cpp takes the
// program's steps and lays out courses and their blocks; course_layout_joins.cpp puts pieces
// on one bed (joined by a course, bound off together, cast on beside each other);
// course_layout_split.cpp the casts-on along a split; course_layout_finish.cpp checks the
// stitches and each finished layout (borders, wraps, yarn ends).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "knitout/course_layout.hpp"
#include "lowering/live_runs.hpp"

namespace skein::knitout::layout {

// Throws UnsupportedError "not yet supported by the knitout target: <what>, at <stitch>".
[[noreturn]] void unsupported(const KnitGraph& g, const std::string& what, StitchId s);
// Every stitch has a machine recipe; every loop joins two stitches along a wale (or is a
// cast-on along a split's, or a three-needle bind-off's).
void check_stitches(const KnitGraph& g);
bool is_bind_off(const KnitGraph& g, StitchId s);
void check_borders(const KnitGraph& g, const YarnPieces& yarns, const CourseLayout& l);
void choose_wrap(const KnitGraph& g, StitchId turning, std::uint32_t beyond, Course& course,
                 std::vector<std::uint8_t>& wrapped);
std::uint32_t taker_of_round_start(const KnitGraph& g, const CourseLayout& l, const Course& c,
                                   std::uint32_t start);
void check_sr5_turn_loops(const KnitGraph& g, const CourseLayout& l);

// The pieces' courses as the live-loop program gives them: one per course step, with its
// direction and stitches in working order. The program's runs are followed on LiveRuns (the
// lowering's own list of live loops) only for what the program does not say outright: where a
// tube's last full round started (a round that starts elsewhere is laid out from there) and
// which loop waits beyond a short row's turn (its wrap).
class ProgramLayouts {
 public:
  explicit ProgramLayouts(const Compilation& c);

  std::vector<CourseLayout> run() && {
    for (const Step& step : p_.steps) take_step(step);
    for (std::uint32_t i = 0; i < layouts_.size(); ++i) finish(i);
    return std::move(layouts_);
  }

 private:
  // A short row's turn beside a waiting loop (`beyond`), which may take a wrap.
  struct Turn {
    std::uint32_t layout, course;
    StitchId turning;
    std::uint32_t beyond;
  };
  std::uint32_t index_of(const CourseLayout& l) const {
    return static_cast<std::uint32_t>(&l - layouts_.data());
  }

  struct Piece {
    std::uint32_t round_start = kNoWrap;  // the first loop of the last full round
    std::uint32_t on_bed = 0;             // live loops on the bed (every run of the layout)
    // The places in their join of the runs cast on so far (the leftmost and rightmost).
    std::uint32_t leftmost = kNoWrap, rightmost = 0;
    // The last cast-on along a split: the loop at the front's left end of the branch right of
    // the crotch, which the emitter lays out where the crotch's sts change beds (the first
    // side's loop just after that place when the first side is right, the other side's just
    // before it when the first side is left). When the branch knit first takes the round's
    // start with it (it is the left one), the other's rounds start there.
    std::array<std::uint32_t, 2> right_branch_start{kNoWrap, kNoWrap};
  };

  // ---- pieces on one bed (course_layout_joins.cpp) ----
  void place_bound_off_together(const Step& step);
  std::uint32_t root(std::uint32_t run);
  void unite(std::uint32_t run, std::uint32_t into) { joined_to_[root(run)] = root(into); }
  Beside side_of(const Step& step, const CourseLayout& l, Piece& piece, StitchId at);
  void join(const Step& step);
  void turn_outer_arc_away(const Segment& seg);
  void note_arc_ends(const Step& step);

  // ---- the program's steps, courses and their blocks (course_layout.cpp) ----
  void take_step(const Step& step);
  void check_binds_off_once(const Step& step) const;
  StitchId first_stitch(const Step& step) const;
  std::vector<std::uint32_t> left_in_run(Range stitches, bool left_to_right,
                                         LoopPlace place = LoopPlace::in_run) const;
  std::uint32_t layout_of(const Step& step, StitchId at);
  void add_course(const Step& step);
  // A course's blocks: sts knit on, bound off, or bound off with a second needle's loops.
  enum class BlockKind : std::uint8_t { knit, bound_off, bound_off_together };
  BlockKind block_kind(StitchId s) const;
  void take_second_needles(const Step& step, Piece& piece);
  void take_off(Segment seg, Piece& piece);
  void add_three_needle_bind_off(const Step& step);
  Course append(CourseLayout& l, Range stitches, bool left_to_right) const;
  Segment segment_of(Range stitches, bool left_to_right) const;
  void add_block(CourseLayout& l, Piece& piece, Range stitches, bool left_to_right, RowShape shape);
  bool continues_chain(const CourseLayout& l, Range stitches) const;
  // A run for the loops beyond a bind-off in the middle of a line (numbered after the
  // program's, which the target never meets again).
  RunId tail_run() { return RunId(static_cast<std::uint32_t>(p_.runs.size() + tails_++)); }
  std::uint32_t new_round_start(const Piece& piece, const Course& c) const;

  // ---- casts-on along a split (course_layout_split.cpp) ----
  void note_whether_alone(const Segment& seg);
  void add_along_split(const Step& step, CourseLayout& l, Piece& piece, bool left_to_right);
  static void note_right_branch_starts(Piece& piece, const std::vector<std::uint32_t>& first,
                                       const std::vector<std::uint32_t>& second);
  bool is_sco(std::uint32_t worked) const;
  bool casts_on_along_split(const Step& step) const;
  void add_round_along_split(const Step& step, CourseLayout& l, Piece& piece, bool left_to_right);
  void note_arc_ends_in_round(Course& c, Range sco, const std::vector<std::uint32_t>& ring) const;
  std::uint32_t where_it_waits(std::uint32_t loop, Range crotch) const;

  // ---- each layout finished (course_layout_finish.cpp) ----
  void finish(std::uint32_t index);
  void wrap_turns(std::uint32_t index);
  bool takes_loops_made_since(const CourseLayout& l, const Course& c, std::uint32_t since,
                              const std::vector<std::uint32_t>& course_of) const;
  void mark_yarn_ends(CourseLayout& l) const;

  const KnitGraph& g_;
  const Program& p_;
  const YarnPieces& yarns_;
  LiveRuns runs_;
  std::vector<std::uint32_t> layout_of_;  // per yarn piece: its layout (kNoWrap: none yet)
  std::vector<CourseLayout> layouts_;
  std::vector<Piece> pieces_;              // per layout
  std::vector<std::uint8_t> wrapped_;      // per loop: a short row's turn wraps it
  std::vector<Turn> turns_;                // in knitting order
  std::vector<std::uint32_t> joined_to_;   // per run of the program: a run it is joined into
  std::vector<std::uint32_t> join_place_;  // per run: its place in the first join taking it
  std::vector<std::uint32_t> split_from_;  // per run: the run it was split off (kNoWrap: none)
  std::unordered_map<std::uint32_t, std::uint32_t> layout_of_group_;  // root run -> layout + 1
  // Per tube cast on beside others, until the join that takes it: its layout and course.
  std::unordered_map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> beside_cast_on_;
  // Per first side of a cast-on along a split not yet joined: its layout and course.
  std::unordered_map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> crotch_course_;
  std::uint32_t tails_ = 0;
  // The last cast-on along a split, until the split after it: its layout, course, and the
  // loops it put in runs of their own.
  struct PendingCrotch {
    std::uint32_t layout, course, own_loops;
  };
  std::optional<PendingCrotch> crotch_alone_;
};

}  // namespace skein::knitout::layout
