// What a hand knitter does, spelled with the standard abbreviations, and how each operation
// shows on the right side (RS) of the fabric: a knit worked with the wrong side (WS) facing is
// a purl seen from the RS. The pattern writer and the hand simulator share this one table, so
// what one writes the other reads the same way.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "mesh/stitch_type.hpp"

namespace skein::hand {

enum class Side : std::uint8_t { rs, ws };
inline Side other(Side side) {
  return side == Side::rs ? Side::ws : Side::rs;
}
std::string_view side_name(Side side);  // "RS", "WS"

enum class HandOp : std::uint8_t {
  // Work loops off the left needle.
  k,
  p,
  k2tog,
  ssk,
  p2tog,
  ssp,
  s2kp,
  s2pp,
  kfb,
  pfb,
  // Make a loop from the strand or the yarn: take nothing, belong to the stitch worked just
  // before (or, first in a row, just after): "k1, M1L" is one stitch of the model.
  m1l,
  m1r,
  m1pl,
  m1pr,
  yo,
  bo,  // bind off one stitch
  // Cast on one st onto the right needle in the middle of a row with a provisional cast-on (a
  // cast-on along a split): its waste-yarn chain's loop waits for the other side.
  provisional_co,
  // Cast on one st onto the right needle in the middle of a row with the working yarn (a
  // backward loop): a gap's sts, cast on over it (a thumb's, a crotch's).
  co,
  // Three-needle bind-off in a row: the next st together with the next st held behind it
  // (another piece's, waiting on a spare needle), bound off.
  tnbo,
  pm,
  sm,
  rm,  // place, slip, remove a marker
  // Short rows (paper Fig. 10a: the sr4 face is the stitch the yarn turns at). Wrap and turn:
  // "w&t" wraps the next st and turns, and a later row works the wrap with it ("kw", "pw").
  // German short rows: the last st worked before "turn" becomes a double stitch ("DS") first
  // in the next row, and a later row works its two legs as one ("k DS", "p DS").
  wt,
  turn,
  // "do not turn": the row ends where the yarn goes round a corner into the next rnd, along the
  // edge of the st just worked (the teapot's tube after its strip): the work is not turned.
  no_turn,
  ds,
  // AutoKnit turns its short rows on a tuck: "sl1yo" slips the next st with a yo laid over it
  // (a tuck), the row back slips it first ("sl1", the st with its yo as one), and a later row
  // works the st and its yo together ("brk", "brp").
  sl1yo,
  sl1,
  kw,
  pw,
  kds,
  pds,
  brk,
  brp,
  // A piece beside this one (a contracting perpendicular edge) gives its sts one at a time:
  // the next st waiting on the spare needle goes onto the left needle, to be worked next.
  from_spare,
  from_spare_behind,  // ... behind the first st of the left needle (worked second)
  // The same from a second spare needle, where two wait at once (at the two edges of rows).
  from_second_spare,
  from_second_spare_behind,
  // A row that decreases across a gap into a st of its own needle worked before it (a heel
  // turn's st on the other side of the gap): that st goes back from the right needle's tip to
  // the left needle's, to be worked next.
  slip_back,
};
inline constexpr std::size_t kHandOpCount = static_cast<std::size_t>(HandOp::slip_back) + 1;

struct HandOpInfo {
  HandOp op;
  std::string_view abbreviation;  // as written in a row: "k2tog", "M1L"
  std::string_view meaning;       // for the list of abbreviations
  std::uint8_t takes;             // loops taken off the left needle
  std::uint8_t makes;             // loops put on the right needle
};

const HandOpInfo& info(HandOp op);
std::optional<HandOp> hand_op_from(std::string_view word);  // case-insensitive

bool is_make_one(HandOp op);        // M1L, M1R, M1PL, M1PR, yo
bool is_plain(HandOp op);           // k, p: written with a count ("k12")
bool is_cast_on_in_row(HandOp op);  // CO N sts with a provisional or backward-loop cast-on
bool ends_row(HandOp op);           // w&t, turn, do not turn: the rest of the needle waits
// kw, pw, k DS, p DS: a plain st worked over the loop a short row turned at.
bool resolves_turn(HandOp op);
bool works_with_yo(HandOp op);  // brk, brp: a plain st worked over a st and its yo

// The model stitch (as seen from the RS) that `op` makes when worked with `side` facing;
// nullopt when no stitch of the catalogue looks like that (ssk worked on the WS). For a
// make-one, the stitch it forms with the knit stitch it belongs to.
std::optional<StitchType> rs_face(HandOp op, Side side);

// How a knitter works a model stitch of type `type` with `side` facing: one operation, or a
// stitch that shows as a knit on the RS followed by a make-one. nullopt for types hand
// patterns do not cover yet.
struct Working {
  HandOp op;
  std::optional<HandOp> make;
};
std::optional<Working> working_of(StitchType type, Side side);

}  // namespace skein::hand
