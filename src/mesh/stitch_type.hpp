// The catalogue of stitch types, spelled as knitters spell them. Each entry says how many
// course edges a face of that type has at the bottom (loops it consumes) and at the top
// (loops it makes), how its two wale edges sit (opposite, or side by side on a short-row
// face), and the facts every target reads instead of keeping its own list: how its loops
// stack, its mirror image, whether it shows as a purl, and which targets work it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace skein {

enum class StitchType : std::uint8_t {
  k,         // knit
  p,         // purl
  co,        // cast-on: bottom course edge is the border, makes one loop
  bo,        // bind-off: consumes one loop, top course edge is the border
  kfb,       // knit front and back: 1 loop in, 2 out
  m1l,       // make 1 left: 1 in, 2 out (the new loop lifted from the bar)
  m1r,       // make 1 right
  yo,        // knit then yarn over: 1 in, 2 out
  k2tog,     // knit 2 together: 2 in, 1 out (right-leaning)
  ssk,       // slip, slip, knit: 2 in, 1 out (left-leaning)
  p2tog,     // purl 2 together
  s2kp,      // centred double decrease: 3 in, 1 out
  sr4,       // short-row face with four edges (Fig. 10a): wale edges side by side
  sr5,       // short-row face with five edges (Fig. 10b): an extra loop at the turn
  srn,       // short-row face with more than five edges (Fig. 10c): extra segments collapse
  tnbo,      // extruded three-needle bind-off face of a join: 2 in, bound off
  sco,       // extruded cast-on face of a split: makes 2 loops, one to each side
  sl,        // slip: the loop passes through unworked (AutoKnit's miss)
  tuck,      // tuck: a new loop held with the old one (AutoKnit's tuck)
  k2tog_bo,  // knit 2 together and bind off: a bind-off that also takes a loop across a
             // contracting perpendicular edge
};

// How the loops a stitch takes together lie on one another, as seen from the right side.
enum class LoopStack : std::uint8_t {
  single,         // it takes at most one loop
  left_on_top,    // the left loop in front: the decrease leans right (k2tog, p2tog, k2tog-bo)
  right_on_top,   // the right loop in front: the decrease leans left (ssk)
  centre_on_top,  // the centre loop in front, the right one behind it, the left one at the back
                  // (s2kp: the two slipped loops passed over the knitted one)
  by_side,        // each loop on the side of the piece it comes from (3nbo: two needles held
                  // together, the front one's loop in front)
};

// The targets that can make a stitch type (flags).
enum WorkedBy : std::uint8_t {
  by_none = 0,
  by_hand = 1,     // hand patterns write it
  by_machine = 2,  // the knitout target has a recipe for it
  by_both = by_hand | by_machine,
};

struct StitchTypeInfo {
  StitchType type;
  std::string_view abbreviation;  // standard abbreviation, also the name in files
  std::string_view name;          // spelled out for reports
  std::uint8_t bottom_edges;      // course edges at the bottom
  std::uint8_t top_edges;         // course edges at the top
  std::uint8_t loops_in;          // loops consumed (a cast-on's bottom edge carries none)
  std::uint8_t loops_out;         // loops made (a bind-off's top edge carries none)
  bool wales_adjacent;            // short-row faces: the two wale edges are side by side
  bool variable_course_edges;     // srn: top course edge count may be larger
  LoopStack stack;                // how the loops it takes lie on one another
  StitchType mirror;              // the stitch that looks like it in a mirror (k2tog: ssk)
  // Mirroring reverses the order of its taken / made loops, unless they are not left and
  // right: a three-needle bind-off takes a front and a back loop, a cast-on along a split makes
  // one loop to each side of the split.
  bool mirror_reverses_taken;
  bool mirror_reverses_made;
  bool purl;           // it shows as a purl from the right side (knit on the back bed)
  WorkedBy worked_by;  // the targets that can make it
};

const StitchTypeInfo& info(StitchType type);
std::span<const StitchTypeInfo> stitch_catalogue();
std::optional<StitchType> stitch_type_from_abbreviation(std::string_view abbreviation);
// Where the loop in `slot` (counted left to right, right side facing) of the `loops` a stitch of
// `type` takes lies in their stack: from -(loops - 1) / 2 at the back to (loops - 1) / 2 in
// front, in loop thicknesses; 0 for a single loop. A `by_side` stitch's loops lie in slot
// order, the right one in front, until their pieces say otherwise.
float stack_position(StitchType type, std::uint32_t slot, std::uint32_t loops);
// The slots of the loops a stitch of `type` takes, in the order they land on one needle, bottom
// first: the last lies on top and gives the lean (k2tog, p2tog: {1, 0}; ssk: {0, 1}; s2kp: the
// centre loop on top, the right one under it, {0, 2, 1}; a three-needle bind-off: the second
// needle's loop on the first's, {0, 1}); {0} for a stitch that takes one loop.
std::span<const std::uint8_t> stacking_order(StitchType type);

inline StitchType mirrored(StitchType type) {
  return info(type).mirror;
}
inline bool is_purl(StitchType type) {
  return info(type).purl;
}
inline bool worked_by(StitchType type, WorkedBy target) {
  return (info(type).worked_by & target) != 0;
}

inline std::string_view abbreviation(StitchType type) {
  return info(type).abbreviation;
}

}  // namespace skein
