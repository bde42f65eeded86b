#include <fmt/format.h>

#include "lowering/program.hpp"

namespace skein {

const char* run_shape_name(RunShape shape) {
  return shape == RunShape::ring ? "ring" : "line";
}

const char* step_kind_name(StepKind kind) {
  switch (kind) {
    case StepKind::cast_on:
      return "cast on";
    case StepKind::course:
      return "course";
    case StepKind::bind_off:
      return "bind off";
    case StepKind::three_needle_bind_off:
      return "three-needle bind-off";
    case StepKind::split:
      return "split";
    case StepKind::join:
      return "join";
    case StepKind::reverse:
      return "reverse";
    case StepKind::hold:
      return "hold";
    case StepKind::resume:
      return "resume";
  }
  return "?";
}

std::vector<std::uint8_t> loops_along_edges(const KnitGraph& g) {
  std::vector<std::uint8_t> along(g.loops.size(), 0);
  for (std::uint32_t l = 0; l < g.loops.size(); ++l)
    along[l] = g.loops[l].kind == LoopKind::perpendicular;
  for (const MismatchEdge& e : g.mismatch_edges)
    if (g.groups[e.group].kind == MismatchKind::contracting && e.loop[0] != kNoGroup)
      along[e.loop[0]] = 0;
  return along;
}

namespace {

const char* course_name(RowShape shape) {
  switch (shape) {
    case RowShape::open:
      return "row";
    case RowShape::closed:
      return "rnd";
    case RowShape::short_row:
      return "short row";
  }
  return "?";
}

std::string run_name(RunId r) {
  return fmt::format("R{}", r.index() + 1);
}

// "3 loops from face 12 (k, row 2)": a segment named by the maker of its first loop.
std::string segment_text(const KnitGraph& g, const Segment& s) {
  return fmt::format("{} {} loop{} from {}{}", run_name(s.run), s.count, s.count == 1 ? "" : "s",
                     g.describe(g.loops[s.first].maker),
                     s.walk == Walk::backward ? " backward" : "");
}

std::string stitches_text(const KnitGraph& g, const Program& p, const Step& s) {
  return fmt::format("{} st{} from {}", s.stitches.size(), s.stitches.size() == 1 ? "" : "s",
                     g.describe(p.stitches[s.stitches.begin].stitch));
}

std::string course_text(const KnitGraph& g, const Program& p, const Step& s) {
  std::string out =
      fmt::format("{} {} yarn {} {} {}: {}", step_kind_name(s.kind), run_name(s.run), s.yarn + 1,
                  course_name(s.shape), course_direction_name(s.direction), stitches_text(g, p, s));
  for (std::uint32_t i = s.reads.begin; i < s.reads.end; ++i)
    out += fmt::format("; {} {}", i == s.reads.begin ? "takes" : "and on the second needle",
                       segment_text(g, p.segments[i]));
  if (s.picked_up) out += fmt::format("; picks up {}", s.picked_up);
  out += fmt::format("; {} {}", run_name(s.run), s.run_ends ? "ends" : run_shape_name(s.run_shape));
  if (s.other.valid()) out += fmt::format(", and {}", run_name(s.other));
  return out;
}

std::string step_text(const KnitGraph& g, const Program& p, const Step& s) {
  switch (s.kind) {
    case StepKind::hold:
      return fmt::format("hold yarn {}: waits for {}", s.yarn + 1, g.describe(s.waits_for));
    case StepKind::resume:
      return fmt::format("resume yarn {}", s.yarn + 1);
    case StepKind::reverse:
      return fmt::format("reverse {}: cast on across a split, it takes its takers' order",
                         run_name(s.run));
    case StepKind::split: {
      std::string out = fmt::format("split {} off {}", run_name(s.run),
                                    segment_text(g, p.segments[s.reads.begin]));
      if (s.other.valid()) out += fmt::format("; its tail {}", run_name(s.other));
      return out;
    }
    case StepKind::join: {
      std::string out = fmt::format("join into {}:", run_name(s.run));
      for (std::uint32_t i = s.reads.begin; i < s.reads.end; ++i)
        out += fmt::format(" {}", segment_text(g, p.segments[i]));
      return out;
    }
    default:
      return course_text(g, p, s);
  }
}

}  // namespace

std::string program_text(const KnitGraph& g, const Program& p) {
  std::string out = fmt::format("program: {} steps, {} runs, {} stitches\n", p.steps.size(),
                                p.runs.size(), p.stitches.size());
  for (std::size_t i = 0; i < p.steps.size(); ++i)
    out += fmt::format("{:4} {}\n", i + 1, step_text(g, p, p.steps[i]));
  if (p.gap) out += fmt::format("stopped at {}: {}\n", g.describe(p.gap->stitch), p.gap->why);
  return out;
}

}  // namespace skein
