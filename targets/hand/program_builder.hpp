// The builder behind build_hand_pattern (program_pattern.hpp), private to the hand
// target: it walks the lowering's live-loop program step by step, keeping what each piece has on
// its needle and where every other live loop waits. Its jobs live in three files:
// program_pattern.cpp (pieces and sections, cast-ons, three-needle bind-offs), program_gather.cpp
// (gathering a course's loops from holders, spare needles and chains; picking up along an edge)
// and program_courses.cpp (courses worked in rows and in the rnd).
#pragma once

#include <fmt/format.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "common/error.hpp"
#include "driver/pipeline.hpp"
#include "hand/loop_places.hpp"
#include "hand/pattern_model.hpp"
#include "knitgraph/worked_by_hand.hpp"

namespace skein::hand::from_program {

using T = StitchType;
constexpr std::uint32_t kNone = 0xffffffffu;

// What the knitter holds for one piece: its sts, split between the left needle (ahead of the
// tip) and the right one (behind) on a flat piece; in the rnd, the ring of its sts from the
// beginning-of-round marker on, the way the rnds go, and where the yarn is.
struct Needle {
  std::uint32_t section = 0;  // its latest section
  std::uint32_t live = 0, ahead = 0, behind = 0;
  bool in_round = false;
  bool double_stitch_next = false;  // German short rows: the next row begins with DS
  std::size_t turn_loops = 0;       // loops of the st the last course turned at (sr4, sr5)
  bool worked = false;              // a course has worked its sts
  bool opened = false;              // a rnd bound off in places: only a rnd takes it up again
  CourseDirection last = CourseDirection::left_to_right;
  CourseDirection rnds = CourseDirection::left_to_right;  // the way its rnds go
  std::vector<std::uint32_t> ring;  // its loops: from the marker (in the rnd), as cast on (flat)
  std::uint32_t gap = 0;            // the yarn is before ring[gap], going the way the rnds go
  // A row across the gap removed the beginning-of-round marker ("rm, sl1 back"): the next rnd
  // places a new one where it starts.
  bool marker_off = false;
  // The op that slipped the marker in the row in the rnd worked last (kNone: none): a rnd
  // begun where the yarn is turns it into "rm".
  std::uint32_t marker_slipped_at = 0xffffffffu;
  // The first op of the row in the rnd worked last that began at the marker (kNone: none): a
  // row that decreases across the marker later removes it there ("Rm, k1, k2tog, turn").
  std::uint32_t row_began_at_marker = 0xffffffffu;
};

class ProgramPatternBuilder {
 public:
  ProgramPatternBuilder(const Compilation& c, const Program& program, TurnMethod turns,
                        bool mirror);

  HandPattern run() &&;

 private:
  [[noreturn]] static void unsupported(const std::string& what) {
    throw UnsupportedError(fmt::format("hand target: {}", what));
  }

  // "step 12 (course of yarn 2 at face 40 (k, row 7)) works ...".
  [[noreturn]] void not_yet(const Step& s, const std::string& what) const;

  // A rnd that binds off none of its sts leaves them in a ring, also where the lowering keeps
  // them in a longer line with sts that wait for a later course (a spout's first rnds, worked
  // while the body's sts wait beside it); one that binds off in places leaves lines.
  // The first short row of a tube whose pieces the program joins into a ring right before it
  // (a tube bent by short rows where its branches join): its sts are placed in the rnd first.
  bool joins_a_tube(const Step& s) const {
    if (s.shape != RowShape::short_row || s.run_shape != RunShape::ring || step_ == 0) return false;
    const Step& before = p_.steps[step_ - 1];
    return before.kind == StepKind::join && before.run == s.run &&
           before.run_shape == RunShape::ring;
  }
  bool works_a_whole_rnd(const Step& s) const {
    if (s.shape != RowShape::closed) return false;
    return s.run_shape == RunShape::ring ||
           std::none_of(stitches_of(s).begin(), stitches_of(s).end(),
                        [&](const WorkedStitch& w) { return g_.type[w.stitch] == T::bo; });
  }
  std::span<const WorkedStitch> stitches_of(const Step& s) const {
    return {p_.stitches.data() + s.stitches.begin, s.stitches.size()};
  }
  std::span<const std::uint32_t> all_taken_by(std::uint32_t worked) const {
    return {p_.taken.data() + p_.taken_at[worked], p_.taken_at[worked + 1] - p_.taken_at[worked]};
  }
  // The loops a stitch takes off the needle it works: a three-needle bind-off st's second
  // loop comes from the needle held behind.
  std::span<const std::uint32_t> taken_by(std::uint32_t worked) const {
    auto all = all_taken_by(worked);
    return g_.type[p_.stitches[worked].stitch] == T::tnbo ? all.first(1) : all;
  }
  std::span<const PlacedLoop> made_by(std::uint32_t worked) const {
    return {p_.made.data() + p_.made_at[worked], p_.made_at[worked + 1] - p_.made_at[worked]};
  }

  // The loops a course takes, in the order it meets them.
  std::vector<std::uint32_t> loops_met(const Step& s) const;

  // --- pieces and sections ------------------------------------------------------------------

  PatternSection& section() { return out_.sections.back(); }
  const PatternSection& section() const { return out_.sections.back(); }
  bool working() const { return current_ != kNone; }
  Needle& needle() { return needles_[current_]; }

  // The section worked now ends: its sts stay on the needle (set aside), wait on a spare
  // needle for another piece (in the order the pattern counts them: as cast on, or round from
  // the marker), or are all bound off.
  void end_section(bool set_aside = false);

  // A new piece, or the yarn of one set aside taken up again (its rows count on).
  void start_section(std::uint32_t yarn, std::uint32_t needle_index);

  // The last row written of a piece (into HandPattern::rows), in whichever of its sections.
  std::uint32_t last_row_of_piece(std::uint32_t piece) const;

  // A row in the rnd that the yarn leaves (set aside, or casting on aside) ends there.
  void end_row_the_yarn_leaves();

  void set_aside(const Step& s);

  // Does the yarn's next course go back the other way from the row it stops in?
  bool turns_when_taken_up(std::uint32_t yarn) const;

  // The yarn's next course, bind-off or three-needle bind-off after this step, if any.
  const Step* next_course_of(std::uint32_t yarn) const;

  // Before a piece in the rnd is set aside, the sts of its needle that other yarns take go to
  // holders (a block of the rnd each), where those can take them.
  void hold_what_others_take(const Step& s);

  void take_up(const Step& s);

  // A cast-on starts a piece; a provisional one (along a split) keeps its chain's loops for
  // the other side.
  void cast_on(const Step& s);

  // A yarn that has worked casts on at the end of a row it worked: the sts wait on a holder of
  // their own for the course that takes them, the chain's loops (provisional) on the piece's
  // chain; the yarn goes on from the last st cast on.
  void cast_on_aside(const Step& s, bool provisional);

  // Does a section of the piece hold loops on a provisional cast-on's chain?
  bool has_chain(std::uint32_t piece) const;

  // A yarn binds off the sts of two pieces together, pair by pair: the first loop of each st
  // from the front needle, the second from the back. A new yarn joins two pieces left on spare
  // needles (or holders); a piece's own yarn binds off all its sts with another's held behind.
  void three_needle_bind_off(const Step& s);

  // The order a knitter counts the sts left on a spare needle in: a flat piece's as its last
  // row went; in the rnd from the marker, or after a row in the rnd round from its first st,
  // the way it went.
  std::vector<std::uint32_t> counted_on_spare_needle(const Needle& n) const;

  // The pairs of one spare needle folded in half (the sts of one holder put back on it first,
  // where the fold has them): its section in `section`; none where they are not.
  std::optional<PatternSection::Fold> fold_of(const std::vector<std::uint32_t> (&side)[2],
                                              std::uint32_t& section) const;

  // The piece just worked ends by binding off its sts with another's: its section says so.
  void bind_off_with_its_yarn(const PatternSection& join, std::uint32_t section);

  // --- gathering a rnd ------------------------------------------------------------------------

  // The needle the course works: the yarn's own, once the loops it meets are on it in order.
  Needle& needle_for(const Step& s, const std::vector<std::uint32_t>& met);

  // Slips the needle's loops the rnd leaves to holders, joins the yarn to (or carries it on
  // to) the loops it starts on, places the others: the needle then holds `met` from the
  // marker, the rnd's way round.
  void gather(const Step& s, std::vector<std::uint32_t> met);

  // A row in the rnd that takes sts from elsewhere (a gusset's sides, a crotch): all the sts of
  // each place it takes from go into the rnd beside the st it meets them next to, the ones it
  // meets first nearest; later rows take the rest from the needle. The beginning-of-round
  // marker, where the yarn is, goes where the row then begins at the yarn (or one st behind
  // it, slipped back).
  void place_into_ring_row(const Step& s, const std::vector<std::uint32_t>& met);

  // A spare needle whose sts the rows have all slipped is free for another holder's.
  void let_go_of_used_spare_needles();

  // Rows that each take sts of a holder one at a time, each together with another st (a
  // gusset's decreases, a bowl closing at both edges, a lid's middle joined to its sides
  // row by row): the holder goes on a spare needle (two at once at the most) and the row
  // slips its next st from there ("sl1 from spare", or behind the st it is worked with).
  // Is `holder` one of those for this row? (Or a piece's spare needle, whose sts the rows slip
  // from there as they are.)
  bool waits_for_rows(LoopAt holder, const Step& s) const;

  // Puts the holders whose sts wait for the rows (waits_for_rows) on spare needles, the st
  // the row takes first at the tip.
  void put_on_spare_needles(const Step& s);
  // The rows slip the sts of a piece left on its spare needle from there, `first` first.
  void slip_from_piece_left_on_spare_needle(const Step& s, LoopAt spare, std::uint32_t k,
                                            std::uint32_t first);

  // Before the stitch is worked, the sts it takes from spare needles go onto the left needle;
  // returns how many.
  std::uint32_t slip_from_spare_needles(std::uint32_t worked, Needle& n);

  // Calls `f` with each of a stitch's loops in the order the course going `d` meets them.
  template <class F>
  static void for_each_met(std::span<const std::uint32_t> taken, CourseDirection d, F&& f) {
    if (d == CourseDirection::right_to_left)
      std::for_each(taken.rbegin(), taken.rend(), f);
    else
      std::for_each(taken.begin(), taken.end(), f);
  }

  // The loops of the course on the needle (not those it slips from spare needles).
  std::vector<std::uint32_t> on_the_needle(std::vector<std::uint32_t> met) const {
    std::erase_if(met, [&](std::uint32_t l) { return spare_slot(l) != kNone; });
    return met;
  }

  // The spare needle (0 or 1) the loop waits on for rows, or kNone.
  std::uint32_t spare_slot(std::uint32_t loop) const {
    LoopAt at = places_.at(loop);
    for (std::uint32_t k : {0u, 1u})
      if (at.place != Place::none && spare_rows_[k] == at) return k;
    return kNone;
  }

  // All of `source`'s loops in the order the course would meet them, `run` (the ones it takes
  // now) first when it meets them after the st before, last when before the st after; none
  // where `run` lies at neither end of them.
  std::vector<std::uint32_t> whole_source(LoopAt source, std::span<const std::uint32_t> run,
                                          bool run_first) const;

  // A rnd begins where the yarn is, away from the marker: the last row that passed the marker
  // removes it ("rm"), a row still going this way ends there without turning, and the rnd
  // places it anew.
  void begin_rnd_at_yarn(const Step& s, Needle& n);

  // Does the work go all the way round from here (the courses from this step on going this
  // way, with this yarn) before it turns?
  bool goes_round(const Step& s, std::size_t ring) const;

  // A flat piece whose yarn goes on to work in the rnd on sts from elsewhere only (a set-in
  // sweater's back, whose yarn goes on to the sleeve; the teapot's strip going on as a tube):
  // the sts of its last row go to a holder ("Slip the 75 sts of Row 30 to holder 4"), and the
  // rnd is made of sts placed and picked up onto the empty needle, from a new marker. Or the
  // rnd takes all the needle's sts where they are (those a short row left, between the edges
  // of a strip going round a corner): it returns them, in the order met.
  // The course's loops are marked in in_met_.
  std::vector<std::uint32_t> join_flat_piece_in_the_rnd(const Step& s,
                                                        const std::vector<std::uint32_t>& met);

  // A flat piece's next row, all of whose own sts it works, takes others placed among them:
  // its own sts are those ahead once it turns, in the order it meets them.
  std::vector<std::uint32_t> row_ahead(const Step& s);

  // After a flat gather the needle holds the row's loops, all ahead of the tip once the work
  // is turned; `own`: the piece's own were there before.
  void lay_row_ahead(const Step& s, const std::vector<std::uint32_t>& met, bool own);

  // Parts of a piece that waits on a spare needle go different ways (a body's front and back
  // into a yoke, each between the sleeves; a leg's inside to the crotch; a glove's fingers,
  // each taking part of one cast-on): before the piece is left, its last rnd, last row or
  // cast-on is parted, a run of sts for each course that takes them, each to a holder of its own
  // but the one that goes round past the end of the needle, where `round_the_end_stays` (a
  // rnd places it from its middle; a three-needle bind-off holds each part behind in turn).
  // Returns where `loop` then waits.
  LoopAt hold_parts_of_spare_needle(std::uint32_t section, std::uint32_t loop,
                                    bool round_the_end_stays = true);

  // Where `block` lies in `source` (places_.lie); a piece's spare needle whose sts go
  // different ways is parted first, and `source` becomes where the block then waits.
  std::optional<Lie> lie_parting_spare_needle(LoopAt& source, std::span<const std::uint32_t> block);

  // The sts held behind for the three-needle bind-off from worked st `i` on, as long as they
  // wait in one place.
  std::vector<std::uint32_t> held_behind_from(std::uint32_t i) const;

  // Are loops `a` and `b` taken by two rows of one yarn, neither its first (a lid's sides,
  // joined to its middle one st a row: they wait together on a spare needle for "sl1 from
  // spare")?
  bool taken_by_rows_one_by_one(std::uint32_t a, std::uint32_t b) const;

  // Are loops `a` and `b` taken side by side by one course (or both by none)?
  bool taken_together(std::uint32_t a, std::uint32_t b) const;

  // How the sts a piece left on a spare needle are counted to slip a part of them to a holder:
  // of its last rnd, of its last row (in the order it worked them) or of its cast-on; none
  // where the pattern cannot name them so (after a row in the rnd on part of them).
  std::optional<PatternSection::Holding> counting_of_spare_needle(
      const PatternSection& sec, const std::vector<std::uint32_t>& spare) const;

  // The needle's loops the rnd does not take go to holders, a block of the rnd each; the rest
  // stay, from the marker on.
  std::vector<std::uint32_t> hold_what_it_leaves(const Step& s);

  // The sts of `order` (as the pattern counts them) that do not stay go to holders, a block
  // for each course that takes them side by side, counted in the rnd or (`of_row`) in the
  // last row; returns those that stay, in order.
  std::vector<std::uint32_t> hold_blocks(const std::vector<std::uint32_t>& order,
                                         const std::function<bool(std::uint32_t)>& stays,
                                         bool of_row);

  // The section's latest holder, if the course that takes its loops meets `block` right after
  // them, one after the other (a tube parting over two rnds: the leg's sts go to one holder);
  // else 0.
  std::uint32_t holder_met_before(std::span<const std::uint32_t> block,
                                  std::uint32_t section) const;

  // The yarn whose course takes the loop (kNone: none does).
  std::uint32_t taker_yarn(std::uint32_t loop) const {
    return taker_step_[loop] == kNone ? kNone : p_.steps[taker_step_[loop]].yarn;
  }

  // Which holder a loop left behind goes to, as a key: one for each yarn that takes them, and
  // one for each three-needle bind-off (its sts are held behind the needle on their own).
  std::uint64_t holder_for(std::uint32_t loop) const {
    StitchId taker = g_.loops[loop].taker;
    bool joined = taker != kNoStitch && g_.type[taker] == T::tnbo;
    return joined ? (std::uint64_t{1} << 32) | taker_step_[loop] : taker_yarn(loop);
  }

  // Do loops `a` and `b`, left side by side, go to one holder? Those one yarn takes, but a
  // yarn's first course starts on a holder of its own (it is joined to all of that holder's
  // sts): a set-in sweater's back, beside an underarm its sleeve takes later.
  bool held_together(std::uint32_t a, std::uint32_t b) const;

  // Is the course at `step` (a loop's taker step, or kNone) its yarn's first?
  bool starts_its_yarn(std::uint32_t step) const {
    return step != kNone && course_number_[step] == 0;
  }

  // Are the loops met by one course, one after the other (either way)?
  bool met_one_after_another(const std::vector<std::uint32_t>& loops) const;

  // Per loop: the course that takes it and its place in the order that course meets them.
  void index_loops_met();

  // A yarn that starts on loops another piece left (a holder, a spare needle, a chain) is
  // joined to them; the yarn of a piece all bound off is carried on to a holder's. Returns the
  // loops it starts on, in the order the rnd meets them.
  std::vector<std::uint32_t> join_to_first_source(const Step& s,
                                                  const std::vector<std::uint32_t>& met,
                                                  bool round);

  // Each run of the rnd from elsewhere is placed into it where the rnd meets it, after the
  // sts before it; what stays must then be the rest of the rnd, in order.
  void place_the_others(const Step& s, const std::vector<std::uint32_t>& met,
                        const std::vector<std::uint32_t>& host);

  void place(const Step& s, LoopAt source, std::span<const std::uint32_t> block,
             std::uint32_t after);

  // --- picking up along an edge ----------------------------------------------------------------
  // A loop made across an expanding perpendicular edge (paper §3.2) waits along the edge of
  // its maker's piece; a knitter picks it up, one in each row, from the edge st of that row.

  // The first and last st a row worked, and the side facing: which is its edge st.
  struct RowEnds {
    StitchId first = kNoStitch, last = kNoStitch;
    Side side = Side::rs;
  };

  void note_row_end(StitchId st, const PatternRow& r);
  // A cast-on st whose loop waits along the edge: the cast-on is the edge's row 0, its first
  // st on the side the cast-on began (as a row going its way).
  void note_cast_on_end(StitchId st, CourseDirection direction);
  const RowEnds* ends_of_row_of(StitchId st) const;  // its row's, or its cast-on's; or none
  // Which edge of its row `maker`'s `loop` waits along. A st that makes it with its wale's
  // loop says so by their order; one that makes only that loop, by the end of the row it sits
  // at (a row of one st: either). None: the st is not at that edge.
  enum class Edge : std::uint8_t { left, right, either };
  std::optional<Edge> edge_of(StitchId maker, std::uint32_t loop, const RowEnds& ends) const;

  // The pick-up that gives `loops` in their order: one in each row, rows numbered one after
  // the other, each from the st at the same edge of its row; none where they are not.
  std::optional<PatternSection::PickUp> pick_up_of(LoopAt source,
                                                   std::span<const std::uint32_t> loops) const;
  // The pick-up of the longest start of `loops` that is one; and how many loops that is.
  std::pair<PatternSection::PickUp, std::size_t> longest_pick_up(
      LoopAt source, std::span<const std::uint32_t> loops) const;

  // A piece that starts on loops picked up along another's edge: the knitter picks them up,
  // and its first course works them, the last picked up first.
  std::vector<std::uint32_t> start_from_pick_up(const Step& s,
                                                const std::vector<std::uint32_t>& host, bool round);

  // Loops picked up along an edge go into the rnd where it meets them, in the order picked up.
  void pick_up_into_rnd(const Step& s, LoopAt source, std::span<const std::uint32_t> block,
                        std::uint32_t after);

  // --- courses ------------------------------------------------------------------------------

  void course(const Step& s);

  PatternRow open_row(const Step& s, const Needle& n) const;

  // One stitch of the course: its ops; returns the loops it takes.
  std::uint32_t work(const Step& s, std::uint32_t i, Needle& n, PatternRow& r);

  // A three-needle bind-off in a row: its st in front, the other piece's held behind the
  // needle (from a spare needle or holder, all of it, an end at the tip), said before the row
  // that binds off its first st.
  std::uint32_t bind_off_with_held_st(std::uint32_t i, Needle& n);

  bool binds_off_together(std::uint32_t worked) const {
    return g_.type[p_.stitches[worked].stitch] == T::tnbo;
  }

  // A cast-on in the middle of a row: the st goes on the needle; a provisional one's chain
  // loop waits for the piece on the other side of the split, a backward loop has none.
  std::uint32_t cast_on_in_row(std::uint32_t i, Needle& n);

  void note_course(const Step& s, Needle& n);

  // --- in the rnd ---------------------------------------------------------------------------
  // A knitter's rnd runs from the beginning-of-round marker round to it, the way the rnds go;
  // a course that turns is a row in the rnd (a short row), which slips the marker where it
  // passes it. Courses going on the same way are one row until the work turns or the marker
  // ends a rnd.

  void ring_course(const Step& s, Needle& n);

  // A course going the other way from the last turns the work: the row in the rnd ends.
  void turn_in_ring(const Step& s, Needle& n);
  // A short row's decrease takes the sts on both sides of the beginning-of-round marker (a heel
  // turned across it): the marker came off where it was last at the tip of the needle, and the
  // next rnd places it anew.
  bool decreases_across_marker(std::uint32_t worked, const Needle& n) const;
  void take_marker_off(const Step& s, Needle& n);
  void insert_op(std::uint32_t at, HandOp op);  // into ops written, the rows after moved on

  // The work turns right after a rnd ended at the marker: that rnd ends with the turn.
  void turn_after_last_rnd();

  // German short rows slip the st the work turned at (DS); a wrapped st went back to the left
  // needle: either way the row after the turn begins past it.
  void step_over_turn(Needle& n, bool forward);

  // The course meets its loops side by side on the needle, from where the yarn is, or from
  // the st behind it, slipped back first (a decrease across the gap): returns which.
  bool check_met_at_the_yarn(const Step& s, const Needle& n, const std::vector<std::uint32_t>& met,
                             bool forward) const;

  void open_ring_row(const Step& s, Needle& n, bool forward);

  // "sl1 back": the row begins with the st behind the yarn; where the marker lies between,
  // it is removed first ("rm") and the next rnd places it anew.
  void slip_back_across_gap(Needle& n, bool across_marker);

  // Ends the hand row: at a turn, a row in the rnd (a short row); at the marker, a rnd.
  void close_ring_row(const Step& s, Needle& n, bool turn);

  // The loops the course took, a block of the ring, give way to those it made; the marker
  // stays before the loops of the st that took the one after it.
  void replace_in_ring(const Step& s, Needle& n, bool forward, std::uint32_t first,
                       std::uint32_t count);

  void index_ring(const Needle& n) {
    for (std::uint32_t i = 0; i < n.ring.size(); ++i) pos_[n.ring[i]] = i;
  }

  // A flat row turns the work: the sts behind the tip come ahead of it. German short rows
  // begin the row after a turn with the double stitch.
  void begin_row(const Step& s, Needle& n);

  // Loops ahead of and behind the needle tip as the stitch is worked; returns the loops it
  // takes. A wrapped st goes back to the left needle.
  std::uint32_t move_loops(StitchId st, Needle& n, const Step& s) const;

  // Sts of a flat piece that other yarns work (a flap of their own, a spout and a lid's
  // middle) go to holders before the row that leaves them: a block for each course that takes
  // them, counted in the order the last row worked them; only where some of its own stay.
  // Before the course gathers (needle_for): a needle it lays out holds only its own loops.
  void hold_what_others_work(const Step& s, Needle& n);
  // The place on the needle [begin, end) of the sts the last row (`last_row`, into the rows
  // written) worked (a short row's).
  std::pair<std::uint32_t, std::uint32_t> last_rows_sts(const Needle& n,
                                                        std::uint32_t last_row) const;

  // A flat row meets its loops side by side along the line from where the yarn is.
  void check_met_along_the_row(const Step& s, const Needle& n) const;

  // The row's loops give way to those it made, in the line's order; the yarn stays at the
  // end it went to.
  void replace_in_line(const Step& s, Needle& n);

  // A row that stops with sts left ahead turns there (a short row); German short rows make the
  // st it turned at a double stitch first in the next row.
  void end_row(const Step& s, Needle& n, PatternRow& r, std::uint32_t takes);

  // The schedule's mismatch and short-row markers go before the stitch's operations.
  void note_region_mark(StitchId st, const PatternRow& r);

  const KnitGraph& g_;
  const Program& p_;
  HandPattern out_;
  std::uint32_t pieces_ = 0;
  std::vector<Needle> needles_;    // per piece, in the order they start
  std::uint32_t current_ = kNone;  // the needle of the section being written
  LoopPlaces places_;
  std::vector<std::uint32_t> needle_of_yarn_;  // per yarn
  const std::vector<std::uint32_t>& yarn_of_;  // per stitch
  std::vector<std::uint8_t> in_met_ = std::vector<std::uint8_t>(g_.loops.size(), 0);
  std::unordered_map<StitchId, MarkerKind> marked_;
  std::size_t step_ = 0;
  std::vector<std::uint32_t> pos_ = std::vector<std::uint32_t>(g_.loops.size(), 0);  // in ring
  // Per stitch worked in a row: the row (into out_.rows) and its number; per row, its ends.
  std::vector<std::uint32_t> row_of_ = std::vector<std::uint32_t>(g_.size(), kNone);
  std::vector<std::uint32_t> number_of_ = std::vector<std::uint32_t>(g_.size(), 0);
  std::vector<RowEnds> row_ends_;
  std::unordered_map<StitchId, RowEnds> cast_on_ends_;  // cast-on sts with a loop on an edge
  std::vector<std::uint32_t> taker_step_ = std::vector<std::uint32_t>(g_.loops.size(), kNone);
  // Per course step: how many courses its yarn worked before it (0: its yarn's first).
  std::vector<std::uint32_t> course_number_ = std::vector<std::uint32_t>(p_.steps.size(), 0);
  std::vector<std::uint32_t> met_at_ = std::vector<std::uint32_t>(g_.loops.size(), 0);
  // The row in the rnd being written, until the work turns or the marker ends it.
  PatternRow pending_;
  bool row_open_ = false, row_forward_ = false, ds_next_ = false;
  bool row_at_marker_after_turn_ = false;
  bool row_from_marker_ = false;  // the row in the rnd began at the marker
  bool pm_next_ = false;          // the next row places the beginning-of-round marker first
  LoopAt spare_rows_[2];          // the holders (or a piece's spare needle) that rows slip sts from
  std::vector<std::uint32_t> spare_queue_[2];  // their sts, the one slipped next first
  CourseDirection row_dir_ = CourseDirection::left_to_right;
  std::uint32_t pending_takes_ = 0;
  std::uint32_t held_behind_left_ = 0;  // sts held behind the needle for 3-needle BO
};

}  // namespace skein::hand::from_program
