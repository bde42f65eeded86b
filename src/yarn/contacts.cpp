#include "yarn/contacts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

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

// A piece of a segment in the hash: a segment longer than the grid's piece length (a bridge
// across a turn, a stretched float) goes in as several pieces, so one long segment does not
// make every cell as wide as itself.
struct Entry {
  std::uint32_t segment;
  Point3 centre;
  float radius;  // bounding sphere of the piece, grown by half the reach
};

// Entries counting-sorted by the bucket of the cell their centre lies in.
struct Grid {
  float cell = 1;
  std::uint64_t mask = 0;
  std::vector<std::uint32_t> first;  // per bucket, CSR into order
  std::vector<std::uint32_t> order;  // entry indices
  std::vector<Entry> entry;
  std::vector<Cell> cell_of;  // per entry

  Cell cell_at(const Point3& p) const {
    return {static_cast<std::int32_t>(std::floor(p.x() / cell)),
            static_cast<std::int32_t>(std::floor(p.y() / cell)),
            static_cast<std::int32_t>(std::floor(p.z() / cell))};
  }
};

std::uint32_t piece_count(float length, float piece) {
  return static_cast<std::uint32_t>(std::max(1.0f, std::ceil(length / piece)));
}

// Pieces at most `piece` long; cells piece + reach wide, so two pieces whose segments come
// within the reach have their centres in neighbouring cells.
Grid build_grid(std::span<const Point3> point, std::span<const std::uint8_t> starts, float piece,
                float reach) {
  Grid g;
  g.cell = piece + reach;
  for (std::size_t i = 0; i + 1 < point.size(); ++i) {
    if (!starts[i]) continue;
    const Point3 along = point[i + 1] - point[i];
    const float length = along.norm();
    const std::uint32_t parts = piece_count(length, piece);
    for (std::uint32_t k = 0; k < parts; ++k)
      g.entry.push_back({static_cast<std::uint32_t>(i),
                         point[i] + along * ((static_cast<float>(k) + 0.5f) / parts),
                         length / (2.0f * parts) + reach / 2});
  }
  std::uint64_t size = 1;
  while (size < 2 * g.entry.size()) size *= 2;
  g.mask = size - 1;
  g.first.assign(size + 1, 0);
  g.cell_of.resize(g.entry.size());
  std::vector<std::uint32_t> bucket(g.entry.size());
  for (std::size_t e = 0; e < g.entry.size(); ++e) {
    g.cell_of[e] = g.cell_at(g.entry[e].centre);
    bucket[e] = static_cast<std::uint32_t>(bucket_of(g.cell_of[e], g.mask));
    ++g.first[bucket[e] + 1];
  }
  for (std::uint64_t b = 0; b < size; ++b) g.first[b + 1] += g.first[b];
  g.order.resize(g.entry.size());
  std::vector<std::uint32_t> fill(g.first.begin(), g.first.end() - 1);
  for (std::size_t e = 0; e < g.entry.size(); ++e)
    g.order[fill[bucket[e]]++] = static_cast<std::uint32_t>(e);
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
  std::vector<float> lengths;
  for (std::size_t i = 0; i + 1 < point.size(); ++i)
    if (starts[i]) lengths.push_back((point[i + 1] - point[i]).norm());
  // Twice the median: nearly every segment is one piece, and cells stay a few segments wide.
  const float piece = 2 * median(lengths, reach);
  const Grid grid = build_grid(point, starts, piece, reach);
  // Each pair of entries once: from a cell to itself (the later entry) and to the 13 cells
  // after it.
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
  auto pieces_of = [&](std::uint32_t i) {
    return piece_count((point[i + 1] - point[i]).norm(), piece) > 1;
  };
  // Pairs of segments with more than one piece may be found once per pair of pieces: kept
  // apart and made unique.
  std::vector<std::vector<SegmentPair>> found(std::max(1u, threads)), repeated(found.size());
  parallel_for(grid.entry.size(), threads, [&](std::size_t begin, std::size_t end, unsigned part) {
    for (std::size_t e = begin; e < end; ++e) {
      const Entry& me = grid.entry[e];
      const Cell c = grid.cell_of[e];
      for (const auto& d : kHalfShell) {
        const Cell n{c.x + d[0], c.y + d[1], c.z + d[2]};
        const bool own = d == kHalfShell[0];
        std::uint64_t b = bucket_of(n, grid.mask);
        for (std::uint32_t k = grid.first[b]; k < grid.first[b + 1]; ++k) {
          std::uint32_t f = grid.order[k];
          const Cell& cf = grid.cell_of[f];
          if (cf.x != n.x || cf.y != n.y || cf.z != n.z || (own && f <= e)) continue;
          const Entry& other = grid.entry[f];
          std::uint32_t lo = std::min(me.segment, other.segment);
          std::uint32_t hi = std::max(me.segment, other.segment);
          if (hi <= lo + kNeighbourSegments) continue;
          float r = me.radius + other.radius;
          if ((me.centre - other.centre).squaredNorm() >= r * r) continue;
          const float distance =
              closest_points(point[lo], point[lo + 1], point[hi], point[hi + 1]).distance;
          if (distance < reach && !close_along_yarn(point, starts, lo, hi, along))
            (pieces_of(lo) || pieces_of(hi) ? repeated : found)[part].push_back({lo, hi, distance});
        }
      }
    }
  });
  std::vector<SegmentPair> pairs, multi;
  for (const auto& part : found) pairs.insert(pairs.end(), part.begin(), part.end());
  for (const auto& part : repeated) multi.insert(multi.end(), part.begin(), part.end());
  auto key = [](const SegmentPair& p) { return std::pair{p.a, p.b}; };
  std::sort(multi.begin(), multi.end(), [&](auto& x, auto& y) { return key(x) < key(y); });
  multi.erase(
      std::unique(multi.begin(), multi.end(), [&](auto& x, auto& y) { return key(x) == key(y); }),
      multi.end());
  pairs.insert(pairs.end(), multi.begin(), multi.end());
  return pairs;
}

}  // namespace skein
