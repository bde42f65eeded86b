// The proof of a knitout file against its input: the fabric the virtual v-bed knitted (which
// loop was pulled through which, in which order along each carrier's yarn) must be the input's
// knit graph, stitch for stitch. Comments (;!source) are not trusted: the match is structural.
//
// Each yarn piece of the input is matched along one carrier's yarn, in a yarn piece of its own.
// After any border (cast-on tucks, waste yarn, draw thread), every stitch of the piece must
// appear in yarn order as its loops: a cast-on as one loop pulled through border
// loops only; a knit, purl or decrease as one loop pulled through exactly the loops its
// stitch takes (a decrease with the right loop on top); an increase as two loops in the
// order the yarn makes them (both pulled through for kfb, the new one through nothing for yo,
// m1l, m1r); a bind-off as one loop pulled through its stitch's loop and the previous
// bind-off's loop (a three-needle bind-off likewise, through its two loops: each link of the
// chain takes the one before, whichever bind-off made it); an sr5 as its knit loop and a turn loop
// made going back. Each loop runs the way the input's course runs (seen from the right side: a
// tube's back half from behind). A short row's turn may be followed by a tuck (its wrap) that one
// st pulls through with its loops. Every loop of the input is pulled through exactly as often as it
// should be, and, on a sheet, every knit is made on the front bed and every purl on the back. The
// proof reads the knit graph and the replayed fabric only: none of the emitter's or the lowering's
// code.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "driver/pipeline.hpp"
#include "knitout/vbed_simulator.hpp"

namespace skein::knitout {

struct ProofResult {
  bool proven = false;
  std::string summary;  // what was proven, or the first difference
  // When proven: the lines that make the input's first and last loops (what lies outside is
  // border, waste yarn or tag).
  std::size_t first_line = 0, last_line = 0;
  // When proven: each piece's loops, a run of its carrier's yarn (Fabric::by_carrier).
  struct Run {
    std::size_t carrier = 0, start = 0, count = 0;
  };
  std::vector<Run> pieces;
  // When proven: the lines of the tucks it took for short-row wraps (a tuck through nothing
  // after a turn, pulled through by the st that takes a waiting loop). The model has no wraps:
  // the proof accepts a turn with or without one.
  std::vector<std::uint32_t> wrap_lines;
};

// `text` is the replayed file, quoted in the message when the proof fails.
ProofResult prove_fabric(const Replay& replay, std::string_view text, const Compilation& input);

}  // namespace skein::knitout
