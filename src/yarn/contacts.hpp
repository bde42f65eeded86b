// Yarn-yarn proximity: which segments of the yarn polylines come close to each other. A
// spatial hash on segment pieces (none longer than twice the median segment, so a few long
// bridges do not widen every cell; cells a piece plus the reach wide, counting-sorted into a
// table twice the number of pieces), so a query is linear in yarn length.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "yarn/layout.hpp"

namespace skein {

// Segment i joins point i and i + 1 of one piece.
struct SegmentPair {
  std::uint32_t a, b;  // a < b, more than kNeighbourSegments apart along the points
  float distance;      // their closest distance when found
};
inline constexpr std::uint32_t kNeighbourSegments = 3;

// The closest points of segments p0p1 and q0q1 (Ericson, Real-Time Collision Detection
// §5.1.9): the parameters s, t in [0, 1] and the distance.
struct Closest {
  float s, t, distance;
};
Closest closest_points(const Point3& p0, const Point3& p1, const Point3& q0, const Point3& q1);

// A cheap bound: false when segments a and b (their first points' indices) are surely
// `reach` or more apart (their midpoints farther than the half lengths and the reach).
bool may_touch(std::span<const Point3> point, std::size_t a, std::size_t b, float reach);

// Every pair of segments whose closest distance is below `reach`, but neighbours along a
// piece: fewer than kNeighbourSegments apart, or with less than `along` of yarn between them.
// `piece_first` is the CSR of points per piece (a segment never spans two pieces).
std::vector<SegmentPair> close_segments(std::span<const Point3> point,
                                        std::span<const std::uint32_t> piece_first, float reach,
                                        float along, unsigned threads);

// Per point: 1 when a segment starts there (the point is not its piece's last).
std::vector<std::uint8_t> segment_starts(std::size_t points,
                                         std::span<const std::uint32_t> piece_first);

}  // namespace skein
