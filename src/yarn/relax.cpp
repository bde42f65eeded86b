#include "yarn/relax.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "yarn/contacts.hpp"
#include "yarn/parallel.hpp"

namespace skein {
namespace {

constexpr float kClamp = 0.25f;   // largest move per step, in radii
constexpr float kSkin = 1.5f;     // Verlet skin, in radii
constexpr float kFeed = 0.5f;     // share of a stretch the yarn gives in a step
constexpr float kMaxFeed = 1.5f;  // the most a segment grows, of its template length
// Room left for rounding when a pair is skipped on its distance bound, in radii: a skipped
// pair would have been found no closer than a diameter, so the output does not change.
constexpr float kSkipMargin = 0.02f;

class Relaxation {
 public:
  Relaxation(YarnModel& model, const RelaxOptions& options)
      : m_(model),
        o_(options),
        threads_(options.threads ? options.threads : default_threads()),
        diameter_(2 * model.radius),
        starts_(segment_starts(model.point.size(), model.piece_first)),
        anchor_(model.point),
        next_(model.point.size()),
        rest_(model.point.size(), 0),
        moved_(model.point.size(), 0),
        push_(threads_, std::vector<Point3>(model.point.size())),
        touches_(threads_, std::vector<std::uint16_t>(model.point.size())) {
    for (std::size_t i = 0; i + 1 < m_.point.size(); ++i)
      if (starts_[i]) rest_[i] = (m_.point[i + 1] - m_.point[i]).norm();
    template_ = rest_;
  }

  RelaxReport run() {
    auto start = std::chrono::steady_clock::now();
    RelaxReport report;
    float drift = kSkin;  // forces a first build of the pair list
    for (report.steps = 0; report.steps < o_.max_steps;) {
      if (drift >= kSkin / 2) {
        pairs_ = close_segments(m_.point, m_.piece_first, diameter_ + kSkin * m_.radius, diameter_,
                                threads_);
        built_ = m_.point;
        std::fill(moved_.begin(), moved_.end(), 0.0f);
        ++report.pair_builds;
      }
      report.overlap = push_apart();
      move();
      feed_yarn();
      project_lengths();
      report.max_move = clamp_moves();
      drift = farthest_from_build();
      ++report.steps;
      if (o_.progress && report.steps % o_.progress_every == 0)
        o_.progress({report.steps, report.max_move, report.overlap});
      if (report.max_move < o_.tolerance && report.overlap < o_.overlap) {
        report.converged = true;
        break;
      }
    }
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
  }

 private:
  // Each overlapping pair's correction, spread over its segments' ends by where the closest
  // points lie, summed per thread. Returns the deepest overlap in diameters.
  float push_apart() {
    std::vector<float> deepest(threads_, 0);
    parallel_for(m_.point.size(), threads_, [&](std::size_t begin, std::size_t end, unsigned) {
      for (unsigned t = 0; t < threads_; ++t) {
        std::fill(push_[t].begin() + begin, push_[t].begin() + end, Point3::Zero());
        std::fill(touches_[t].begin() + begin, touches_[t].begin() + end, 0);
      }
    });
    const float margin = diameter_ + kSkipMargin * m_.radius;
    parallel_for(pairs_.size(), threads_, [&](std::size_t begin, std::size_t end, unsigned t) {
      std::vector<Point3>& push = push_[t];
      std::vector<std::uint16_t>& touches = touches_[t];
      for (std::size_t k = begin; k < end; ++k) {
        const auto [a, b, found_at] = pairs_[k];
        // No point of a segment has moved farther than its farther end since the pairs were
        // found, so the pair is no closer than found_at less both ends' moves: most pairs of
        // the list (a skin wider than the contact) need no closer look.
        if (found_at - std::max(moved_[a], moved_[a + 1]) - std::max(moved_[b], moved_[b + 1]) >=
            margin)
          continue;
        const Point3 &p0 = m_.point[a], &p1 = m_.point[a + 1];
        const Point3 &q0 = m_.point[b], &q1 = m_.point[b + 1];
        if (!may_touch(m_.point, a, b, diameter_)) continue;
        Closest c = closest_points(p0, p1, q0, q1);
        if (c.distance >= diameter_ || c.distance < 1e-9f) continue;
        Point3 n = ((p0 + (p1 - p0) * c.s) - (q0 + (q1 - q0) * c.t)) / c.distance;
        float depth = diameter_ - c.distance;
        deepest[t] = std::max(deepest[t], depth);
        float weight = (1 - c.s) * (1 - c.s) + c.s * c.s + (1 - c.t) * (1 - c.t) + c.t * c.t;
        Point3 lambda = n * (depth / weight);
        push[a] += (1 - c.s) * lambda, push[a + 1] += c.s * lambda;
        push[b] -= (1 - c.t) * lambda, push[b + 1] -= c.t * lambda;
        for (std::uint32_t v : {a, a + 1, b, b + 1})
          touches[v] = static_cast<std::uint16_t>(std::min(touches[v] + 1, 60000));
      }
    });
    return *std::max_element(deepest.begin(), deepest.end()) / diameter_;
  }

  // Jacobi: contact, bending and anchor moves from the same positions into next_.
  void move() {
    const std::size_t n = m_.point.size();
    parallel_for(n, threads_, [&](std::size_t begin, std::size_t end, unsigned) {
      for (std::size_t i = begin; i < end; ++i) {
        Point3 push = Point3::Zero();
        int touches = 0;
        for (unsigned t = 0; t < threads_; ++t) push += push_[t][i], touches += touches_[t][i];
        Point3 x = m_.point[i];
        Point3 d = touches ? Point3(push / static_cast<float>(touches)) : Point3::Zero();
        d += o_.bend * bending(i);
        d += o_.anchor * (anchor_[i] - x);
        next_[i] = x + d;
      }
    });
  }

  // Where contact stretches a segment, the yarn gives a little (up to kMaxFeed of its
  // template length): a thicker yarn than the template's room needs more length per stitch.
  void feed_yarn() {
    parallel_for(next_.size(), threads_, [&](std::size_t begin, std::size_t end, unsigned) {
      for (std::size_t i = begin; i < end; ++i) {
        if (!starts_[i] || i + 1 >= next_.size()) continue;
        float length = (next_[i + 1] - next_[i]).norm();
        rest_[i] =
            std::clamp(rest_[i] + kFeed * (length - rest_[i]), rest_[i], kMaxFeed * template_[i]);
      }
    });
  }

  // Towards the cubic through the two neighbours on each side: takes out kinks and zigzags
  // but leaves a loop's even curvature alone (a plain neighbour average would shrink loops).
  // Next to a piece's end, towards the neighbours' midpoint.
  Point3 bending(std::size_t i) const {
    const auto& x = m_.point;
    bool inner = i > 0 && starts_[i - 1] && starts_[i];
    if (!inner) return Point3::Zero();
    bool wide = i > 1 && starts_[i - 2] && i + 2 < x.size() && starts_[i + 1];
    if (!wide) return (x[i - 1] + x[i + 1]) / 2 - x[i];
    return (4 * (x[i - 1] + x[i + 1]) - x[i - 2] - x[i + 2]) / 6 - x[i];
  }

  // Red-black Gauss-Seidel on |x_{i+1} - x_i| = rest_i: even segments, then odd ones.
  void project_lengths() {
    const std::size_t n = next_.size();
    for (int sweep = 0; sweep < o_.length_sweeps; ++sweep)
      for (std::size_t parity = 0; parity < 2; ++parity)
        parallel_for(n / 2 + 1, threads_, [&](std::size_t begin, std::size_t end, unsigned) {
          for (std::size_t k = begin; k < end; ++k) {
            std::size_t i = 2 * k + parity;
            if (i + 1 >= n || !starts_[i]) continue;
            Point3 e = next_[i + 1] - next_[i];
            float length = e.norm();
            if (length < 1e-12f) continue;
            Point3 c = e * ((length - rest_[i]) / length / 2);
            next_[i] += c;
            next_[i + 1] -= c;
          }
        });
  }

  // No point moves more than kClamp radii in a step; returns the largest move, in radii.
  float clamp_moves() {
    const float limit = kClamp * m_.radius;
    std::vector<float> largest(threads_, 0);
    parallel_for(next_.size(), threads_, [&](std::size_t begin, std::size_t end, unsigned t) {
      for (std::size_t i = begin; i < end; ++i) {
        Point3 d = next_[i] - m_.point[i];
        float length = d.norm();
        if (length > limit) d *= limit / length, length = limit;
        m_.point[i] += d;
        largest[t] = std::max(largest[t], length);
      }
    });
    return *std::max_element(largest.begin(), largest.end()) / m_.radius;
  }

  // How far each point lies from where it was when the pair list was built (kept for the
  // pair skip) and the farthest, in radii: no pair closer than the reach can have come from
  // outside the list while no point has moved half the skin (summing each step's largest
  // move instead rebuilt the list nearly every step, as different points moved most).
  float farthest_from_build() {
    std::vector<float> farthest(threads_, 0);
    parallel_for(built_.size(), threads_, [&](std::size_t begin, std::size_t end, unsigned t) {
      for (std::size_t i = begin; i < end; ++i) {
        moved_[i] = (m_.point[i] - built_[i]).norm();
        farthest[t] = std::max(farthest[t], moved_[i]);
      }
    });
    return *std::max_element(farthest.begin(), farthest.end()) / m_.radius;
  }

  YarnModel& m_;
  const RelaxOptions& o_;
  unsigned threads_;
  float diameter_;
  std::vector<std::uint8_t> starts_;
  std::vector<Point3> anchor_, next_, built_;
  std::vector<float> rest_, template_;
  std::vector<float> moved_;  // per point, since the pair list was built
  std::vector<std::vector<Point3>> push_;
  std::vector<std::vector<std::uint16_t>> touches_;
  std::vector<SegmentPair> pairs_;
};

}  // namespace

RelaxReport relax_yarn(YarnModel& model, const RelaxOptions& options) {
  if (model.point.size() < 2) return {};
  return Relaxation(model, options).run();
}

}  // namespace skein
