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

std::vector<SegmentPair> close_segments(std::span<const Point3> point,
                                        std::span<const std::uint32_t> piece_first, float reach,
                                        unsigned threads) {
  std::vector<std::uint8_t> starts = segment_starts(point.size(), piece_first);
  float longest = 0;
  for (std::size_t i = 0; i + 1 < point.size(); ++i)
    if (starts[i]) longest = std::max(longest, (point[i + 1] - point[i]).norm());
  const Grid grid = build_grid(point, starts, longest + reach);
  std::vector<std::vector<SegmentPair>> found(std::max(1u, threads));
  parallel_for(point.size(), threads, [&](std::size_t begin, std::size_t end, unsigned part) {
    std::vector<SegmentPair>& out = found[part];
    std::array<std::uint64_t, 27> visited{};
    for (std::size_t i = begin; i < end; ++i) {
      if (!starts[i]) continue;
      const Cell c = grid.cell_of[i];
      int n = 0;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            std::uint64_t b = bucket_of({c.x + dx, c.y + dy, c.z + dz}, grid.mask);
            if (std::find(visited.begin(), visited.begin() + n, b) != visited.begin() + n) continue;
            visited[n++] = b;
            for (std::uint32_t k = grid.first[b]; k < grid.first[b + 1]; ++k) {
              std::uint32_t j = grid.segment[k];
              if (j <= i + kNeighbourSegments) continue;
              Closest cp = closest_points(point[i], point[i + 1], point[j], point[j + 1]);
              if (cp.distance < reach) out.push_back({static_cast<std::uint32_t>(i), j});
            }
          }
    }
  });
  std::vector<SegmentPair> pairs;
  for (const auto& part : found) pairs.insert(pairs.end(), part.begin(), part.end());
  return pairs;
}

}  // namespace skein
