// Small stitch meshes built in code for tests: unit squares on a grid, each with its stitch
// type and edge roles given as in the file format (bottom, right, top, left edge order).
#pragma once

#include <functional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "driver/pipeline.hpp"
#include "knitgraph/knit_graph.hpp"
#include "mesh/stitch_mesh.hpp"

namespace skein::testing {

struct Square {
  int x, y;  // lower-left corner
  StitchType type;
  std::string roles;  // four letters for the lower, right, upper and left edges: b t i o
};

struct YarnMark {
  int x0, y0, x1, y1;  // the edge between two grid points
  MismatchYarn::Kind kind;
  int own_square = -1;  // index into the squares, with Kind::own
};

StitchMesh grid_mesh(int width, int height, const std::vector<Square>& squares,
                     const std::vector<YarnMark>& yarn = {});

// The paper's Fig. 13: two groups of joining edges on one row, one knit with the upper
// side's yarn and one with the lower side's: a dependency cycle.
StitchMesh fig13_deadlock_mesh();

// One small mesh per mismatched direction (paper Fig. 5), three stitches wide where it can be.
// `yarn` applies to every mismatched edge (joins and splits); `own_upper` picks the side.
StitchMesh join_mesh(MismatchYarn::Kind yarn = MismatchYarn::Kind::by_default,
                     bool own_upper = false);
StitchMesh split_mesh(MismatchYarn::Kind yarn = MismatchYarn::Kind::by_default,
                      bool own_upper = false);
// A split in the middle of a row, worked with the upper piece's own yarn: a sheet 5 sts wide
// binds off its middle 3 sts (Row 1) and casts them on again provisionally in Row 2 (the
// opening of a pocket); a second piece hangs from the cast-on's chain, 2 rows knit downwards.
// With `rs_row`, a plain row comes first, so that the cast-on is worked in the other direction.
StitchMesh mid_row_split_mesh(bool rs_row = false);
// The same in the round: a tube 6 sts around binds off 3 sts in Rnd 1, casts them on again
// provisionally in Rnd 2 (an afterthought thumb's opening) and decreases across the seam in
// Rnd 3 (a k2tog: its rnds run left to right); a second piece hangs from the chain.
StitchMesh mid_round_split_mesh();
// A three-needle bind-off in the middle of a row, with the lower piece's own yarn: a sheet 5
// sts wide binds off 3 of its sts in Row 1 with the 3 of a second piece (wales down, knit first
// and left on a spare needle), and goes on with the other 2.
StitchMesh mid_row_join_mesh();
StitchMesh contracting_mesh();
StitchMesh expanding_mesh();

// Fig. 9: four stitches cast on, a pair of short rows over the two right-hand stitches that turns
// at a short-row face (sr4, or sr5 with a k2tog above its two top edges), a full row and a
// bind-off. Faces: 0-3 cast-on, 4-5 first short row, 6 the short-row face, 7-8 second short row,
// 9-12 the full row (right to left), 13-16 bind-off.
StitchMesh short_row_mesh(StitchType turn = StitchType::sr4);

// A sample's project (samples/SAMPLE/SAMPLE.yaml) changed by `edit`, written to the temporary
// directory (its mesh named by its full path; `tag` in the file's name) and compiled.
Compilation sample_variant(const std::string& sample, const std::string& tag,
                           const std::function<void(std::string&)>& edit);

// A sample's project at another gauge (`gauge: {stitches: S, rows: R}` replaced or added).
Compilation sample_at_gauge(const std::string& sample, int stitches, int rows);

// The sock at 10 sts and 44 rows to 10 cm: its heel's short rows turn twice at some sts.
Compilation sock_turning_twice_at_a_st();

// A sample's project ("sock", "short-row-wedge") with its short rows turning at sr5 faces
// (`short_rows: {method: sr5}`) and the lines `more` ("pattern: purl\n"), written to the
// temporary directory (its mesh named by its full path) and compiled.
Compilation sample_turning_at_sr5_faces(const std::string& sample, const std::string& more = "");

// A heel turn on a tube, as a knit graph: 6 sts cast on in the rnd and a rnd (a0..a5); a band
// over a0 and a1 worked back and forth that decreases across the gap into the sts beside it
// (a row ends with a k2tog into a2; the row back starts with a3 slipped back and ends with
// a k2tog into a5, round the end of the needle); a rnd over the band and a4; a bind-off.
KnitGraph heel_turn_graph();

// A heel turn with a new yarn on a flat piece's last row (the teapot's top): 6 sts cast on and
// a row (a0..a5) left live; a new yarn on a2 and a3 whose rows take the sts beside them one
// at a time across each edge (its first row a k2tog into a1 and one into a4, the row back one
// into a5 and one into a0); a bind-off.
KnitGraph heel_turn_on_new_yarn_graph();

// A new yarn on sts a piece set aside left on its needle (the teapot's yarn 4): 4 sts cast on
// and a row (a3 worked first), a short row and the row back over a0, a1, set aside; a new yarn
// on a2, a3 (2 rows, left live); the first piece bound off with it by a three-needle bind-off.
KnitGraph new_yarn_on_set_aside_needle_graph();

// A flat piece taken up again on a provisional cast-on's chain and another piece's held sts
// (the teapot's top): 6 sts cast on and a row (a5 worked first), 2 rows over a0, a1, set aside
// (a2, a3 and a4, a5 to two holders); a new yarn over a4, a5 (2 rows, then held) goes on in the
// rnd round the hole above a2, a3: 2 sts cast on provisionally, its edge and Piece 1's picked
// up, a2, a3 (8 sts), a rnd and a bind-off; Piece 1's next row works d, the chain and h, and it
// is bound off.
KnitGraph flat_piece_taken_up_on_a_chain_graph();

// A tube closed by a three-needle bind-off of its last rnd folded in half: 6 sts cast on in the
// rnd, a rnd, and with a new yarn 3 pairs (a2 with a3, a1 with a4, a0 with a5).
KnitGraph folded_tube_graph();

// A gusset on a tube, as a knit graph: 6 sts cast on in the rnd and a rnd (a0..a5); a flap
// over a0..a2 worked back and forth for 2 rows (b, then d back); a rnd over the flap that picks
// up a st along its left edge in each of its rows (d2, b2), knits a3..a5 and picks up along its
// right edge (b0, d0): 10 sts; a bind-off.
KnitGraph gusset_graph();

// The gusset's flap goes on as a leg of its own: the rnd over the flap picks up along its
// edges (d2, b2; b0, d0) and knits a3..a5 only (7 sts; a bind-off), leaving the flap's sts
// (d0..d2) to a new yarn that works them in a row and binds them off.
KnitGraph gusset_leg_graph();
// The gusset's tube with a strip beside its flap: a4, a5 go on as a strip of 2 rows with a new
// yarn (h, i), and the rnd after the flap picks up down the flap's left edge, knits a3 and
// picks up the strip's right edge, so the tube waits for the strip (set aside, taken up
// again); the flap's sts go on with a third yarn. `round_a_corner`: the flap has a third row
// (RS, from the beginning of the rnd), whose yarn goes round the corner into the rnd after it
// (its next st picks up the edge of the st just made), leaving a3..a5 before the marker.
KnitGraph flap_and_strip_graph(bool round_a_corner = false);

// The gusset leg's flap the other way round (as letter-r's), after two rnds (z, a) of 6 sts:
// its first row (b) goes back over
// the rnd's last 3 sts from a5, linked to it by a shift-path, and its last row (d) ends at the
// beginning of the rnd, where the rnd over the flap goes on down its edge (d2, b0), knits
// a0..a2 and picks up the other edge (b2, d0), linked to it by a turn. The flap's sts go on
// with a new yarn in a row, bound off.
KnitGraph reversed_gusset_leg_graph();

// A flat strip joined to work in the rnd: 3 sts cast on flat, 2 rows (b, then d back); a rnd
// of the same yarn that picks up along the strip's left edge (d2, b2) and right edge (b0, d0)
// only, then binds off; the strip's sts (d0..d2) go on with a new yarn in a row, bound off (or,
// `leg_in_the_rnd`, in a rnd: a new yarn joined to held sts to work in the rnd).
KnitGraph strip_joined_in_the_rnd_graph(bool leg_in_the_rnd = false);
// A flat strip worked on 3 of its 5 sts (short rows leave 2) whose yarn goes round a corner
// into a rnd: the rnd starts along the edge of the strip's last st (down its left edge), works
// the 2 sts left and goes up the right edge; the strip's sts go on with a new yarn.
KnitGraph corner_strip_graph();
// The strip joined in the rnd, its tube (2 rnds) left live: a new yarn starts on the strip's
// held sts (d0..d2), goes on around over the tube's 4 sts (placed into its first rnd) and
// binds off.
KnitGraph strip_and_tube_joined_graph();

// How often `what` occurs in `text`.
std::size_t occurrences(std::string_view text, std::string_view what);

// A knitted-on edging: a piece `width` sts wide knit for `rows` rows, each after the cast-on
// taking one st of a cast-on column beside its left edge (a contracting perpendicular edge,
// worked "Sl1 from spare, k2tog"), then bound off.
StitchMesh edging_mesh(int width, int rows);

// A sheet (even trials) or tube (odd trials, which keep at least 6 sts) of random width, height
// and shaping, drawn from `rng`: the randomized tests' stitch meshes.
StitchMesh random_sheet_or_tube(int trial, std::mt19937_64& rng);

}  // namespace skein::testing
