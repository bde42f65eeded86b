#include "yarn/contacts.hpp"

#include <algorithm>
#include <cmath>

#include "yarn/parallel.hpp"

namespace skein {
namespace {

struct Cell {
  std::int32_t x, y, z;
};

std::uint64_t bucket_of(const Cell& c, std::uint64_t mask) {
  auto h = static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.x)) * 73856093u ^
           static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.y)) * 19349663u ^
           static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.z)) * 83492791u;
  return (h ^ (h >> 17)) & mask;
}

// Segments counting-sorted by the bucket of the cell their midpoint lies in.
struct Grid {
  float cell = 1;
  std::uint64_t mask = 0;
  std::vector<std::uint32_t> first;  // per bucket, CSR into segment
  std::vector<std::uint32_t> segment;
  std::vector<Cell> cell_of;  // per point (meaningful where a segment starts)

  Cell cell_at(const Point3& p) const {
    return {static_cast<std::int32_t>(std::floor(p.x() / cell)),
            static_cast<std::int32_t>(std::floor(p.y() / cell)),
            static_cast<std::int32_t>(std::floor(p.z() / cell))};
  }
};

Grid build_grid(std::span<const Point3> point, std::span<const std::uint8_t> starts, float cell) {
  Grid g;
  g.cell = cell;
  std::size_t segments = std::count(starts.begin(), starts.end(), 1);
  std::uint64_t size = 1;
  while (size < 2 * segments) size *= 2;
  g.mask = size - 1;
  g.first.assign(size + 1, 0);
  g.cell_of.resize(point.size());
  std::vector<std::uint32_t> bucket(point.size());
  for (std::size_t i = 0; i < point.size(); ++i) {
    if (!starts[i]) continue;
    g.cell_of[i] = g.cell_at((point[i] + point[i + 1]) / 2);
    bucket[i] = static_cast<std::uint32_t>(bucket_of(g.cell_of[i], g.mask));
    ++g.first[bucket[i] + 1];
  }
  for (std::uint64_t b = 0; b < size; ++b) g.first[b + 1] += g.first[b];
  g.segment.resize(segments);
  std::vector<std::uint32_t> fill(g.first.begin(), g.first.end() - 1);
  for (std::size_t i = 0; i < point.size(); ++i)
    if (starts[i]) g.segment[fill[bucket[i]]++] = static_cast<std::uint32_t>(i);
  return g;
}

}  // namespace

bool may_touch(std::span<const Point3> point, std::size_t a, std::size_t b, float reach) {
  const Point3 ma = point[a] + point[a + 1], mb = point[b] + point[b + 1];  // twice the midpoints
  float bound = (point[a + 1] - point[a]).norm() + (point[b + 1] - point[b]).norm() + 2 * reach;
  return (ma - mb).squaredNorm() < bound * bound;
}

Closest closest_points(const Point3& p0, const Point3& p1, const Point3& q0, const Point3& q1) {
  const Point3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const float a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  constexpr float kTiny = 1e-20f;
  float s = 0, t = 0;
  if (a <= kTiny && e <= kTiny) return {0, 0, r.norm()};
  if (a <= kTiny) {
    t = std::clamp(f / e, 0.0f, 1.0f);
  } else {
    const float c = d1.dot(r);
    if (e <= kTiny) {
      s = std::clamp(-c / a, 0.0f, 1.0f);
    } else {
      const float b = d1.dot(d2), denom = a * e - b * b;
      s = denom > kTiny ? std::clamp((b * f - c * e) / denom, 0.0f, 1.0f) : 0.0f;
      t = (b * s + f) / e;
      if (t < 0)
        t = 0, s = std::clamp(-c / a, 0.0f, 1.0f);
      else if (t > 1)
        t = 1, s = std::clamp((b - c) / a, 0.0f, 1.0f);
    }
  }
  return {s, t, ((p0 + d1 * s) - (q0 + d2 * t)).norm()};
}

std::vector<std::uint8_t> segment_starts(std::size_t points,
                                         std::span<const std::uint32_t> piece_first) {
  std::vector<std::uint8_t> starts(points, 1);
  for (std::size_t p = 1; p < piece_first.size(); ++p)
    if (piece_first[p] > piece_first[p - 1]) starts[piece_first[p] - 1] = 0;
  return starts;
}

namespace {

// Segments lo < hi of one piece with less than `length` of yarn between them are neighbours
// whatever their indices: a straight float's points lie close together (a slip's yarn
// across the back of its cell), and yarn cannot pass through itself there.
bool close_along_yarn(std::span<const Point3> point, std::span<const std::uint8_t> starts,
                      std::uint32_t lo, std::uint32_t hi, float length) {
  constexpr std::uint32_t kLongest = 96;  // segments (a few stitches): bounds the walk
  if (hi - lo > kLongest) return false;
  float between = 0;
  for (std::uint32_t k = lo + 1; k < hi; ++k) {
    if (!starts[k]) return false;  // another piece
    between += (point[k + 1] - point[k]).norm();
    if (between >= length) return false;
  }
  return true;
}

}  // namespace

std::vector<SegmentPair> close_segments(std::span<const Point3> point,
                                        std::span<const std::uint32_t> piece_first, float reach,
                                        float along, unsigned threads) {
  std::vector<std::uint8_t> starts = segment_starts(point.size(), piece_first);
  float longest = 0;
  for (std::size_t i = 0; i + 1 < point.size(); ++i)
    if (starts[i]) longest = std::max(longest, (point[i + 1] - point[i]).norm());
  const Grid grid = build_grid(point, starts, longest + reach);
  // Bounding spheres of the segments, for a one-multiply rejection of most candidates.
  struct Sphere {
    Point3 centre;
    float radius;
  };
  std::vector<Sphere> sphere(point.size());
  for (std::size_t i = 0; i + 1 < point.size(); ++i)
    sphere[i] = {(point[i] + point[i + 1]) / 2, (point[i + 1] - point[i]).norm() / 2 + reach / 2};
  // Each pair once: from a cell to itself (the later segment) and to the 13 cells after it.
  static constexpr std::array<std::array<int, 3>, 14> kHalfShell{{{0, 0, 0},
                                                                  {1, 0, 0},
                                                                  {-1, 1, 0},
                                                                  {0, 1, 0},
                                                                  {1, 1, 0},
                                                                  {-1, -1, 1},
                                                                  {0, -1, 1},
                                                                  {1, -1, 1},
                                                                  {-1, 0, 1},
                                                                  {0, 0, 1},
                                                                  {1, 0, 1},
                                                                  {-1, 1, 1},
                                                                  {0, 1, 1},
                                                                  {1, 1, 1}}};
  std::vector<std::vector<SegmentPair>> found(std::max(1u, threads));
  parallel_for(point.size(), threads, [&](std::size_t begin, std::size_t end, unsigned part) {
    std::vector<SegmentPair>& out = found[part];
    for (std::size_t i = begin; i < end; ++i) {
      if (!starts[i]) continue;
      const Cell c = grid.cell_of[i];
      for (const auto& d : kHalfShell) {
        const Cell n{c.x + d[0], c.y + d[1], c.z + d[2]};
        const bool own = d == kHalfShell[0];
        std::uint64_t b = bucket_of(n, grid.mask);
        for (std::uint32_t k = grid.first[b]; k < grid.first[b + 1]; ++k) {
          std::uint32_t j = grid.segment[k];
          const Cell& cj = grid.cell_of[j];
          if (cj.x != n.x || cj.y != n.y || cj.z != n.z || (own && j <= i)) continue;
          std::uint32_t lo = std::min<std::uint32_t>(static_cast<std::uint32_t>(i), j);
          std::uint32_t hi = std::max<std::uint32_t>(static_cast<std::uint32_t>(i), j);
          if (hi <= lo + kNeighbourSegments) continue;
          float r = sphere[i].radius + sphere[j].radius;
          if ((sphere[i].centre - sphere[j].centre).squaredNorm() >= r * r) continue;
          if (closest_points(point[lo], point[lo + 1], point[hi], point[hi + 1]).distance < reach &&
              !close_along_yarn(point, starts, lo, hi, along))
            out.push_back({lo, hi});
        }
      }
    }
  });
  std::vector<SegmentPair> pairs;
  for (const auto& part : found) pairs.insert(pairs.end(), part.begin(), part.end());
  return pairs;
}

}  // namespace skein
