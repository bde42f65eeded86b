#include "yarn/checks.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>

#include "yarn/contacts.hpp"
#include "yarn/parallel.hpp"

namespace skein {
namespace {

// Does segment ab cross triangle pqr (Moller-Trumbore)?
bool crosses(const Point3& a, const Point3& b, const Point3& p, const Point3& q, const Point3& r) {
  const Point3 dir = b - a, e1 = q - p, e2 = r - p;
  const Point3 h = dir.cross(e2);
  const float det = e1.dot(h);
  if (std::abs(det) < 1e-14f) return false;
  const float inv = 1 / det;
  const Point3 s = a - p;
  const float u = inv * s.dot(h);
  if (u < 0 || u > 1) return false;
  const Point3 qv = s.cross(e1);
  const float v = inv * dir.dot(qv);
  if (v < 0 || u + v > 1) return false;
  const float t = inv * e2.dot(qv);
  return t >= 0 && t <= 1;
}

// The eye of a lobe: from the middle of its rising leg over the head to the middle of the
// falling one, as a fan of triangles round its centroid.
struct Eye {
  std::vector<Point3> rim;
  Point3 centre = Point3::Zero();
};

Eye eye_of(const YarnModel& model, std::uint32_t first) {
  Eye eye;
  for (std::uint32_t k = kLobeSamples / 4; k <= 3 * kLobeSamples / 4; ++k)
    eye.rim.push_back(model.point[first + k]);
  for (const Point3& p : eye.rim) eye.centre += p / static_cast<float>(eye.rim.size());
  return eye;
}

int piercings(const Eye& eye, const YarnModel& model, const KnitGraph& graph, StitchId s) {
  std::uint32_t first = model.stitch_first[s];
  if (first == kNoPoint) return 0;
  std::uint32_t count = stitch_template(graph.type[s]).lobes * kLobeSamples;
  int hits = 0;
  for (std::uint32_t i = first; i + 1 < first + count; ++i)
    for (std::size_t k = 0; k < eye.rim.size(); ++k) {
      const Point3& next = eye.rim[(k + 1) % eye.rim.size()];
      hits += crosses(model.point[i], model.point[i + 1], eye.centre, eye.rim[k], next);
    }
  return hits;
}

bool pulls_through(StitchType type) {
  LobeKind kind = stitch_template(type).kind;
  return kind == LobeKind::pulled_through || kind == LobeKind::bound_off;
}

// The first stitch above `taker` along its wale (kNoStitch if none).
StitchId above(const KnitGraph& graph, StitchId taker) {
  for (std::uint32_t l : graph.loops_made_by(taker))
    if (graph.loops[l].taker != kNoStitch) return graph.loops[l].taker;
  return kNoStitch;
}

}  // namespace

Clearance yarn_clearance(const YarnModel& model, float allowed, unsigned threads) {
  threads = threads ? threads : default_threads();
  const float diameter = 2 * model.radius;
  std::vector<SegmentPair> pairs =
      close_segments(model.point, model.piece_first, diameter, diameter, threads);
  Clearance c;
  c.checked = pairs.size();
  for (const SegmentPair& p : pairs) {
    float d = p.distance / diameter;
    c.closest = std::min(c.closest, d);
    c.closer += d < allowed;
  }
  return c;
}

TopologyReport check_yarn_topology(const KnitGraph& graph, const YarnModel& model) {
  TopologyReport report;
  auto note = [&](std::string problem) {
    if (report.first_problem.empty()) report.first_problem = std::move(problem);
  };
  for (std::uint32_t l = 0; l < graph.loops.size(); ++l) {
    const Loop& loop = graph.loops[l];
    if (loop.maker == kNoStitch || loop.taker == kNoStitch) continue;
    StitchTemplate t = stitch_template(graph.type[loop.maker]);
    if (!pulls_through(graph.type[loop.taker]) || t.kind == LobeKind::slipped ||
        t.kind == LobeKind::tucked || model.stitch_first[loop.maker] == kNoPoint)
      continue;
    // The lobe that made the loop (lobes run along the yarn, slots left to right).
    std::uint32_t lobe = lobe_making(graph, l);
    if (lobe == kPickedUp) {
      ++report.picked_up;
      continue;
    }
    if (model.right_to_left[loop.maker]) lobe = t.lobes - 1u - lobe;
    Eye eye = eye_of(model, model.stitch_first[loop.maker] + lobe * kLobeSamples);
    ++report.loops;
    if (piercings(eye, model, graph, loop.taker) == 0) {
      ++report.not_held;
      report.problems.push_back({l});
      note(fmt::format("the loop {} makes is not held by {}", graph.describe(loop.maker),
                       graph.describe(loop.taker)));
    }
    for (StitchId other : {above(graph, loop.taker), graph.yarn_next[loop.maker]}) {
      if (other == kNoStitch || other == loop.taker || piercings(eye, model, graph, other) == 0)
        continue;
      ++report.wrongly_held;
      report.problems.push_back({l, other});
      note(fmt::format("the loop {} makes is held by {} too", graph.describe(loop.maker),
                       graph.describe(other)));
    }
  }
  return report;
}

double yarn_length_per_stitch(const KnitGraph& graph, const YarnModel& model, StitchType type) {
  double length = 0;
  std::uint32_t stitches = 0;
  for (StitchId s = 0; s < graph.size(); ++s) {
    if (graph.type[s] != type || model.stitch_first[s] == kNoPoint) continue;
    std::uint32_t first = model.stitch_first[s];
    std::uint32_t end = first + stitch_template(type).lobes * kLobeSamples;
    // Up to the next stitch's first point, where the yarn goes on.
    end = std::min<std::uint32_t>(end, static_cast<std::uint32_t>(model.point.size()) - 1);
    for (std::uint32_t i = first; i < end; ++i)
      length += (model.point[i + 1] - model.point[i]).norm();
    ++stitches;
  }
  return stitches ? length / stitches : 0;
}

double total_yarn_length(const YarnModel& model) {
  std::vector<std::uint8_t> starts = segment_starts(model.point.size(), model.piece_first);
  double length = 0;
  for (std::size_t i = 0; i + 1 < model.point.size(); ++i)
    if (starts[i]) length += (model.point[i + 1] - model.point[i]).norm();
  return length;
}

}  // namespace skein
