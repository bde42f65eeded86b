#include "yarn/curves.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "yarn/parallel.hpp"

namespace skein {
namespace {

// The lobe's shape in its share of the cell (x across the lobe, y up the cell): an omega,
// narrow at the neck where it passes through the old loop and wide at the head.
constexpr float kLean = 0.2f;       // how far the legs lean in at the neck (of the lobe width)
constexpr float kDip = -0.15f;      // the lobe's foot reaches into the row below
constexpr float kHeadTop = 1.2f;    // and its head into the row above
constexpr float kBoundTop = 0.55f;  // a bound-off lobe's head stays in its cell
constexpr float kDepth = 1.2f;      // front-to-back amplitude, in yarn diameters
// A slip's float passes a diameter behind the loop it holds (a tuck's lies at 0.8 of the depth).
constexpr float kFloatDepth = 1.9f;  // of the depth amplitude
constexpr float kStack = 1.0f;       // stacked loops lie side by side, a yarn diameter apart
// A loop that comes in across a perpendicular edge lies on its side in the taker's cell, so its
// eye already spans the depth a stack needs: at a full diameter apart the taker's yarn passed
// outside it (letter-h's k2togs, 25 loops not held as laid; 7 at half).
constexpr float kSideStack = 0.5f;
constexpr float kWiden = 1.25f;         // an increase's old loop is gripped wider than its lobes
constexpr float kRowsPerStitch = 1.5f;  // rows of this height take yarn sized by the width
// A lobe's legs turn to the depth its taker grips the loop at between these heights of its
// cell (above the old loops' heads, which reach 0.2), then lean over to the grip above them.
constexpr float kTurnFrom = 0.25f;
constexpr float kTurnTo = 0.55f;

struct Sample {
  float x, y, z;
};

struct LobeTable {
  std::array<float, kLobeSamples> u, lean, rise, depth;
};

const LobeTable& lobe_table() {
  static const LobeTable table = [] {
    LobeTable t;
    for (std::uint32_t k = 0; k < kLobeSamples; ++k) {
      float a = 2 * std::numbers::pi_v<float> * static_cast<float>(k) / kLobeSamples;
      t.u[k] = static_cast<float>(k) / kLobeSamples;
      t.lean[k] = kLean * std::sin(2 * a);
      t.rise[k] = (1 - std::cos(a)) / 2;
      t.depth[k] = -std::cos(2 * a);
    }
    return t;
  }();
  return table;
}

// Sample k of lobe j of `lobes` in the stitch's cell; z in model units.
Sample lobe_sample(const StitchTemplate& t, std::uint32_t j, std::uint32_t k, float amplitude) {
  const LobeTable& table = lobe_table();
  float lobes = t.lobes;
  float x = (static_cast<float>(j) + table.u[k] + table.lean[k]) / lobes;
  switch (t.kind) {
    case LobeKind::slipped:
      return {(static_cast<float>(j) + table.u[k]) / lobes, 0.5f, -kFloatDepth * amplitude};
    case LobeKind::tucked:
      return {x, 0.35f + (kHeadTop - 0.35f) * table.rise[k], -0.8f * amplitude};
    case LobeKind::cast_on:
      return {x, 0.1f + (kHeadTop - 0.1f) * table.rise[k], t.side * amplitude * table.depth[k]};
    case LobeKind::bound_off:
      return {x, kDip + (kBoundTop - kDip) * table.rise[k], t.side * amplitude * table.depth[k]};
    case LobeKind::pulled_through:
      break;
  }
  return {x, kDip + (kHeadTop - kDip) * table.rise[k], t.side * amplitude * table.depth[k]};
}

float smoothstep(float a, float b, float v) {
  float t = std::clamp((v - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

bool takes_across_perpendicular_edge(const KnitGraph& graph, StitchId taker) {
  for (std::uint32_t l : graph.loops_taken_by(taker))
    if (graph.loops[l].kind == LoopKind::perpendicular) return true;
  return false;
}

// How far the stitch making the loop in the taker's input slot lies in front of the taker's
// cell (behind it: negative), along its normal; 0 for a loop of no stitch.
float maker_depth(const KnitGraph& graph, const StitchLayout& layout, StitchId taker,
                  std::uint32_t slot) {
  StitchId maker = kNoStitch;
  for (std::uint32_t l : graph.loops_taken_by(taker))
    if (graph.loops[l].taker_slot == slot) maker = graph.loops[l].maker;
  if (maker == kNoStitch) return 0;
  const StitchFrame& f = layout.frame[taker];
  return (layout.frame[maker].at(0.5f, 0.5f, 0) - f.at(0.5f, 0.5f, 0)).dot(f.normal);
}

// The place in the stack of the loop in `slot` of a stitch taking `inputs` loops: by the
// catalogue; a three-needle bind-off's loop whose piece lies in front of the taker's cell or
// behind it (a join's two sides meet at its ridge) more than a quarter row off its surface, on
// that side.
float stack_place(const KnitGraph& graph, const StitchLayout& layout, StitchId taker,
                  std::uint32_t slot, std::uint32_t inputs) {
  const StitchType type = graph.type[taker];
  const float place = stack_position(type, slot, inputs);
  if (info(type).stack != LoopStack::by_side) return place;
  const float depth = maker_depth(graph, layout, taker, slot);
  if (std::abs(depth) < 0.25f * layout.frame[taker].wale.norm()) return place;
  return depth > 0 ? std::abs(place) : -std::abs(place);
}

// Where a stitch grips the old loop in its input slot: the centre and width (in its cell's
// x) the loop's head takes there, how far up the cell it reaches, its offset in depth, and
// the side it pulls its loop to (the old loop's head lies on the other).
struct Grip {
  float centre, width, lift, depth, side;
};

Grip grip(const KnitGraph& graph, const StitchLayout& layout, StitchId taker, std::uint32_t slot,
          float diameter) {
  StitchTemplate t = stitch_template(graph.type[taker]);
  auto inputs = static_cast<std::uint32_t>(graph.loops_taken_by(taker).size());
  std::uint32_t at = layout.right_to_left[taker] ? inputs - 1 - slot : slot;
  float lobes = t.lobes;
  // An unworked or tucked loop is held at the top of the cell with the new one.
  if (t.kind == LobeKind::slipped || t.kind == LobeKind::tucked) return {0.5f, 1, 1, 0, t.side};
  if (inputs == t.lobes) return {(static_cast<float>(at) + 0.5f) / lobes, 1 / lobes, 0, 0, t.side};
  if (inputs > t.lobes) {  // a decrease: the old loops stack on one lobe
    float lobe = std::floor(static_cast<float>(at * t.lobes) / static_cast<float>(inputs));
    float stack = stack_place(graph, layout, taker, slot, inputs) * kStack;
    if (takes_across_perpendicular_edge(graph, taker)) stack *= kSideStack;
    return {(lobe + 0.5f) / lobes, 1 / lobes, 0, stack * diameter, t.side};
  }
  float share = 1.0f / static_cast<float>(inputs);  // an increase: one old loop, many lobes
  return {(static_cast<float>(at) + 0.5f) * share, kWiden * share, 0, 0, t.side};
}

// The lobe j of stitch s, its head bent over to where the loop's taker grips it.
class Lobe {
 public:
  Lobe(const KnitGraph& graph, const StitchLayout& layout, StitchId s, std::uint32_t j,
       float diameter)
      : t_(stitch_template(graph.type[s])),
        frame_(layout.frame[s]),
        amplitude_(kDepth * diameter),
        j_(j),
        centre_((static_cast<float>(j) + 0.5f) / t_.lobes) {
    std::uint32_t slot = layout.right_to_left[s] ? t_.lobes - 1 - j : j;
    const Loop* loop = nullptr;
    for (std::uint32_t l : graph.loops_made_by(s))
      if (lobe_making(graph, l) == slot) loop = &graph.loops[l];
    if (loop && t_.kind != LobeKind::slipped && loop->taker != kNoStitch) {
      taker_ = &layout.frame[loop->taker];
      grip_ = grip(graph, layout, loop->taker, loop->taker_slot, diameter);
      // A stitch beside its taker's cell (AutoKnit's wales lean up to a stitch and a half
      // beside a decrease) turns its legs as they lean over: turned below, they met the heads
      // of the loops stacked with its own (test-A did not relax clear).
      Point3 aside = frame_.at(0.5f, 0.5f, 0) - taker_->at(0.5f, 0.5f, 0);
      turn_from_ = std::abs(aside.dot(taker_->course)) > 0.5f * taker_->course.squaredNorm()
                       ? kTurnTo
                       : kTurnFrom;
      turn_to_ = turn_from_ == kTurnTo ? 1.0f : kTurnTo;
    }
  }

  Point3 at(std::uint32_t k) const {
    Sample p = lobe_sample(t_, j_, k, amplitude_);
    if (!taker_) return frame_.at(p.x, p.y, p.z);
    // The head lies behind the new loop's legs as the taker sees it (a purl takes a knit
    // loop's head in front), at its depth in the taker's stack. The legs turn to that depth
    // above the old loops they pass through and before they lean towards the grip: where the
    // heads of a decrease converge, each loop's legs already lie in front of the loops stacked
    // behind it, so no maker's yarn passes through the eye of a loop stacked with its own.
    float turn = smoothstep(turn_from_, turn_to_, p.y);
    float z = p.z + turn * (p.z * (grip_.side * t_.side - 1) + grip_.depth);
    Point3 own = frame_.at(p.x, p.y, z);
    float w = smoothstep(kTurnTo, 1.0f, p.y);
    if (w == 0) return own;
    float x = grip_.centre + (p.x - centre_) * t_.lobes * grip_.width;
    return (1 - w) * own + w * taker_->at(x, p.y - 1 + grip_.lift, z);
  }

 private:
  StitchTemplate t_;
  const StitchFrame& frame_;
  float amplitude_;
  std::uint32_t j_;
  float centre_;
  const StitchFrame* taker_ = nullptr;
  float turn_from_ = kTurnFrom, turn_to_ = kTurnTo;
  Grip grip_{};
};

// The straight way between two lobes far apart (a turn, a shift-path's step) gets points so
// that no segment is much longer than those of the lobes: how many, and writing them.
std::uint32_t bridge_points(const Point3& from, const Point3& to, float spacing) {
  auto steps = static_cast<std::uint32_t>(std::ceil((to - from).norm() / spacing));
  return steps > 1 ? steps - 1 : 0;
}

void bridge(const Point3& from, const Point3& to, std::uint32_t points, Point3* out) {
  for (std::uint32_t i = 1; i <= points; ++i)
    out[i - 1] = from + (to - from) * (static_cast<float>(i) / static_cast<float>(points + 1));
}

}  // namespace

StitchTemplate stitch_template(StitchType type) {
  const StitchTypeInfo& i = info(type);
  auto lobes = static_cast<std::uint8_t>(std::max<int>(i.loops_out, 1));
  float side = is_purl(type) ? -1.0f : 1.0f;
  if (type == StitchType::sl) return {LobeKind::slipped, side, lobes};
  if (type == StitchType::tuck) return {LobeKind::tucked, side, lobes};
  if (i.loops_in == 0) return {LobeKind::cast_on, side, lobes};
  if (i.loops_out == 0) return {LobeKind::bound_off, side, lobes};
  return {LobeKind::pulled_through, side, lobes};
}

std::uint32_t lobe_making(const KnitGraph& graph, std::uint32_t loop) {
  const Loop& made = graph.loops[loop];
  auto loops = graph.loops_made_by(made.maker);
  if (loops.size() == 1) return 0;  // most stitches: no table look-up
  const bool picks_up = loops.size() > stitch_template(graph.type[made.maker]).lobes;
  auto picked_up = [&](const Loop& l) { return picks_up && l.kind == LoopKind::perpendicular; };
  if (picked_up(made)) return kPickedUp;
  std::uint32_t lobe = 0;  // the maker's own loops left of this one
  for (std::uint32_t l : loops)
    lobe += !picked_up(graph.loops[l]) && graph.loops[l].maker_slot < made.maker_slot;
  return lobe;
}

std::vector<StitchId> yarn_order(const KnitGraph& graph, const YarnPieces& pieces) {
  std::vector<StitchId> order;
  order.reserve(graph.size());
  for (std::uint32_t p = 0; p < pieces.size(); ++p) {
    StitchId s = pieces.first[p];
    for (std::uint32_t i = 0; i < pieces.length[p]; ++i, s = graph.yarn_next[s]) order.push_back(s);
  }
  return order;
}

YarnModel generate_yarn(const KnitGraph& graph, const YarnPieces& pieces,
                        const StitchLayout& layout, const CurveOptions& options) {
  // Yarn as thick as a quarter stitch fits rows 0.7 stitches high (Munden's plain knit);
  // flatter fabric (AutoKnit's rows are half a stitch high) gets yarn sized by its rows.
  const float diameter = options.diameter * std::min(layout.gauge.stitch_width,
                                                     kRowsPerStitch * layout.gauge.row_height);
  const float spacing = diameter / 2;
  const std::vector<StitchId> order = yarn_order(graph, pieces);
  const unsigned threads = options.threads ? options.threads : default_threads();
  auto lobes_of = [&](std::size_t i) { return stitch_template(graph.type[order[i]]).lobes; };
  // Two passes, in parallel, writing every point once in its place: first each stitch's ends
  // (where its yarn comes in and leaves), which size the bridges, then the lobes and bridges.
  std::vector<Point3> first(order.size()), last(order.size());
  parallel_for(order.size(), threads, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t i = begin; i < end; ++i) {
      first[i] = Lobe(graph, layout, order[i], 0, diameter).at(0);
      last[i] = Lobe(graph, layout, order[i], lobes_of(i) - 1, diameter).at(kLobeSamples - 1);
    }
  });
  // at[i]: where stitch i's bridge (from the stitch before it on its piece) begins.
  std::vector<std::uint32_t> at(order.size() + 1, 0);
  YarnModel model;
  model.radius = diameter / 2;
  model.piece_first.push_back(0);
  std::size_t i = 0;
  for (std::uint32_t p = 0; p < pieces.size(); ++p) {
    for (std::uint32_t k = 0; k < pieces.length[p]; ++k, ++i) {
      std::uint32_t gap = k > 0 ? bridge_points(last[i - 1], first[i], spacing) : 0;
      at[i + 1] = at[i] + gap + lobes_of(i) * kLobeSamples;
    }
    model.piece_first.push_back(at[i]);
  }
  model.point.resize(at.back());
  model.stitch_first.assign(graph.size(), kNoPoint);
  model.right_to_left = layout.right_to_left;
  parallel_for(order.size(), threads, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t n = begin; n < end; ++n) {
      std::uint32_t lobes = lobes_of(n), start = at[n + 1] - lobes * kLobeSamples;
      if (start > at[n]) bridge(last[n - 1], first[n], start - at[n], &model.point[at[n]]);
      model.stitch_first[order[n]] = start;
      for (std::uint32_t j = 0; j < lobes; ++j) {
        Lobe lobe(graph, layout, order[n], j, diameter);
        Point3* out = &model.point[start + j * kLobeSamples];
        for (std::uint32_t k = 0; k < kLobeSamples; ++k) out[k] = lobe.at(k);
      }
    }
  });
  return model;
}

}  // namespace skein
