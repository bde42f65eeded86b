// Makes every mismatched edge knittable (paper §3.2), in the knit graph; the modelling mesh
// stays as it is.
//   join, extra yarn:  a row of extruded three-needle bind-off stitches (3nbo) on a new yarn
//                      piece, each joining the two loops that meet on one edge;
//   join, own yarn:    the own side's stitch pulls its loop through the other side's loop and
//                      binds off (it becomes a 3nbo: no extra row, no extra yarn);
//   split, extra yarn: a row of extruded cast-on stitches (sco) on a new yarn piece, each
//                      making the loop both sides' stitches are pulled through;
//   split, own yarn:   the own side's stitch becomes the cast-on (sco) that makes both loops;
//   contracting perpendicular: the stitch treating the edge as a wale edge becomes a decrease
//                      (a bind-off becomes k2tog-bo: knit 2 together, then bind off; a
//                      cast-on becomes a knit stitch: it knits the loop beside it);
//   expanding perpendicular:   nothing to change: the stitches treating the edge as a course
//                      edge are pulled through the other side's edge ("pick up and knit").
#pragma once

#include "knitgraph/knit_graph.hpp"

namespace skein {

// Throws Error naming the stitch when a stitch on a mismatch cannot take the role it needs.
void make_mismatches_knittable(KnitGraph& graph);

}  // namespace skein
