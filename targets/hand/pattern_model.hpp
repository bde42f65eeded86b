// The pattern as a knitter works it: sections (one per yarn piece), each a cast-on followed by
// rows or rounds of hand operations in working order, each row worked with one side facing.
// Built from the knit graph and Algorithm 1's schedule; the writers only phrase it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hand/hand_ops.hpp"
#include "schedule/schedule.hpp"

namespace skein {
struct Compilation;
}

namespace skein::hand {

// How short rows turn (paper Fig. 10: the sr4 or sr5 stitch is where the yarn turns), the target's
// short-rows setting (`--set short-rows=german`, or the project's `short_rows: {hand: german}`):
// German short rows work the st, turn and make it a double stitch (DS), later worked as one ("k
// DS"); wrap and turn wraps the next st (w&t), later worked with its wrap ("kw").
enum class TurnMethod : std::uint8_t { german, wrap_and_turn };

// Hand knitting works a rnd right to left with the side facing the knitter. The pattern knits
// the model's mirror image when most of its rounds run left to right seen from the RS, and
// works the others with the WS facing (the tube inside out: `Rnd 30 (WS): Purl.`); or it
// works every round that runs left to right with the WS facing and mirrors nothing.
enum class Rounds : std::uint8_t { mirror_most, ws_facing };

struct PatternRow {
  std::uint32_t first_op = 0, end_op = 0;  // into HandPattern::ops
  std::uint32_t number = 0;                // 1-based in its section; the cast-on is not a row
  bool round = false;
  Side side = Side::rs;  // the side facing the knitter (rnds: the WS when worked inside out)
  std::uint32_t sts_before = 0, sts_after = 0;
  bool bind_off = false;     // the row binds off every stitch
  bool short_row = false;    // ends where the work turns, with sts left on the left needle
  bool partial = false;      // works only some of the sts (short rows and the rows back)
  bool wraps_again = false;  // ends with a w&t at a st a short row wrapped before
};

struct PatternSection {
  std::uint32_t yarn = 0;     // model yarn piece (0-based)
  std::uint32_t cast_on = 0;  // stitches cast on
  bool in_round = false;      // joined to work in the round after the cast-on
  // A flat piece joined to work in the rnd in the middle of its work (its sts slipped to a
  // holder, the rnd made of sts picked up and placed): the first rnd (into HandPattern::rows).
  std::optional<std::uint32_t> joined_in_rnd_at;
  std::uint32_t first_row = 0, end_row = 0;  // into HandPattern::rows
  std::uint64_t stitches = 0;                // model stitches worked with this yarn
  std::uint32_t piece = 0;         // 1-based, in the order pieces start (kept when taken up)
  std::uint32_t first_number = 1;  // of its first row: a piece taken up again counts on
  bool left_live = false;          // ends with its sts on a spare needle, to be joined or placed
  bool set_aside = false;          // ends with its sts and yarn set aside, to be taken up again
  bool resumed = false;            // takes up a piece set aside
  std::string part;                // the garment part most of its sts are in ("" for none)
  std::uint32_t live_at_end = 0;
  // A piece that starts on loops picked up along the right (or left) edge of another, one in
  // each of its rows from `from_row` to `to_row` (0: the cast-on).
  struct PickUp {
    std::uint32_t section = 0, from_row = 0, to_row = 0;
    bool right = true;
  };
  // Sts of another section's spare needle (or its provisional cast-on's chain) placed into
  // the rnd before the row `before_row` works them (when this one is taken up, or in the
  // middle of its work), `after` sts from the beginning of the rnd, that needle's last st
  // first if `from_last` (from st `start` of its last rnd, going round, if that is not 0).
  struct Placement {
    std::uint32_t section, count, after;
    bool from_last;
    bool chain = false;
    std::uint32_t before_row = 0;  // into HandPattern::rows
    std::uint32_t holder = 0;      // 1-based: the sts of that holder instead
    // The holder's sts go on a spare needle instead, for rows that work them one at a time.
    bool to_spare = false;
    bool second_spare = false;  // ... on a second spare needle, while the first holds sts
    std::optional<PickUp> edge =
        std::nullopt;         // loops picked up along the edge of section `section` instead
    std::uint32_t start = 0;  // 1-based: from that st of its last rnd on, going round
  };
  // Where the sts of one rnd go different ways (to the piece's next rnd, into another piece's
  // rnd, into a join), those the piece does not work itself are slipped to holders after it:
  // `count` sts from the `first` (1-based, from the beginning of the rnd) to holder `holder`.
  // `flat_row`: the sts of a flat piece's last row, in the order it worked them, before the piece
  // is joined to work in the rnd.
  struct Holding {
    std::uint32_t after_row, first, count, holder;
    std::uint32_t onto = 0;  // the sts already on the holder, which these go after
    bool flat_row = false;
    // `of_row`: a run of a flat piece's last row ("sts 1–30 of Row 57"), counted in the order
    // the row worked them, the piece's sts parted between the pieces that work them.
    bool of_row = false;
    // of_row: the row's number when it is not the last the piece worked (a set-aside piece's
    // needle), else 0.
    std::uint32_t of_number = 0;
    // `of_cast_on`: the sts of a piece that is only a cast-on, counted as cast on ("sts 1–11
    // of the cast-on"); `after_row` is then the row before its first.
    bool of_cast_on = false;
  };
  std::vector<Holding> holdings;
  // Its sts after its last row went to holders (a last row or rnd parted between pieces).
  bool last_row_held() const {
    return !holdings.empty() && end_row > 0 && holdings.back().after_row + 1 >= end_row;
  }
  // After binding off every st, the yarn goes on to the sts of a holder (a tube's second leg,
  // worked with the yarn of the first), joined to work in the rnd from row `before_row` on:
  // `count` sts, the first (or the last) slipped to it at the tip.
  struct CarryOn {
    std::uint32_t before_row, holder, count;
    bool from_last;
  };
  std::vector<CarryOn> carries;
  std::vector<Placement> placements;
  bool provisional = false;  // its cast-on is a provisional one (a cast-on along a split)
  // A piece that starts on the sts of another's provisional cast-on: the sts on its needle,
  // or the loops of its chain; the first or the last st cast on first.
  struct Start {
    std::uint32_t section;
    bool chain, from_last;
    std::uint32_t count;
    std::uint32_t holder = 0;  // the sts another piece slipped to this holder
    // A piece in the rnd that begins in the middle of a holder's run (a tube parting: the hand
    // begins after the thumb's cast-on): that st, 1-based in the order the sts were slipped to
    // the holder, at the tip; 0: the first or last.
    std::uint32_t at = 0;
  };
  // A provisional cast-on in the middle of one of its rows ("CO 3 sts with a provisional
  // cast-on"): how many sts, and the model stitches cast on first and last (its chain's ends).
  std::uint32_t row_chain = 0;
  std::uint32_t row_chain_ends[2] = {0, 0};
  // A yarn that has worked casts on sts another course takes later (the teapot's handle bridge,
  // cast on after the body's flat rows): "With the working yarn, cast on 4 sts with a
  // provisional cast-on onto holder 5." after row `after_row`, the sts on that holder in the
  // order cast on, the chain's loops (provisional) the piece's chain.
  struct CastOnAside {
    std::uint32_t after_row = 0, count = 0, holder = 0;
    bool provisional = false;
  };
  std::vector<CastOnAside> casts_on_aside;
  // Pieces left on spare needles held behind the needle for "3-needle BO" in one of its rows
  // (a three-needle bind-off with its own yarn in the middle of a row), in the order worked.
  struct Hold {
    std::uint32_t section = 0, count = 0;
    bool from_last = false;        // its last row's last st at the tip
    std::uint32_t first = 0;       // the model stitch that binds off its first st
    std::uint32_t holder = 0;      // the holder its sts were slipped to (0: its spare needle)
    std::uint32_t before_row = 0;  // into HandPattern::rows: the row that binds them off
  };
  std::vector<Hold> holds;
  std::optional<Start> starts_from;
  std::optional<PickUp> picks_up;
  // A join: three-needle bind-off of two sections left live (front, back), with a new yarn.
  bool joins = false;
  std::uint32_t front = 0, back = 0;   // section indices
  bool from_last[2] = {false, false};  // which end of each last row starts: first or last st
  bool own_yarn = false;               // worked with the front piece's yarn, taken up again
  std::uint32_t holders[2] = {0, 0};   // 1-based: the front (back) sts wait on that holder
  // 1-based: the st of a needle's last rnd (a holder's, as slipped) at the tip, the others
  // following round the needle, down if from_last (0: the first or the last st).
  std::uint32_t tips[2] = {0, 0};
  std::uint32_t pairs = 0;
  // A join of one needle's sts folded in half (the sts of section `front`, counted 1-based
  // round the needle from the first st of its last row): the front needle's from st `tip[0]`
  // on, the back one's from `tip[1]`, each going down (towards st 1) or up.
  struct Fold {
    std::uint32_t sts = 0;
    std::uint32_t tip[2] = {0, 0};
    bool down[2] = {false, false};
    // The sts of holder `holder` (`held` of them) go on the needle after its st `after` first,
    // the last st slipped first if `held_from_last`.
    std::uint32_t holder = 0, held = 0, after = 0;
    bool held_from_last = false;
  };
  std::optional<Fold> fold;
  // Model stitches: the first and last of the section's last row (or of its cast-on).
  std::uint32_t last_row_ends[2] = {0, 0};
};

struct HandPattern {
  std::string source;  // the input, as given
  // Most of the model's rounds run left to right seen from the RS, and hand knitting runs right
  // to left: the pattern knits the model's mirror image (decreases and increases swap lean).
  bool mirror = false;
  bool ws_rounds = false;  // some rnds are worked with the WS facing
  TurnMethod turns = TurnMethod::german;
  bool short_rows = false;    // some row turns before the end of the needle
  std::uint32_t markers = 0;  // the most stitch markers on the needle at once
  std::vector<PatternSection> sections;
  std::vector<std::string> piece_names;  // by piece number - 1: "Thumb", "Leg 2", "Piece 3"
  std::vector<PatternRow> rows;
  std::vector<HandOp> ops;
  // Where Algorithm 1's schedule puts a marker around a mismatch group or a short-row turn
  // (paper §5.1): before the `op`-th operation of row `row`, counting no pm / sm / rm.
  struct RegionMark {
    std::uint32_t row, op;
    MarkerKind kind;
  };
  std::vector<RegionMark> region_marks;

  std::span<const HandOp> ops_of(const PatternRow& row) const {
    return {ops.data() + row.first_op, ops.data() + row.end_op};
  }
};

}  // namespace skein::hand
