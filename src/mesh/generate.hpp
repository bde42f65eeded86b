// Parametric stitch meshes: flat sheets and tubes built row by row from a row plan. Used by
// the samples, the randomized tests and the benchmarks.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <map>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/stitch_mesh.hpp"

namespace skein {

// Per row, its stitches from left to right as seen on the right side (chart order). The
// first row must be cast-on stitches and the last bind-offs; each row consumes exactly the
// loops the row below makes.
using RowPlan = std::vector<std::vector<StitchType>>;

enum class Layout : std::uint8_t {
  sheet,  // open rows knit back and forth, odd rows right to left
  tube,   // closed rounds, one shift-path up the seam at the first stitch
};

// The two steps build_from_rows repeats, for builders of other row plans (the fabric a knitout
// file makes): the vertices of a ring between two rows, `loops` course edges wide at height
// `level` (a tube's ring closes: its last vertex is its first again); and a row of faces, its
// stitches left to right, on the ring below (from its first vertex on) under the ring above.
std::vector<Vertex> add_ring(StitchMeshBuilder& builder, std::uint32_t loops, std::uint32_t level,
                             Layout layout);
void add_row(StitchMeshBuilder& builder, const std::vector<StitchType>& row,
             const std::vector<Vertex>& below, const std::vector<Vertex>& above,
             bool left_to_right);

// Throws Error when a row does not consume what the row below makes.
StitchMesh build_from_rows(const RowPlan& plan, Layout layout);

// co row, `rows` rows of the repeat (e.g. {k, k, p, p} for k2p2 rib), bo row.
RowPlan ribbed_rows(std::uint32_t width, std::uint32_t rows, const std::vector<StitchType>& repeat);

// A hat: co, `body_rounds` of knit, then crown decrease rounds in `sections` wedges (a k2tog at
// the end of each wedge every other round) down to `sections` stitches, then bo.
RowPlan hat_rows(std::uint32_t circumference, std::uint32_t body_rounds, std::uint32_t sections);

struct RandomShaping {
  double purl = 0.2;       // share of plain stitches that are purls
  double increase = 0.05;  // chance per stitch of an increase
  double decrease = 0.05;  // chance per stitch of a decrease (s2kp one time in four)
  std::uint32_t min_width = 4;
  std::uint32_t max_width = 64;
};
RowPlan random_rows(std::uint32_t width, std::uint32_t rows, const RandomShaping& shaping,
                    std::uint64_t seed);

// Builds faces from corner coordinates, sharing a vertex wherever coordinates repeat (the
// generators below and hand-built test meshes).
class CornerBuilder {
 public:
  explicit CornerBuilder(const char* name) : builder_(name) {}
  // Roles are edge-role letters (b t i o), one per edge from the first corner on.
  void face(std::initializer_list<std::pair<float, float>> corners, std::string_view roles,
            StitchType type);
  // A unit square with its lower-left corner at (x, y); roles lower, right, upper, left.
  void square(float x, float y, std::string_view roles, StitchType type) {
    face({{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}, roles, type);
  }
  StitchMesh build() && { return std::move(builder_).build(); }

 private:
  Vertex vertex(float x, float y);
  StitchMeshBuilder builder_;
  std::map<std::pair<float, float>, Vertex> index_;
  std::vector<Vertex> vertices_;
  std::vector<EdgeRole> roles_;
};

// A flat sheet of knit and purl rows with pairs of short rows over its right-hand stitches,
// each pair turning at a short-row face (sr4 or sr5, Fig. 10) and followed by a full row.
// Stitches are random (seeded); about one row in three starts a pair.
StitchMesh short_row_sheet(std::uint32_t width, std::uint32_t rows, std::uint64_t seed);

// Two flat pieces meeting on a mismatched edge line: a join (both wales point at the line:
// three-needle bind-off) or a split (both point away: cast on along it), with `yarn` on every
// edge of the line (own yarn: the lower piece's when `own_lower`).
enum class Meeting : std::uint8_t { join, split };
StitchMesh meeting_sheets(Meeting meeting, std::uint32_t width, std::uint32_t lower_rows,
                          std::uint32_t upper_rows, MismatchYarn::Kind yarn, bool own_lower,
                          std::uint64_t seed);

}  // namespace skein
