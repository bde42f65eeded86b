// The knitout emitter: one sheet (full gauge, front bed; purls knit on the back bed) or one
// tube (half gauge: front loops on even needles, back loops on odd ones, so every loop has an
// empty needle facing it for transfers) at a time, course by course along the yarn:
//   cast-on border (tucks), the cast-on course, then per course a transfer plan (loops home,
//   decrease stacks in lean order, re-spacing within the racking limit, purls to the other
//   bed) and the course itself; the last course is a chain bind-off ending in a tag. A short
//   row is knit where its loops wait and, where it turns beside a waiting loop, tucks over
//   that loop's needle. Yarn pieces are knit one after another, each with its own carrier.
#pragma once

#include <iosfwd>

#include "driver/pipeline.hpp"
#include "knitout/machine_profile.hpp"

namespace skein::knitout {

// Throws Error in the user's words when the model does not fit the profile or uses what the
// target cannot knit yet.
void emit_knitout(const Compilation& compilation, const MachineProfile& profile, std::ostream& out);

}  // namespace skein::knitout
