#include "hand/hand_ops.hpp"

#include <array>
#include <vector>

#include "common/error.hpp"

namespace skein::hand {
namespace {

using O = HandOp;
using T = StitchType;

// clang-format off
constexpr std::array kOps{
  HandOpInfo{O::k,     "k",     "knit", 1, 1},
  HandOpInfo{O::p,     "p",     "purl", 1, 1},
  HandOpInfo{O::k2tog, "k2tog", "knit 2 sts together (decrease leaning right; on a WS row it "
                                "shows as a purl decrease on the RS)", 2, 1},
  HandOpInfo{O::ssk,   "ssk",   "slip 2 sts knitwise one at a time, then knit them together "
                                "through the back loops (decrease leaning left)", 2, 1},
  HandOpInfo{O::p2tog, "p2tog", "purl 2 sts together (on a WS row: a decrease leaning right as "
                                "seen from the RS)", 2, 1},
  HandOpInfo{O::ssp,   "ssp",   "slip 2 sts knitwise one at a time, return them to the left "
                                "needle and purl them together through the back loops (on a WS "
                                "row: a decrease leaning left as seen from the RS)", 2, 1},
  HandOpInfo{O::s2kp,  "s2kp",  "slip 2 sts together knitwise, k1, pass the 2 slipped sts over "
                                "(centred double decrease)", 3, 1},
  HandOpInfo{O::s2pp,  "s2pp",  "slip 2 sts knitwise one at a time, return them to the left "
                                "needle, slip them together through the back loops, p1, pass the "
                                "2 slipped sts over (on a WS row: centred double decrease as seen "
                                "from the RS)", 3, 1},
  HandOpInfo{O::kfb,   "kfb",   "knit into the front and then the back of the same st (1 st "
                                "increased)", 1, 2},
  HandOpInfo{O::pfb,   "pfb",   "purl into the front and then the back of the same st (1 st "
                                "increased)", 1, 2},
  HandOpInfo{O::m1l,   "M1L",   "make 1 left: lift the strand between the needles from front "
                                "to back with the left needle and knit it through the back loop "
                                "(1 st increased, leaning left)", 0, 1},
  HandOpInfo{O::m1r,   "M1R",   "make 1 right: lift the strand between the needles from back "
                                "to front with the left needle and knit it through the front "
                                "loop (1 st increased, leaning right)", 0, 1},
  HandOpInfo{O::m1pl,  "M1PL",  "make 1 purlwise left: lift the strand between the needles from "
                                "front to back and purl it through the back loop (1 st "
                                "increased, leaning left as seen from the RS)", 0, 1},
  HandOpInfo{O::m1pr,  "M1PR",  "make 1 purlwise right: lift the strand between the needles from "
                                "back to front and purl it through the front loop (1 st "
                                "increased, leaning right as seen from the RS)", 0, 1},
  HandOpInfo{O::yo,    "yo",    "yarn over: wrap the yarn once over the right needle (1 st "
                                "increased)", 0, 1},
  HandOpInfo{O::bo,    "BO",    "bind off", 1, 0},
  HandOpInfo{O::provisional_co, "CO", "cast on (in a row: onto the right needle, with the "
                                "cast-on the row names)", 0, 1},
  HandOpInfo{O::co, "CO", "cast on (in a row: onto the right needle, with the cast-on the row "
                                "names)", 0, 1},
  HandOpInfo{O::tnbo,  "3-needle BO", "three-needle bind-off: knit the next st together with "
                                "the st held behind it and bind it off", 1, 0},
  HandOpInfo{O::pm,    "pm",    "place marker", 0, 0},
  HandOpInfo{O::sm,    "sm",    "slip marker", 0, 0},
  HandOpInfo{O::rm,    "rm",    "remove marker", 0, 0},
  HandOpInfo{O::wt,    "w&t",   "wrap and turn (short row): bring the yarn between the needles, "
                                "slip the next st purlwise, take the yarn back between the "
                                "needles, slip the st back and turn the work", 1, 1},
  HandOpInfo{O::turn,  "turn",  "turn the work before the end of the row (short row)", 0, 0},
  HandOpInfo{O::no_turn, "do not turn", "end the row here without turning the work: the next "
                                "rnd goes on from the edge of the st just worked", 0, 0},
  HandOpInfo{O::ds,    "DS",    "double stitch (German short row): with the yarn in front, "
                                "slip the first st purlwise and pull the yarn up over the needle "
                                "to the back, so the st shows two legs", 0, 0},
  HandOpInfo{O::sl1yo, "sl1yo", "slip 1 yarn over: with the yarn in front, slip the next st "
                                "purlwise and take the yarn over the needle to the back (a tuck: "
                                "the st is not worked, the yo lies over it)", 1, 1},
  HandOpInfo{O::sl1,   "sl1",   "slip the next st purlwise (a st with its yo: both as one)", 1, 1},
  HandOpInfo{O::kw,    "kw",    "knit the wrapped st together with its wrap (or wraps): lift "
                                "them onto the left needle and knit them with the st", 1, 1},
  HandOpInfo{O::pw,    "pw",    "purl the wrapped st together with its wrap (or wraps): lift "
                                "them from the RS onto the left needle and purl them with the st", 1, 1},
  HandOpInfo{O::kds,   "k DS",  "knit the two legs of the double stitch together as one st",
                                1, 1},
  HandOpInfo{O::pds,   "p DS",  "purl the two legs of the double stitch together as one st",
                                1, 1},
  HandOpInfo{O::brk,   "brk",   "brioche knit: knit the st together with its yo", 1, 1},
  HandOpInfo{O::brp,   "brp",   "brioche purl: purl the st together with its yo", 1, 1},
  HandOpInfo{O::from_spare, "sl1 from spare", "slip the next st waiting on the spare needle "
                                "onto the left needle (it is worked next)", 0, 0},
  HandOpInfo{O::from_spare_behind, "sl1 from spare behind", "slip the next st waiting on the "
                                "spare needle onto the left needle behind its first st (the two "
                                "are worked together, that one first)", 0, 0},
  HandOpInfo{O::from_second_spare, "sl1 from 2nd spare", "slip the next st waiting on the "
                                "second spare needle onto the left needle (it is worked next)",
                                0, 0},
  HandOpInfo{O::from_second_spare_behind, "sl1 from 2nd spare behind", "slip the next st "
                                "waiting on the second spare needle onto the left needle behind "
                                "its first st (the two are worked together, that one first)",
                                0, 0},
  HandOpInfo{O::slip_back, "sl1 back", "slip the st at the tip of the right needle back to the "
                                "left needle (it is worked next, across the gap)", 0, 0},
};

// How each operation shows from the RS when worked with a side facing. A make-one shows as
// the stitch it forms with the knit it follows.
struct FaceRule {
  HandOp op;
  Side side;
  StitchType face;
};
constexpr std::array kFaces{
  FaceRule{O::k, Side::rs, T::k},         FaceRule{O::p, Side::ws, T::k},
  FaceRule{O::p, Side::rs, T::p},         FaceRule{O::k, Side::ws, T::p},
  FaceRule{O::k2tog, Side::rs, T::k2tog}, FaceRule{O::p2tog, Side::ws, T::k2tog},
  FaceRule{O::ssk, Side::rs, T::ssk},     FaceRule{O::ssp, Side::ws, T::ssk},
  FaceRule{O::p2tog, Side::rs, T::p2tog}, FaceRule{O::k2tog, Side::ws, T::p2tog},
  FaceRule{O::s2kp, Side::rs, T::s2kp},   FaceRule{O::s2pp, Side::ws, T::s2kp},
  FaceRule{O::kfb, Side::rs, T::kfb},     FaceRule{O::pfb, Side::ws, T::kfb},
  FaceRule{O::m1l, Side::rs, T::m1l},     FaceRule{O::m1pl, Side::ws, T::m1l},
  FaceRule{O::m1r, Side::rs, T::m1r},     FaceRule{O::m1pr, Side::ws, T::m1r},
  FaceRule{O::yo, Side::rs, T::yo},       FaceRule{O::yo, Side::ws, T::yo},
  FaceRule{O::bo, Side::rs, T::bo},       FaceRule{O::bo, Side::ws, T::bo},
  FaceRule{O::wt, Side::rs, T::sr4},      FaceRule{O::wt, Side::ws, T::sr4},
  FaceRule{O::sl1yo, Side::rs, T::tuck},  FaceRule{O::sl1yo, Side::ws, T::tuck},
  FaceRule{O::sl1, Side::rs, T::sl},      FaceRule{O::sl1, Side::ws, T::sl},
};
// clang-format on

constexpr bool table_is_indexed_by_op() {
  for (std::size_t i = 0; i < kOps.size(); ++i)
    if (static_cast<std::size_t>(kOps[i].op) != i) return false;
  return true;
}
static_assert(table_is_indexed_by_op());

char ascii_lower(char ch) {
  return ch >= 'A' && ch <= 'Z' ? static_cast<char>(ch - 'A' + 'a') : ch;
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (ascii_lower(a[i]) != ascii_lower(b[i])) return false;
  return true;
}

// rs_face and working_of answer from tables filled once from kFaces.

struct FaceTables {
  std::array<std::array<std::optional<StitchType>, 2>, kHandOpCount> face{};
  // By stitch type: the catalogue grows with the core, so it is sized from it.
  std::vector<std::array<std::optional<HandOp>, 2>> op =
      std::vector<std::array<std::optional<HandOp>, 2>>(stitch_catalogue().size());
  FaceTables() {
    for (const FaceRule& rule : kFaces) {
      auto side = static_cast<std::size_t>(rule.side);
      face[static_cast<std::size_t>(rule.op)][side] = rule.face;
      op[static_cast<std::size_t>(rule.face)][side] = rule.op;
    }
  }
};

const FaceTables& face_tables() {
  static const FaceTables tables;
  return tables;
}

}  // namespace

std::string_view side_name(Side side) {
  return side == Side::rs ? "RS" : "WS";
}

const HandOpInfo& info(HandOp op) {
  auto index = static_cast<std::size_t>(op);
  SKEIN_ASSERT(index < kOps.size(), "hand op out of range");
  return kOps[index];
}

std::optional<HandOp> hand_op_from(std::string_view word) {
  for (const HandOpInfo& entry : kOps)
    if (equal_ignoring_case(entry.abbreviation, word)) return entry.op;
  return std::nullopt;
}

bool is_make_one(HandOp op) {
  return op >= HandOp::m1l && op <= HandOp::yo;
}
bool is_plain(HandOp op) {
  return op == HandOp::k || op == HandOp::p;
}
bool is_cast_on_in_row(HandOp op) {
  return op == HandOp::provisional_co || op == HandOp::co;
}
bool ends_row(HandOp op) {
  return op == HandOp::wt || op == HandOp::turn || op == HandOp::no_turn;
}
bool resolves_turn(HandOp op) {
  return op >= HandOp::kw && op <= HandOp::pds;
}
bool works_with_yo(HandOp op) {
  return op == HandOp::brk || op == HandOp::brp;
}

std::optional<StitchType> rs_face(HandOp op, Side side) {
  // Resolving a short-row turn works the loop as a plain st (not in the table, so that
  // working_of keeps k and p for plain stitches).
  if (resolves_turn(op)) op = (op == HandOp::kw || op == HandOp::kds) ? HandOp::k : HandOp::p;
  if (works_with_yo(op)) op = op == HandOp::brk ? HandOp::k : HandOp::p;
  return face_tables().face[static_cast<std::size_t>(op)][static_cast<std::size_t>(side)];
}

std::optional<Working> working_of(StitchType type, Side side) {
  if (static_cast<std::size_t>(type) >= face_tables().op.size()) return std::nullopt;
  std::optional<HandOp> op =
      face_tables().op[static_cast<std::size_t>(type)][static_cast<std::size_t>(side)];
  if (!op) return std::nullopt;
  if (!is_make_one(*op)) return Working{*op, std::nullopt};
  return Working{side == Side::rs ? HandOp::k : HandOp::p, *op};
}

}  // namespace skein::hand
