// The needle simulator of needle_sim.hpp's replay, shared by the files that implement its
// steps (needle_sim_*.cpp): its state (the needles, spare needles, holders, the row being
// worked) and its operations.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hand/needle_sim.hpp"

namespace skein::hand::sim {

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr std::uint32_t kMarkerBit = 0x80000000u;  // needle entries: a loop, or a marker

inline bool is_marker_entry(std::uint32_t entry) {
  return entry & kMarkerBit;
}

inline std::string sts(std::uint32_t n) {
  return fmt::format("{} st{}", n, n == 1 ? "" : "s");
}

// An impossible step: where, and why.
struct StepFailure {
  std::string message;
};

class NeedleSimulator {
 public:
  NeedleSimulator(const Script& script, const std::string& file, std::uint64_t max_work)
      : script_(script), file_(file), max_work_(max_work) {
    work_even_.resize(2);
    for (HandOp op : {HandOp::k, HandOp::p}) {
      Program& p = work_even_[op == HandOp::k ? 0 : 1];
      p.nodes.push_back({Node::Kind::op, op, 1, {Until::Kind::end, 0}});
      p.top_end = 1;
    }
  }

  Replay run() &&;

 private:
  Fabric& fab() { return out_.fabric; }

  [[noreturn]] void fail(const std::string& why) const;

  void do_step(const Step& s);

  // --- pieces -------------------------------------------------------------------------------

  // A provisional cast-on makes each st with two loops (a cast-on along a split): one on the
  // needle, one in the waste-yarn chain, which waits on a spare needle for the other side.
  void cast_on(std::uint32_t n, bool provisional);

  // One st cast on onto the right needle; a provisional one also makes the loop of its
  // waste-yarn chain, which waits on a spare needle for the other side of the split.
  void cast_on_st(bool provisional);

  // "CO 3 sts with a provisional cast-on" in the middle of a row: as a provisional cast-on of
  // its own, the needle's loop first seen from the RS; the chain joins the piece's chain.
  // "... with a backward-loop cast-on": a loop of the working yarn, with the row's side facing.
  void cast_on_in_row(bool provisional);

  // A new piece worked from loops picked up along an edge of a finished piece, one in each
  // of its rows: the loop of the st at that edge, the last one picked up at the needle tip.
  void pick_up(const Step& given);

  // "... along the left edge of the flap": the piece on the needle, picked up into its rnd (a
  // gusset).
  Step along_the_flap(Step s) const;

  // Loops picked up along another piece's edge go into the rnd of the piece worked, the first
  // picked up worked first; counted as "Place" counts.
  void pick_up_into_rnd(const Step& s, const std::vector<std::uint32_t>& rows);

  // Per row number of a piece (0: its cast-on), the row worked (kNone: none with stitches).
  std::vector<std::uint32_t> rows_of_piece(std::uint32_t piece) const;

  // The loop picked up at the right (or left) edge of a row, seen from the RS: a row worked
  // with the RS facing starts at the right; a cast-on ends where the next row starts.
  std::uint32_t pick_up_loop(const std::vector<std::uint32_t>& rows, std::uint32_t n, bool right);

  // A new piece worked from a spare needle's sts with a new yarn.
  void join_spare(const Step& s);

  // "; the rnd begins at its st 6": the holder's sts (tip first) go round from its 6th
  // slipped, the way the st named at the tip says.
  void begin_at_holder_st(std::vector<std::uint32_t>& loops, const Step& s) const;

  // A new piece with its own yarn and needles.
  // A flat piece's first row works the cast-on from its last st (turn_before).
  void start_piece();

  // "Do not fasten off: carry the yarn to the sts of holder 1": every st bound off, the yarn
  // goes on to a holder's sts (joined in the rnd next); the rows count on.
  void carry_on(const Step& s);

  // Before a piece's first row, or after its yarn is carried to held sts; or a flat piece in
  // the middle of its work.
  void join(const Step& s);

  // A flat piece joined to work in the rnd in the middle of its work: its last row's sts were
  // slipped to a holder; the BOR marker goes where the yarn is (the tip of the right needle),
  // and the sts picked up and placed next go in after it.
  void join_flat_piece(const Step& s);

  void fasten_off();

  void check_live(std::uint32_t n, const char* what) const;

  // A count printed after a sentence that changes what is on the needle ("— 36 sts").
  void check_printed_count(const Step& s, const char* what);

  // The piece waits, sts and yarn, until it is taken up again.
  void set_aside(std::uint32_t n);

  void take_up(std::uint32_t number);

  // The sts of a spare needle join the rnd of the piece being worked, after the first `last`
  // sts from the beginning of the rnd (or, when a row across a gap removed its marker, from
  // where the next rnd starts).
  void place(const Step& s);

  static std::string placing(const Step& s);

  // The sts a "Place" sentence takes from a holder, a spare needle or a chain, from the one it
  // names first; as many as it says.
  std::vector<std::uint32_t> sts_to_place(const Step& s) const;

  void release_placed(const Step& s);

  // On a flat piece the next row works them after the first `last` sts of the needle it works
  // (counted from its tip), the first placed next (the teapot's top, taken up on a chain).
  void place_into_row(const Step& s);

  // A holder's sts go back on a piece's spare needle (before it is folded), after its st
  // `last` counted round from the first st of its last row.
  void place_on_spare_needle(const Step& s);

  // "..., st 16 of its last rnd first": the placed sts go round from that one.
  void start_at(std::vector<std::uint32_t>& placed, const Step& s) const;

  // The loops go into the rnd after its first `after` sts, from the beginning-of-round marker.
  void insert_into_rnd(const std::vector<std::uint32_t>& loops, std::uint32_t after,
                       const std::string& what);

  // The loops of the rnd, the beginning-of-round marker first, go on the right needle, so that
  // the next rnd starts at the marker; after a row that turned, on the left one, where the turn
  // still to come puts them on the right.
  void lay_out_from_bor(const std::vector<std::uint32_t>& ring);

  // "With the working yarn, cast on 4 sts with a provisional cast-on onto holder 5": the sts
  // go on that holder in the order cast on, the chain's loops on the piece's chain; the piece's
  // needle stays as it is, the yarn goes on from the last st cast on.
  void cast_on_aside(const Step& s);

  // A holder's sts go on the spare needle that "sl1 from spare" takes from.
  // (Where two wait at once, the second goes on a second spare needle.)
  void put_on_spare_needle(const Step& s);

  // Sts A–B of the rnd, counted from the beginning-of-round marker, go to a holder of their
  // own (the reader gives the runs of one sentence last first, so the counts stay true).
  void hold(const Step& s);

  // "Slip sts 1–8 of Row 57 to holder 7": a run of the sts the last row left on the needle,
  // counted in the order it worked them (the reader gives the runs last first, so the counts
  // stay true); the others stay. "Of the cast-on": of a piece only cast on, as cast on.
  void hold_run_of_row(const Step& s);

  // "(after the 1 st on it)": the holder must hold that many sts.
  void check_held_before(const Step& s) const;

  // "Slip the 35 sts of Row 33 to holder 3": the sts a flat piece's last row left on the needle,
  // in the order it worked them (before the piece is joined in the rnd); the others stay.
  void hold_all(const Step& s);

  // The loops the piece's row `number` (its last) made that are on the needles, in the order
  // it made them; taken off. (Another piece's rows may have come since: a piece taken up.)
  std::vector<std::uint32_t> sts_of_row_off_the_needle(std::uint32_t number);

  // Made by Row `number` of the piece being worked.
  bool made_by_row(std::uint32_t entry, std::uint32_t number);

  bool made_by_last_row(std::uint32_t entry);

  // A holder's sts from the needle tip: the first or the last st of the run slipped to it.
  std::vector<std::uint32_t> held(std::uint32_t holder, bool from_last, const char* what) const;

  // The loops around the needle from the beginning-of-round marker on (markers left out).
  // A turn still to come (after a row that turned) swaps the needles first.
  std::vector<std::uint32_t> ring_from_bor() const;

  // The piece's live sts wait on a spare needle, in the order its last row worked them (in
  // the rnd, after a row that turned, going on round the needle with those it left).
  void leave(std::uint32_t n);

  // After a row that turned in the rnd the right needle holds sts of earlier rows behind those
  // it worked: the ring starts at the row's first st.
  void start_at_last_row(std::vector<std::uint32_t>& ring);

  // Pairs the sts of two spare needles, each from the end the pattern puts at the tip, and
  // binds them off with a new yarn.
  // With its own yarn the front piece is the one being worked: its needle is the front one.
  void three_needle_bind_off(const Step& s);

  // A needle's sts from st `tip` (1-based) at the tip, the others following round the needle,
  // down (towards st 1) or up.
  std::vector<std::uint32_t> round_from(const std::vector<std::uint32_t>& sts, std::uint32_t tip,
                                        bool down, const std::string& whose) const;

  void bind_off_pairs(const std::vector<std::uint32_t>& f, const std::vector<std::uint32_t>& b);

  // One piece's spare needle folded in half, counted round from the first st of its last row:
  // each needle's run goes from its tip, down or up (round past either end), with a new yarn.
  void folded_bind_off(const Step& s);

  std::vector<std::uint32_t> folded_run(const Step& s, int side,
                                        const std::vector<std::uint32_t>& ring) const;

  // The sts from the needle tip: the first or the last st of the piece's last row.
  // A spare needle held behind the work for "3-needle BO" in the rows that follow, from the
  // end the sentence names.
  void hold_behind(const Step& s);

  std::vector<std::uint32_t> spare_needle(std::uint32_t piece, bool from_last, const char* what,
                                          bool chain = false) const;

  void finish();

  // --- rows ---------------------------------------------------------------------------------

  void check_kind(bool round_label, const char* what) const;

  void work_rows(const Step& s);

  void repeat_rows(const Step& s);

  void work_even(const Step& s);

  void check_count(const Step& s);

  // The side a written row says faces the knitter. A rnd without (WS) is worked with the RS
  // facing; a flat row without a side follows from the turns.
  static std::optional<Side> label_of(const Step& s);

  // A row turns the work first when the one before ended at a turn (every flat row does);
  // after a rnd, or a row that did not turn, the work goes on in the same direction. The first
  // row of a piece says which side faces (a rnd (WS): the tube is worked inside out).
  Side facing_of(std::optional<Side> label) const;

  void work_row(const Program& p, bool round, std::uint32_t repeat_of, std::optional<Side> label,
                std::size_t line);

  void begin_row(Side facing);

  // A row that goes on from the end of a rnd starts, like a rnd, by slipping the marker.
  void slip_bor_if_next();

  // "Pm and join to work in the rnd" before a row (a short row first): the marker goes where
  // the row begins, as before a first rnd.
  void place_bor_before_first_row();

  // A rnd runs from here to the beginning-of-round marker (all the way round when the marker
  // is next: it is slipped): the loops before the marker go on the left needle, the marker
  // and the rest behind.
  void gather_round();

  // In the rnd the needle has no end: a row that turns goes on past the last st on the left
  // needle to the first on the right one.
  void wrap_around();

  // ... and a row that turns goes "to m" round to a marker beyond the last st on the left
  // needle (the BOR marker a stitch graph's short rows pass): the right needle's sts follow
  // the left needle's there.
  void look_round_for_marker();

  // ... and a row that turns may work the last st of the left needle together with the first
  // of the right one's far end (a decrease across a gap, on the other side of the needle).
  void reach_around(std::uint32_t takes);

  void end_row();

  // For each place on the left needle, the loops from there to the next marker (the tip is at
  // the back), and whether a marker comes at all: "to m" in constant time.
  void index_left_needle();

  std::uint32_t loops_to_marker() const;
  // In the round the beginning-of-round marker ends the round: it counts as the last marker.
  bool end_is_marker() const { return row_round_ && pc_.bor != kNone; }
  bool marker_ahead() const;

  // --- instructions -------------------------------------------------------------------------

  void run_nodes(const Program& p, std::uint32_t begin, std::uint32_t end);

  // Every instruction and st worked counts against the work limit, so that repeats inside
  // repeats cannot run for minutes: each loop below works at least one of them per turn.
  void count_work();

  void run_node(const Program& p, const Node& n);

  // Loops one working of nodes[begin, end) takes, when that does not depend on the needle.
  static std::optional<std::uint32_t> fixed_takes(const Program& p, std::uint32_t begin,
                                                  std::uint32_t end);

  // Sts between the needle tip and where `until` stops.
  std::uint32_t remaining(const Until& u, std::string_view what) const;

  std::uint32_t whole_repeats(const Until& u, std::uint32_t takes, std::string_view what) const;

  void apply(HandOp op);

  // "3-needle BO": the next st and the first st held behind it knit together and bound off;
  // as in a three-needle bind-off of whole pieces, the front loop first seen from the RS.
  void three_needle_bind_off_st();

  // w&t: the st just slipped and wrapped goes back to the left needle, and the work turns. A
  // wrapped st wrapped again keeps its wraps: it has one more.
  void wrap_and_turn();

  // Puts a loop at the tip of the left needle, keeping its index.
  void push_left(std::uint32_t loop);

  // The next st of the one piece waiting on a spare needle (in the order its last row worked
  // them) joins the work at the tip of the left needle.
  void slip_from_spare(bool behind);

  // "sl1 from 2nd spare": from the second of two holders put on spare needles.
  void slip_from_second_spare(bool behind);

  // The spare needle's next st goes to the tip of the left needle, or behind the st there.
  void slip_onto_left_needle(std::vector<std::uint32_t>& spare, bool behind, const char* what);

  // sl1 back: the st at the tip of the right needle (in the rnd, the last st of the left
  // needle when the right one is empty: the needle has no end) goes back to the left needle.
  void slip_back();

  // A row that goes on from the end of a rnd slips the beginning-of-round marker first; "rm"
  // before any st removes it (a row that works across it, as "sl1 back" does).
  bool bor_just_slipped() const;

  // In the rnd with no beginning-of-round marker (it was removed), the first marker placed in
  // a rnd marks the new beginning.
  void place_marker();

  // DS: first after a turn, the st worked last before it is pulled up into a double stitch
  // and slipped.
  void double_stitch();

  // sl1yo lays a yo over the st it slips; sl1 slips a st with its yo as it is.
  void mark_st_with_yo(HandOp op);

  // A loop a short row turned at must be worked with what resolves it, and only such a loop.
  void check_turn_loop(HandOp op, std::uint32_t loop) const;

  std::string wrapped(std::uint32_t loop) const;

  [[noreturn]] void with_yo_or_not(HandOp op, std::uint32_t loop) const;

  void remove_bor();

  void stitch(HandOp op);

  // A make-one goes with the stitch just worked, or (first in a row) with the next one.
  void make_one(HandOp op);

  void adopt(std::uint32_t x, HandOp op, std::uint32_t loop);

  [[noreturn]] void wrong_side(HandOp op) const;

  std::uint32_t new_stitch(StitchType type);

  std::uint32_t new_loop(std::uint32_t maker);

  std::uint32_t new_marker() { return kMarkerBit | markers_++; }

  struct Pending {
    HandOp op;
    std::uint32_t loop;
  };

  const Script& script_;
  const std::string& file_;
  Replay out_;
  std::vector<Program> work_even_;  // "k to end", "p to end"

  // Per piece number (1-based): the sts it left on a spare needle.
  // (and with a provisional cast-on, the loops of its chain).
  static constexpr std::uint32_t kNeedle = 0, kChain = 1;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> spare_needles_;
  std::vector<std::uint32_t> held_behind_;  // for "3-needle BO", the next at the front
  std::map<std::uint32_t, std::vector<std::uint32_t>> holders_;  // by holder number
  // Holders' sts that sl1 from spare (and sl1 from 2nd spare) take.
  std::array<std::vector<std::uint32_t>, 2> spare_for_rows_;

  // Per loop: whether a short row turned at it, and how.
  static constexpr std::uint8_t kPlainLoop = 0, kWrapped = 1, kDouble = 2, kWithYo = 3;
  std::vector<std::uint8_t> turn_mark_;
  std::vector<std::uint8_t> wraps_;  // per wrapped loop: how many times (w&t over a wrapped st)

  // The piece being worked: what a knitter sets aside with its yarn and takes up again.
  struct Piece {
    std::uint32_t number = 0;  // 1-based, in the order the pieces start
    bool joined = false, place_bor = false;
    bool turn_before = true;     // the next row starts by turning the work
    bool joined_to_sts = false;  // started by joining a yarn to another piece's sts
    bool carried = false;        // the yarn was carried to held sts, not yet joined in the rnd
    bool cast_on_aside = false;  // sts were cast on onto a holder: the yarn goes on from there
    std::uint32_t bor = kNone;
    std::uint32_t next_number = 1;
    std::optional<Side> last_side;
    std::vector<std::uint32_t> defined;  // per row number: the program that worked it
    std::uint32_t live = 0;
    std::uint32_t last_stitch = kNone;       // along its yarn
    std::vector<std::uint32_t> left, right;  // the needles; tips at the back
  };
  bool active_ = false;
  Piece pc_;
  std::map<std::uint32_t, Piece> set_aside_;  // by piece number
  YarnLink next_link_ = YarnLink::course;

  // The left needle's index.
  std::vector<std::uint32_t> to_marker_;
  std::vector<std::uint8_t> marker_ahead_;
  std::uint32_t left_loops_ = 0;
  std::uint64_t work_ = 0;  // instructions and sts worked, up to max_work_
  std::uint64_t max_work_;
  std::uint32_t markers_ = 0;

  // The row being worked.
  bool in_row_ = false, row_round_ = false;
  bool row_ended_ = false;   // by w&t or turn (or "do not turn")
  bool not_turned_ = false;  // ... by "do not turn": the next row goes on the same way
  std::uint32_t row_ = 0;
  Side facing_ = Side::rs;
  std::uint32_t position_ = 0;
  std::uint32_t row_last_stitch_ = kNone;
  std::vector<Pending> pending_;
  std::optional<HandOp> last_make_;
};

}  // namespace skein::hand::sim
