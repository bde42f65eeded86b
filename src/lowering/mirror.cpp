// The program of a model's mirror image (left and right swapped, yarn order kept).
#include <algorithm>

#include "lowering/program.hpp"

namespace skein {

std::uint64_t stitches_in_rounds_going(const Program& program, CourseDirection direction) {
  std::uint64_t count = 0;
  for (const Step& s : program.steps)
    if (s.kind == StepKind::course && s.shape == RowShape::closed && s.direction == direction)
      count += s.stitches.size();
  return count;
}

Program mirror_image(const KnitGraph& graph, const Program& program) {
  Program m = program;
  for (Step& s : m.steps) s.direction = reversed(s.direction);
  for (Segment& seg : m.segments)
    seg.walk = seg.walk == Walk::forward ? Walk::backward : Walk::forward;
  for (std::size_t i = 0; i < m.stitches.size(); ++i) {
    const StitchTypeInfo& type = info(graph.type[m.stitches[i].stitch]);
    if (type.mirror_reverses_taken)
      std::reverse(m.taken.begin() + m.taken_at[i], m.taken.begin() + m.taken_at[i + 1]);
    if (type.mirror_reverses_made)
      std::reverse(m.made.begin() + m.made_at[i], m.made.begin() + m.made_at[i + 1]);
  }
  return m;
}

}  // namespace skein
