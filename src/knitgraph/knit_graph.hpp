// The compile IR: a knit graph. Stitches, the loops each consumes and makes, and the order
// of the yarn through them. A stitch mesh and an AutoKnit stitch graph both become one; every
// later stage (dependencies, scheduling, targets) reads only this.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "mesh/stitch_type.hpp"

namespace skein {

using StitchId = std::uint32_t;
inline constexpr StitchId kNoStitch = std::numeric_limits<StitchId>::max();

// How the yarn travels from a stitch to the next one along it.
enum class YarnLink : std::uint8_t {
  none,    // the yarn piece ends here
  course,  // next stitch of the same row
  shift,   // across a shift-path: last stitch of a round to the first of the next (helix)
  turn,    // end of an open row (or short row): turn the work, next row goes back
};

// Why a loop exists between two stitches.
enum class LoopKind : std::uint8_t {
  wale,           // made at the top of one stitch, consumed at the bottom of the next
  perpendicular,  // crosses a perpendicular mismatched edge (paper §3.2)
  joined,         // made on a joining mismatch: closed by a three-needle bind-off
  split,          // to be consumed from a cast-on along a splitting mismatch
};

struct Loop {
  StitchId maker = kNoStitch;  // kNoStitch: supplied by a split cast-on not yet extruded
  StitchId taker = kNoStitch;  // kNoStitch: joined, or the open end of a stitch graph
  LoopKind kind = LoopKind::wale;
  // Which of the maker's loops this is, and which of the taker's, each counted left to right
  // in that stitch's own frame (wale up, right side facing).
  std::uint8_t maker_slot = 0;
  std::uint8_t taker_slot = 0;
};

// Why one stitch waits for another (paper §4.1); says which arrow of a cycle is which.
enum class DependencyReason : std::uint8_t {
  yarn,                // the previous stitch along the yarn
  loop,                // the stitch that made a loop this one consumes
  perpendicular_loop,  // ... across a perpendicular mismatched edge
  joined_loop,         // ... joined to it by a three-needle bind-off
  split_loop,          // ... cast on along a split
};
const char* explain(DependencyReason reason);  // "it consumes its loop"

enum class MismatchKind : std::uint8_t { join, split, contracting, expanding };
const char* mismatch_kind_name(MismatchKind kind);

// Which yarn works a join or split (paper §3.2): an extra piece, or one side's own yarn.
enum class MismatchYarnUse : std::uint8_t { extra, own };

inline constexpr std::uint32_t kNoGroup = std::numeric_limits<std::uint32_t>::max();

// A group of mismatched edges of one kind that touch each other.
struct MismatchGroup {
  MismatchKind kind;
  MismatchYarnUse yarn = MismatchYarnUse::extra;
  StitchId own_side = kNoStitch;  // with `own`: a stitch on the side whose yarn is used
  std::uint32_t edges = 0;
  std::uint32_t rows[2] = {0, 0};  // the rows on either side of its first edge, lower first
};

// One mismatched edge: the loops that meet on it (a join's two joined loops, a split's two
// cast-on loops, or the one loop crossing a perpendicular edge) and its vertices, for messages.
struct MismatchEdge {
  std::uint32_t group;
  std::uint32_t loop[2] = {kNoGroup, kNoGroup};
  std::uint32_t vertex[2];  // 0-based mesh vertices
};

enum class RowShape : std::uint8_t { open, closed, short_row };
const char* row_shape_name(RowShape shape);

// Which way a stitch's yarn runs through it, in its own frame (right side facing, wale up), as
// the input says: a stitch mesh by its face's wale edges (StitchMesh::runs_left_to_right), a
// stitch graph by its dir field. The stitches the transforms extrude along a join or a split
// lie across the edge between two sides that face each other; their order is that of the loops
// they take or make (the lowering reads it there).
enum class CourseDirection : std::uint8_t { left_to_right, right_to_left, along_its_loops };
const char* course_direction_name(CourseDirection direction);  // "left to right", ...
inline CourseDirection reversed(CourseDirection d) {
  return d == CourseDirection::left_to_right   ? CourseDirection::right_to_left
         : d == CourseDirection::right_to_left ? CourseDirection::left_to_right
                                               : d;
}

// Flags for stitches that sit in a special region, so schedules can place markers.
enum StitchFlag : std::uint8_t {
  kBesideMismatch = 1,  // touches a mismatched edge
  kShortRowEnd = 2,     // a short-row face
  kShiftPathStart = 4,  // first stitch after a shift-path edge (beginning of round)
  kExtruded = 8,        // added by the transforms along a join or split (no face of its own)
  kRoundsACorner = 16,  // the yarn goes on round a corner, down its edge into a round (the
                        // model's turn there; see transforms/corner_links.hpp)
  kGoesOnRound = 32,    // with kRoundsACorner: a row in the rnd whose yarn goes on round into
                        // the rnd after it without turning (a band's or a face's last row)
};

struct KnitGraph {
  std::string source_name;  // the input file, for messages
  std::string element;      // what a stitch's source number counts: "face" or "line"

  // Per stitch.
  std::vector<StitchType> type;
  std::vector<std::uint32_t> row;          // 0-based row number in knitting order
  std::vector<std::uint32_t> source;       // 0-based face index or .st line index
  std::vector<StitchId> yarn_next;         // kNoStitch at the end of a yarn piece
  std::vector<YarnLink> yarn_link;         // how the yarn reaches yarn_next
  std::vector<std::uint8_t> flags;         // StitchFlag bits
  std::vector<CourseDirection> direction;  // from the input, never derived
  // The garment's named parts and per stitch its part (kNoPart of mesh/stitch_mesh.hpp: none,
  // e.g. extruded); both empty when the input names no parts (a stitch mesh file, a graph).
  std::vector<std::string> part_names;
  std::vector<std::uint32_t> part;

  // Per row.
  std::vector<RowShape> row_shape;

  // Loops, and per stitch the loops it consumes and makes, each by slot (CSR, size N+1).
  std::vector<Loop> loops;
  std::vector<std::uint32_t> taken_first, taken;  // loop indices by taker_slot
  std::vector<std::uint32_t> made_first, made;    // loop indices by maker_slot

  std::vector<MismatchGroup> groups;
  std::vector<MismatchEdge> mismatch_edges;
  // Stitches from `first_extruded` on were added by the transforms; extruded_at[s -
  // first_extruded] is the mismatched edge each sits on.
  StitchId first_extruded = kNoStitch;
  std::vector<std::uint32_t> extruded_at;  // index into mismatch_edges

  std::uint32_t size() const { return static_cast<std::uint32_t>(type.size()); }
  std::span<const std::uint32_t> loops_taken_by(StitchId s) const {
    return {taken.data() + taken_first[s], taken.data() + taken_first[s + 1]};
  }
  std::span<const std::uint32_t> loops_made_by(StitchId s) const {
    return {made.data() + made_first[s], made.data() + made_first[s + 1]};
  }
  // Fills the taken and made indices from loops (call after all loops are added).
  void index_loops();
  // Appends a stitch with no yarn link yet; returns its id.
  StitchId add_stitch(StitchType type, std::uint32_t row, std::uint32_t source, std::uint8_t flags,
                      CourseDirection direction = CourseDirection::left_to_right);
  // "face 12 (k, row 7)" or "line 40 (k)".
  std::string describe(StitchId s) const;
};

// Checks the knit graph the targets consume: yarn links consistent (each stitch has at most
// one predecessor); every loop made once and consumed once (only a stitch graph may leave an
// open end); every stitch consumes exactly the loops its type says and makes no more; the loop
// index current. Throws InternalError (a bug): inputs are validated before.
void check_consistency(const KnitGraph& graph);

}  // namespace skein
